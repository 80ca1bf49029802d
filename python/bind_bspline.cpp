// B-spline nets (solvers/bspline/): extremals and PDE solutions.
#include "bindings.h"

#include <optional>
#include <vector>

#include "bezierpde/solvers/bspline/bspline_extremal.h"
#include "bezierpde/solvers/bspline/bspline_pde.h"

namespace bpde::python {

void bind_bspline(py::module_& m) {
  py::class_<bpde::BSplineExtremalOptions>(m, "BSplineExtremalOptions",
                                           "Options of solve_bspline_extremal (solvers/bspline/bspline_extremal.h).")
      .def(py::init<>())
      .def_property(
          "fixed", [](const bpde::BSplineExtremalOptions& o) { return bpde::to_string(o.fixed); },
          [](bpde::BSplineExtremalOptions& o, const Text& t) {
            const std::string s = text(t, "fixed");
            o.fixed = parse_fixed(s);
          },
          "\"boundary\" (default), \"boundary+adjacent\" or \"u-boundaries\".")
      .def_readwrite("tolerance", &bpde::BSplineExtremalOptions::tolerance,
                     "Relative residual above which the solve fails, in (0, 1) (1e-11).")
      .def("validate", &bpde::BSplineExtremalOptions::validate, "Raises ParameterError naming a bad field.");
  py::class_<bpde::BSplineExtremalResult>(m, "BSplineExtremalResult", "A B-spline extremal: net, energy, summary.")
      .def_readonly("net", &bpde::BSplineExtremalResult::net)
      .def_readonly("energy", &bpde::BSplineExtremalResult::energy)
      .def_readonly("summary", &bpde::BSplineExtremalResult::summary);
  m.def(
      "solve_bspline_extremal",
      [](const bpde::BSplineNet& data, py::handle energy, const bpde::BSplineExtremalOptions& options,
         std::optional<std::vector<int>> fixed_indices) {
        const bpde::EnergySpec spec = energy_arg(energy);
        py::gil_scoped_release release;
        return fixed_indices ? bpde::solve_bspline_extremal(data, spec, *fixed_indices, options)
                             : bpde::solve_bspline_extremal(data, spec, options);
      },
      py::arg("data"), py::arg("energy"), py::arg("options") = bpde::BSplineExtremalOptions(),
      py::arg("fixed_indices") = py::none(),
      "Extremal of a quadratic energy on a B-spline net -> BSplineExtremalResult. The prescribed points are "
      "options.fixed, or the strictly increasing indices i*nv + j of `fixed_indices` when given.");
  py::class_<bpde::BSplinePdeOptions>(m, "BSplinePdeOptions",
                                      "Options of solve_bspline_pde (solvers/bspline/bspline_pde.h).")
      .def(py::init<>())
      .def_property(
          "fixed", [](const bpde::BSplinePdeOptions& o) { return bpde::to_string(o.fixed); },
          [](bpde::BSplinePdeOptions& o, const Text& t) {
            const std::string s = text(t, "fixed");
            o.fixed = parse_fixed(s);
          },
          "\"boundary\" (default), \"boundary+adjacent\" or \"u-boundaries\" (second order only).")
      .def_readwrite("rank_tolerance", &bpde::BSplinePdeOptions::rank_tolerance, "In (0, 1) (1e-10).")
      .def_readwrite("consistency_tolerance", &bpde::BSplinePdeOptions::consistency_tolerance, "In (0, 1) (1e-10).")
      .def("validate", &bpde::BSplinePdeOptions::validate, "Raises ParameterError naming a bad field.");
  py::class_<bpde::BSplinePdeResult>(m, "BSplinePdeResult",
                                     "A B-spline PDE solution: net, summary, equations, ranks, free parameters, ...")
      .def_readonly("net", &bpde::BSplinePdeResult::net)
      .def_readonly("summary", &bpde::BSplinePdeResult::summary)
      .def_readonly("equations", &bpde::BSplinePdeResult::equations)
      .def_readonly("rank", &bpde::BSplinePdeResult::rank)
      .def_readonly("rank_free", &bpde::BSplinePdeResult::rank_free)
      .def_readonly("free_parameters", &bpde::BSplinePdeResult::free_parameters)
      .def_readonly("compatibility_conditions", &bpde::BSplinePdeResult::compatibility_conditions)
      .def_readonly("minimum_energy_member", &bpde::BSplinePdeResult::minimum_energy_member)
      .def_readonly("energy", &bpde::BSplinePdeResult::energy);
  m.def(
      "solve_bspline_pde",
      [](const bpde::BSplineNet& data, py::handle op, const bpde::BSplinePdeOptions& options,
         std::optional<std::vector<int>> fixed_indices) {
        const bpde::EnergySpec spec = energy_arg(op);
        py::gil_scoped_release release;
        return fixed_indices ? bpde::solve_bspline_pde(data, spec, *fixed_indices, options)
                             : bpde::solve_bspline_pde(data, spec, options);
      },
      py::arg("data"), py::arg("operator"), py::arg("options") = bpde::BSplinePdeOptions(),
      py::arg("fixed_indices") = py::none(),
      "B-spline solution of the Euler-Lagrange PDE of `operator` (B-spline Euler-Lagrange, Algorithms 1-2) -> "
      "BSplinePdeResult; converged False with a message (status Incompatible) when the data admit no solution.");
}

}  // namespace bpde::python
