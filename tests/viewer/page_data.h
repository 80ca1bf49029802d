#pragma once
// view.html's embedded data for the viewer tests (io/html_view.h): the JSON of the page's
// <script id="bpde-data"> element and its base64 arrays decoded to float32/uint32 values.
#include <gtest/gtest.h>

#include <cstring>
#include <string>
#include <vector>

#include "bezierpde/io/json_io.h"
#include "tests/io/mesh_readers.h"

namespace bpde::testing {

/// The values of a base64 string of T (float, std::uint32_t), little-endian as the page stores them.
template <class T>
std::vector<T> decode(const Json& j) {
  const std::vector<unsigned char> bytes = base64_decode(j.get<std::string>());
  EXPECT_EQ(bytes.size() % sizeof(T), 0u);
  std::vector<T> out(bytes.size() / sizeof(T));
  std::memcpy(out.data(), bytes.data(), out.size() * sizeof(T));
  return out;
}

/// The JSON text between <script id="bpde-data" type="application/json"> and the next </script>.
inline Json page_data(const std::string& page) {
  const std::string open = "<script id=\"bpde-data\" type=\"application/json\">";
  const size_t a = page.find(open);
  EXPECT_NE(a, std::string::npos);
  const size_t b = page.find("</script>", a);
  return Json::parse(page.substr(a + open.size(), b - a - open.size()));
}

}  // namespace bpde::testing
