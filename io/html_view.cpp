#include "bezierpde/io/html_view.h"

#include <bit>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <string_view>
#include <vector>

#include "bpde_viewer_assets.h"  // generated at build time (CMakeLists.txt): kTemplate, kBundle, kThreeVersion
#include "bezierpde/core/errors.h"
#include "bezierpde/io/atomic_file.h"
#include "bezierpde/io/base64.h"
#include "bezierpde/io/mesh_io.h"

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

// Replace the one occurrence of `marker` in `page` (InternalError if it is missing).
void fill(std::string& page, std::string_view marker, const std::string& value) {
  const size_t p = page.find(marker);
  if (p == std::string::npos) throw InternalError("view.html template: no " + std::string(marker));
  page.replace(p, marker.size(), value);
}

bool finite_number(const Json& j) { return j.is_number() && std::isfinite(j.get<double>()); }

}  // namespace

std::string viewer_three_version() { return std::string(viewer_assets::kThreeVersion); }

std::string view_html(const Net& net, const TriangleMesh& mesh, const SurfaceFields& fields, const Json& report,
                      const std::string& title) {
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
  std::vector<std::uint32_t> lines;
  for (const auto& [a, b] : net_segments(net))
    lines.insert(lines.end(), {static_cast<std::uint32_t>(a), static_cast<std::uint32_t>(b)});
  const Eigen::MatrixX3d P = std::visit([](const auto& n) -> Eigen::MatrixX3d { return n.points(); }, net);

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
  std::string json = data.dump(-1, ' ', true, Json::error_handler_t::replace);
  // inside <script>, "</" could close the element: JSON allows the escaped "<\/"
  for (size_t p = 0; (p = json.find("</", p)) != std::string::npos; p += 3) json.replace(p, 2, "<\\/");

  std::string page(viewer_assets::kTemplate);
  const std::string t = html_escape(title);
  fill(page, "@BPDE_TITLE@", t);
  fill(page, "@BPDE_TITLE@", t);
  fill(page, "@BPDE_THREE_VERSION@", viewer_three_version());
  fill(page, "@BPDE_RANGE_NOTE@", note);
  // the bundle last, so that no marker is searched for inside three.js or the data
  const size_t data_at = page.find("@BPDE_DATA@"), bundle_at = page.find("@BPDE_BUNDLE@");
  if (data_at == std::string::npos || bundle_at == std::string::npos || bundle_at < data_at)
    throw InternalError("view.html template: markers missing");
  std::string out;
  out.reserve(page.size() + json.size() + viewer_assets::kBundle.size());
  out.append(page, 0, data_at);
  out += json;
  out.append(page, data_at + 11, bundle_at - data_at - 11);
  out.append(viewer_assets::kBundle);
  out.append(page, bundle_at + 13, std::string::npos);
  return out;
}

void write_view_html(const std::string& path, const Net& net, const TriangleMesh& mesh, const Json& report,
                     const std::string& title) {
  const std::string page = view_html(net, mesh, surface_fields(net, mesh), report, title);
  write_file_atomically(path, page);
}

}  // namespace bpde
