#include "bezierpde/io/html_view.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <set>
#include <string_view>
#include <utility>
#include <vector>

#include "bpde_viewer_assets.h"  // generated at build time (CMakeLists.txt): kTemplate, kBundle, kThreeVersion
#include "bezierpde/core/errors.h"
#include "bezierpde/io/atomic_file.h"
#include "bezierpde/io/base64.h"
#include "bezierpde/io/mesh_io.h"
#include "bezierpde/tensor/tensor_net.h"
#include "bezierpde/triangular/triangular_net.h"

namespace bpde {
namespace {

static_assert(std::endian::native == std::endian::little, "the page's typed arrays are little-endian");

template <class T>
std::string b64(const std::vector<T>& v) {
  return base64_encode(v.data(), v.size() * sizeof(T));
}

std::vector<float> floats(const Eigen::MatrixX3d& M) {
  std::vector<float> out(static_cast<size_t>(M.rows()) * 3);
  for (Eigen::Index r = 0; r < M.rows(); ++r)
    for (int c = 0; c < 3; ++c) out[static_cast<size_t>(3 * r + c)] = static_cast<float>(M(r, c));
  return out;
}

std::string html_escape(const std::string& s) {
  std::string out;
  for (char c : s) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

// The page: the template with each @BPDE_NAME@ marker replaced by values.at(NAME), in one pass
// over the template by position, so that no value (the title, the report's strings, three.js) is
// ever searched for markers. InternalError for a marker without a value or a value never used.
std::string fill_template(std::string_view page, const std::vector<std::pair<std::string_view, std::string_view>>& values) {
  std::string out;
  std::size_t used = 0, at = 0;
  for (std::size_t p; (p = page.find("@BPDE_", at)) != std::string_view::npos;) {
    const std::size_t end = page.find('@', p + 1);
    if (end == std::string_view::npos) break;
    const std::string_view name = page.substr(p + 1, end - p - 1);
    auto it = std::find_if(values.begin(), values.end(), [&](const auto& v) { return v.first == name; });
    if (it == values.end()) throw InternalError("view.html template: no value for @" + std::string(name) + "@");
    out.append(page.substr(at, p - at));
    out.append(it->second);
    used |= std::size_t(1) << (it - values.begin());
    at = end + 1;
  }
  out.append(page.substr(at));
  if (used != (std::size_t(1) << values.size()) - 1) throw InternalError("view.html template: markers missing");
  return out;
}

// JSON for a <script> element: "<", ">" and "&" (which could end the element or open a comment
// that swallows its end tag) and U+2028/U+2029 as \u escapes; they occur only inside strings, where
// the escapes read back as the same characters.
std::string script_safe(std::string json) {
  std::string out;
  out.reserve(json.size());
  for (std::size_t i = 0; i < json.size(); ++i) {
    const char c = json[i];
    if (c == '<')
      out += "\\u003c";
    else if (c == '>')
      out += "\\u003e";
    else if (c == '&')
      out += "\\u0026";
    else if (c == '\xE2' && i + 2 < json.size() && json[i + 1] == '\x80' && (json[i + 2] == '\xA8' || json[i + 2] == '\xA9')) {
      out += json[i + 2] == '\xA8' ? "\\u2028" : "\\u2029";
      i += 2;
    } else {
      out += c;
    }
  }
  return out;
}

bool finite_number(const Json& j) { return j.is_number() && std::isfinite(j.get<double>()); }

}  // namespace

std::string viewer_three_version() { return std::string(viewer_assets::kThreeVersion); }

namespace {

// The page for a mesh with its fields, a control net (points, segment pairs) and extra data fields.
std::string page(const TriangleMesh& mesh, const SurfaceFields& fields, const Eigen::MatrixX3d& P,
                 const std::vector<std::uint32_t>& lines, const Json& report, const std::string& title, Json extra) {
  const Eigen::Index nv = mesh.V.rows(), nf = mesh.F.rows();
  std::vector<float> H(static_cast<size_t>(nv));
  std::vector<std::uint8_t> regular(static_cast<size_t>(nv));
  double lo = INFINITY, hi = -INFINITY;
  for (Eigen::Index k = 0; k < nv; ++k) {
    H[static_cast<size_t>(k)] = static_cast<float>(fields.H(k));
    regular[static_cast<size_t>(k)] = fields.regular(k);
    if (fields.regular(k)) lo = std::min(lo, fields.H(k)), hi = std::max(hi, fields.H(k));
  }
  std::string note = "Colours: H over its range at the regular vertices.";
  const Json* stats = report.is_object() && report.contains("mean_curvature") ? &report["mean_curvature"] : nullptr;
  if (stats && stats->is_object() && stats->contains("min") && stats->contains("max") &&
      finite_number((*stats)["min"]) && finite_number((*stats)["max"])) {
    lo = (*stats)["min"].get<double>();
    hi = (*stats)["max"].get<double>();
    note = "Colours: H clamped to the report's range (away from the corners).";
  }
  if (!(lo <= hi)) lo = hi = 0;                          // no regular vertex
  if (hi - lo <= 1e-12 * std::max(1.0, std::abs(lo))) {  // a constant H: centre it on the scale
    const double pad = 0.5 * std::max(1e-6, std::abs(lo));
    lo -= pad, hi += pad;
  }
  std::vector<std::uint32_t> tris(static_cast<size_t>(nf) * 3);
  for (Eigen::Index t = 0; t < nf; ++t)
    for (int c = 0; c < 3; ++c) tris[static_cast<size_t>(3 * t + c)] = static_cast<std::uint32_t>(mesh.F(t, c));

  Json data = {{"title", title},
               {"vertices", nv},
               {"triangles", nf},
               {"positions", b64(floats(mesh.V))},
               {"normals", b64(floats(fields.normal))},
               {"H", b64(H)},
               {"regular", b64(regular)},
               {"indices", b64(tris)},
               {"net", {{"points", b64(floats(P))}, {"lines", b64(lines)}}},
               {"range", {lo, hi}},
               {"report", report.is_object() ? report : Json::object()}};
  for (auto it = extra.begin(); it != extra.end(); ++it) data[it.key()] = std::move(it.value());
  const std::string json = script_safe(data.dump(-1, ' ', true, Json::error_handler_t::replace));
  const std::string t = html_escape(title), three = viewer_three_version();
  return fill_template(viewer_assets::kTemplate, {{"BPDE_TITLE", t},
                                                  {"BPDE_THREE_VERSION", three},
                                                  {"BPDE_RANGE_NOTE", note},
                                                  {"BPDE_DATA", json},
                                                  {"BPDE_BUNDLE", viewer_assets::kBundle}});
}

}  // namespace

std::string view_html(const Net& net, const TriangleMesh& mesh, const SurfaceFields& fields, const Json& report,
                      const std::string& title) {
  std::vector<std::uint32_t> lines;
  for (const auto& [a, b] : net_segments(net))
    lines.insert(lines.end(), {static_cast<std::uint32_t>(a), static_cast<std::uint32_t>(b)});
  const Eigen::MatrixX3d P = std::visit([](const auto& n) -> Eigen::MatrixX3d { return n.points(); }, net);
  return page(mesh, fields, P, lines, report, title, Json::object());
}

std::string view_html(const PatchComplex& c, const ComplexMesh& m, const SurfaceFields& fields, const Json& report,
                      const std::string& title, int seam_samples) {
  if (seam_samples < 1 || seam_samples > kMaxSamples)
    throw ParameterError("view_html: seam samples must be in 1.." + std::to_string(kMaxSamples) + ", got " +
                         std::to_string(seam_samples));
  validate(c);
  // every patch's control net, each segment once, on the complex's rows
  std::set<std::pair<int, int>> segments;
  std::vector<Net> nets;
  for (int p = 0; p < static_cast<int>(c.patches.size()); ++p) {
    nets.push_back(c.patches[p].kind == PatchKind::triangular ? Net(triangular_net(c, p)) : Net(tensor_net(c, p)));
    for (const auto& [a, b] : net_segments(nets.back())) {
      const int ga = c.patches[p].points[a], gb = c.patches[p].points[b];
      segments.insert({std::min(ga, gb), std::max(ga, gb)});
    }
  }
  std::vector<std::uint32_t> lines;
  for (const auto& [a, b] : segments) lines.insert(lines.end(), {static_cast<std::uint32_t>(a), static_cast<std::uint32_t>(b)});
  // the seams: interior edges first, then the boundary, each a polyline of seam_samples segments
  std::vector<ComplexEdge> edges = complex_edges(c);
  std::stable_partition(edges.begin(), edges.end(), [](const ComplexEdge& e) { return !e.boundary(); });
  const int N = seam_samples;
  Eigen::MatrixX3d seam_points(static_cast<Eigen::Index>(edges.size()) * (N + 1), 3);
  std::vector<std::uint32_t> seam_lines;
  int interior = 0;
  for (std::size_t k = 0; k < edges.size(); ++k) {
    const ComplexEdge::Side& side = edges[k].sides.front();
    interior += edges[k].boundary() ? 0 : 1;
    const Net& net = nets[static_cast<std::size_t>(side.patch)];
    const Eigen::Index start = static_cast<Eigen::Index>(k) * (N + 1);
    for (int s = 0; s <= N; ++s) {
      const Eigen::Vector2d uv = patch_edge_parameter(c.patches[side.patch].kind, side.edge, static_cast<double>(s) / N);
      seam_points.row(start + s) =
          std::visit([&](const auto& n) -> Eigen::Vector3d { return n.evaluate(uv(0), uv(1)); }, net).transpose();
      if (s < N)
        seam_lines.insert(seam_lines.end(), {static_cast<std::uint32_t>(start + s), static_cast<std::uint32_t>(start + s + 1)});
    }
  }
  Json extra = {{"seams",
                 {{"edges", edges.size()},
                  {"interior", interior},
                  {"samples", N},
                  {"points", b64(floats(seam_points))},
                  {"lines", b64(seam_lines)}}}};
  return page(m.mesh, fields, c.points, lines, report, title, std::move(extra));
}

void write_view_html(const std::string& path, const PatchComplex& c, const ComplexMesh& m, const SurfaceFields& fields,
                     const Json& report, const std::string& title, int seam_samples) {
  write_file_atomically(path, view_html(c, m, fields, report, title, seam_samples));
}

void write_view_html(const std::string& path, const Net& net, const TriangleMesh& mesh, const Json& report,
                     const std::string& title) {
  const std::string page = view_html(net, mesh, surface_fields(net, mesh), report, title);
  write_file_atomically(path, page);
}

}  // namespace bpde
