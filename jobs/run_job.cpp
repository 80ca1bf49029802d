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

// (see jobs/run_job.h)
Json stats_json(const MeanCurvatureStats& st) {
  if (st.count == 0) return nullptr;
  return {{"min", st.min},
          {"max", st.max},
          {"mean", st.mean},
          {"count", st.count},
          {"at_min", {st.at_min[0], st.at_min[1]}},
          {"at_max", {st.at_max[0], st.at_max[1]}}};
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
                   nullptr};
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
  SolveOutcome out = job.complex ? run_complex_job(job) : checked_solver(job, "job").run(job);
  out.report.update(figures_report(out.figures));
  if (!job.boundary_fit.is_null()) out.report["boundary_fit"] = job.boundary_fit;
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

void write_output_files(const std::string& dir, const Json* result, const Net& net, const TriangleMesh& mesh,
                        MeshFormat format, const Exports& exports) {
  const std::vector<std::string> names = output_file_names(result != nullptr, exports);
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
  if (result) write_json_file(out.file("result.json"), *result), wrote(w_result);
  const SurfaceFields fields = surface_fields(net, mesh);
  // in ASCII, the vertex coordinates and H are formatted once for the three files
  std::optional<SharedNumberText> text;
  if (format == MeshFormat::Ascii) text.emplace(mesh, fields);
  const SharedNumberText* shared = text ? &*text : nullptr;
  wrote(w_fields);
  write_obj(out.file("surface.obj"), mesh, shared);
  wrote(w_obj);
  write_ply(out.file("surface.ply"), mesh, fields, format, shared);
  wrote(w_ply);
  write_vtp(out.file("surface.vtp"), mesh, fields, format, shared);
  wrote(w_vtp);
  write_net_obj(out.file("net.obj"), net);
  wrote(w_net);
  const Json report = result && result->contains("report") ? (*result)["report"] : Json::object();
  if (exports.step) write_step(out.file("surface.step"), net), wrote(w_step);
  if (exports.html) write_view_html(out.file("view.html"), net, mesh, report, view_title(net, report)), wrote(w_html);
  out.commit();
}

// The statistics of the mesh that the surface files are written from (one tabulated evaluation).
// Tensor and triangular nets skip the singular samples (energies/cmc.h); B-spline surfaces (blends)
// count every sample, at its robust H, as they always have.
MeanCurvatureStats surface_mean_curvature_stats(const Net& net, const TriangleMesh& mesh, int samples) {
  if (std::holds_alternative<TensorNet>(net))
    return bpde::mean_curvature_stats(mesh, SampleLayout::TensorGrid, samples, 0.1);
  if (std::holds_alternative<TriangularNet>(net))
    return bpde::mean_curvature_stats(mesh, SampleLayout::TriangularGrid, samples, 0.1);
  return bpde::mean_curvature_stats(mesh, SampleLayout::TensorGrid, samples, 0.1, false);
}

Json mean_curvature_stats(const Net& net, const TriangleMesh& mesh, int samples) {
  return stats_json(surface_mean_curvature_stats(net, mesh, samples));
}

Json check_report(const TriangleMesh& mesh) { return check_json(mesh_check(mesh)); }

bool CmcCertificate::near_constant() const { return relative <= kCmcDeviationLimit; }

Json certificate_json(const CmcCertificate& c) {
  return {{"H", c.H},
          {"mean_curvature_deviation", c.deviation},
          {"at", c.at[0] >= 0 ? Json{c.at[0], c.at[1]} : Json(nullptr)},
          {"reference_curvature", c.reference_curvature},
          {"relative_deviation", c.relative},
          {"near_constant", c.near_constant()}};
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

// The report's figures from the sampled mesh, where the solver did not set them.
Json complete_report(const Net& net, const TriangleMesh& mesh, int samples, Json report, WrittenResult* added) {
  WrittenResult local;
  WrittenResult& written = added ? *added : local;
  if (!report.contains("mean_curvature")) {
    const ProgressStage stage(job_progress(), "mean curvature");
    written.mean_curvature = surface_mean_curvature_stats(net, mesh, samples);
    report["mean_curvature"] = stats_json(*written.mean_curvature);
  }
  // A CMC result says how far it is from constant mean curvature (its mesh's samples, its H).
  if (written.mean_curvature && written.mean_curvature->count > 0 && report.value("problem", "") == "cmc" &&
      report.contains("H") && report["H"].is_number()) {
    written.certificate = cmc_certificate(*written.mean_curvature, report["H"].get<double>(), mesh);
    report["certificate"] = certificate_json(*written.certificate);
  }
  if (!report.contains("check")) {
    const ProgressStage stage(job_progress(), kMeshCheckStage);
    written.check = mesh_check(mesh);
    report["check"] = check_json(*written.check);
  }
  return report;
}

// result.json + surface files for a net and its sampled mesh; the report completed
// (complete_report) unless the solver already set its figures.
WrittenResult write_result(const std::string& dir, const Net& net, const TriangleMesh& mesh, int samples, Json report,
                           const Json& extra, Status status, MeshFormat format, const Exports& exports) {
  WrittenResult written;
  report = complete_report(net, mesh, samples, std::move(report), &written);
  const ProgressStage stage(job_progress(), kWritingFilesStage);
  written.result = {{"net", net_to_json(net)}, {"report", report}};
  for (auto it = extra.begin(); it != extra.end(); ++it) written.result[it.key()] = it.value();
  write_output_files(dir, &written.result, net, mesh, format, exports);
  written.exit_code = exit_code(status);
  return written;
}

WrittenResult write_job_result(const std::string& dir, const Job& job, const SolveOutcome& out) {
  if (out.complex && job.complex) return write_complex_result(dir, job, out);
  const TriangleMesh mesh = [&] {
    const ProgressStage stage(job_progress(), kSamplingStage);
    return sample_net(out.net, job.samples, job_progress());
  }();
  Exports exports;
  exports.html = job.export_html;
  exports.step = job.export_step;
  return write_result(dir, out.net, mesh, job.samples, out.report, out.extra, out.status, job.mesh_format, exports);
}

int write_outcome(const std::string& dir, const Job& job, const SolveOutcome& out) {
  return write_job_result(dir, job, out).exit_code;
}

}  // namespace bpde
