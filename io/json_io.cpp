#include "bezierpde/io/json_io.h"

#include <cmath>
#include <cstdint>
#include <fstream>
#include <iomanip>
#include <set>
#include <sstream>
#include <vector>

#include "bezierpde/core/bernstein.h"
#include "bezierpde/core/errors.h"
#include "bezierpde/io/atomic_file.h"

namespace bpde {
namespace {

// SAX pass that rejects duplicate keys (nlohmann silently keeps the last one).
class DuplicateKeyCheck : public nlohmann::json_sax<Json> {
 public:
  std::string duplicate;
  bool null() override { return true; }
  bool boolean(bool) override { return true; }
  bool number_integer(number_integer_t) override { return true; }
  bool number_unsigned(number_unsigned_t) override { return true; }
  bool number_float(number_float_t, const string_t&) override { return true; }
  bool string(string_t&) override { return true; }
  bool binary(binary_t&) override { return true; }
  bool start_object(std::size_t) override {
    keys_.emplace_back();
    return true;
  }
  bool key(string_t& k) override {
    if (!keys_.back().insert(k).second) {
      duplicate = k;
      return false;
    }
    return true;
  }
  bool end_object() override {
    keys_.pop_back();
    return true;
  }
  bool start_array(std::size_t) override { return true; }
  bool end_array() override { return true; }
  bool parse_error(std::size_t, const std::string&, const nlohmann::detail::exception&) override { return false; }

 private:
  std::vector<std::set<std::string>> keys_;
};

std::string clean_nlohmann(const std::string& what) {
  // "[json.exception.parse_error.101] parse error at line 1, column 2: ..." -> keep from "parse error"
  const auto p = what.find("] ");
  return p == std::string::npos ? what : what.substr(p + 2);
}

// Thrown by the parse callback when arrays/objects nest deeper than kMaxJsonDepth.
struct TooDeep {};

}  // namespace

Json parse_json(const std::string& text, const std::string& source) {
  if (text.size() > kMaxJsonBytes)
    throw FileError(source + ": input is larger than the limit of " + std::to_string(kMaxJsonBytes >> 20) + " MiB");
  Json j;
  // The depth is bounded while parsing: the parser itself is iterative, but every reader that
  // walks or prints a value (dump(), the destructor, the strict readers) recurses per level.
  const Json::parser_callback_t depth_limit = [](int depth, Json::parse_event_t event, Json&) {
    if ((event == Json::parse_event_t::object_start || event == Json::parse_event_t::array_start) &&
        depth >= kMaxJsonDepth)
      throw TooDeep{};
    return true;
  };
  try {
    j = Json::parse(text, depth_limit);
  } catch (const TooDeep&) {
    throw ParseError(source + ": arrays and objects nest deeper than the limit of " + std::to_string(kMaxJsonDepth) +
                     " levels");
  } catch (const nlohmann::json::out_of_range& e) {
    // 406: "number overflow parsing '1e999'" (the only out_of_range the parser raises)
    throw NumberOverflowError(source + ": a number overflows a double: " + clean_nlohmann(e.what()));
  } catch (const nlohmann::json::exception& e) {
    throw ParseError(source + ": malformed JSON: " + clean_nlohmann(e.what()));
  }
  DuplicateKeyCheck dup;
  Json::sax_parse(text, &dup);
  if (!dup.duplicate.empty()) throw ParseError(source + ": duplicate key \"" + dup.duplicate + "\"");
  return j;
}

Json read_json_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw FileError("cannot read file '" + path + "' (missing or unreadable)");
  // Read at most kMaxJsonBytes + 1 bytes: endless input (/dev/zero, a pipe) stops at the limit.
  std::string text;
  std::vector<char> chunk(1 << 16);
  while (in && text.size() <= kMaxJsonBytes) {
    in.read(chunk.data(), static_cast<std::streamsize>(chunk.size()));
    text.append(chunk.data(), static_cast<size_t>(in.gcount()));
  }
  if (in.bad()) throw FileError("cannot read file '" + path + "'");
  return parse_json(text, path);
}

std::string json_file_text(const Json& j) { return j.dump(2) + "\n"; }

void write_json_file(const std::string& path, const Json& j) { write_file_atomically(path, json_file_text(j)); }

namespace json_read {

static std::string type_of(const Json& j) { return j.type_name(); }

void require_object(const Json& j, const std::string& path) {
  if (!j.is_object()) throw ParseError(path + ": expected a JSON object, got " + type_of(j));
}

void check_keys(const Json& j, const std::string& path, std::initializer_list<const char*> allowed) {
  require_object(j, path);
  for (auto it = j.begin(); it != j.end(); ++it) {
    bool ok = false;
    for (const char* a : allowed) ok = ok || it.key() == a;
    if (!ok) {
      std::string list;
      for (const char* a : allowed) list += (list.empty() ? "" : ", ") + std::string(a);
      throw ParseError(path + ": unknown field \"" + it.key() + "\" (allowed: " + list + ")");
    }
  }
}

const Json& field(const Json& j, const std::string& path, const char* key) {
  require_object(j, path);
  const auto it = j.find(key);
  if (it == j.end()) throw ParseError(path + ": missing field \"" + key + "\"");
  return *it;
}

double number(const Json& j, const std::string& path) {
  if (!j.is_number()) throw ParseError(path + ": expected a number, got " + type_of(j));
  const double x = j.get<double>();
  if (!std::isfinite(x)) throw NonFiniteError(path + ": number is not finite");
  return x;
}

int integer(const Json& j, const std::string& path) {
  if (!j.is_number()) throw ParseError(path + ": expected an integer, got " + type_of(j));
  // nlohmann stores 0..2^64-1 as unsigned and only negative integers as signed: reading an
  // unsigned one as long long turned 2^64-1 into -1 (which then passed the range check).
  if (j.is_number_unsigned()) {
    const auto v = j.get<std::uint64_t>();
    if (v > static_cast<std::uint64_t>(kMaxJsonInteger))
      throw ParseError(path + ": integer " + std::to_string(v) + " is out of range (|n| <= " +
                       std::to_string(kMaxJsonInteger) + ")");
    return static_cast<int>(v);
  }
  if (j.is_number_integer()) {
    const auto v = j.get<std::int64_t>();
    if (v < -kMaxJsonInteger || v > kMaxJsonInteger)
      throw ParseError(path + ": integer " + std::to_string(v) + " is out of range (|n| <= " +
                       std::to_string(kMaxJsonInteger) + ")");
    return static_cast<int>(v);
  }
  const double x = j.get<double>();
  if (!std::isfinite(x) || x != std::floor(x) || std::abs(x) > kMaxJsonInteger)
    throw ParseError(path + ": expected an integer, got " + j.dump());
  return static_cast<int>(x);
}

std::string string(const Json& j, const std::string& path) {
  if (!j.is_string()) throw ParseError(path + ": expected a string, got " + type_of(j));
  return j.get<std::string>();
}

bool boolean(const Json& j, const std::string& path) {
  if (!j.is_boolean()) throw ParseError(path + ": expected true or false, got " + type_of(j));
  return j.get<bool>();
}

std::vector<double> numbers(const Json& j, const std::string& path, int len) {
  if (!j.is_array()) throw ParseError(path + ": expected an array, got " + type_of(j));
  if (len >= 0 && static_cast<int>(j.size()) != len)
    throw SizeError(path + ": expected " + std::to_string(len) + " numbers, got " + std::to_string(j.size()));
  std::vector<double> out;
  out.reserve(j.size());
  for (size_t i = 0; i < j.size(); ++i) out.push_back(number(j[i], path + "[" + std::to_string(i) + "]"));
  return out;
}

Eigen::MatrixX3d points(const Json& j, const std::string& path) {
  if (!j.is_array()) throw ParseError(path + ": expected an array of [x, y, z], got " + type_of(j));
  Eigen::MatrixX3d P(static_cast<Eigen::Index>(j.size()), 3);
  for (size_t i = 0; i < j.size(); ++i) {
    const std::string pi = path + "[" + std::to_string(i) + "]";
    const std::vector<double> xyz = numbers(j[i], pi, 3);
    P.row(static_cast<Eigen::Index>(i)) << xyz[0], xyz[1], xyz[2];
  }
  return P;
}

}  // namespace json_read

namespace {

int degree_value(const Json& j, const std::string& path) {
  const int d = json_read::integer(j, path);
  if (d < 1 || d > kMaxDegree)
    throw DegreeError(path + ": degree " + std::to_string(d) + " is outside 1.." + std::to_string(kMaxDegree));
  return d;
}

std::array<int, 2> degree_pair(const Json& j, const std::string& path) {
  if (!j.is_array() || j.size() != 2)
    // Not j.dump(): it recurses once per nesting level, and a Json built in code (not read
    // through parse_json) has no depth limit.
    throw ParseError(path + ": expected [n, m], got " +
                     (j.is_structured() ? std::string(j.type_name()) + " of " + std::to_string(j.size()) + " elements"
                                        : j.dump().substr(0, 40)));
  return {degree_value(j[0], path + "[0]"), degree_value(j[1], path + "[1]")};
}

void check_count(const Json& pts, const std::string& path, size_t want, const std::string& what) {
  if (!pts.is_array()) throw ParseError(path + ": expected an array of [x, y, z], got " + std::string(pts.type_name()));
  if (pts.size() != want)
    throw SizeError(path + ": " + what + " needs " + std::to_string(want) + " points, got " +
                    std::to_string(pts.size()));
}

}  // namespace

Net net_from_json(const Json& j, const std::string& path) {
  using namespace json_read;
  require_object(j, path);
  const std::string type = string(field(j, path, "type"), path + ".type");
  if (type == "tensor") {
    check_keys(j, path, {"type", "degree", "points"});
    const auto d = degree_pair(field(j, path, "degree"), path + ".degree");
    const Json& pts = field(j, path, "points");
    check_count(pts, path + ".points", static_cast<size_t>((d[0] + 1) * (d[1] + 1)),
                "a tensor net of degree [" + std::to_string(d[0]) + ", " + std::to_string(d[1]) + "]");
    return TensorNet(d[0], d[1], points(pts, path + ".points"));
  }
  if (type == "triangular") {
    check_keys(j, path, {"type", "degree", "points"});
    const int n = degree_value(field(j, path, "degree"), path + ".degree");
    const Json& pts = field(j, path, "points");
    check_count(pts, path + ".points", static_cast<size_t>(TriangularNet::count(n)),
                "a triangular net of degree " + std::to_string(n));
    return TriangularNet(n, points(pts, path + ".points"));
  }
  if (type == "bspline") {
    check_keys(j, path, {"type", "degree", "knots", "points"});
    const auto d = degree_pair(field(j, path, "degree"), path + ".degree");
    const Json& kn = field(j, path, "knots");
    if (!kn.is_array() || kn.size() != 2) throw ParseError(path + ".knots: expected [[u0, ...], [v0, ...]]");
    std::vector<double> U = numbers(kn[0], path + ".knots[0]"), V = numbers(kn[1], path + ".knots[1]");
    const long nu = static_cast<long>(U.size()) - d[0] - 1, nv = static_cast<long>(V.size()) - d[1] - 1;
    const Json& pts = field(j, path, "points");
    if (nu >= 1 && nv >= 1)
      check_count(pts, path + ".points", static_cast<size_t>(nu * nv),
                  "a bspline net with " + std::to_string(nu) + " x " + std::to_string(nv) + " control points");
    try {
      return BSplineNet(d[0], d[1], std::move(U), std::move(V), points(pts, path + ".points"));
    } catch (const InvalidInput& e) {
      // prefix the path for messages raised by the net's own validation
      if (std::string(e.what()).rfind(path, 0) == 0) throw;
      throw ParameterError(path + ": " + e.what());
    }
  }
  throw ParseError(path + ".type: unknown net type \"" + type + "\" (expected tensor, triangular or bspline)");
}

Net read_net_file(const std::string& path) { return net_from_json(read_json_file(path), path); }

namespace {
Json points_json(const Eigen::MatrixX3d& P) {
  Json a = Json::array();
  for (Eigen::Index r = 0; r < P.rows(); ++r) a.push_back({P(r, 0), P(r, 1), P(r, 2)});
  return a;
}
}  // namespace

Json net_to_json(const TensorNet& net) {
  return {{"type", "tensor"}, {"degree", {net.n(), net.m()}}, {"points", points_json(net.points())}};
}
Json net_to_json(const TriangularNet& net) {
  return {{"type", "triangular"}, {"degree", net.n()}, {"points", points_json(net.points())}};
}
Json net_to_json(const BSplineNet& net) {
  return {{"type", "bspline"},
          {"degree", {net.p(), net.q()}},
          {"knots", {net.knots_u(), net.knots_v()}},
          {"points", points_json(net.points())}};
}
Json net_to_json(const Net& net) {
  return std::visit([](const auto& n) { return net_to_json(n); }, net);
}

std::string net_kind(const Net& net) {
  switch (net.index()) {
    case 0:
      return "tensor";
    case 1:
      return "triangular";
    default:
      return "bspline";
  }
}

}  // namespace bpde
