// Status and Summary (solvers/summary.h): how every solve ends.
#include "bindings.h"

#include "bezierpde/solvers/summary.h"

namespace bpde::python {

void bind_summary(py::module_& m) {
  py::enum_<bpde::Status>(m, "Status", "Why a solve ended (solvers/summary.h).")
      .value("Converged", bpde::Status::Converged)
      .value("NotUnique", bpde::Status::NotUnique)
      .value("Incompatible", bpde::Status::Incompatible)
      .value("Fold", bpde::Status::Fold)
      .value("NoConvergence", bpde::Status::NoConvergence)
      .value("NumericalLimit", bpde::Status::NumericalLimit)
      .def_property_readonly(
          "text", [](bpde::Status s) { return std::string(bpde::to_string(s)); },
          "The FORMATS.md name: \"converged\", \"fold\", ...");
  py::class_<bpde::Summary>(m, "Summary",
                            "How a solve ended: status, converged, iterations, residual, message, seconds.")
      .def(py::init<>())
      .def_readonly("status", &bpde::Summary::status)
      .def_readonly("converged", &bpde::Summary::converged)
      .def_readonly("iterations", &bpde::Summary::iterations)
      .def_readonly("residual", &bpde::Summary::residual)
      .def_readonly("message", &bpde::Summary::message)
      .def_readonly("seconds", &bpde::Summary::seconds)
      .def("__repr__", [](const bpde::Summary& s) {
        return "Summary(status=" + std::string(bpde::to_string(s.status)) +
               ", iterations=" + std::to_string(s.iterations) +
               ", residual=" + py::repr(py::float_(s.residual)).cast<std::string>() +
               (s.message.empty() ? "" : ", message=" + py::repr(py::str(s.message)).cast<std::string>()) + ")";
      });
}

}  // namespace bpde::python
