#include "bezierpde/io/blend_config.h"

#include "bezierpde/io/json_io.h"

#include <cmath>
#include <nlohmann/json.hpp>
#include <set>

#include "bezierpde/core/errors.h"

namespace bpde {

namespace {

using json = nlohmann::json;

std::string type_name(const json& j) { return j.type_name(); }

void check_fields(const json& j, const std::string& where, const std::set<std::string>& allowed,
                  const std::set<std::string>& required) {
  if (!j.is_object())
    throw ParseError((where.empty() ? std::string("the blend config") : where) + " must be a JSON object, not " +
                     type_name(j));
  for (const auto& [key, value] : j.items()) {
    (void)value;
    if (!allowed.count(key)) throw ParseError("unknown field `" + (where.empty() ? key : where + "." + key) + "`");
  }
  for (const auto& key : required)
    if (!j.contains(key)) throw ParseError("missing field `" + (where.empty() ? key : where + "." + key) + "`");
}

double number(const json& j, const std::string& where) {
  if (!j.is_number()) throw ParseError(where + " must be a number, not " + type_name(j));
  const double v = j.get<double>();
  if (!std::isfinite(v)) throw NonFiniteError(where + " is not finite");
  return v;
}

// Integers (partition, samples) are read as every reader reads them (json_read::integer: exact
// for 0..2^64-1, at most kMaxJsonInteger in magnitude).
int integer(const json& j, const std::string& where) { return json_read::integer(j, where); }

/// An array of rows of `width` numbers.
Eigen::MatrixXd rows(const json& j, int width, const std::string& where) {
  if (!j.is_array()) throw ParseError(where + " must be an array, not " + type_name(j));
  Eigen::MatrixXd M(j.size(), width);
  for (std::size_t r = 0; r < j.size(); ++r) {
    const std::string w = where + "[" + std::to_string(r) + "]";
    const json& row = j[r];
    if (!row.is_array())
      throw ParseError(w + " must be an array of " + std::to_string(width) + " numbers, not " + type_name(row));
    if (row.size() != static_cast<std::size_t>(width))
      throw SizeError(w + " has " + std::to_string(row.size()) + " numbers, expected " + std::to_string(width));
    for (int c = 0; c < width; ++c)
      M(static_cast<Eigen::Index>(r), c) = number(row[c], w + "[" + std::to_string(c) + "]");
  }
  return M;
}

Eigen::MatrixX3d edge_array(const json& j, int k, const std::string& where) {
  Eigen::MatrixX3d M = rows(j, 3, where);
  if (M.rows() != k + 1)
    throw SizeError(where + " has " + std::to_string(M.rows()) + " points, expected k+1 = " + std::to_string(k + 1) +
                    " (one per node x_i = i/k)");
  return M;
}

// "kind", when given, must be "blend".
void check_kind(const json& j) {
  if (!j.contains("kind")) return;
  if (!j["kind"].is_string()) throw ParseError("kind must be the string \"blend\", not " + type_name(j["kind"]));
  if (j["kind"].get<std::string>() != "blend")
    throw ParseError("kind must be \"blend\", not \"" + j["kind"].get<std::string>() + "\"");
}

void read_partition(const json& part, SmoothingSplineProblem& p) {
  if (!part.is_array()) throw ParseError("partition must be an array [k, l], not " + type_name(part));
  if (part.size() != 2) throw SizeError("partition has " + std::to_string(part.size()) + " entries, expected [k, l]");
  p.k = integer(part[0], "partition[0]");
  p.l = integer(part[1], "partition[1]");
  if (p.k < 1 || p.k > BfsSpace::kMaxPartition)
    throw ParameterError("partition[0] (k) must be in 1.." + std::to_string(BfsSpace::kMaxPartition));
  if (p.l < 1 || p.l > BfsSpace::kMaxPartition)
    throw ParameterError("partition[1] (l) must be in 1.." + std::to_string(BfsSpace::kMaxPartition));
}

// a and epsilon.
void read_coefficients(const json& j, SmoothingSplineProblem& p) {
  p.a = number(j["a"], "a");
  if (!(p.a > 0)) throw ParameterError("a must be > 0 (got " + std::to_string(p.a) + ")");
  if (p.a < 1e-6 || p.a > 1e6)
    throw ParameterError("a must be in [1e-6, 1e6] (got " + std::to_string(p.a) +
                         "): beyond, the discrete problem is numerically singular");
  p.epsilon = number(j["epsilon"], "epsilon");
  if (!(p.epsilon > 0)) throw ParameterError("epsilon must be > 0 (got " + std::to_string(p.epsilon) + ")");
}

// The value and y-derivative of a net (tensor or bspline, parameters mapped onto [0,1]^2) along
// the line y at the nodes x_i = i/k.
void sample_edge(const json& nj, const std::string& w, int k, double y, Eigen::MatrixX3d& value, Eigen::MatrixX3d& dy) {
  const Net net = net_from_json(nj, w);
  value.resize(k + 1, 3);
  dy.resize(k + 1, 3);
  for (int i = 0; i <= k; ++i) {
    const double x = static_cast<double>(i) / k;
    if (const auto* t = std::get_if<TensorNet>(&net)) {
      value.row(i) = t->evaluate(x, y).transpose();
      dy.row(i) = t->derivative(x, y, 0, 1).transpose();
    } else if (const auto* b = std::get_if<BSplineNet>(&net)) {
      const double u = b->u_min() + x * (b->u_max() - b->u_min());
      const double v = b->v_min() + y * (b->v_max() - b->v_min());
      value.row(i) = b->evaluate(u, v).transpose();
      dy.row(i) = (b->v_max() - b->v_min()) * b->derivative(u, v, 0, 1).transpose();
    } else {
      throw ParseError(w + ": a blend surface is a tensor or bspline net, not a triangular net");
    }
  }
}

// The surfaces to blend (Pasadas, Rodríguez, smoothing PDE splines §6, boundary conditions as
// read in docs/errata.md):
// u(x,0) = f(x,1), u_y(x,0) = f_y(x,1), u(x,1) = g(x,0), u_y(x,1) = g_y(x,0).
void edges_from_surfaces(const json& sj, SmoothingSplineProblem& p) {
  check_fields(sj, "surfaces", {"f", "g"}, {"f", "g"});
  sample_edge(sj["f"], "surfaces.f", p.k, 1.0, p.y0_value, p.y0_dy);
  sample_edge(sj["g"], "surfaces.g", p.k, 0.0, p.y1_value, p.y1_dy);
}

void edges_from_json(const json& edges, SmoothingSplineProblem& p) {
  check_fields(edges, "edges", {"y0", "y1"}, {"y0", "y1"});
  for (const char* e : {"y0", "y1"}) {
    const std::string w = std::string("edges.") + e;
    check_fields(edges[e], w, {"value", "dy"}, {"value", "dy"});
    Eigen::MatrixX3d value = edge_array(edges[e]["value"], p.k, w + ".value");
    Eigen::MatrixX3d dy = edge_array(edges[e]["dy"], p.k, w + ".dy");
    if (e[1] == '0') {
      p.y0_value = std::move(value);
      p.y0_dy = std::move(dy);
    } else {
      p.y1_value = std::move(value);
      p.y1_dy = std::move(dy);
    }
  }
}

// The approximation points a_i in [0,1]^2 and the data β_i.
void read_points(const json& j, SmoothingSplineProblem& p) {
  p.points = j.contains("points") ? Eigen::MatrixX2d(rows(j["points"], 2, "points")) : Eigen::MatrixX2d(0, 2);
  p.data = j.contains("data") ? Eigen::MatrixX3d(rows(j["data"], 3, "data")) : Eigen::MatrixX3d(0, 3);
  if (p.points.rows() != p.data.rows())
    throw SizeError("points has " + std::to_string(p.points.rows()) + " entries but data has " +
                    std::to_string(p.data.rows()));
  for (Eigen::Index i = 0; i < p.points.rows(); ++i)
    for (int c = 0; c < 2; ++c)
      if (p.points(i, c) < 0 || p.points(i, c) > 1)
        throw ParameterError("points[" + std::to_string(i) + "] = [" + std::to_string(p.points(i, 0)) + ", " +
                             std::to_string(p.points(i, 1)) + "] is outside the domain [0,1]^2");
}

}  // namespace

BlendConfig blend_config_from_json(const json& j) {
  if (!j.is_object()) throw ParseError("the blend config must be a JSON object, not " + type_name(j));
  check_kind(j);
  check_fields(j, "", {"kind", "partition", "a", "epsilon", "edges", "surfaces", "points", "data", "samples"},
               {"kind", "partition", "a", "epsilon"});
  if (j.contains("edges") == j.contains("surfaces"))
    throw ParseError("a blend config gives exactly one of \"edges\" and \"surfaces\"");
  BlendConfig cfg;
  SmoothingSplineProblem& p = cfg.problem;
  read_partition(j["partition"], p);
  read_coefficients(j, p);
  if (j.contains("surfaces"))
    edges_from_surfaces(j["surfaces"], p);
  else
    edges_from_json(j["edges"], p);
  read_points(j, p);
  if (j.contains("samples")) {
    cfg.samples = integer(j["samples"], "samples");
    if (cfg.samples < 1 || cfg.samples > kMaxSamples) throw ParameterError(samples_limit_message("samples", cfg.samples));
  }
  p.validate();  // the solver's own checks (nothing left to fail here, kept as a safety net)
  return cfg;
}

// Both go through the bounded reader of io/json_io.h (size, depth, duplicate keys, overflow).
BlendConfig parse_blend_config(const std::string& text) { return blend_config_from_json(parse_json(text, "blend config")); }

BlendConfig read_blend_config(const std::string& path) { return blend_config_from_json(read_json_file(path)); }

json blend_config_to_json(const BlendConfig& cfg) {
  const SmoothingSplineProblem& p = cfg.problem;
  auto arr = [](const Eigen::MatrixXd& M) {
    json a = json::array();
    for (Eigen::Index r = 0; r < M.rows(); ++r) {
      json row = json::array();
      for (Eigen::Index c = 0; c < M.cols(); ++c) row.push_back(M(r, c));
      a.push_back(row);
    }
    return a;
  };
  json j;
  j["kind"] = "blend";
  j["partition"] = {p.k, p.l};
  j["a"] = p.a;
  j["epsilon"] = p.epsilon;
  j["edges"] = {{"y0", {{"value", arr(p.y0_value)}, {"dy", arr(p.y0_dy)}}},
                {"y1", {{"value", arr(p.y1_value)}, {"dy", arr(p.y1_dy)}}}};
  j["points"] = arr(p.points);
  j["data"] = arr(p.data);
  j["samples"] = cfg.samples;
  return j;
}

}  // namespace bpde
