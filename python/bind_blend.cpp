// Smoothing PDE splines (solvers/blend/smoothing_spline.h): the blend of `bpde blend`.
#include "bindings.h"

#include "bezierpde/io/blend_config.h"
#include "bezierpde/solvers/blend/smoothing_spline.h"

namespace bpde::python {

namespace {

// A matrix field of a C++ struct as a property: a read-only numpy view of it, set from any array
// of shape (N, C) (SizeError otherwise).
template <int C, auto Field, class T>
void matrix_field(py::class_<T>& c, const char* name, const char* doc) {
  c.def_property(
      name, [](const T& t) -> const Eigen::Matrix<double, Eigen::Dynamic, C>& { return t.*Field; },
      [name](T& t, py::handle a) { t.*Field = points_arg<C>(a, name); }, py::return_value_policy::reference_internal,
      doc);
}

}  // namespace

void bind_blend(py::module_& m) {
  py::class_<bpde::SmoothingSplineProblem> spline_problem(
      m, "SmoothingSplineProblem",
      "The data of a discrete smoothing PDE spline (smoothing PDE splines, eq. (6)): partition k x l, a, "
      "epsilon, the edges y = 0 and y = 1 ((k+1) x 3 values and d/dy), approximation points (m x 2) and "
      "their data (m x 3), an optional load f(x, y) -> 3 numbers.");
  spline_problem.def(py::init<>())
      .def_static(
          "from_config",
          [](py::handle config) { return bpde::blend_config_from_json(to_json(config, "config")).problem; },
          py::arg("config"), "The problem of a blend CONFIG dict (FORMATS.md; \"edges\" or \"surfaces\").")
      .def_readwrite("k", &bpde::SmoothingSplineProblem::k, "Intervals in x (8).")
      .def_readwrite("l", &bpde::SmoothingSplineProblem::l, "Intervals in y (4).")
      .def_readwrite("a", &bpde::SmoothingSplineProblem::a, "The operator's a, in [1e-6, 1e6] (1).")
      .def_readwrite("epsilon", &bpde::SmoothingSplineProblem::epsilon, "epsilon > 0 (1).")
      .def_readwrite("load", &bpde::SmoothingSplineProblem::load,
                     "f(x, y) -> (3,) or None (f = 0); called with the GIL held.")
      .def("validate", &bpde::SmoothingSplineProblem::validate, "Raises the InvalidInput subclass naming a bad field.");
  matrix_field<3, &bpde::SmoothingSplineProblem::y0_value>(spline_problem, "y0_value",
                                                           "Values at the k+1 nodes of y = 0, (k+1) x 3.");
  matrix_field<3, &bpde::SmoothingSplineProblem::y0_dy>(spline_problem, "y0_dy",
                                                        "d/dy at the k+1 nodes of y = 0, (k+1) x 3.");
  matrix_field<3, &bpde::SmoothingSplineProblem::y1_value>(spline_problem, "y1_value",
                                                           "Values at the k+1 nodes of y = 1, (k+1) x 3.");
  matrix_field<3, &bpde::SmoothingSplineProblem::y1_dy>(spline_problem, "y1_dy",
                                                        "d/dy at the k+1 nodes of y = 1, (k+1) x 3.");
  matrix_field<2, &bpde::SmoothingSplineProblem::points>(spline_problem, "points",
                                                         "Approximation points (x, y) in [0,1]^2, m x 2.");
  matrix_field<3, &bpde::SmoothingSplineProblem::data>(spline_problem, "data", "Their data, m x 3.");
  py::class_<bpde::SmoothingSplineOptions>(m, "SmoothingSplineOptions", "Options of solve_smoothing_spline.")
      .def(py::init<>())
      .def_property(
          "method",
          [](const bpde::SmoothingSplineOptions& o) {
            return o.method == bpde::SmoothingSplineOptions::Method::kElimination ? "elimination" : "kkt-lu";
          },
          [](bpde::SmoothingSplineOptions& o, const Text& t) {
            const std::string s = text(t, "method");
            if (s == "elimination")
              o.method = bpde::SmoothingSplineOptions::Method::kElimination;
            else if (s == "kkt-lu")
              o.method = bpde::SmoothingSplineOptions::Method::kKktLu;
            else
              throw bpde::ParameterError("method: expected \"elimination\" or \"kkt-lu\", got \"" + s + "\"");
          },
          "\"elimination\" (default: reduced SPD system, sparse Cholesky) or \"kkt-lu\" (eq. (8), sparse LU).")
      .def_readwrite("load_quadrature", &bpde::SmoothingSplineOptions::load_quadrature,
                     "Gauss points per direction and element for the load, 1..50 (6).")
      .def_readwrite("threaded_factorization", &bpde::SmoothingSplineOptions::threaded_factorization,
                     "Let CHOLMOD's factorisation run its OpenMP threads (False: they cost more CPU than they "
                     "save on blend systems, docs/performance_measurements.md, \"Blend\").")
      .def("validate", &bpde::SmoothingSplineOptions::validate, "Raises ParameterError naming a bad field.");
  py::class_<bpde::SmoothingSpline>(m, "SmoothingSpline", "The C1 bicubic (BFS) spline on [0,1]^2.")
      .def_property_readonly(
          "coefficients", [](const bpde::SmoothingSpline& s) -> const Eigen::MatrixX3d& { return s.coefficients(); },
          py::return_value_policy::reference_internal, "num_dofs x 3 in the dof order of the BFS space (read-only).")
      .def("evaluate", &bpde::SmoothingSpline::evaluate, py::arg("x"), py::arg("y"), py::arg("dx") = 0,
           py::arg("dy") = 0)
      .def(
          "sample",
          [](const bpde::SmoothingSpline& s, int samples) {
            bpde::TriangleMesh mesh;
            {
              py::gil_scoped_release release;
              mesh = s.sample(samples);
            }
            return mesh_tuple(std::move(mesh));
          },
          py::arg("samples") = 50, "(V, F, H) as `bpde blend` samples the surface.")
      .def("to_bspline_net", &bpde::SmoothingSpline::to_bspline_net, "The same surface as a bicubic BSplineNet.");
  py::class_<bpde::SmoothingSplineResult>(m, "SmoothingSplineResult")
      .def_readonly("spline", &bpde::SmoothingSplineResult::spline)
      .def_readonly("functional", &bpde::SmoothingSplineResult::functional, "J of eq. (6).")
      .def_readonly("data_misfit", &bpde::SmoothingSplineResult::data_misfit)
      .def_readonly("energy", &bpde::SmoothingSplineResult::energy, "|sigma|_L^2.")
      .def_readonly("max_data_error", &bpde::SmoothingSplineResult::max_data_error)
      .def_readonly("multipliers", &bpde::SmoothingSplineResult::multipliers, "4(k+1) x 3.")
      .def_readonly("summary", &bpde::SmoothingSplineResult::summary);
  m.def("solve_smoothing_spline", &bpde::solve_smoothing_spline, py::arg("problem"),
        py::arg("options") = bpde::SmoothingSplineOptions(), py::call_guard<py::gil_scoped_release, InterruptibleSolve>(),
        "The discrete smoothing PDE spline (Theorem 6, eq. (8)) -> SmoothingSplineResult.");
  py::class_<bpde::SmoothingSplineSolver>(m, "SmoothingSplineSolver",
                                          "Assembled and factored once for a partition, a, epsilon and points.")
      .def(py::init<const bpde::SmoothingSplineProblem&, const bpde::SmoothingSplineOptions&>(), py::arg("problem"),
           py::arg("options") = bpde::SmoothingSplineOptions(), py::call_guard<py::gil_scoped_release, InterruptibleSolve>())
      .def("solve", &bpde::SmoothingSplineSolver::solve, py::arg("problem"), py::call_guard<py::gil_scoped_release, InterruptibleSolve>(),
           "Solve for the edges, data and load of `problem` (same k, l, a, epsilon, points).");
}

}  // namespace bpde::python
