#include "bezierpde/jobs/run_complex.h"

#include <algorithm>
#include <cmath>
#include <set>

#include "bezierpde/complex/complex_mesh.h"
#include "bezierpde/core/errors.h"
#include "bezierpde/energies/area_functional.h"
#include "bezierpde/energies/volume.h"
#include "bezierpde/io/atomic_file.h"
#include "bezierpde/io/complex_job.h"
#include "bezierpde/io/mesh_io.h"
#include "bezierpde/io/output_folder.h"
#include "bezierpde/io/vtp_io.h"
#include "bezierpde/jobs/complex_exports.h"
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

SurfaceFields complex_fields(const PatchComplex& c, const ComplexMesh& m) {
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

MeanCurvatureStats regular_stats(const TriangleMesh& mesh) {
  MeanCurvatureStats st;
  double sum = 0;
  for (Eigen::Index k = 0; k < mesh.H.size(); ++k) {
    if (mesh.regular.size() && !mesh.regular(k)) continue;
    st.min = st.count ? std::min(st.min, mesh.H(k)) : mesh.H(k);
    st.max = st.count ? std::max(st.max, mesh.H(k)) : mesh.H(k);
    sum += mesh.H(k);
    ++st.count;
  }
  if (st.count) st.mean = sum / st.count;
  return st;
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


// The report fields every complex result has: its size and the continuity across its seams.
void add_complex_report(SolveOutcome& out, const ComplexJobData& data, const PatchComplex& c) {
  out.report["patches"] = c.patches.size();
  out.report["degree"] = c.patches.front().degree;
  out.report["refine"] = data.refine;
  out.report["seam_angle_max"] = finite_or_null(seam_angle_max(c));
  out.report["continuity"] = data.continuity == Continuity::C1 ? "C1" : "C0";
}

// The cmc problem on a complex: the single-patch solve (solvers/cmc/complex_cmc.h).
SolveOutcome run_complex_cmc(const Job& job) {
  const ComplexJobData& data = *job.complex;
  if (data.continuity == Continuity::C1)
    throw ParameterError("job.boundary.continuity: C1 takes the quadratic energies' extremals, not cmc");
  const CmcOptions o = job_cmc_options(job);
  const CmcResult<PatchComplex> r = solve_cmc(data.complex, o);
  const Status status = checked_status(r.summary);
  SolveOutcome out{job.net, SolveFigures{}, Json::object(), Json::object(), status == Status::Converged, status,
                   std::make_shared<const PatchComplex>(r.net)};
  out.figures.problem = job.problem.kind;
  out.figures.summary = r.summary;
  if (r.summary.iterations > 0) out.figures.iterations = r.summary.iterations;
  add_cmc_figures(out, o, r);
  add_complex_report(out, data, r.net);
  return out;
}

}  // namespace

SolveOutcome run_complex_job(const Job& job) {
  if (job.problem.kind == ProblemKind::CmcH || job.problem.kind == ProblemKind::CmcV) return run_complex_cmc(job);
  const ComplexJobData& data = *job.complex;
  const EnergySpec& e = *job.problem.energy;
  ComplexExtremalOptions options;
  options.continuity = data.continuity;
  options.domain = data.domain;
  const ComplexExtremal r = solve_complex_extremal(data.complex, e, options);
  const Status status = checked_status(r.summary);
  SolveOutcome out{job.net, SolveFigures{}, Json::object(), Json::object(), status == Status::Converged, status, nullptr};
  out.complex = std::make_shared<const PatchComplex>(r.complex);
  out.figures.problem = job.problem.kind;
  out.figures.summary = r.summary;
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

WrittenResult write_complex_result(const std::string& dir, const Job& job, const SolveOutcome& out) {
  const PatchComplex& c = *out.complex;
  const ComplexMesh m = [&] {
    const ProgressStage stage(job_progress(), "sampling");
    return sample_complex(c, job.samples);
  }();
  WrittenResult written;
  Json report = out.report;
  written.mean_curvature = regular_stats(m.mesh);
  report["mean_curvature"] = written.mean_curvature->count
                                 ? Json{{"min", written.mean_curvature->min}, {"max", written.mean_curvature->max},
                                        {"mean", written.mean_curvature->mean}, {"count", written.mean_curvature->count}}
                                 : Json(nullptr);
  // A cmc complex says how far it is from constant mean curvature (run_job.h, CmcCertificate).
  if (written.mean_curvature->count > 0 && report.value("problem", "") == "cmc" && report.contains("H") &&
      report["H"].is_number()) {
    written.certificate = cmc_certificate(*written.mean_curvature, report["H"].get<double>(), m.mesh);
    report["certificate"] = certificate_json(*written.certificate);
  }
  {
    const ProgressStage stage(job_progress(), "checking (CGAL)");
    report["check"] = check_report(m.mesh);
  }
  const ProgressStage stage(job_progress(), "writing files");
  written.result = {{"net", complex_to_json(*job.complex, c)}, {"report", report}};
  const SurfaceFields fields = complex_fields(c, m);
  std::vector<std::int32_t> patch(m.patch.data(), m.patch.data() + m.patch.size());
  OutputFolder folder(dir, output_file_names(true, job_exports(job)));
  write_json_file(folder.file("result.json"), written.result);
  write_obj(folder.file("surface.obj"), m.mesh);
  write_ply(folder.file("surface.ply"), m.mesh, fields, job.mesh_format);
  write_vtp(folder.file("surface.vtp"), m.mesh, fields, job.mesh_format, nullptr, &patch);
  write_file_atomically(folder.file("net.obj"), net_obj(c));
  write_complex_exports(folder, job_exports(job), c, m, fields, report, job.samples);
  folder.commit();
  written.exit_code = exit_code(out.status);
  return written;
}

}  // namespace bpde
