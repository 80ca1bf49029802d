// Dispatch of a validated job to the library's solvers (FORMATS.md problem table), and the
// report each one writes. The combination of net, fixed set and problem was already checked by
// io/job.cpp; the solvers check their own preconditions again and throw InvalidInput.
#include <chrono>
#include <string>

#include "jobs/run_job.h"

#include <cmath>
#include <filesystem>

#include "checks/mesh_checks.h"
#include "io/mesh_io.h"
#include "core/errors.h"
#include "energies/cmc.h"
#include "energies/quadratic_energy.h"
#include "energies/triangular_gram.h"
#include "energies/volume.h"
#include "solvers/c1/biharmonic_load.h"
#include "solvers/bspline/bspline_extremal.h"
#include "solvers/bspline/bspline_pde.h"
#include "solvers/cmc/cmc.h"
#include "solvers/c1/tetraharmonic.h"
#include "solvers/extremal.h"
#include "solvers/pde/harmonic_pde.h"
#include "solvers/pde/pde_explicit.h"
#include "solvers/pde/pde_lu.h"
#include "solvers/pde/pde_residual.h"

namespace bpde {
namespace {


Json check_report_impl(const TriangleMesh& mesh) {
  std::vector<double> V(static_cast<size_t>(mesh.V.rows()) * 3);
  for (Eigen::Index r = 0; r < mesh.V.rows(); ++r)
    for (int c = 0; c < 3; ++c) V[static_cast<size_t>(3 * r + c)] = mesh.V(r, c);
  std::vector<int> F(static_cast<size_t>(mesh.F.rows()) * 3);
  for (Eigen::Index r = 0; r < mesh.F.rows(); ++r)
    for (int c = 0; c < 3; ++c) F[static_cast<size_t>(3 * r + c)] = mesh.F(r, c);
  const MeshCheckReport rep = check_mesh(V, F);
  Json j = {{"self_intersections", rep.self_intersections}, {"closed", rep.closed}, {"cone_volume", rep.cone_volume}};
  j["volume"] = rep.volume ? Json(*rep.volume) : Json(nullptr);
  return j;
}

// (see jobs/run_job.h)
Json stats_json(const MeanCurvatureStats& st) {
  if (st.count == 0) return nullptr;
  return {{"min", st.min}, {"max", st.max}, {"mean", st.mean}, {"count", st.count}};
}

// B-spline surfaces (blends): the tensor rule of energies/cmc.h (leave out samples with both
// parameters within 0.1 of the domain's ends) applied to the already sampled mesh.
Json bspline_stats(const TriangleMesh& mesh, int N) {
  MeanCurvatureStats st;
  double sum = 0;
  for (int a = 0; a <= N; ++a)
    for (int b = 0; b <= N; ++b) {
      const double u = static_cast<double>(a) / N, v = static_cast<double>(b) / N;
      if (std::min(u, 1 - u) < 0.1 - 1e-12 && std::min(v, 1 - v) < 0.1 - 1e-12) continue;
      const double h = mesh.H(a * (N + 1) + b);
      st.min = st.count ? std::min(st.min, h) : h;
      st.max = st.count ? std::max(st.max, h) : h;
      sum += h;
      ++st.count;
    }
  if (st.count) st.mean = sum / st.count;
  return stats_json(st);
}

Json base_report(const Job& job, const Summary& s) {
  Json r = {{"problem", to_string(job.problem.kind)}, {"converged", s.converged}, {"seconds", s.seconds}};
  if (!s.message.empty()) r["message"] = s.message;
  if (s.iterations > 0) r["iterations"] = s.iterations;
  return r;
}

// Energy values of non-finite nets (a failed solve) are reported as null, never NaN.
Json finite_or_null(double x) { return std::isfinite(x) ? Json(x) : Json(nullptr); }

SolveOutcome tensor_extremal(const Job& job, const TensorNet& net) {
  const EnergySpec& e = *job.problem.energy;
  const ExtremalResult r = solve_extremal(net, e, job.fixed);
  SolveOutcome out{r.net, base_report(job, r.summary), Json::object(), r.summary.converged};
  out.report["energy"] = finite_or_null(r.energy);
  out.report["energy_name"] = e.name();
  if (e.order() == 4 || e.order() == 2) out.report["pde_residual"] = finite_or_null(pde_residual(r.net, e, job.samples));
  return out;
}

SolveOutcome tensor_pde(const Job& job, const TensorNet& net) {
  const EnergySpec& e = *job.problem.energy;
  PdeSolution sol = [&]() {
    if (job.fixed == FixedSet::UBoundaries) return solve_harmonic_pde(net, e);
    if (job.problem.method == PdeMethod::Explicit) return solve_pde_explicit(net, e);
    return solve_pde_lu(net, e);
  }();
  SolveOutcome out{sol.net, base_report(job, sol.summary), Json::object(), sol.summary.converged};
  out.report["method"] = to_string(job.problem.method);
  out.report["energy"] = finite_or_null(energy_value(sol.net, e));
  out.report["energy_name"] = e.name();
  out.report["pde_residual"] = finite_or_null(pde_residual(sol.net, e, job.samples));
  return out;
}

SolveOutcome triangular_extremal(const Job& job, const TriangularNet& net) {
  const EnergySpec& e = *job.problem.energy;
  const auto t0 = std::chrono::steady_clock::now();
  const ExtremalSolver solver(triangular_gram(net.n(), e), net.fixed_indices(job.fixed));
  Summary s;
  const TriangularNet x(net.n(), solver.solve(net.points()));
  s.residual = solver.reduced_residual(net.points());
  s.converged = s.residual <= 1e-11;
  if (!s.converged) s.message = "optimality residual " + std::to_string(s.residual) + " above 1e-11";
  s.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  SolveOutcome out{x, base_report(job, s), Json::object(), s.converged};
  out.report["energy"] = finite_or_null(solver.extremal_energy(net.points()));
  out.report["energy_name"] = e.name();
  return out;
}

template <class NetT>
SolveOutcome cmc(const Job& job, const NetT& net) {
  CmcOptions o;
  o.fixed = job.fixed;
  o.solver = job.problem.solver;
  if (job.problem.kind == ProblemKind::CmcV)
    o.V = job.problem.V;
  else
    o.H = job.problem.H;
  const CmcResult<NetT> r = solve_cmc(net, o);
  SolveOutcome out{r.net, base_report(job, r.summary), Json::object(), r.summary.converged};
  out.report["solver"] = to_string(o.solver);
  out.report["energy"] = finite_or_null(r.DH);
  out.report["D"] = finite_or_null(r.D);
  out.report["volume"] = finite_or_null(r.V);
  out.report["H"] = finite_or_null(r.H);
  out.report["continuation_steps"] = r.continuation_steps;
  out.report["iterations"] = r.summary.iterations;
  out.report["residual"] = finite_or_null(r.summary.residual);
  return out;
}

// Δ⁴ = (∂²u + ∂²v)⁴ as PDE terms {du, dv, coefficient} for the residual report.
std::vector<PdeTerm> tetraharmonic_terms() {
  return {{8, 0, 1.0}, {6, 2, 4.0}, {4, 4, 6.0}, {2, 6, 4.0}, {0, 8, 1.0}};
}

SolveOutcome tetraharmonic(const Job& job, const TensorNet& net) {
  TetraharmonicOptions o;
  o.method = job.problem.method == PdeMethod::Explicit ? TetraharmonicOptions::Method::Explicit
                                                        : TetraharmonicOptions::Method::LU;
  const TetraharmonicResult r = solve_tetraharmonic(net, o);
  SolveOutcome out{r.net, base_report(job, r.summary), Json::object(), r.summary.converged};
  out.report["method"] = to_string(job.problem.method);
  out.report["energy"] = nullptr;
  out.report["pde_residual"] = finite_or_null(pde_residual(r.net, tetraharmonic_terms(), job.samples));
  return out;
}

SolveOutcome biharmonic_load(const Job& job, const TensorNet& net) {
  const BiharmonicLoadResult r = solve_biharmonic_load(net);
  SolveOutcome out{r.net, base_report(job, r.summary), Json::object(), r.summary.converged};
  out.report["energy"] = nullptr;
  out.extra["load"] = net_to_json(r.load);
  return out;
}

SolveOutcome bspline_extremal(const Job& job, const BSplineNet& net) {
  const EnergySpec& e = *job.problem.energy;
  BSplineExtremalOptions o;
  o.fixed = job.fixed;
  const BSplineExtremalResult r = solve_bspline_extremal(net, e, o);
  SolveOutcome out{r.net, base_report(job, r.summary), Json::object(), r.summary.converged};
  out.report["energy"] = finite_or_null(r.energy);
  out.report["energy_name"] = e.name();
  out.report["pde_residual"] = finite_or_null(bspline_pde_residual(r.net, e, job.samples));
  return out;
}

SolveOutcome bspline_pde(const Job& job, const BSplineNet& net) {
  const EnergySpec& e = *job.problem.energy;
  BSplinePdeOptions o;
  o.fixed = job.fixed;
  const BSplinePdeResult r = solve_bspline_pde(net, e, o);
  SolveOutcome out{r.net, base_report(job, r.summary), Json::object(), r.summary.converged};
  out.report["method"] = "lu";
  out.report["energy"] = finite_or_null(r.energy);
  out.report["energy_name"] = e.name();
  out.report["rank"] = r.rank;
  out.report["equations"] = r.equations;
  out.report["free_parameters"] = r.free_parameters;
  out.report["compatibility_conditions"] = r.compatibility_conditions;
  out.report["minimum_energy_member"] = r.minimum_energy_member;
  if (r.summary.converged) out.report["pde_residual"] = finite_or_null(bspline_pde_residual(r.net, e, job.samples));
  return out;
}

}  // namespace

SolveOutcome run_job(const Job& job) {
  const ProblemKind k = job.problem.kind;
  const bool is_cmc = k == ProblemKind::CmcH || k == ProblemKind::CmcV;
  if (const auto* t = std::get_if<TensorNet>(&job.net)) {
    if (k == ProblemKind::Extremal) return tensor_extremal(job, *t);
    if (k == ProblemKind::Pde) return tensor_pde(job, *t);
    if (is_cmc) return cmc(job, *t);
    if (k == ProblemKind::Tetraharmonic) return tetraharmonic(job, *t);
    if (k == ProblemKind::BiharmonicLoad) return biharmonic_load(job, *t);
  }
  if (const auto* t = std::get_if<TriangularNet>(&job.net)) {
    if (k == ProblemKind::Extremal) return triangular_extremal(job, *t);
    if (is_cmc) return cmc(job, *t);
  }
  if (const auto* b = std::get_if<BSplineNet>(&job.net)) {
    if (k == ProblemKind::Extremal) return bspline_extremal(job, *b);
    if (k == ProblemKind::Pde) return bspline_pde(job, *b);
  }
  throw UnsupportedProblem("problem \"" + to_string(k) + "\" on a " + net_kind(job.net) +
                           " net: this solver is not available in this build yet");
}

void make_output_dir(const std::string& dir) {
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec || !std::filesystem::is_directory(dir)) throw FileError("cannot create output directory '" + dir + "'");
}

Json mean_curvature_stats(const Net& net, const TriangleMesh& mesh, int samples) {
  if (const auto* t = std::get_if<TensorNet>(&net)) return stats_json(bpde::mean_curvature_stats(*t, samples, 0.1));
  if (const auto* t = std::get_if<TriangularNet>(&net)) return stats_json(bpde::mean_curvature_stats(*t, samples, 0.1));
  return bspline_stats(mesh, samples);
}

Json check_report(const TriangleMesh& mesh) { return check_report_impl(mesh); }

// result.json + surface files for a net and its sampled mesh; the report gains the mean-curvature
// statistics and the CGAL figures unless the solver already set them.
int write_result(const std::string& dir, const Net& net, const TriangleMesh& mesh, int samples, Json report,
                 const Json& extra, bool converged) {
  if (!report.contains("mean_curvature")) report["mean_curvature"] = mean_curvature_stats(net, mesh, samples);
  if (!report.contains("check")) report["check"] = check_report(mesh);
  Json result = {{"net", net_to_json(net)}, {"report", report}};
  for (auto it = extra.begin(); it != extra.end(); ++it) result[it.key()] = it.value();
  make_output_dir(dir);
  write_json_file(dir + "/result.json", result);
  write_surface_files(dir, net, mesh);
  return converged ? 0 : 1;
}

int write_outcome(const std::string& dir, const Job& job, const SolveOutcome& out) {
  const TriangleMesh mesh = sample_net(out.net, job.samples);
  return write_result(dir, out.net, mesh, job.samples, out.report, out.extra, out.converged);
}

}  // namespace bpde
