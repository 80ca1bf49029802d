#include "bezierpde/jobs/run_complex.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <optional>
#include <map>
#include <set>

#include "bezierpde/complex/complex_mesh.h"
#include "bezierpde/complex/layout.h"
#include "bezierpde/core/errors.h"
#include "bezierpde/energies/area_functional.h"
#include "bezierpde/energies/volume.h"
#include "bezierpde/io/atomic_file.h"
#include "bezierpde/io/boundary_json.h"
#include "bezierpde/io/complex_job.h"
#include "bezierpde/io/mesh_io.h"
#include "bezierpde/jobs/job_progress.h"
#include "bezierpde/solvers/cmc/complex_cmc.h"
#include "bezierpde/solvers/complex/complex_extremal.h"

namespace bpde {
namespace {

Json finite_or_null(double x) { return std::isfinite(x) ? Json(x) : Json(nullptr); }

/// Geometry of patch p at (u, v), nudged towards the domain's centre where it is singular.
FundamentalForms robust_geometry(const PatchComplex& c, int p, double u, double v) {
  const bool tri = c.patches[p].kind == PatchKind::triangular;
  const double cu = tri ? 1.0 / 3 : 0.5, cv = cu;
  for (double h : {0.0, 1e-7, 1e-5, 1e-3, 1e-2}) {
    const double a = u + h * (cu - u), b = v + h * (cv - v);
    const FundamentalForms g = tri ? triangular_net(c, p).geometry(a, b) : tensor_net(c, p).geometry(a, b);
    if (g.regular) return g;
  }
  FundamentalForms none;
  none.normal = Eigen::Vector3d::UnitZ();
  return none;
}

/// net.obj: every row once, each patch's control-net segments once.
std::string net_obj(const PatchComplex& c) {
  std::string s = "# bezierpde patch complex control net: " + std::to_string(c.patches.size()) + " patches\n";
  char buf[96];
  for (int r = 0; r < c.points.rows(); ++r) {
    std::snprintf(buf, sizeof buf, "v %.17g %.17g %.17g\n", c.points(r, 0), c.points(r, 1), c.points(r, 2));
    s += buf;
  }
  std::set<std::pair<int, int>> lines;
  for (int p = 0; p < static_cast<int>(c.patches.size()); ++p) {
    const Net net = c.patches[p].kind == PatchKind::triangular ? Net(triangular_net(c, p)) : Net(tensor_net(c, p));
    for (const auto& [a, b] : net_segments(net)) {
      const int ga = c.patches[p].points[a], gb = c.patches[p].points[b];
      lines.insert({std::min(ga, gb), std::max(ga, gb)});
    }
  }
  for (const auto& [a, b] : lines) s += "l " + std::to_string(a + 1) + " " + std::to_string(b + 1) + "\n";
  return s;
}

// ---------------------------------------------------------------- the boundary error

/// A Bézier curve's point and first two derivatives at t (de Casteljau on the difference nets).
struct CurvePoint {
  Eigen::Vector3d x, d1, d2;
};
Eigen::Vector3d de_casteljau(Eigen::MatrixX3d P, double t) {
  for (Eigen::Index k = P.rows() - 1; k > 0; --k)
    for (Eigen::Index i = 0; i < k; ++i) P.row(i) = (1 - t) * P.row(i) + t * P.row(i + 1);
  return P.row(0).transpose();
}
struct Bezier {
  Eigen::MatrixX3d P, D1, D2;
  explicit Bezier(const Eigen::MatrixX3d& points) : P(points) {
    const Eigen::Index n = P.rows() - 1;
    D1 = n >= 1 ? Eigen::MatrixX3d(n * (P.bottomRows(n) - P.topRows(n))) : Eigen::MatrixX3d::Zero(1, 3);
    D2 = n >= 2 ? Eigen::MatrixX3d((n - 1) * (D1.bottomRows(n - 1) - D1.topRows(n - 1))) : Eigen::MatrixX3d::Zero(1, 3);
  }
  CurvePoint at(double t) const { return {de_casteljau(P, t), de_casteljau(D1, t), de_casteljau(D2, t)}; }
};

/// The rows of the coarse complex along layout boundary edge a -> b, s = 0..n from a to b
/// (complex/layout.h: vertex rows, then each layout edge's n - 1 inner rows from its smaller to
/// its larger vertex id, edges in layout_edges order).
std::vector<int> coarse_edge_rows(const Layout& L, const std::vector<LayoutEdge>& edges, int n, int a, int b) {
  const int lo = std::min(a, b), hi = std::max(a, b);
  int k = 0;
  while (k < static_cast<int>(edges.size()) && !(edges[k].a == lo && edges[k].b == hi)) ++k;
  if (k == static_cast<int>(edges.size())) throw InternalError("complex boundary error: no layout edge " +
                                                               std::to_string(a) + "-" + std::to_string(b));
  std::vector<int> rows(n + 1);
  rows[0] = lo, rows[n] = hi;
  const int first = static_cast<int>(L.vertices.rows()) + k * (n - 1);
  for (int s = 1; s < n; ++s) rows[s] = first + s - 1;
  if (a > b) std::reverse(rows.begin(), rows.end());
  return rows;
}

// ---------------------------------------------------------------- the solve

// The report fields every complex result has: its size and the continuity across its seams.
void add_complex_report(SolveOutcome& out, const ComplexJobData& data, const PatchComplex& c) {
  out.report["patches"] = c.patches.size();
  out.report["degree"] = c.patches.front().degree;
  out.report["refine"] = data.refine;
  out.report["seam_angle_max"] = finite_or_null(seam_angle_max(c));
  out.report["continuity"] = data.continuity == Continuity::C1 ? "C1" : "C0";
  out.report["boundary_fit"] = boundary_fit_to_json(data.coarse.fits);
  out.report["boundary_error"] = boundary_error_json(complex_boundary_error(data));
}

SolveOutcome base_outcome(const Job& job, const Summary& s, const PatchComplex& solved) {
  const Status status = checked_status(s);
  SolveOutcome out{job.net, SolveFigures{}, Json::object(), Json::object(), status == Status::Converged, status,
                   std::make_shared<const PatchComplex>(solved), nullptr};
  out.figures.problem = job.problem.kind;
  out.figures.summary = s;
  if (s.iterations > 0) out.figures.iterations = s.iterations;
  return out;
}

// The cmc problem on a complex: the single-patch solve (solvers/cmc/complex_cmc.h).
SolveOutcome solve_complex_cmc(const Job& job, const ComplexJobData& data) {
  if (data.continuity == Continuity::C1)
    throw ParameterError("job.boundary.continuity: C1 takes the quadratic energies' extremals, not cmc");
  const CmcOptions o = job_cmc_options(job);
  const CmcResult<PatchComplex> r = solve_cmc(data.complex, o);
  SolveOutcome out = base_outcome(job, r.summary, r.net);
  add_cmc_figures(out, o, r);
  add_complex_report(out, data, r.net);
  return out;
}

SolveOutcome solve_complex_extremal(const Job& job, const ComplexJobData& data) {
  const EnergySpec& e = *job.problem.energy;
  ComplexExtremalOptions options;
  options.continuity = data.continuity;
  options.domain = data.domain;
  const ComplexExtremal r = solve_complex_extremal(data.complex, e, options);
  SolveOutcome out = base_outcome(job, r.summary, r.complex);
  out.figures.energy = r.energy;
  out.figures.energy_name = e.name();
  double area_sum = 0, volume_sum = 0;
  for (int p = 0; p < static_cast<int>(r.complex.patches.size()); ++p) {
    if (r.complex.patches[p].kind == PatchKind::triangular) {
      area_sum += area(triangular_net(r.complex, p));
      volume_sum += volume(triangular_net(r.complex, p));
    } else {
      area_sum += area(tensor_net(r.complex, p));
      volume_sum += volume(tensor_net(r.complex, p));
    }
  }
  add_complex_report(out, data, r.complex);
  if (data.continuity == Continuity::C1) out.report["c1_residual"] = finite_or_null(r.c1_residual);
  out.report["area"] = finite_or_null(area_sum);
  out.report["volume"] = finite_or_null(volume_sum);
  return out;
}

SolveOutcome solve_on(const Job& job, const std::shared_ptr<const ComplexJobData>& data) {
  const bool cmc = job.problem.kind == ProblemKind::CmcH || job.problem.kind == ProblemKind::CmcV;
  SolveOutcome out = cmc ? solve_complex_cmc(job, *data) : solve_complex_extremal(job, *data);
  out.complex_data = data;
  return out;
}

// ---------------------------------------------------------------- tolerance rounds

std::string short_number(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3g", x);
  return buf;
}

Json tolerance_json(const Tolerance& t) {
  auto opt = [](const std::optional<double>& x) { return x ? Json(*x) : Json(nullptr); };
  return {{"mean_curvature", opt(t.mean_curvature)}, {"seam_angle", opt(t.seam_angle)}, {"boundary", opt(t.boundary)},
          {"max_degree", t.max_degree},          {"max_refine", t.max_refine},       {"max_rounds", t.max_rounds}};
}

/// A tolerance that a round does not meet: its name, the measured figure (NaN: none) and the tolerance.
struct Failure {
  std::string name;
  double value, tolerance;
  double ratio() const { return std::isfinite(value) ? value / tolerance : std::numeric_limits<double>::infinity(); }
};

/// The figures of one round's result that the tolerances are checked on, and its report entry.
struct RoundFigures {
  std::optional<CmcCertificate> certificate;
  double seam = std::numeric_limits<double>::quiet_NaN();
  double boundary = std::numeric_limits<double>::quiet_NaN();
};

RoundFigures measure(const Job& job, const SolveOutcome& out) {
  RoundFigures f;
  const SampledSurface sampled = sampled_complex(*out.complex, job.samples);
  const SurfaceStats st = surface_stats(sampled);
  if (st.count > 0 && out.figures.H && std::isfinite(*out.figures.H))
    f.certificate = cmc_certificate(st, *out.figures.H, sampled);
  const Json& seam = out.report["seam_angle_max"];
  if (seam.is_number()) f.seam = seam.get<double>();
  const Json& b = out.report["boundary_error"]["max_error"];
  if (b.is_number()) f.boundary = b.get<double>();
  return f;
}

std::vector<Failure> failures(const Tolerance& t, const RoundFigures& f) {
  std::vector<Failure> out;
  const double none = std::numeric_limits<double>::quiet_NaN();
  if (t.mean_curvature) {
    const double dev = f.certificate ? f.certificate->deviation : none;
    if (!(dev <= *t.mean_curvature)) out.push_back({"mean_curvature", dev, *t.mean_curvature});
  }
  if (t.seam_angle && !(f.seam <= *t.seam_angle)) out.push_back({"seam_angle", f.seam, *t.seam_angle});
  if (t.boundary && !(f.boundary <= *t.boundary)) out.push_back({"boundary", f.boundary, *t.boundary});
  return out;
}

Json round_json(const SolveOutcome& out, const RoundFigures& f, double seconds, const std::vector<Failure>& failing) {
  Json r = {{"degree", out.report["degree"]},
            {"refine", out.report["refine"]},
            {"patches", out.report["patches"]},
            {"status", to_string(out.status)},
            {"seam_angle_max", finite_or_null(f.seam)},
            {"boundary_error", finite_or_null(f.boundary)},
            {"seconds", seconds}};
  if (f.certificate) {
    const CmcCertificate& c = *f.certificate;
    r["mean_curvature_deviation"] = finite_or_null(c.deviation);
    r["relative_deviation"] = finite_or_null(c.relative);
    r["at"] = c.at[0] >= 0 ? Json{c.at[0], c.at[1]} : Json(nullptr);
    r["patch"] = c.patch >= 0 ? Json(c.patch) : Json(nullptr);
  } else {
    r["mean_curvature_deviation"] = nullptr;
    r["relative_deviation"] = nullptr;
    r["at"] = nullptr;
    r["patch"] = nullptr;
  }
  Json failed = Json::array();
  for (const Failure& x : failing) failed.push_back(x.name);
  r["failed"] = failed;
  return r;
}

SolveOutcome run_rounds(const Job& job) {
  const Tolerance& tol = *job.tolerance;
  std::shared_ptr<const ComplexJobData> data = job.complex;
  int n = data->coarse.complex.patches.front().degree, refine = data->refine;
  Json rounds = Json::array();
  double total_seconds = 0;
  for (int k = 0;; ++k) {
    const auto start = std::chrono::steady_clock::now();
    // progress: each round is a stage of its own around the solver's stages
    const std::string stage = "tolerance round " + std::to_string(k + 1) + " (degree " + std::to_string(n) +
                              ", refine " + std::to_string(refine) + ")";
    std::optional<ProgressStage> round_stage(std::in_place, job_progress(), stage);
    SolveOutcome out = solve_on(job, data);
    const RoundFigures f = measure(job, out);
    round_stage.reset();
    const std::vector<Failure> failing = failures(tol, f);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    total_seconds += seconds;
    rounds.push_back(round_json(out, f, seconds, failing));
    out.report["tolerance"] = tolerance_json(tol);
    out.report["rounds"] = rounds;
    out.figures.summary.seconds = total_seconds;
    // A solve that failed ends the rounds with its own status and message.
    if (!out.converged || failing.empty()) return out;
    // The next round: p first, then h, within the limits; else no solution within them.
    std::string stop;
    double worst = 0;
    bool boundary_fails = false;
    for (const Failure& x : failing) worst = std::max(worst, x.ratio()), boundary_fails |= x.name == "boundary";
    int next_n = n, next_refine = refine;
    if (k + 1 >= tol.max_rounds) {
      stop = "the round limit (" + std::to_string(tol.max_rounds) + ")";
    } else if (n < tol.max_degree) {
      next_n = std::min(tol.max_degree, n + (worst > 10 ? 2 : 1));
    } else if (boundary_fails) {
      stop = "the degree limit (" + std::to_string(tol.max_degree) +
             "; h refinement splits the fitted boundary exactly and keeps its error)";
    } else if (refine < tol.max_refine) {
      next_refine = refine + 1;
    } else {
      stop = "the degree and refine limits (" + std::to_string(tol.max_degree) + ", " + std::to_string(tol.max_refine) +
             ")";
    }
    std::shared_ptr<const ComplexJobData> next;
    if (stop.empty()) {
      try {
        next = std::make_shared<const ComplexJobData>(complex_job_at(*job.complex, next_n, next_refine, "job.boundary"));
        const long long vertices =
            static_cast<long long>(next->complex.patches.size()) * (job.samples + 1) * (job.samples + 1);
        if (vertices > kMaxComplexSampleVertices)
          stop = "the sampled-vertex limit (" + std::to_string(next->complex.patches.size()) + " patches at " +
                 std::to_string(job.samples) + " samples)";
      } catch (const InvalidInput& e) {  // past the degree, patch or Gram-entry limits
        stop = std::string("a size limit (") + e.what() + ")";
      }
    }
    if (!stop.empty()) {
      std::string what;
      for (const Failure& x : failing)
        what += (what.empty() ? "" : ", ") + x.name + " " + (std::isfinite(x.value) ? short_number(x.value) : "none") +
                " > " + short_number(x.tolerance);
      out.figures.summary.set_failed(Status::NoConvergence, "tolerance not met after " + std::to_string(k + 1) +
                                                                " rounds (degree " + std::to_string(n) + ", refine " +
                                                                std::to_string(refine) + "): " + what + "; stopped by " +
                                                                stop);
      out.status = Status::NoConvergence;
      out.converged = false;
      return out;
    }
    data = next;
    n = next_n, refine = next_refine;
  }
}

}  // namespace

SampledSurface sampled_complex(const PatchComplex& c, int samples) {
  ComplexMesh m = sample_complex(c, samples);
  SampledSurface s;
  s.complex = true;
  s.vertex_patch = m.vertex_patch;
  s.uv = m.uv;
  s.triangle_patch = m.patch;
  // Corners of each patch where the surface's boundary turns: a boundary row at the end of two
  // boundary edges whose tangents there (from the control points next to it) differ by more than
  // kStatsCornerAngle. Where a smooth loop is merely cut (a circle in arcs), the samples count.
  std::map<int, std::vector<Eigen::Vector3d>> tangents;  // boundary corner row -> outgoing directions
  for (const ComplexEdge& edge : complex_edges(c)) {
    if (!edge.boundary() || edge.rows.size() < 2) continue;
    const std::vector<int>& r = edge.rows;
    const std::size_t last = r.size() - 1;
    tangents[r.front()].push_back(c.points.row(r[1]) - c.points.row(r.front()));
    tangents[r.back()].push_back(c.points.row(r[last - 1]) - c.points.row(r.back()));
  }
  std::set<int> boundary;
  for (const auto& [row, d] : tangents) {
    if (d.size() != 2 || d[0].norm() == 0 || d[1].norm() == 0) {  // degenerate: treat as a corner
      boundary.insert(row);
      continue;
    }
    // outgoing directions of a smooth boundary are opposite: the turn is the angle from -d0 to d1
    const double cosang = std::clamp((-d[0]).normalized().dot(d[1].normalized()), -1.0, 1.0);
    if (std::acos(cosang) > kStatsCornerAngle) boundary.insert(row);
  }
  const int np = static_cast<int>(c.patches.size());
  const PatchKind kind = c.patches.front().kind;
  const int n = c.patches.front().degree, corners = patch_edge_count(kind);
  std::vector<Eigen::Vector2d> corner_uv(corners);
  std::vector<int> corner_local(corners);
  for (int e = 0; e < corners; ++e) {
    corner_uv[e] = patch_edge_parameter(kind, e, 0.0);
    corner_local[e] = patch_edge_local_rows(kind, n, e).front();
  }
  std::vector<std::vector<char>> on_boundary(np, std::vector<char>(corners, 0));
  for (int p = 0; p < np; ++p)
    for (int e = 0; e < corners; ++e) on_boundary[p][e] = boundary.count(c.patches[p].points[corner_local[e]]) ? 1 : 0;
  const Eigen::Index nv = m.mesh.V.rows();
  s.counted.setZero(nv);
  for (Eigen::Index k = 0; k < nv; ++k) {
    if (m.mesh.regular.size() && !m.mesh.regular(k)) continue;
    if (!std::isfinite(m.mesh.H(k))) continue;
    const int p = m.vertex_patch(k);
    const double u = m.uv(k, 0), v = m.uv(k, 1);
    bool near = false;
    for (int e = 0; e < corners && !near; ++e) {
      if (!on_boundary[p][e]) continue;
      const double cu = corner_uv[e](0), cv = corner_uv[e](1);
      if (kind == PatchKind::triangular) {
        // the barycentric coordinate of that corner
        const double b = cu == 1 ? u : cv == 1 ? v : 1 - u - v;
        near = b > 1 - kStatsCornerMargin + 1e-12;
      } else {
        near = std::abs(u - cu) < kStatsCornerMargin - 1e-12 && std::abs(v - cv) < kStatsCornerMargin - 1e-12;
      }
    }
    s.counted(k) = near ? 0 : 1;
  }
  s.mesh = std::move(m.mesh);
  s.samples = samples;
  return s;
}

SurfaceFields complex_surface_fields(const PatchComplex& c, const SampledSurface& m) {
  const Eigen::Index nv = m.mesh.V.rows();
  SurfaceFields f;
  f.uv = m.uv;
  f.normal.resize(nv, 3);
  f.H = m.mesh.H;
  f.K.resize(nv);
  f.regular.resize(nv);
  for (Eigen::Index k = 0; k < nv; ++k) {
    const FundamentalForms g = robust_geometry(c, m.vertex_patch(k), m.uv(k, 0), m.uv(k, 1));
    f.normal.row(k) = g.normal.transpose();
    f.K(k) = g.K;
    f.regular(k) = m.mesh.regular.size() ? m.mesh.regular(k) : 1;
  }
  return f;
}

void write_complex_net_obj(const std::string& path, const PatchComplex& c) { write_file_atomically(path, net_obj(c)); }

BoundaryError complex_boundary_error(const ComplexJobData& data) {
  // With refit the refined boundary is fitted piece by piece: its fits' errors (no location).
  if (data.refit) {
    Json fits = Json::array();
    for (const EdgeFit& f : data.coarse.fits) fits.push_back({{"max_error", f.max_error}});
    return fit_boundary_error(fits).value_or(BoundaryError{});
  }
  const Layout& L = data.coarse.layout;
  const PatchComplex& c = data.coarse.complex;
  const int n = c.patches.front().degree;
  const std::vector<LayoutEdge> edges = layout_edges(L);
  const int S = 64 * n + 1;  // samples of each curve piece and of each edge
  BoundaryError worst;
  for (int k = 0; k < static_cast<int>(data.coarse.boundary.size()); ++k) {
    const LayoutBoundaryEdge& be = data.coarse.boundary[k];
    const std::vector<int> rows = coarse_edge_rows(L, edges, n, be.a, be.b);
    Eigen::MatrixX3d P(n + 1, 3);
    for (int s = 0; s <= n; ++s) P.row(s) = c.points.row(rows[s]);
    const Bezier edge(P);
    std::vector<Eigen::Vector3d> xs(S);
    for (int i = 0; i < S; ++i) xs[i] = de_casteljau(P, double(i) / (S - 1));
    const BoundaryCurve& curve = data.loops[be.piece.loop][be.piece.curve];
    for (int j = 0; j < S; ++j) {
      const double t = be.piece.t0 + (be.piece.t1 - be.piece.t0) * double(j) / (S - 1);
      const Eigen::Vector3d q = curve.evaluate(t);
      int best = 0;
      double dist = std::numeric_limits<double>::infinity();
      for (int i = 0; i < S; ++i) {
        const double d = (xs[i] - q).norm();
        if (d < dist) dist = d, best = i;
      }
      // Newton on (x(τ) - q)·x'(τ) = 0 from the nearest sample, kept while the distance falls.
      double tau = double(best) / (S - 1);
      for (int it = 0; it < 20; ++it) {
        const CurvePoint x = edge.at(tau);
        const Eigen::Vector3d r = x.x - q;
        const double g = r.dot(x.d1), h = x.d1.squaredNorm() + r.dot(x.d2);
        if (!(h > 0)) break;
        const double next = std::clamp(tau - g / h, 0.0, 1.0);
        const double d = (de_casteljau(P, next) - q).norm();
        if (!(d < dist)) break;
        dist = d, tau = next;
      }
      if (worst.edge < 0 || dist > worst.max_error || std::isnan(dist)) {
        worst.max_error = dist, worst.edge = k;
        worst.loop = be.piece.loop, worst.curve = be.piece.curve, worst.t = t;
        worst.point = std::array<double, 3>{q(0), q(1), q(2)};
      }
    }
  }
  return worst;
}

SolveOutcome run_complex_job(const Job& job) {
  if (job.tolerance) return run_rounds(job);
  return solve_on(job, job.complex);
}

}  // namespace bpde
