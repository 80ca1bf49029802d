#include "bezierpde/io/boundary_json.h"

#include <cmath>
#include <optional>
#include <utility>

#include "bezierpde/boundaries/reference_boundaries.h"
#include "bezierpde/boundaries/reference_curves.h"
#include "bezierpde/core/bernstein.h"
#include "bezierpde/core/errors.h"
#include "bezierpde/io/error_path.h"

namespace bpde {
namespace {

// at_path (io/error_path.h) without the fit's leading "boundary: ", which the path names.
template <class F>
auto at(const std::string& path, F&& f) -> decltype(f()) {
  return at_path(path, std::forward<F>(f), "boundary: ");
}

Eigen::Vector3d vec3(const Json& j, const std::string& path) {
  const std::vector<double> v = json_read::numbers(j, path, 3);
  return {v[0], v[1], v[2]};
}

std::optional<Eigen::Vector3d> optional_vec3(const Json& j, const std::string& path, const char* key) {
  if (!j.contains(key)) return std::nullopt;
  return vec3(j[key], path + "." + key);
}

int degree_value(const Json& j, const std::string& path) {
  const int d = json_read::integer(j, path);
  if (d < 1 || d > kMaxDegree)
    throw DegreeError(path + ": degree " + std::to_string(d) + " is outside 1.." + std::to_string(kMaxDegree));
  return d;
}

// The reference boundaries by name: the net type they build and their curves.
struct Builder {
  const char* name;
  const char* type;
};
constexpr Builder kBuilders[] = {
    {"circle-three-arcs", "triangular"},
    {"sphere-triangle", "triangular"},
    {"sphere-square", "tensor"},
    {"planar-triangle", "triangular"},
};

BoundaryData builder_curves(const Json& j, const std::string& path, const std::string& name, const std::string& type) {
  using namespace json_read;
  const Builder* b = nullptr;
  for (const Builder& x : kBuilders)
    if (name == x.name) b = &x;
  if (!b)
    throw ParseError(path + ".builder: unknown reference boundary \"" + name + "\" (expected " +
                     reference_boundary_names() + ")");
  if (type != b->type)
    throw UnsupportedProblem(path + ".builder: \"" + name + "\" builds " + b->type + " nets, not " + type);
  if (name == "circle-three-arcs") {
    check_keys(
        j, path,
        {"type", "degree", "builder", "fit", "corner_tolerance", "smooth_corner_angle", "radius", "center", "normal"});
    const double r = j.contains("radius") ? number(j["radius"], path + ".radius") : 1.0;
    const Eigen::Vector3d c = optional_vec3(j, path, "center").value_or(Eigen::Vector3d::Zero());
    const Eigen::Vector3d n = optional_vec3(j, path, "normal").value_or(Eigen::Vector3d::UnitZ());
    return at(path, [&] { return circle_three_arcs_curves(r, c, n); });
  }
  check_keys(j, path, {"type", "degree", "builder", "fit", "corner_tolerance", "smooth_corner_angle"});
  if (name == "sphere-triangle") return triangular_surface_curves(sphere_triangle);
  if (name == "sphere-square") return tensor_surface_curves(sphere_square);
  return triangular_surface_curves(planar_triangle);
}

}  // namespace

std::string reference_boundary_names() {
  std::string s;
  for (const Builder& b : kBuilders) s += std::string(s.empty() ? "" : ", ") + b.name;
  return s;
}

BoundaryCurve curve_from_json(const Json& j, const std::string& path) {
  using namespace json_read;
  require_object(j, path);
  const std::string type = string(field(j, path, "type"), path + ".type");
  if (type == "bezier") {
    check_keys(j, path, {"type", "points"});
    Eigen::MatrixX3d P = points(field(j, path, "points"), path + ".points");
    return at(path, [&] { return BoundaryCurve::bezier(std::move(P)); });
  }
  if (type == "bspline") {
    check_keys(j, path, {"type", "degree", "knots", "points"});
    const int p = degree_value(field(j, path, "degree"), path + ".degree");
    std::vector<double> K = numbers(field(j, path, "knots"), path + ".knots");
    Eigen::MatrixX3d P = points(field(j, path, "points"), path + ".points");
    return at(path, [&] { return BoundaryCurve::bspline(p, std::move(K), std::move(P)); });
  }
  if (type == "samples") {
    check_keys(j, path, {"type", "points", "parameters", "closed"});
    Eigen::MatrixX3d P = points(field(j, path, "points"), path + ".points");
    if (j.contains("closed") && !j["closed"].is_boolean())
      throw ParseError(path + ".closed: expected true or false");
    if (j.contains("closed") && j["closed"].get<bool>()) {
      if (j.contains("parameters") && !j["parameters"].is_string()) {
        const std::vector<double> t = numbers(j["parameters"], path + ".parameters");
        return at(path, [&] { return BoundaryCurve::closed_samples(std::move(P), t); });
      }
      const bool kept = j.contains("parameters");  // "chord-length": checked below for the open form
      if (kept && j["parameters"].get<std::string>() != "chord-length")
        throw ParseError(path + ".parameters: unknown parameters \"" + j["parameters"].get<std::string>() +
                         "\" (expected an array of numbers, or \"chord-length\")");
      return at(path, [&] {
        return BoundaryCurve::closed_samples(std::move(P), kept ? BoundaryCurve::SampleParameters::ChordLength
                                                                : BoundaryCurve::SampleParameters::Corrected);
      });
    }
    if (j.contains("parameters")) {
      if (j["parameters"].is_string()) {
        if (j["parameters"].get<std::string>() != "chord-length")
          throw ParseError(path + ".parameters: unknown parameters \"" + j["parameters"].get<std::string>() +
                           "\" (expected an array of numbers, or \"chord-length\")");
        return at(path, [&] {
          return BoundaryCurve::samples(std::move(P), BoundaryCurve::SampleParameters::ChordLength);
        });
      }
      const std::vector<double> t = numbers(j["parameters"], path + ".parameters");
      return at(path, [&] { return BoundaryCurve::samples(std::move(P), t); });
    }
    return at(path, [&] { return BoundaryCurve::samples(std::move(P)); });
  }
  if (type == "segment") {
    check_keys(j, path, {"type", "from", "to"});
    const Eigen::Vector3d a = vec3(field(j, path, "from"), path + ".from");
    const Eigen::Vector3d b = vec3(field(j, path, "to"), path + ".to");
    return at(path, [&] { return BoundaryCurve::segment(a, b); });
  }
  if (type == "arc" && j.contains("through")) {
    check_keys(j, path, {"type", "through"});
    const Eigen::MatrixX3d P = points(j["through"], path + ".through");
    if (P.rows() != 3) throw SizeError(path + ".through: expected 3 points, got " + std::to_string(P.rows()));
    return at(path, [&] { return BoundaryCurve::arc_through(P.row(0), P.row(1), P.row(2)); });
  }
  if (type == "arc" || type == "helix") {
    const bool helix = type == "helix";
    const char* axis_key = helix ? "axis" : "normal";
    if (helix)
      check_keys(j, path, {"type", "center", "axis", "radius", "angles", "pitch", "reference"});
    else
      check_keys(j, path, {"type", "center", "normal", "radius", "angles", "reference"});
    const Eigen::Vector3d c = vec3(field(j, path, "center"), path + ".center");
    const Eigen::Vector3d n = vec3(field(j, path, axis_key), path + "." + axis_key);
    const double r = number(field(j, path, "radius"), path + ".radius");
    const std::vector<double> a = numbers(field(j, path, "angles"), path + ".angles", 2);
    const std::optional<Eigen::Vector3d> ref = optional_vec3(j, path, "reference");
    if (!helix) return at(path, [&] { return BoundaryCurve::arc(c, n, r, a[0], a[1], ref); });
    const double pitch = number(field(j, path, "pitch"), path + ".pitch");
    return at(path, [&] { return BoundaryCurve::helix(c, n, r, a[0], a[1], pitch, ref); });
  }
  if (type == "circle") {
    check_keys(j, path, {"type", "center", "normal", "radius", "reference"});
    const Eigen::Vector3d c = vec3(field(j, path, "center"), path + ".center");
    const Eigen::Vector3d n = vec3(field(j, path, "normal"), path + ".normal");
    const double r = number(field(j, path, "radius"), path + ".radius");
    const std::optional<Eigen::Vector3d> ref = optional_vec3(j, path, "reference");
    return at(path, [&] { return BoundaryCurve::circle(c, n, r, ref); });
  }
  throw ParseError(path + ".type: unknown curve type \"" + type +
                   "\" (expected bezier, bspline, samples, segment, arc, helix or circle)");
}

BoundaryNet boundary_from_json(const Json& j, const std::string& path, FitMethod default_fit) {
  using namespace json_read;
  require_object(j, path);
  const std::string type = string(field(j, path, "type"), path + ".type");
  if (type != "tensor" && type != "triangular")
    throw ParseError(path + ".type: a boundary form builds a \"tensor\" or \"triangular\" net, got \"" + type + "\"");
  // Degrees first (FORMATS.md: checked before anything else of the net).
  int n = 0, m = 0;
  const Json& dj = field(j, path, "degree");
  if (type == "tensor") {
    if (!dj.is_array() || dj.size() != 2) throw ParseError(path + ".degree: expected [n, m]");
    n = degree_value(dj[0], path + ".degree[0]");
    m = degree_value(dj[1], path + ".degree[1]");
  } else {
    n = degree_value(dj, path + ".degree");
  }
  BoundaryFitOptions o;
  o.method = default_fit;
  if (j.contains("fit")) {
    const std::string f = string(j["fit"], path + ".fit");
    if (f == "interpolation")
      o.method = FitMethod::Interpolation;
    else if (f == "least-squares")
      o.method = FitMethod::LeastSquares;
    else if (f == "geometric")
      o.method = FitMethod::Geometric;
    else
      throw ParseError(path + ".fit: unknown fit \"" + f + "\" (expected interpolation, least-squares or geometric)");
  }
  if (j.contains("corner_tolerance")) {
    o.corner_tolerance = number(j["corner_tolerance"], path + ".corner_tolerance");
    at(path + ".corner_tolerance", [&] { o.validate(); });
  }
  if (j.contains("smooth_corner_angle")) {
    o.smooth_corner_angle = number(j["smooth_corner_angle"], path + ".smooth_corner_angle");
    at(path + ".smooth_corner_angle", [&] { o.validate(); });
  }
  BoundaryData data;
  if (j.contains("builder")) {
    data = builder_curves(j, path, string(j["builder"], path + ".builder"), type);
  } else {
    check_keys(j, path, {"type", "degree", "edges", "tangents", "fit", "corner_tolerance", "smooth_corner_angle"});
    const size_t E = type == "tensor" ? 4 : 3;
    auto curves = [&](const char* key) {
      const Json& a = field(j, path, key);
      const std::string p = path + "." + key;
      if (!a.is_array()) throw ParseError(p + ": expected an array of " + std::to_string(E) + " curves");
      if (a.size() != E)
        throw SizeError(p + ": a " + type + " net has " + std::to_string(E) + " edges, got " +
                        std::to_string(a.size()));
      std::vector<BoundaryCurve> c;
      for (size_t e = 0; e < E; ++e) c.push_back(curve_from_json(a[e], p + "[" + std::to_string(e) + "]"));
      return c;
    };
    data.edges = curves("edges");
    if (j.contains("tangents")) data.tangents = curves("tangents");
  }
  BoundaryNet out;
  out.c1 = !data.tangents.empty();
  if (type == "tensor") {
    auto fit = at(path, [&] { return fit_tensor_boundary(n, m, data, o); });
    out.net = std::move(fit.net);
    out.fits = std::move(fit.edges);
  } else {
    auto fit = at(path, [&] { return fit_triangular_boundary(n, data, o); });
    out.net = std::move(fit.net);
    out.fits = std::move(fit.edges);
  }
  return out;
}

Json boundary_fit_to_json(const std::vector<EdgeFit>& fits) {
  Json a = Json::array();
  for (const EdgeFit& f : fits) {
    Json r = {{"edge", f.edge}, {"curve", f.curve}, {"method", f.method}, {"max_error", f.max_error}};
    if (f.tangent_max_error) {
      r["tangent_curve"] = *f.tangent_curve;
      r["tangent_method"] = *f.tangent_method;
      r["tangent_max_error"] = *f.tangent_max_error;
    }
    if (f.end_corner) {
      r["end_corner"] = *f.end_corner;
      r["end_corner_turn"] = *f.end_corner_turn;
    }
    if (f.parameters) {
      r["parameters"] = *f.parameters;
      if (*f.parameters == "corrected") r["corrections"] = *f.corrections;
    }
    a.push_back(std::move(r));
  }
  return a;
}

}  // namespace bpde
