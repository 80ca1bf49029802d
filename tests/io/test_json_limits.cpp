// Input limits of the JSON readers (issue 14; docs/FORMATS.md "Input limits").
#include <gtest/gtest.h>

#include <unistd.h>
#include <filesystem>
#include <fstream>
#include <string>

#include "core/errors.h"
#include "io/json_io.h"

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
