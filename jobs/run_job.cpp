// The problem table of the job layer: for each problem kind and net kind, the solver that runs it
// and that solver's requirements (declared next to its Options, solvers/requirements.h). The same
// table validates a job when it is read (validate_job) and dispatches it (run_job); the solvers
// check their own preconditions again and throw InvalidInput. Also the report each solver writes.
#include <optional>
#include <string>
#include <utility>

#include "bezierpde/jobs/run_job.h"

#include <cmath>
#include <limits>
#include <filesystem>

#include "bezierpde/checks/mesh_checks.h"
#include "bezierpde/core/errors.h"
#include "bezierpde/energies/cmc.h"
#include "bezierpde/energies/quadratic_energy.h"
#include "bezierpde/energies/volume.h"
#include "bezierpde/io/mesh_io.h"
#include "bezierpde/io/html_view.h"
#include "bezierpde/io/output_folder.h"
#include "bezierpde/io/step_export.h"
#include "bezierpde/io/vtp_io.h"
#include "bezierpde/jobs/complex_exports.h"
#include "bezierpde/jobs/exports.h"
#include "bezierpde/jobs/job_progress.h"
#include "bezierpde/jobs/run_complex.h"
#include "bezierpde/solvers/cmc/complex_cmc.h"
#include "bezierpde/solvers/bspline/bspline_extremal.h"
#include "bezierpde/solvers/bspline/bspline_pde.h"
#include "bezierpde/solvers/c1/biharmonic_load.h"
#include "bezierpde/solvers/c1/tetraharmonic.h"
#include "bezierpde/solvers/cmc/cmc.h"
#include "bezierpde/solvers/extremal.h"
#include "bezierpde/solvers/pde/harmonic_pde.h"
#include "bezierpde/solvers/pde/pde_explicit.h"
#include "bezierpde/solvers/pde/pde_lu.h"
#include "bezierpde/solvers/pde/pde_residual.h"
#include "bezierpde/solvers/requirements.h"

namespace bpde {
namespace {

MeshCheckReport mesh_check(const TriangleMesh& mesh) {
  std::vector<double> V(static_cast<size_t>(mesh.V.rows()) * 3);
  for (Eigen::Index r = 0; r < mesh.V.rows(); ++r)
    for (int c = 0; c < 3; ++c) V[static_cast<size_t>(3 * r + c)] = mesh.V(r, c);
  std::vector<int> F(static_cast<size_t>(mesh.F.rows()) * 3);
  for (Eigen::Index r = 0; r < mesh.F.rows(); ++r)
    for (int c = 0; c < 3; ++c) F[static_cast<size_t>(3 * r + c)] = mesh.F(r, c);
  MeshCheckOptions options;
  options.progress = job_progress();
  return check_mesh(V, F, options);
}

Json check_json(const MeshCheckReport& rep) {
  Json j = {{"self_intersections", rep.self_intersections}, {"closed", rep.closed}, {"cone_volume", rep.cone_volume}};
  j["volume"] = rep.volume ? Json(*rep.volume) : Json(nullptr);
  return j;
}

// Energy values of non-finite nets (a failed solve) are reported as null, never NaN.
Json finite_or_null(double x) { return std::isfinite(x) ? Json(x) : Json(nullptr); }

// The report's fields that come from the figures.
Json figures_report(const SolveFigures& f) {
  const Summary& s = f.summary;
  Json r = {{"problem", to_string(f.problem)}, {"converged", s.converged}, {"seconds", s.seconds}};
  if (!s.message.empty()) r["message"] = s.message;
  if (f.iterations) r["iterations"] = *f.iterations;
  if (f.continuation_steps) r["continuation_steps"] = *f.continuation_steps;
  if (!f.energy_name.empty()) r["energy_name"] = f.energy_name;
  if (!f.method.empty()) r["method"] = f.method;
  if (!f.solver.empty()) r["solver"] = f.solver;
  const std::pair<const char*, const std::optional<double>*> numbers[] = {
      {"energy", &f.energy}, {"D", &f.D},     {"volume", &f.volume}, {"H", &f.H}, {"residual", &f.residual},
      {"pde_residual", &f.pde_residual}};
  for (const auto& [key, x] : numbers)
    if (*x) r[key] = finite_or_null(**x);
  return r;
}

// The outcome of a solve with its base figures; the status is checked against the Summary contract.
// The solver's function adds its figures and its own report fields; run_job writes the figures
// into the report.
SolveOutcome outcome(const Job& job, Net net, const Summary& s) {
  const Status status = checked_status(s);
  SolveOutcome out{std::move(net), SolveFigures{}, Json::object(), Json::object(), status == Status::Converged, status,
                   nullptr, nullptr};
  out.figures.problem = job.problem.kind;
  out.figures.summary = s;
  if (s.iterations > 0) out.figures.iterations = s.iterations;
  return out;
}

// NaN: reported as null (a figure the problem reports without a value).
constexpr double kNoValue = std::numeric_limits<double>::quiet_NaN();

// The area solve's route records (FORMATS.md, "Report fields": `routes`).
Json routes_json(const AreaRouteLog& log) {
  Json routes = Json::array();
  for (const AreaRouteRecord& r : log.records) {
    Json phases = Json::object();
    for (const AreaPhaseRecord& ph : r.phases) phases[to_string(ph.phase)] = ph.count;
    routes.push_back({{"route", to_string(r.route)},
                      {"tried", r.tried},
                      {"status", r.tried ? Json(to_string(r.status)) : Json(nullptr)},
                      {"first_variation", r.first_variation ? finite_or_null(*r.first_variation) : Json(nullptr)},
                      {"least_squares_residual",
                       r.least_squares_residual ? finite_or_null(*r.least_squares_residual) : Json(nullptr)},
                      {"least_squares_converged", r.least_squares_converged},
                      {"start_volume", r.start_volume ? finite_or_null(*r.start_volume) : Json(nullptr)},
                      {"iterations", r.iterations},
                      {"continuation_steps", r.continuation_steps},
                      {"seconds", finite_or_null(r.seconds)},
                      {"phases", phases},
                      {"soft_mode_end", to_string(r.soft_mode_end)},
                      {"kept", r.kept},
                      {"why", r.why}});
  }
  return routes;
}


SolveOutcome tensor_extremal(const Job& job, const TensorNet& net) {
  const EnergySpec& e = *job.problem.energy;
  const ExtremalResult r = solve_extremal(net, e, job.fixed);
  SolveOutcome out = outcome(job, r.net, r.summary);
  out.figures.energy = r.energy;
  out.figures.energy_name = e.name();
  if (e.order() == 4 || e.order() == 2) out.figures.pde_residual = pde_residual(r.net, e, job.samples);
  return out;
}

// The tensor PDE solvers share their report.
SolveOutcome tensor_pde_outcome(const Job& job, const PdeSolution& sol) {
  const EnergySpec& e = *job.problem.energy;
  SolveOutcome out = outcome(job, sol.net, sol.summary);
  out.figures.method = to_string(job.problem.method);
  out.figures.energy = energy_value(sol.net, e);
  out.figures.energy_name = e.name();
  out.figures.pde_residual = pde_residual(sol.net, e, job.samples);
  return out;
}

SolveOutcome harmonic(const Job& job, const TensorNet& net) {
  return tensor_pde_outcome(job, solve_harmonic_pde(net, *job.problem.energy));
}
SolveOutcome pde_explicit(const Job& job, const TensorNet& net) {
  return tensor_pde_outcome(job, solve_pde_explicit(net, *job.problem.energy));
}
SolveOutcome pde_lu(const Job& job, const TensorNet& net) {
  return tensor_pde_outcome(job, solve_pde_lu(net, *job.problem.energy));
}

SolveOutcome triangular_extremal(const Job& job, const TriangularNet& net) {
  const EnergySpec& e = *job.problem.energy;
  const TriangularExtremalResult r = solve_extremal(net, e, job.fixed);
  SolveOutcome out = outcome(job, r.net, r.summary);
  out.figures.energy = r.energy;
  out.figures.energy_name = e.name();
  return out;
}

template <class NetT>
SolveOutcome cmc(const Job& job, const NetT& net) {
  const CmcOptions o = job_cmc_options(job);
  const CmcResult<NetT> r = solve_cmc(net, o);
  SolveOutcome out = outcome(job, r.net, r.summary);
  add_cmc_figures(out, o, r);
  return out;
}

}  // namespace

CmcOptions job_cmc_options(const Job& job) {
  CmcOptions o;
  o.fixed = job.fixed;
  o.solver = job.problem.solver;
  o.progress = job_progress();
  o.functional = job.problem.functional;
  o.mean_curvature_tolerance = job.problem.mean_curvature_tolerance;
  o.area_start = job.problem.area_start;
  if (job.problem.kind == ProblemKind::CmcV)
    o.V = job.problem.V;
  else
    o.H = job.problem.H;
  return o;
}

template <class NetT>
void add_cmc_figures(SolveOutcome& out, const CmcOptions& o, const CmcResult<NetT>& r) {
  out.figures.solver = to_string(o.solver);
  out.figures.energy = r.energy;
  out.figures.D = r.D;
  out.figures.volume = r.V;
  out.figures.H = r.H;
  out.figures.continuation_steps = r.continuation_steps;
  out.figures.iterations = r.summary.iterations;
  out.figures.residual = r.summary.residual;
  out.report["functional"] = to_string(o.functional);
  out.report["area"] = finite_or_null(r.A);
  // The quadrature rule of the area and mean-curvature functionals (their results depend on it;
  // the Dirichlet functional's matrices are exact).
  if (o.functional != CmcFunctionalKind::Dirichlet)
    out.report["quadrature"] = {{"points_per_direction", r.quadrature_points},
                                {"grading", r.quadrature_grading},
                                {"levels", r.quadrature_levels},
                                {"nodes", r.quadrature_nodes}};
  // The area solve's routes, in the order considered, and the regularity of its net.
  if (o.functional == CmcFunctionalKind::Area) out.report["routes"] = routes_json(r.routes);
  if (r.parametrisation.checked)
    out.report["parametrisation"] = {{"regular", r.parametrisation.regular},
                                     {"min_ratio", finite_or_null(r.parametrisation.min_ratio)},
                                     {"flipped", r.parametrisation.flipped},
                                     {"fold_corner_angle", r.parametrisation.fold_u >= 0
                                                               ? finite_or_null(r.parametrisation.fold_corner_angle)
                                                               : Json(nullptr)}};
}
template void add_cmc_figures(SolveOutcome&, const CmcOptions&, const CmcResult<TriangularNet>&);
template void add_cmc_figures(SolveOutcome&, const CmcOptions&, const CmcResult<TensorNet>&);
template void add_cmc_figures(SolveOutcome&, const CmcOptions&, const CmcResult<PatchComplex>&);

namespace {

// Δ⁴ = (∂²u + ∂²v)⁴ as PDE terms {du, dv, coefficient} for the residual report.
std::vector<PdeTerm> tetraharmonic_terms() { return {{8, 0, 1.0}, {6, 2, 4.0}, {4, 4, 6.0}, {2, 6, 4.0}, {0, 8, 1.0}}; }

SolveOutcome tetraharmonic(const Job& job, const TensorNet& net) {
  TetraharmonicOptions o;
  o.method = job.problem.method == PdeMethod::Explicit ? TetraharmonicOptions::Method::Explicit
                                                       : TetraharmonicOptions::Method::LU;
  const TetraharmonicResult r = solve_tetraharmonic(net, o);
  SolveOutcome out = outcome(job, r.net, r.summary);
  out.figures.method = to_string(job.problem.method);
  out.figures.energy = kNoValue;
  out.figures.pde_residual = pde_residual(r.net, tetraharmonic_terms(), job.samples);
  return out;
}

SolveOutcome biharmonic_load(const Job& job, const TensorNet& net) {
  const BiharmonicLoadResult r = solve_biharmonic_load(net);
  SolveOutcome out = outcome(job, r.net, r.summary);
  out.figures.energy = kNoValue;
  out.extra["load"] = net_to_json(r.load);
  return out;
}

SolveOutcome bspline_extremal(const Job& job, const BSplineNet& net) {
  const EnergySpec& e = *job.problem.energy;
  BSplineExtremalOptions o;
  o.fixed = job.fixed;
  const BSplineExtremalResult r = solve_bspline_extremal(net, e, o);
  SolveOutcome out = outcome(job, r.net, r.summary);
  out.figures.energy = r.energy;
  out.figures.energy_name = e.name();
  out.figures.pde_residual = bspline_pde_residual(r.net, e, job.samples);
  return out;
}

SolveOutcome bspline_pde(const Job& job, const BSplineNet& net) {
  const EnergySpec& e = *job.problem.energy;
  BSplinePdeOptions o;
  o.fixed = job.fixed;
  const BSplinePdeResult r = solve_bspline_pde(net, e, o);
  SolveOutcome out = outcome(job, r.net, r.summary);
  out.figures.method = "lu";
  out.figures.energy = r.energy;
  out.figures.energy_name = e.name();
  out.report["rank"] = r.rank;
  out.report["equations"] = r.equations;
  out.report["free_parameters"] = r.free_parameters;
  out.report["compatibility_conditions"] = r.compatibility_conditions;
  out.report["minimum_energy_member"] = r.minimum_energy_member;
  if (r.summary.converged) out.figures.pde_residual = bspline_pde_residual(r.net, e, job.samples);
  return out;
}

// ---------------------------------------------------------------- the problem table

// A solver as the job layer runs it: its requirements for this problem and the run function.
struct Solver {
  SolverRequirements requirements;
  SolveOutcome (*run)(const Job&);
};

template <class NetT, SolveOutcome (*F)(const Job&, const NetT&)>
SolveOutcome on(const Job& job) {
  return F(job, std::get<NetT>(job.net));
}

// One row per problem kind and net kind. `select` picks the solver from the problem (operator
// order, method): the same choice for validation and for the run.
struct Route {
  ProblemKind problem;
  NetKind net;
  Solver (*select)(const Problem&);
};

Solver select_tensor_pde(const Problem& p) {
  const EnergySpec& e = *p.energy;
  if (e.order() == 2) return {harmonic_pde_requirements(e), on<TensorNet, harmonic>};
  if (p.method == PdeMethod::Explicit) return {pde_explicit_requirements(e), on<TensorNet, pde_explicit>};
  return {pde_lu_requirements(e), on<TensorNet, pde_lu>};
}

// The cmc requirements of the job's functional and form (solvers/cmc/cmc.h).
SolverRequirements cmc_requirements_for(const Problem& p) {
  return cmc_requirements(p.functional, p.kind == ProblemKind::CmcV);
}

const Route kRoutes[] = {
    {ProblemKind::Extremal, NetKind::Tensor,
     [](const Problem&) {
       return Solver{extremal_requirements(), on<TensorNet, tensor_extremal>};
     }},
    {ProblemKind::Extremal, NetKind::Triangular,
     [](const Problem&) {
       return Solver{extremal_requirements(), on<TriangularNet, triangular_extremal>};
     }},
    {ProblemKind::Extremal, NetKind::BSpline,
     [](const Problem&) {
       return Solver{bspline_extremal_requirements(), on<BSplineNet, bspline_extremal>};
     }},
    {ProblemKind::Pde, NetKind::Tensor, select_tensor_pde},
    {ProblemKind::Pde, NetKind::BSpline,
     [](const Problem& p) {
       return Solver{bspline_pde_requirements(*p.energy), on<BSplineNet, bspline_pde>};
     }},
    {ProblemKind::Tetraharmonic, NetKind::Tensor,
     [](const Problem&) {
       return Solver{tetraharmonic_requirements(), on<TensorNet, tetraharmonic>};
     }},
    {ProblemKind::BiharmonicLoad, NetKind::Tensor,
     [](const Problem&) {
       return Solver{biharmonic_load_requirements(), on<TensorNet, biharmonic_load>};
     }},
    {ProblemKind::CmcH, NetKind::Triangular,
     [](const Problem& p) {
       return Solver{cmc_requirements_for(p), on<TriangularNet, cmc<TriangularNet>>};
     }},
    {ProblemKind::CmcH, NetKind::Tensor,
     [](const Problem& p) {
       return Solver{cmc_requirements_for(p), on<TensorNet, cmc<TensorNet>>};
     }},
    {ProblemKind::CmcV, NetKind::Triangular,
     [](const Problem& p) {
       return Solver{cmc_requirements_for(p), on<TriangularNet, cmc<TriangularNet>>};
     }},
    {ProblemKind::CmcV, NetKind::Tensor,
     [](const Problem& p) {
       return Solver{cmc_requirements_for(p), on<TensorNet, cmc<TensorNet>>};
     }},
};

// The method name a problem chooses ("" when it has no choice of method).
std::string method_name(const Problem& p) {
  switch (p.kind) {
    case ProblemKind::Pde:
    case ProblemKind::Tetraharmonic:
      return to_string(p.method);
    case ProblemKind::CmcH:
    case ProblemKind::CmcV:
      return to_string(p.solver);
    case ProblemKind::Extremal:
    case ProblemKind::BiharmonicLoad:
      return "";
  }
  return "";
}

// The solver of the job, its requirements checked.
Solver checked_solver(const Job& job, const std::string& where) {
  const NetShape shape = net_shape(job.net);
  SolverRequirements no_solver;  // the problem's net kinds, for the message when none fits
  no_solver.problem = "problem \"" + to_string(job.problem.kind) + "\"";
  for (const Route& r : kRoutes) {
    if (r.problem != job.problem.kind) continue;
    if (r.net == shape.kind) {
      Solver s = r.select(job.problem);
      check_requirements(s.requirements, shape, job.fixed, method_name(job.problem), where);
      return s;
    }
    no_solver.nets.push_back(r.net);
  }
  check_requirements(no_solver, shape, job.fixed, "", where);  // throws UnsupportedProblem
  throw InternalError("job: no solver for problem \"" + to_string(job.problem.kind) + "\"");
}

}  // namespace

NetShape net_shape(const Net& net) {
  if (const auto* t = std::get_if<TensorNet>(&net)) return {NetKind::Tensor, t->n(), t->m()};
  if (const auto* t = std::get_if<TriangularNet>(&net)) return {NetKind::Triangular, t->n(), t->n()};
  const auto& b = std::get<BSplineNet>(net);
  return {NetKind::BSpline, b.p(), b.q()};
}

void validate_job(const Job& job, const std::string& where) {
  if (!job.complex) checked_solver(job, where);  // a complex job is checked when it is read
}

Job job_from_json(const Json& j, const std::string& source) {
  Job job = parse_job(j, source);
  validate_job(job, source);
  return job;
}

Job read_job_file(const std::string& path) { return job_from_json(read_json_file(path), path); }

Status checked_status(const Summary& s) {
  if (s.converged != (s.status == Status::Converged)) {
    // Every solver sets both through Summary::set_converged / set_failed: a disagreement is a bug.
    throw InternalError(std::string("solver summary: status \"") + to_string(s.status) +
                        "\" with converged = " + (s.converged ? "true" : "false"));
  }
  return s.status;
}

SolveOutcome run_job(const Job& job) {
  if (job.tolerance && !job.complex)  // io/job.cpp refuses it when it reads the job
    throw UnsupportedProblem("job.tolerance: tolerances and refinement rounds take a complex boundary");
  SolveOutcome out = job.complex ? run_complex_job(job) : checked_solver(job, "job").run(job);
  out.report.update(figures_report(out.figures));
  // a complex's report has the fits of the complex it was solved on (the last tolerance round's)
  if (!job.boundary_fit.is_null() && !out.report.contains("boundary_fit")) out.report["boundary_fit"] = job.boundary_fit;
  if (!job.complex)
    if (const std::optional<BoundaryError> e = fit_boundary_error(job.boundary_fit))
      out.report["boundary_error"] = boundary_error_json(*e);
  return out;
}

const std::vector<std::string>& result_file_names() {
  static const std::vector<std::string> names = {"result.json", "surface.obj", "surface.ply", "surface.vtp",
                                                 "net.obj"};
  return names;
}

const std::vector<std::string>& surface_file_names() {
  static const std::vector<std::string> names = {"surface.obj", "surface.ply", "surface.vtp", "net.obj"};
  return names;
}

std::vector<std::string> output_file_names(bool with_result, const Exports& exports) {
  std::vector<std::string> names = with_result ? result_file_names() : surface_file_names();
  if (exports.step) names.push_back("surface.step");
  if (exports.html) names.push_back("view.html");
  return names;
}

void check_output_dir(const std::string& dir, const std::vector<std::string>& names) { OutputFolder::check(dir, names); }

ResultSurface result_surface(const Job& job, const SolveOutcome& out) {
  ResultSurface s;
  s.net = out.net;
  if (out.complex && job.complex) s.complex = out.complex, s.complex_data = out.complex_data ? out.complex_data : job.complex;
  return s;
}

SampledSurface sampled_net(const Net& net, TriangleMesh mesh, int samples) {
  SampledSurface s;
  const bool tri = std::holds_alternative<TriangularNet>(net);
  const bool bspline = std::holds_alternative<BSplineNet>(net);
  const Eigen::Index nv = mesh.V.rows();
  s.vertex_patch = Eigen::VectorXi::Zero(nv);
  s.uv.resize(nv, 2);
  s.counted.setZero(nv);
  const int N = samples;
  const Eigen::Index expected = tri ? Eigen::Index(N + 1) * (N + 2) / 2 : Eigen::Index(N + 1) * (N + 1);
  if (nv != expected || mesh.H.size() != nv)
    throw SizeError("sampled_net: the mesh has " + std::to_string(nv) + " samples, expected " +
                    std::to_string(expected) + " for N = " + std::to_string(N));
  // The rules of energies/cmc.h mean_curvature_stats: singular samples skipped (not for the
  // B-spline surfaces of blends, which count every sample at its robust H), and the corners.
  const bool skip_singular = !bspline;
  const bool flags = skip_singular && mesh.regular.size() == nv;
  Eigen::Index id = 0;
  auto put = [&](double u, double v, bool in_corner) {
    s.uv(id, 0) = u, s.uv(id, 1) = v;
    const bool ok = !in_corner && !(flags && !mesh.regular(id)) && !(skip_singular && !std::isfinite(mesh.H(id)));
    s.counted(id) = ok ? 1 : 0;
    ++id;
  };
  if (tri) {
    const double lim = 1.0 - kStatsCornerMargin + 1e-12;
    for (int a = 0; a <= N; ++a)
      for (int b = 0; b <= N - a; ++b) {
        const double u = double(a) / N, v = double(b) / N, w = 1.0 - u - v;
        put(u, v, u > lim || v > lim || w > lim);
      }
  } else {
    const double lim = kStatsCornerMargin - 1e-12;
    for (int a = 0; a <= N; ++a)
      for (int b = 0; b <= N; ++b) {
        const double u = double(a) / N, v = double(b) / N;
        put(u, v, std::min(u, 1 - u) < lim && std::min(v, 1 - v) < lim);
      }
  }
  s.mesh = std::move(mesh);
  s.samples = N;
  return s;
}

SampledSurface sample_surface(const ResultSurface& r, int samples) {
  const ProgressStage stage(job_progress(), kSamplingStage);
  if (r.complex) return sampled_complex(*r.complex, samples);
  return sampled_net(r.net, sample_net(r.net, samples, job_progress()), samples);
}

SurfaceStats surface_stats(const SampledSurface& s) {
  SurfaceStats st;
  double sum = 0;
  for (Eigen::Index k = 0; k < s.mesh.H.size(); ++k) {
    if (!s.counted(k)) continue;
    const double h = s.mesh.H(k);
    if (st.count == 0 || h < st.min) st.min = h, st.vertex_min = k;
    if (st.count == 0 || h > st.max) st.max = h, st.vertex_max = k;
    sum += h;
    ++st.count;
  }
  if (st.count > 0) {
    st.mean = sum / st.count;
    st.at_min = {s.uv(st.vertex_min, 0), s.uv(st.vertex_min, 1)};
    st.at_max = {s.uv(st.vertex_max, 0), s.uv(st.vertex_max, 1)};
  }
  return st;
}

Json surface_stats_json(const SurfaceStats& st, const SampledSurface& s) {
  if (st.count == 0) return nullptr;
  Json j = {{"min", st.min},
            {"max", st.max},
            {"mean", st.mean},
            {"count", st.count},
            {"at_min", {st.at_min[0], st.at_min[1]}},
            {"at_max", {st.at_max[0], st.at_max[1]}}};
  if (s.complex) j["patch_at_min"] = s.vertex_patch(st.vertex_min), j["patch_at_max"] = s.vertex_patch(st.vertex_max);
  return j;
}

MeanCurvatureStats surface_mean_curvature_stats(const Net& net, const TriangleMesh& mesh, int samples) {
  return surface_stats(sampled_net(net, mesh, samples));
}

Json mean_curvature_stats(const Net& net, const TriangleMesh& mesh, int samples) {
  const SampledSurface s = sampled_net(net, mesh, samples);
  return surface_stats_json(surface_stats(s), s);
}

void write_output_files(const std::string& dir, const Json* result, const Net& net, const TriangleMesh& mesh,
                        MeshFormat format, const Exports& exports) {
  ResultSurface r;
  r.net = net;
  SampledSurface s;
  s.mesh = mesh;
  write_output_files(dir, result, r, s, format, exports);
}

void write_output_files(const std::string& dir, const Json* result, const ResultSurface& surface,
                        const SampledSurface& sampled, MeshFormat format, const Exports& exports) {
  const std::vector<std::string> names = output_file_names(result != nullptr, exports);
  const TriangleMesh& mesh = sampled.mesh;
  OutputFolder out(dir, names);
  // Progress: one step per file and one for the fields, each weighted by the bytes per vertex it
  // writes (measured at N = 1200: OBJ 108, PLY 128 in ASCII and 43 in binary, VTP 250 and 97,
  // view.html 71; the fields' computation about as long as 40), plus 1 for the small files; the
  // commit, reported by the caller's end of the stage, adds 1 more.
  const bool ascii = format == MeshFormat::Ascii;
  const double w_result = 1, w_fields = 41, w_obj = 109, w_ply = ascii ? 129 : 44, w_vtp = ascii ? 251 : 98,
               w_net = 1, w_step = 1, w_html = 72;
  const double total = (result ? w_result : 0) + w_fields + w_obj + w_ply + w_vtp + w_net +
                       (exports.step ? w_step : 0) + (exports.html ? w_html : 0) + 1;
  double done = 0;
  auto wrote = [&](double weight) { bpde::report(job_progress(), kWritingFilesStage, done += weight, total); };
  if (result) out.write("result.json", json_file_text(*result)), wrote(w_result);
  const SurfaceFields fields =
      surface.complex ? complex_surface_fields(*surface.complex, sampled) : surface_fields(surface.net, mesh);
  // in ASCII, the vertex coordinates and H are formatted once for the three files
  std::optional<SharedNumberText> text;
  if (format == MeshFormat::Ascii) text.emplace(mesh, fields);
  const SharedNumberText* shared = text ? &*text : nullptr;
  wrote(w_fields);
  write_obj(out.file("surface.obj"), mesh, shared);
  wrote(w_obj);
  write_ply(out.file("surface.ply"), mesh, fields, format, shared);
  wrote(w_ply);
  std::vector<std::int32_t> patch;  // a complex: the patch of each triangle as the VTP cell data
  if (surface.complex) patch.assign(sampled.triangle_patch.data(), sampled.triangle_patch.data() + sampled.triangle_patch.size());
  out.write("surface.vtp", vtp_text(mesh, fields, format, shared, surface.complex ? &patch : nullptr));
  wrote(w_vtp);
  if (surface.complex)
    out.write("net.obj", complex_net_obj(*surface.complex));
  else
    write_net_obj(out.file("net.obj"), surface.net);
  wrote(w_net);
  const Json report = result && result->contains("report") ? (*result)["report"] : Json::object();
  if (surface.complex) {  // surface.step (one sewn shell) and view.html of a complex: jobs/complex_exports.h
    const ComplexMesh m{mesh, sampled.triangle_patch, sampled.vertex_patch, sampled.uv};
    write_complex_exports(out, exports, *surface.complex, m, fields, report, sampled.samples);
    out.commit();
    return;
  }
  if (exports.step) write_step(out.file("surface.step"), surface.net), wrote(w_step);
  if (exports.html)
    write_view_html(out.file("view.html"), surface.net, mesh, report, view_title(surface.net, report)), wrote(w_html);
  out.commit();
}

Json check_report(const TriangleMesh& mesh) { return check_json(mesh_check(mesh)); }

bool CmcCertificate::near_constant() const { return relative <= kCmcDeviationLimit; }

namespace {
Json point_json(const std::optional<std::array<double, 3>>& p) {
  return p ? Json{(*p)[0], (*p)[1], (*p)[2]} : Json(nullptr);
}
}  // namespace

Json certificate_json(const CmcCertificate& c) {
  Json j = {{"H", c.H},
            {"mean_curvature_deviation", c.deviation},
            {"at", c.at[0] >= 0 ? Json{c.at[0], c.at[1]} : Json(nullptr)},
            {"point", point_json(c.point)},
            {"reference_curvature", c.reference_curvature},
            {"relative_deviation", c.relative},
            {"near_constant", c.near_constant()}};
  if (c.patch >= 0) j["patch"] = c.patch;
  return j;
}

CmcCertificate cmc_certificate(const MeanCurvatureStats& stats, double H, const TriangleMesh& mesh) {
  CmcCertificate c;
  c.H = H;
  const double below = H - stats.min, above = stats.max - H;
  c.deviation = std::max(below, above);
  c.at = below >= above ? stats.at_min : stats.at_max;
  const double R = 0.5 * (mesh.V.colwise().maxCoeff() - mesh.V.colwise().minCoeff()).norm();
  c.reference_curvature = std::max(std::abs(H), R > 0 ? 1.0 / R : 0.0);
  c.relative = c.reference_curvature > 0 ? c.deviation / c.reference_curvature : 0.0;
  return c;
}

CmcCertificate cmc_certificate(const SurfaceStats& stats, double H, const SampledSurface& s) {
  CmcCertificate c = cmc_certificate(static_cast<const MeanCurvatureStats&>(stats), H, s.mesh);
  const Eigen::Index k = H - stats.min >= stats.max - H ? stats.vertex_min : stats.vertex_max;
  if (k >= 0) {
    c.point = std::array<double, 3>{s.mesh.V(k, 0), s.mesh.V(k, 1), s.mesh.V(k, 2)};
    if (s.complex) c.patch = s.vertex_patch(k);
  }
  return c;
}

Json boundary_error_json(const BoundaryError& e) {
  Json j = {{"max_error", finite_or_null(e.max_error)}, {"edge", e.edge}};
  j["loop"] = e.loop ? Json(*e.loop) : Json(nullptr);
  j["curve"] = e.curve ? Json(*e.curve) : Json(nullptr);
  j["t"] = e.t ? Json(*e.t) : Json(nullptr);
  j["point"] = point_json(e.point);
  return j;
}

std::optional<BoundaryError> fit_boundary_error(const Json& boundary_fit) {
  if (!boundary_fit.is_array() || boundary_fit.empty()) return std::nullopt;
  BoundaryError e;
  for (std::size_t k = 0; k < boundary_fit.size(); ++k) {
    const Json& f = boundary_fit[k];
    const double x = f.contains("max_error") && f["max_error"].is_number() ? f["max_error"].get<double>()
                                                                           : std::numeric_limits<double>::quiet_NaN();
    if (e.edge < 0 || !(x <= e.max_error)) e.max_error = x, e.edge = static_cast<int>(k);
    if (std::isnan(x)) break;  // a NaN error is the answer
  }
  return e;
}

// The report's figures from the sampled mesh, where the solver did not set them.
Json complete_report(const Net& net, const TriangleMesh& mesh, int samples, Json report, WrittenResult* added) {
  return complete_report(sampled_net(net, mesh, samples), std::move(report), added);
}

Json complete_report(const SampledSurface& sampled, Json report, WrittenResult* added) {
  WrittenResult local;
  WrittenResult& written = added ? *added : local;
  if (!report.contains("mean_curvature")) {
    const ProgressStage stage(job_progress(), "mean curvature");
    written.mean_curvature = surface_stats(sampled);
    report["mean_curvature"] = surface_stats_json(*written.mean_curvature, sampled);
  }
  // A CMC result says how far it is from constant mean curvature (its mesh's samples, its H),
  // and how far its boundary is from the curves the job gave.
  if (written.mean_curvature && written.mean_curvature->count > 0 && report.value("problem", "") == "cmc" &&
      report.contains("H") && report["H"].is_number()) {
    written.certificate = cmc_certificate(*written.mean_curvature, report["H"].get<double>(), sampled);
    report["certificate"] = certificate_json(*written.certificate);
    report["certificate"]["boundary"] = report.contains("boundary_error") ? report["boundary_error"] : Json(nullptr);
  }
  if (!report.contains("check")) {
    const ProgressStage stage(job_progress(), kMeshCheckStage);
    written.check = mesh_check(sampled.mesh);
    report["check"] = check_json(*written.check);
  }
  return report;
}

// result.json + surface files for a net and its sampled mesh; the report completed
// (complete_report) unless the solver already set its figures.
WrittenResult write_result(const std::string& dir, const Net& net, const TriangleMesh& mesh, int samples, Json report,
                           const Json& extra, Status status, MeshFormat format, const Exports& exports) {
  ResultSurface r;
  r.net = net;
  return write_result(dir, r, sampled_net(net, mesh, samples), std::move(report), extra, status, format, exports);
}

namespace {
// result.json's "net": the net, or the complex with its layout.
Json result_net_json(const ResultSurface& surface) {
  return surface.complex ? complex_to_json(*surface.complex_data, *surface.complex) : net_to_json(surface.net);
}
}  // namespace

Json job_result_json(const Job& job, const SolveOutcome& out) {
  const ResultSurface surface = result_surface(job, out);
  Json result = {{"net", result_net_json(surface)},
                 {"report", complete_report(sample_surface(surface, job.samples), out.report)}};
  for (auto it = out.extra.begin(); it != out.extra.end(); ++it) result[it.key()] = it.value();
  return result;
}

WrittenResult write_result(const std::string& dir, const ResultSurface& surface, const SampledSurface& sampled,
                           Json report, const Json& extra, Status status, MeshFormat format, const Exports& exports) {
  WrittenResult written;
  report = complete_report(sampled, std::move(report), &written);
  const ProgressStage stage(job_progress(), kWritingFilesStage);
  written.result = {{"net", result_net_json(surface)}, {"report", report}};
  for (auto it = extra.begin(); it != extra.end(); ++it) written.result[it.key()] = it.value();
  write_output_files(dir, &written.result, surface, sampled, format, exports);
  written.exit_code = exit_code(status);
  return written;
}

WrittenResult write_job_result(const std::string& dir, const Job& job, const SolveOutcome& out) {
  const ResultSurface surface = result_surface(job, out);
  const SampledSurface sampled = sample_surface(surface, job.samples);
  Exports exports;
  exports.html = job.export_html;
  exports.step = job.export_step;
  return write_result(dir, surface, sampled, out.report, out.extra, out.status, job.mesh_format, exports);
}

int write_outcome(const std::string& dir, const Job& job, const SolveOutcome& out) {
  return write_job_result(dir, job, out).exit_code;
}

}  // namespace bpde
