// Extremals of quadratic energies (solvers/extremal.h): tensor and triangular nets.
#include "bindings.h"

#include "bezierpde/solvers/extremal.h"

namespace bpde::python {

void bind_extremal(py::module_& m) {
  py::class_<bpde::ExtremalOptions>(m, "ExtremalOptions",
                                    "Options of solve_extremal and ExtremalSolver (solvers/extremal.h).")
      .def(py::init<>())
      .def_readwrite("singular_tolerance", &bpde::ExtremalOptions::singular_tolerance,
                     "Smallest accepted reciprocal condition number of the reduced system, in [0, 1) (1e-13).")
      .def_readwrite("conditioned_basis", &bpde::ExtremalOptions::conditioned_basis,
                     "Tensor nets: assemble in the conditioned (Gegenbauer) basis (True).")
      .def_readwrite("use_cache", &bpde::ExtremalOptions::use_cache,
                     "Tensor nets: reuse a process-wide cache of factored solvers (False).")
      .def("validate", &bpde::ExtremalOptions::validate, "Raises ParameterError naming a bad field.");
  py::class_<bpde::ExtremalResult>(m, "ExtremalResult", "A tensor extremal: net, energy, summary.")
      .def_readonly("net", &bpde::ExtremalResult::net)
      .def_readonly("energy", &bpde::ExtremalResult::energy)
      .def_readonly("summary", &bpde::ExtremalResult::summary);
  py::class_<bpde::TriangularExtremalResult>(m, "TriangularExtremalResult",
                                             "A triangular extremal: net, energy, summary.")
      .def_readonly("net", &bpde::TriangularExtremalResult::net)
      .def_readonly("energy", &bpde::TriangularExtremalResult::energy)
      .def_readonly("summary", &bpde::TriangularExtremalResult::summary);
  m.def(
      "solve_extremal",
      [](const bpde::TensorNet& data, py::handle energy, const Text& fixed, const bpde::ExtremalOptions& options) {
        const bpde::EnergySpec spec = energy_arg(energy);
        const bpde::FixedSet f = parse_fixed(text(fixed, "fixed"));
        py::gil_scoped_release release;
        InterruptibleSolve ctrl_c;
        return bpde::solve_extremal(data, spec, f, options);
      },
      py::arg("data"), py::arg("energy"), py::arg("fixed") = "boundary", py::arg("options") = bpde::ExtremalOptions(),
      "The minimiser of a quadratic energy over the free control points, the `fixed` points of `data` "
      "prescribed (FORMATS.md problem \"extremal\") -> ExtremalResult, or TriangularExtremalResult for a "
      "TriangularNet. `energy` is a name or an ENERGY dict.");
  m.def(
      "solve_extremal",
      [](const bpde::TriangularNet& data, py::handle energy, const Text& fixed, const bpde::ExtremalOptions& options) {
        const bpde::EnergySpec spec = energy_arg(energy);
        const bpde::FixedSet f = parse_fixed(text(fixed, "fixed"));
        check_limits(bpde::extremal_requirements(), {bpde::NetKind::Triangular, data.n(), data.n()}, f, "",
                     "solve_extremal");
        py::gil_scoped_release release;
        InterruptibleSolve ctrl_c;
        return bpde::solve_extremal(data, spec, f, options);
      },
      py::arg("data"), py::arg("energy"), py::arg("fixed") = "boundary", py::arg("options") = bpde::ExtremalOptions());
  py::class_<bpde::ExtremalSolver>(
      m, "ExtremalSolver",
      "A factored extremal problem (solvers/extremal.h): X_free = mould @ X_fixed, one product per boundary.")
      .def(py::init([](py::handle energy, int n, int m, const Text& fixed, const bpde::ExtremalOptions& o) {
             const bpde::EnergySpec spec = energy_arg(energy);
             const bpde::FixedSet f = parse_fixed(text(fixed, "fixed"));
             py::gil_scoped_release release;
             InterruptibleSolve ctrl_c;
             return bpde::ExtremalSolver(spec, n, m, f, o);
           }),
           py::arg("energy"), py::arg("n"), py::arg("m"), py::arg("fixed") = "boundary",
           py::arg("options") = bpde::ExtremalOptions(), "Tensor nets of degree (n, m).")
      .def(py::init([](py::handle gram, std::vector<int> fixed, const bpde::ExtremalOptions& o) {
             // A 2-d array (SizeError naming `gram` otherwise, as points_arg does for N x 3).
             using Array = py::array_t<double, py::array::f_style | py::array::forcecast>;
             const Array a = Array::ensure(gram);
             if (!a) throw bpde::ParseError("gram: expected an array of numbers");
             if (a.ndim() != 2)  // (a non-square one is the solver's SizeError)
               throw bpde::SizeError("gram: expected an array of shape (N, N), got shape " +
                                     py::repr(a.attr("shape")).cast<std::string>());
             const Eigen::MatrixXd Q = Eigen::Map<const Eigen::MatrixXd>(a.data(), a.shape(0), a.shape(1));
             require_finite(Q, "gram");
             py::gil_scoped_release release;
             InterruptibleSolve ctrl_c;
             return bpde::ExtremalSolver(Q, std::move(fixed), o);
           }),
           py::arg("gram"), py::arg("fixed_indices"), py::arg("options") = bpde::ExtremalOptions(),
           "Generic: an N x N Gram matrix and the prescribed point indices.")
      .def_property_readonly("size", &bpde::ExtremalSolver::size)
      .def_property_readonly("fixed_indices", &bpde::ExtremalSolver::fixed_indices)
      .def_property_readonly("free_indices", &bpde::ExtremalSolver::free_indices)
      .def_property_readonly("mould", &bpde::ExtremalSolver::mould, py::return_value_policy::reference_internal,
                             "#free x #fixed (read-only view).")
      .def_property_readonly("gram", &bpde::ExtremalSolver::gram, py::return_value_policy::reference_internal)
      .def(
          "solve",
          [](const bpde::ExtremalSolver& s, py::handle points) {
            const Eigen::MatrixX3d P = points_arg<3>(points, "points", s.size());
            Eigen::MatrixX3d X;
            {
              py::gil_scoped_release release;
              X = s.solve(P);
            }
            return adopt(std::move(X));
          },
          py::arg("points"), "The extremal's points (N x 3) for the fixed rows of `points` (N x 3).")
      .def(
          "reduced_residual",
          [](const bpde::ExtremalSolver& s, py::handle points) {
            return s.reduced_residual(points_arg<3>(points, "points", s.size()));
          },
          py::arg("points"))
      .def(
          "extremal_energy",
          [](const bpde::ExtremalSolver& s, py::handle points) {
            return s.extremal_energy(points_arg<3>(points, "points", s.size()));
          },
          py::arg("points"))
      .def(
          "energy",
          [](const bpde::ExtremalSolver& s, py::handle points) {
            return s.energy(points_arg<3>(points, "points", s.size()));
          },
          py::arg("points"));
}

}  // namespace bpde::python
