#include "bezierpde/io/complex_json.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <utility>

#include "bezierpde/complex/refine.h"
#include "bezierpde/core/errors.h"
#include "bezierpde/io/error_path.h"
#include "bezierpde/solvers/complex/complex_extremal.h"

namespace bpde {
namespace {

std::string at(const std::string& path, std::size_t k) { return path + "[" + std::to_string(k) + "]"; }


Layout layout_from_json(const Json& j, const std::string& path, PatchKind kind) {
  json_read::require_object(j, path);
  json_read::check_keys(j, path, {"vertices", "faces", "boundary"});
  Layout L = layout_vertices_and_faces_from_json(j, path, kind);
  at_path(path, [&] { validate_layout(L); });
  return L;
}

// layout.boundary: every boundary edge of the layout once, in the faces' direction.
std::vector<LayoutBoundaryEdge> boundary_from_json(const Json& j, const std::string& path, const Layout& L) {
  using namespace json_read;
  if (!j.is_array()) throw ParseError(path + ": expected an array of boundary edges");
  std::set<std::pair<int, int>> expected;
  for (const std::vector<int>& loop : layout_boundary_loops(L))
    for (std::size_t k = 0; k < loop.size(); ++k) expected.insert({loop[k], loop[(k + 1) % loop.size()]});
  std::vector<LayoutBoundaryEdge> edges;
  std::set<std::pair<int, int>> seen;
  for (std::size_t k = 0; k < j.size(); ++k) {
    const std::string bp = at(path, k);
    const Json& b = j[k];
    const LayoutBoundaryEdge e = layout_boundary_edge_from_json(b, bp);
    if (!expected.count({e.a, e.b}))
      throw LayoutMismatchError(bp + ": " + std::to_string(e.a) + " -> " + std::to_string(e.b) +
                                " is not a boundary edge of the layout in the direction its face runs along it");
    if (!seen.insert({e.a, e.b}).second)
      throw LayoutMismatchError(bp + ": the boundary edge " + std::to_string(e.a) + " -> " + std::to_string(e.b) +
                                " is listed twice");
    edges.push_back(e);
  }
  if (seen.size() != expected.size())
    throw LayoutMismatchError(path + ": lists " + std::to_string(seen.size()) + " of the layout's " +
                              std::to_string(expected.size()) + " boundary edges");
  return edges;
}

}  // namespace

std::pair<PatchKind, int> complex_patch_and_degree(const Json& j, const std::string& path) {
  using namespace json_read;
  const std::string patch = string(field(j, path, "patch"), path + ".patch");
  if (patch != "triangular" && patch != "tensor")
    throw ParseError(path + ".patch: expected \"triangular\" or \"tensor\", got \"" + patch + "\"");
  const int n = integer(field(j, path, "degree"), path + ".degree");
  if (n < 1 || n > kMaxComplexExtremalDegree)
    throw DegreeError(path + ".degree: a complex takes degrees 1.." + std::to_string(kMaxComplexExtremalDegree) +
                      " (the Bernstein Gram systems lose a digit per degree), got " + std::to_string(n));
  return {patch == "triangular" ? PatchKind::triangular : PatchKind::tensor, n};
}

Layout layout_vertices_and_faces_from_json(const Json& j, const std::string& path, PatchKind kind) {
  using namespace json_read;
  Layout L;
  L.kind = kind;
  L.vertices = points(field(j, path, "vertices"), path + ".vertices");
  const Json& faces = field(j, path, "faces");
  if (!faces.is_array()) throw ParseError(path + ".faces: expected an array of faces");
  if (faces.size() > static_cast<std::size_t>(kMaxComplexPatches))
    throw SizeError(path + ".faces: at most " + std::to_string(kMaxComplexPatches) + " faces, got " +
                    std::to_string(faces.size()));
  for (std::size_t f = 0; f < faces.size(); ++f) {
    const std::string fp = at(path + ".faces", f);
    if (!faces[f].is_array()) throw ParseError(fp + ": expected an array of integers");
    std::vector<int> face;
    for (std::size_t k = 0; k < faces[f].size(); ++k) face.push_back(integer(faces[f][k], at(fp, k)));
    L.faces.push_back(std::move(face));
  }
  return L;
}

LayoutBoundaryEdge layout_boundary_edge_from_json(const Json& b, const std::string& bp) {
  using namespace json_read;
  require_object(b, bp);
  check_keys(b, bp, {"from", "to", "loop", "curve", "range"});
  LayoutBoundaryEdge e;
  e.a = integer(field(b, bp, "from"), bp + ".from");
  e.b = integer(field(b, bp, "to"), bp + ".to");
  e.piece.loop = integer(field(b, bp, "loop"), bp + ".loop");
  e.piece.curve = integer(field(b, bp, "curve"), bp + ".curve");
  if (e.piece.loop < 0 || e.piece.curve < 0)
    throw ParameterError(bp + ": loop and curve are indices (>= 0), got " + std::to_string(e.piece.loop) + " and " +
                         std::to_string(e.piece.curve));
  if (b.contains("range")) {
    const std::vector<double> r = numbers(b["range"], bp + ".range", 2);
    e.piece.t0 = r[0], e.piece.t1 = r[1];
  }
  return e;
}

std::string patch_kind_name(PatchKind kind) { return kind == PatchKind::triangular ? "triangular" : "tensor"; }

bool is_complex_net(const Json& j) { return j.is_object() && j.contains("type") && j["type"] == "complex"; }

ComplexNetFile complex_net_from_json(const Json& j, const std::string& path) {
  using namespace json_read;
  require_object(j, path);
  check_keys(j, path, {"type", "patch", "degree", "refine", "refit", "patches", "layout"});
  const std::string type = string(field(j, path, "type"), path + ".type");
  if (type != "complex") throw ParseError(path + ".type: expected \"complex\", got \"" + type + "\"");
  const std::pair<PatchKind, int> patch_and_degree = complex_patch_and_degree(j, path);
  const PatchKind kind = patch_and_degree.first;  // (not a structured binding: lambdas capture these)
  const int n = patch_and_degree.second;
  const std::string patch = patch_kind_name(kind);
  ComplexNetFile out;
  if (j.contains("refine")) out.refine = integer(j["refine"], path + ".refine");
  if (j.contains("refit")) {
    if (!j["refit"].is_boolean()) throw ParseError(path + ".refit: expected true or false");
    out.refit = j["refit"].get<bool>();
  }
  if (out.refine < 0 || out.refine > kMaxComplexRefine)
    throw SizeError(path + ".refine: must be in 0.." + std::to_string(kMaxComplexRefine) + ", got " +
                    std::to_string(out.refine));
  const std::string lp = path + ".layout";
  const Json& layout = field(j, path, "layout");
  out.layout = layout_from_json(layout, lp, kind);
  if (layout.contains("boundary")) out.boundary = boundary_from_json(layout["boundary"], lp + ".boundary", out.layout);

  // Sizes before any work: the patch count the layout and refine give, and the Gram limit of a job.
  const long long patches = static_cast<long long>(out.layout.faces.size()) << (2 * out.refine);
  if (patches > kMaxComplexPatches)
    throw SizeError(path + ": " + std::to_string(out.layout.faces.size()) + " faces refined " +
                    std::to_string(out.refine) + " times are " + std::to_string(patches) + " patches, more than " +
                    std::to_string(kMaxComplexPatches));
  const long long per_patch = patch_point_count(kind, n);
  if (patches * per_patch * per_patch > kMaxComplexGramEntries)
    throw SizeError(path + ": " + std::to_string(patches) + " patches of degree " + std::to_string(n) + " are " +
                    std::to_string(patches * per_patch * per_patch) + " Gram entries, more than " +
                    std::to_string(kMaxComplexGramEntries));
  const std::string pp = path + ".patches";
  const Json& pj = field(j, path, "patches");
  if (!pj.is_array()) throw ParseError(pp + ": expected an array of nets");
  if (static_cast<long long>(pj.size()) != patches)
    throw SizeError(pp + ": " + std::to_string(out.layout.faces.size()) + " faces refined " +
                    std::to_string(out.refine) + " times are " + std::to_string(patches) + " patches, got " +
                    std::to_string(pj.size()));
  std::vector<Eigen::MatrixX3d> local;
  local.reserve(pj.size());
  for (std::size_t p = 0; p < pj.size(); ++p) {
    const std::string np = at(pp, p);
    if (pj[p].is_object() && pj[p].contains("type") && pj[p]["type"] != patch)
      throw ParseError(np + ".type: a " + patch + " complex holds " + patch + " nets, got " + pj[p]["type"].dump());
    const Net net = net_from_json(pj[p], np);
    if (kind == PatchKind::triangular) {
      const auto& t = std::get<TriangularNet>(net);
      if (t.n() != n)
        throw DegreeError(np + ".degree: every patch has the complex's degree " + std::to_string(n) + ", got " +
                          std::to_string(t.n()));
      local.push_back(t.points());
    } else {
      const auto& t = std::get<TensorNet>(net);
      if (t.n() != n || t.m() != n)
        throw DegreeError(np + ".degree: every patch has the complex's degree [" + std::to_string(n) + ", " +
                          std::to_string(n) + "], got [" + std::to_string(t.n()) + ", " + std::to_string(t.m()) + "]");
      local.push_back(t.points());
    }
  }

  // The row structure of the job, then the points, shared rows checked.
  PatchComplex c = at_path(lp, [&] { return complex_topology(out.layout, n); });
  for (int r = 0; r < out.refine; ++r) c = refine_h(c);
  double lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
  for (const Eigen::MatrixX3d& P : local)
    for (int k = 0; k < 3; ++k) lo[k] = std::min(lo[k], P.col(k).minCoeff()), hi[k] = std::max(hi[k], P.col(k).maxCoeff());
  const double diag = std::sqrt((hi[0] - lo[0]) * (hi[0] - lo[0]) + (hi[1] - lo[1]) * (hi[1] - lo[1]) +
                                (hi[2] - lo[2]) * (hi[2] - lo[2]));
  const double tolerance = kComplexSeamTolerance * std::max(1.0, std::isfinite(diag) ? diag : 1.0);
  std::vector<int> owner(static_cast<std::size_t>(c.points.rows()), -1);  // patch that set the row
  for (int p = 0; p < static_cast<int>(c.patches.size()); ++p) {
    const std::vector<int>& rows = c.patches[p].points;
    for (int k = 0; k < static_cast<int>(rows.size()); ++k) {
      const int row = rows[k];
      if (owner[row] < 0) {
        owner[row] = p;
        c.points.row(row) = local[p].row(k);
        continue;
      }
      const double gap = (c.points.row(row) - local[p].row(k)).norm();
      if (!(gap <= tolerance))
        throw ParameterError(at(pp, p) + ".points[" + std::to_string(k) + "]: differs by " + std::to_string(gap) +
                             " from the same control point of patch " + std::to_string(owner[row]) +
                             " (patches share the control points of a common edge or corner)");
    }
  }
  c.fixed = boundary_rows(c);
  at_path(path, [&] { validate(c); });
  out.complex = std::move(c);
  return out;
}

Json complex_net_to_json(const ComplexNetFile& c) {
  const PatchComplex& pc = c.complex;
  const PatchKind kind = pc.patches.front().kind;
  Json patches = Json::array();
  for (int p = 0; p < static_cast<int>(pc.patches.size()); ++p)
    patches.push_back(kind == PatchKind::triangular ? net_to_json(triangular_net(pc, p)) : net_to_json(tensor_net(pc, p)));
  Json vertices = Json::array(), faces = Json::array();
  for (int v = 0; v < c.layout.vertices.rows(); ++v)
    vertices.push_back({c.layout.vertices(v, 0), c.layout.vertices(v, 1), c.layout.vertices(v, 2)});
  for (const auto& f : c.layout.faces) faces.push_back(f);
  Json layout = {{"vertices", vertices}, {"faces", faces}};
  if (!c.boundary.empty()) {
    Json boundary = Json::array();
    for (const LayoutBoundaryEdge& e : c.boundary)
      boundary.push_back({{"from", e.a}, {"to", e.b}, {"loop", e.piece.loop}, {"curve", e.piece.curve},
                          {"range", Json::array({e.piece.t0, e.piece.t1})}});
    layout["boundary"] = boundary;
  }
  return {{"type", "complex"},
          {"patch", patch_kind_name(kind)},
          {"degree", pc.patches.front().degree},
          {"refine", c.refine},
          {"refit", c.refit},
          {"patches", patches},
          {"layout", layout}};
}

}  // namespace bpde
