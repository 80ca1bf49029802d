// The cmc problem (solvers/cmc/cmc.h): CmcOptions, the results, solve_cmc.
#include "bindings.h"

#include "bezierpde/solvers/cmc/cmc.h"

namespace bpde::python {

namespace {

// solve_cmc within the limits of a cmc job (its degrees), interruptible by Ctrl-C, the GIL released.
template <class NetT>
bpde::CmcResult<NetT> cmc(const bpde::NetShape& shape, const NetT& data, const bpde::CmcOptions& options) {
  check_limits(bpde::cmc_requirements(options.functional, options.V.has_value()), shape, options.fixed,
               bpde::to_string(options.solver), "solve_cmc");
  bpde::CmcOptions o = options;
  o.progress = interruptible(options.progress);
  py::gil_scoped_release release;
  return bpde::solve_cmc(data, o);
}

}  // namespace

void bind_cmc(py::module_& m) {
  py::class_<bpde::CmcOptions>(m, "CmcOptions")
      .def(py::init<>())
      .def_readwrite("H", &bpde::CmcOptions::H)
      .def_readwrite("V", &bpde::CmcOptions::V)
      .def_property(
          "solver", [](const bpde::CmcOptions& o) { return bpde::to_string(o.solver); },
          [](bpde::CmcOptions& o, const Text& t) {
            const std::string s = text(t, "solver");
            o.solver = bpde::parse_cmc_solver(s);
          })
      .def_property(
          "fixed", [](const bpde::CmcOptions& o) { return bpde::to_string(o.fixed); },
          [](bpde::CmcOptions& o, const Text& t) {
            const std::string s = text(t, "fixed");
            o.fixed = parse_fixed(s);
          })
      .def_property(
          "functional", [](const bpde::CmcOptions& o) { return bpde::to_string(o.functional); },
          [](bpde::CmcOptions& o, const Text& t) {
            const std::string s = text(t, "functional");
            o.functional = bpde::parse_cmc_functional(s);
          },
          "\"dirichlet\" (default), \"area\" or \"mean-curvature\" (solvers/cmc/cmc.h).")
      .def_readwrite("tolerance", &bpde::CmcOptions::tolerance)
      .def_readwrite("mean_curvature_tolerance", &bpde::CmcOptions::mean_curvature_tolerance)
      .def_readwrite("max_least_squares_iterations", &bpde::CmcOptions::max_least_squares_iterations)
      .def_readwrite("geodesic_acceleration", &bpde::CmcOptions::geodesic_acceleration)
      .def_property(
          "area_start", [](const bpde::CmcOptions& o) { return bpde::to_string(o.area_start); },
          [](bpde::CmcOptions& o, const Text& t) {
            const std::string s = text(t, "area_start");
            o.area_start = bpde::parse_area_start(s);
          },
          "area functional: \"mean-curvature\" (default: the route mean-curvature-start first, the "
          "least-squares mean-curvature surface, not tried where the D_H solution is already within 1e-6 of "
          "a critical point of A_H, as on conformal data), \"dirichlet\" (from the D_H solution) or "
          "\"minimal-surface\" (the branch from the minimal surface, H = 0, alone); docs/cmc_algorithm.md.")
      .def_readwrite("area_trust_region", &bpde::CmcOptions::area_trust_region,
                     "area functional: the trust-region part of the soft-mode phase (default True; False "
                     "stops where its Levenberg-Marquardt loop stops); docs/cmc_algorithm.md, \"The final phases\".")
      .def_readwrite("max_corrector_iterations", &bpde::CmcOptions::max_corrector_iterations)
      .def_readwrite("max_continuation_steps", &bpde::CmcOptions::max_continuation_steps)
      .def_readwrite("min_step", &bpde::CmcOptions::min_step);
  py::class_<bpde::AreaRouteRecord>(m, "AreaRouteRecord",
                                    "One route of the area solve (solvers/cmc/area_route.h; docs/cmc_algorithm.md).")
      .def_property_readonly("route", [](const bpde::AreaRouteRecord& r) { return bpde::to_string(r.route); })
      .def_readonly("tried", &bpde::AreaRouteRecord::tried)
      .def_readonly("status", &bpde::AreaRouteRecord::status)
      .def_readonly("first_variation", &bpde::AreaRouteRecord::first_variation, "None where the route failed")
      .def_readonly("least_squares_residual", &bpde::AreaRouteRecord::least_squares_residual,
                    "mean-curvature-start: √Φ of its least squares (None otherwise)")
      .def_readonly("least_squares_converged", &bpde::AreaRouteRecord::least_squares_converged)
      .def_readonly("start_volume", &bpde::AreaRouteRecord::start_volume,
                    "smaller-volume-start: the volume V1 its continuation started from (None otherwise)")
      .def_readonly("iterations", &bpde::AreaRouteRecord::iterations)
      .def_readonly("continuation_steps", &bpde::AreaRouteRecord::continuation_steps)
      .def_readonly("seconds", &bpde::AreaRouteRecord::seconds)
      .def_property_readonly(
          "phases",
          [](const bpde::AreaRouteRecord& r) {
            py::dict d;
            for (const bpde::AreaPhaseRecord& ph : r.phases) d[bpde::to_string(ph.phase)] = ph.count;
            return d;
          },
          "iterations of each final phase run, by name")
      .def_property_readonly("soft_mode_end",
                             [](const bpde::AreaRouteRecord& r) { return bpde::to_string(r.soft_mode_end); })
      .def_readonly("kept", &bpde::AreaRouteRecord::kept)
      .def_readonly("message", &bpde::AreaRouteRecord::message)
      .def_readonly("why", &bpde::AreaRouteRecord::why)
      .def("__repr__", [](const bpde::AreaRouteRecord& r) {
        return std::string("<AreaRouteRecord ") + bpde::to_string(r.route) + " " +
               (r.tried ? bpde::to_string(r.status) : "not tried") + (r.kept ? ", kept>" : ">");
      });
  auto cmc_result = [&m](const char* name, auto tag) {
    using R = decltype(tag);
    py::class_<R>(m, name)
        .def_readonly("net", &R::net)
        .def_readonly("H", &R::H)
        .def_readonly("D", &R::D)
        .def_readonly("V", &R::V)
        .def_readonly("DH", &R::DH)
        .def_readonly("A", &R::A)
        .def_readonly("energy", &R::energy)
        .def_property_readonly("functional", [](const R& r) { return bpde::to_string(r.functional); })
        .def_readonly("quadrature_points", &R::quadrature_points)
        .def_readonly("quadrature_grading", &R::quadrature_grading)
        .def_readonly("quadrature_levels", &R::quadrature_levels)
        .def_readonly("quadrature_nodes", &R::quadrature_nodes)
        .def_readonly("continuation_steps", &R::continuation_steps)
        .def_readonly("summary", &R::summary)
        .def_property_readonly(
            "routes", [](const R& r) { return r.routes.records; },
            "area functional: the routes considered, in order (list of AreaRouteRecord); empty otherwise")
        .def_property_readonly(
            "kept_route",
            [](const R& r) -> py::object {
              const bpde::AreaRouteRecord* k = r.routes.kept();
              return k ? py::object(py::str(bpde::to_string(k->route))) : py::object(py::none());
            },
            "area functional: the name of the route the result comes from, or None")
        .def_property_readonly(
            "routes_report", [](const R& r) { return bpde::full_report(r.routes); },
            "area functional: one line per route considered (route, status, first variation, iterations, ...)")
        .def_property_readonly(
            "parametrisation",
            [](const R& r) {
              const bpde::ParametrisationCheck& c = r.parametrisation;
              py::dict d;
              d["regular"] = c.regular;
              d["checked"] = c.checked;
              d["min_ratio"] = c.min_ratio;
              d["flipped"] = c.flipped;
              d["fold_corner_angle"] = c.fold_u >= 0 ? py::object(py::float_(c.fold_corner_angle)) : py::none();
              return d;
            },
            "area and mean-curvature functionals: the regularity verdict on the net");
  };
  cmc_result("CmcResultTriangular", bpde::CmcResult<bpde::TriangularNet>{});
  cmc_result("CmcResultTensor", bpde::CmcResult<bpde::TensorNet>{});
  m.def(
      "solve_cmc",
      [](const bpde::TriangularNet& data, const bpde::CmcOptions& options) {
        return cmc({bpde::NetKind::Triangular, data.n(), data.n()}, data, options);
      },
      py::arg("data"), py::arg("options"),
      "The cmc problem of solvers/cmc/cmc.h (options.functional: the critical point of D + 2HV, of A + 2HV, "
      "or the least squares of the mean curvature) -> CmcResult (net, H, D, V, DH, A, energy, functional, summary).");
  m.def(
      "solve_cmc",
      [](const bpde::TensorNet& data, const bpde::CmcOptions& options) {
        return cmc({bpde::NetKind::Tensor, data.n(), data.m()}, data, options);
      },
      py::arg("data"), py::arg("options"));
}

}  // namespace bpde::python
