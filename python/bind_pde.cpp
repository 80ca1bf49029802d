// Polynomial PDE solutions (solvers/pde/) and C1 surfaces (solvers/c1/) with their Options.
#include "bindings.h"

#include "bezierpde/solvers/c1/clamped_plate.h"
#include "bezierpde/solvers/c1/tetraharmonic.h"
#include "bezierpde/solvers/pde/pde_explicit.h"
#include "bezierpde/solvers/pde/pde_lu.h"

namespace bpde::python {

void bind_pde(py::module_& m) {
  py::class_<bpde::PdeExplicitOptions>(m, "PdeExplicitOptions")
      .def(py::init<>())
      .def_readwrite("singular_tolerance", &bpde::PdeExplicitOptions::singular_tolerance)
      .def_readwrite("rank_tolerance", &bpde::PdeExplicitOptions::rank_tolerance);
  py::class_<bpde::PdeLuOptions>(m, "PdeLuOptions")
      .def(py::init<>())
      .def_property(
          "formulation",
          [](const bpde::PdeLuOptions& o) {
            return o.formulation == bpde::PdeLuOptions::Formulation::Bernstein ? "bernstein" : "anti-diagonal";
          },
          [](bpde::PdeLuOptions& o, const Text& t) {
            const std::string s = text(t, "formulation");
            if (s == "bernstein")
              o.formulation = bpde::PdeLuOptions::Formulation::Bernstein;
            else if (s == "anti-diagonal")
              o.formulation = bpde::PdeLuOptions::Formulation::AntiDiagonal;
            else
              throw bpde::ParameterError("formulation: expected \"anti-diagonal\" or \"bernstein\", got \"" + s + "\"");
          })
      .def_readwrite("compatibility_tolerance", &bpde::PdeLuOptions::compatibility_tolerance)
      .def_readwrite("rank_tolerance", &bpde::PdeLuOptions::rank_tolerance);
  m.def(
      "solve_pde_explicit",
      [](const bpde::TensorNet& data, py::handle op, const bpde::PdeExplicitOptions& options) {
        const bpde::EnergySpec spec = energy_arg(op);
        py::gil_scoped_release release;
        bpde::PdeSolution s = bpde::solve_pde_explicit(data, spec, options);
        return std::make_pair(std::move(s.net), s.summary);
      },
      py::arg("data"), py::arg("operator"), py::arg("options") = bpde::PdeExplicitOptions(),
      "Explicit polynomial PDE solution (solvers/pde/pde_explicit.h) -> (TensorNet, Summary).");
  m.def(
      "solve_pde_lu",
      [](const bpde::TensorNet& data, py::handle op, const bpde::PdeLuOptions& options) {
        const bpde::EnergySpec spec = energy_arg(op);
        py::gil_scoped_release release;
        bpde::PdeSolution s = bpde::solve_pde_lu(data, spec, options);
        return std::make_pair(std::move(s.net), s.summary);
      },
      py::arg("data"), py::arg("operator"), py::arg("options") = bpde::PdeLuOptions(),
      "PDE solution by the block LU (solvers/pde/pde_lu.h) -> (TensorNet, Summary).");

  py::class_<bpde::TetraharmonicOptions>(m, "TetraharmonicOptions")
      .def(py::init<>())
      .def_property(
          "method",
          [](const bpde::TetraharmonicOptions& o) {
            return o.method == bpde::TetraharmonicOptions::Method::Explicit ? "explicit" : "lu";
          },
          [](bpde::TetraharmonicOptions& o, const Text& t) {
            const std::string s = text(t, "method");
            o.method = bpde::parse_tetraharmonic_method(s);
          });
  m.def(
      "solve_tetraharmonic",
      [](const bpde::TensorNet& data, const bpde::TetraharmonicOptions& options) {
        check_limits(bpde::tetraharmonic_requirements(), {bpde::NetKind::Tensor, data.n(), data.m()},
                     bpde::FixedSet::BoundaryAdjacent, "", "solve_tetraharmonic");
        py::gil_scoped_release release;
        InterruptibleSolve ctrl_c;
        bpde::TetraharmonicResult r = bpde::solve_tetraharmonic(data, options);
        return std::make_pair(std::move(r.net), r.summary);
      },
      py::arg("data"), py::arg("options") = bpde::TetraharmonicOptions(),
      "Tetraharmonic C1 surface (C1 methods, Theorem 1) -> (TensorNet, Summary).");

  py::class_<bpde::ClampedPlateOptions>(m, "ClampedPlateOptions")
      .def(py::init<>())
      .def_readwrite("aspect", &bpde::ClampedPlateOptions::aspect)
      .def_readwrite("degree", &bpde::ClampedPlateOptions::degree)
      .def_property(
          "method",
          [](const bpde::ClampedPlateOptions& o) {
            return o.method == bpde::ClampedPlateOptions::Method::AdmissibleLoad ? "admissible-load" : "ritz";
          },
          [](bpde::ClampedPlateOptions& o, const Text& t) {
            const std::string s = text(t, "method");
            o.method = bpde::parse_plate_method(s);
          });
  py::class_<bpde::ClampedPlateResult>(m, "ClampedPlateResult")
      .def_readonly("center_deflection", &bpde::ClampedPlateResult::center_deflection)
      .def_readonly("energy", &bpde::ClampedPlateResult::energy)
      .def_readonly("net", &bpde::ClampedPlateResult::net)
      .def_readonly("load", &bpde::ClampedPlateResult::load)
      .def_readonly("summary", &bpde::ClampedPlateResult::summary);
  m.def("solve_clamped_plate", &bpde::solve_clamped_plate, py::arg("options"), py::call_guard<py::gil_scoped_release>(),
        "Clamped plate under uniform load (C1 methods §6).");
}

}  // namespace bpde::python
