#include "bezierpde/jobs/complex_exports.h"

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <set>
#include <utility>
#include <vector>

#include "bezierpde/io/atomic_file.h"
#include "bezierpde/io/html_view.h"
#include "bezierpde/io/step_export.h"
#include "bezierpde/io/vtp_io.h"
#include "bezierpde/tensor/tensor_net.h"
#include "bezierpde/triangular/triangular_net.h"

namespace bpde {
namespace {

std::string problem_of(const Json& report) {
  if (report.is_object() && report.contains("problem") && report["problem"].is_string())
    return report["problem"].get<std::string>();
  return "surface";
}

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

}  // namespace

Exports job_exports(const Job& job) {
  Exports e;
  e.step = job.export_step;
  e.html = job.export_html;
  return e;
}

std::string view_title(const PatchComplex& c, const Json& report) {
  const std::size_t P = c.patches.size();
  const std::string kind = c.patches.empty() || c.patches.front().kind == PatchKind::triangular ? "triangular" : "tensor";
  return "bezierpde: " + problem_of(report) + " on a complex of " + std::to_string(P) + " " + kind +
         (P == 1 ? " patch" : " patches");
}

SurfaceFields complex_surface_fields(const PatchComplex& c, const TriangleMesh& mesh,
                                     const Eigen::VectorXi& vertex_patch, const Eigen::MatrixX2d& uv) {
  const Eigen::Index nv = mesh.V.rows();
  SurfaceFields f;
  f.uv = uv;
  f.normal.resize(nv, 3);
  f.H = mesh.H;
  f.K.resize(nv);
  f.regular.resize(nv);
  for (Eigen::Index k = 0; k < nv; ++k) {
    const FundamentalForms g = robust_geometry(c, vertex_patch(k), uv(k, 0), uv(k, 1));
    f.normal.row(k) = g.normal.transpose();
    f.K(k) = g.K;
    f.regular(k) = mesh.regular.size() ? mesh.regular(k) : 1;
  }
  return f;
}

SurfaceFields complex_surface_fields(const PatchComplex& c, const ComplexMesh& m) {
  return complex_surface_fields(c, m.mesh, m.vertex_patch, m.uv);
}

std::string complex_net_obj(const PatchComplex& c) {
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

void write_complex_exports(OutputFolder& folder, const Exports& exports, const PatchComplex& c, const ComplexMesh& m,
                           const SurfaceFields& fields, const Json& report, int samples) {
  if (exports.step) write_step(folder.file("surface.step"), c);
  if (exports.html)
    write_view_html(folder.file("view.html"), c, m, fields, report, view_title(c, report), samples);
}

void write_complex_surface_files(const std::string& dir, const PatchComplex& c, const ComplexMesh& m,
                                 MeshFormat format) {
  const SurfaceFields fields = complex_surface_fields(c, m);
  const std::vector<std::int32_t> patch(m.patch.data(), m.patch.data() + m.patch.size());
  OutputFolder folder(dir, {"surface.obj", "surface.ply", "surface.vtp", "net.obj"});
  write_obj(folder.file("surface.obj"), m.mesh);
  write_ply(folder.file("surface.ply"), m.mesh, fields, format);
  folder.write("surface.vtp", vtp_text(m.mesh, fields, format, nullptr, &patch));
  folder.write("net.obj", complex_net_obj(c));
  folder.commit();
}

}  // namespace bpde
