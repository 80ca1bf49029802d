// Input limits of the JSON readers (docs/FORMATS.md "Input limits").
#include <gtest/gtest.h>

#include <unistd.h>
#include <filesystem>
#include <cstdint>
#include <fstream>
#include <functional>
#include <string>

#include "bezierpde/core/errors.h"
#include "bezierpde/io/blend_config.h"
#include "bezierpde/io/json_io.h"

using namespace bpde;
namespace fs = std::filesystem;

namespace {
std::string nested(int levels) { return std::string(levels, '[') + std::string(levels, ']'); }
}  // namespace

TEST(JsonLimits, NestingDepthIsBoundedWhileParsing) {
  EXPECT_NO_THROW(parse_json(nested(kMaxJsonDepth), "t"));
  EXPECT_THROW(parse_json(nested(kMaxJsonDepth + 1), "t"), ParseError);
  // Objects count as levels too, and 100000 levels fail fast instead of overflowing the stack.
  std::string objs;
  for (int i = 0; i < kMaxJsonDepth + 1; ++i) objs += "{\"a\":";
  objs += "1" + std::string(kMaxJsonDepth + 1, '}');
  EXPECT_THROW(parse_json(objs, "t"), ParseError);
  try {
    parse_json(nested(100000), "deep.json");
    ADD_FAILURE() << "100000 levels accepted";
  } catch (const ParseError& e) {
    EXPECT_NE(std::string(e.what()).find("nest deeper than the limit of 256"), std::string::npos) << e.what();
  }
}

TEST(JsonLimits, SizeIsBoundedAndEndlessInputStopsAtTheLimit) {
  EXPECT_THROW(parse_json(std::string(kMaxJsonBytes + 1, ' '), "t"), FileError);
  EXPECT_THROW(read_json_file("/dev/zero"), FileError);
  const fs::path p = fs::temp_directory_path() / ("bpde_json_limit_" + std::to_string(::getpid()) + ".json");
  { std::ofstream(p) << "[1]"; }
  EXPECT_EQ(read_json_file(p.string()), Json::array({1}));
  fs::resize_file(p, kMaxJsonBytes + 1);  // sparse: "[1]" and NUL bytes
  EXPECT_THROW(read_json_file(p.string()), FileError);
  fs::remove(p);
}

TEST(JsonLimits, DegreeErrorsDoNotPrintDeepValues) {
  // blend configs parse with their own parser and reach net_from_json: a deep degree must give a
  // bounded message, not a recursive dump.
  Json deep = Json::array({1});
  for (int i = 0; i < 2000; ++i) deep = Json::array({deep});
  const Json net = {{"type", "tensor"}, {"degree", deep}, {"points", Json::array()}};
  try {
    net_from_json(net);
    ADD_FAILURE() << "accepted";
  } catch (const ParseError& e) {
    EXPECT_LT(std::string(e.what()).size(), 200u) << e.what();
  }
}

namespace {
const char* kBlend = R"({"kind": "blend", "partition": [1, 1], "a": 1, "epsilon": 0.01,
  "edges": {"y0": {"value": [[0,0,0],[1,0,0]], "dy": [[0,1,0],[0,1,0]]},
            "y1": {"value": [[0,1,0],[1,1,0]], "dy": [[0,1,0],[0,1,0]]}}, "samples": 4})";

// kBlend with `field` appended once more at the top level (a duplicate key).
std::string blend_with(const std::string& extra) {
  std::string t = kBlend;
  t.insert(t.rfind('}'), ", " + extra);
  return t;
}

template <class E>
std::string message_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const E& e) {
    return e.what();
  }
  ADD_FAILURE() << "no exception of the expected type";
  return "";
}
}  // namespace

// The blend config had its own json::parse: the last of two "epsilon" silently won, and 100000
// nested levels in `surfaces` were read without bound.
TEST(JsonLimits, BlendConfigsAreReadByTheBoundedReader) {
  EXPECT_NO_THROW(parse_blend_config(kBlend));
  for (const char* dup : {R"("epsilon": 0.5)", R"("samples": 8)", R"("a": 1)"}) {
    const std::string m = message_of<ParseError>([&] { parse_blend_config(blend_with(dup)); });
    EXPECT_NE(m.find("duplicate key"), std::string::npos) << m;
  }
  // A duplicate inside a nested object too.
  std::string nested_dup = kBlend;
  nested_dup.replace(nested_dup.find(R"("dy": [[0,1,0],[0,1,0]]})"), 1, R"("value": [], ")");
  EXPECT_THROW(parse_blend_config(nested_dup), ParseError);
  const std::string deep = std::string(100000, '[') + std::string(100000, ']');
  const std::string m = message_of<ParseError>([&] { parse_blend_config(blend_with(R"("points": )" + deep)); });
  EXPECT_NE(m.find("nest deeper"), std::string::npos) << m;
  EXPECT_THROW(parse_blend_config(std::string(kMaxJsonBytes + 1, ' ')), FileError);
  EXPECT_THROW(read_blend_config("/dev/zero"), FileError);
}

// 1e999 is malformed for a reader (ParseError) and would be infinite (NonFiniteError): the same
// typed error for every reader, catchable as either and naming the overflow.
TEST(JsonLimits, OverflowingNumbersAreOneTypedError) {
  for (const char* text : {"[1e999]", "[-1e400]", R"({"x": 2e308})"}) {
    const std::string m = message_of<NumberOverflowError>([&] { parse_json(text, "f"); });
    EXPECT_NE(m.find("overflows"), std::string::npos) << m;
    EXPECT_THROW(parse_json(text, "f"), ParseError);
    EXPECT_THROW(parse_json(text, "f"), NonFiniteError);
    EXPECT_THROW(parse_json(text, "f"), InvalidInput);
  }
  std::string big_a = kBlend;
  big_a.replace(big_a.find(R"("a": 1)"), 6, R"("a": 1e999)");
  EXPECT_THROW(parse_blend_config(big_a), NumberOverflowError);
  // Just inside double range is a number (and then a's own range check applies).
  std::string max_a = kBlend;
  max_a.replace(max_a.find(R"("a": 1)"), 6, R"("a": 1.7e308)");
  EXPECT_THROW(parse_blend_config(max_a), ParameterError);
}

// 2^64-1 is stored by nlohmann as an unsigned integer; read as long long it became -1, which
// passed the range check and was reported as "degree -1".
TEST(JsonLimits, HugeUnsignedIntegersAreReportedAsWritten) {
  const Json j = parse_json(R"({"type": "triangular", "degree": 18446744073709551615, "points": []})", "t");
  const std::string m = message_of<ParseError>([&] { net_from_json(j); });
  EXPECT_NE(m.find("18446744073709551615"), std::string::npos) << m;
  EXPECT_EQ(m.find("-1"), std::string::npos) << m;
  EXPECT_THROW(json_read::integer(Json(std::uint64_t{1} << 63), "n"), ParseError);
  EXPECT_THROW(json_read::integer(Json(std::int64_t{-1000000001}), "n"), ParseError);
  EXPECT_EQ(json_read::integer(Json(std::uint64_t{1000000000}), "n"), 1000000000);
  EXPECT_EQ(json_read::integer(Json(std::int64_t{-1000000000}), "n"), -1000000000);
  EXPECT_THROW(json_read::integer(Json(1000000001), "n"), ParseError);
  // The same reader for the blend config's integers.
  const std::string mb = message_of<ParseError>([&] {
    std::string t = kBlend;
    t.replace(t.find(R"("samples": 4)"), 12, R"("samples": 18446744073709551615)");
    parse_blend_config(t);
  });
  EXPECT_NE(mb.find("samples: integer 18446744073709551615 is out of range"), std::string::npos) << mb;
}
