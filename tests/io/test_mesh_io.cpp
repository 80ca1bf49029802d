// io/mesh_io: numbers are written as the shortest decimal that reads back to the same double
// (std::to_chars); check that every coordinate and curvature of an OBJ and a PLY file parses
// (strtod, the independent reader) to exactly the double that was written, on values that need
// all 17 digits, short ones, signed zero, subnormals and the extremes of the range.
#include <gtest/gtest.h>

#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include "bezierpde/io/mesh_io.h"

using namespace bpde;

namespace {

std::vector<double> awkward_values() {
  return {0.1,
          1.0 / 3.0,
          -2.0 / 3.0,
          0.0,
          -0.0,
          1.0,
          1e-300,
          5e-324,
          std::numeric_limits<double>::min(),
          std::numeric_limits<double>::max(),
          -std::numeric_limits<double>::max(),
          123456789.123456789,
          0.30000000000000004,
          2.5e-8,
          std::nextafter(1.0, 2.0)};
}

TriangleMesh awkward_mesh() {
  const std::vector<double> x = awkward_values();
  const int n = static_cast<int>(x.size());
  TriangleMesh m;
  m.V.resize(n, 3);
  m.H.resize(n);
  for (int r = 0; r < n; ++r) {
    m.V.row(r) << x[r], x[(r + 1) % n], x[(r + 5) % n];
    m.H(r) = x[(r + 7) % n];
  }
  m.F.resize(n - 2, 3);
  for (int f = 0; f < n - 2; ++f) m.F.row(f) << 0, f + 1, f + 2;
  return m;
}

std::vector<std::string> lines(const std::string& path) {
  std::ifstream in(path);
  std::vector<std::string> out;
  for (std::string l; std::getline(in, l);) out.push_back(l);
  return out;
}

// The doubles of a line after its first `skip` tokens, read by strtod.
std::vector<double> numbers(const std::string& line, int skip) {
  std::istringstream s(line);
  std::string tok;
  std::vector<double> out;
  for (int i = 0; s >> tok; ++i) {
    if (i < skip) continue;
    char* end = nullptr;
    out.push_back(std::strtod(tok.c_str(), &end));
    EXPECT_EQ(*end, '\0') << "token '" << tok << "' of '" << line << "'";
  }
  return out;
}

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

TEST(MeshIo, ObjAndPlyNumbersReadBackBitExact) {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "bpde_test_mesh_io";
  std::filesystem::create_directories(dir);
  const TriangleMesh m = awkward_mesh();
  write_obj((dir / "s.obj").string(), m);
  SurfaceFields fields;
  fields.H = m.H;
  fields.regular.setOnes(m.V.rows());
  write_ply((dir / "s.ply").string(), m, fields);

  const std::vector<std::string> obj = lines((dir / "s.obj").string());
  int v = 0, f = 0;
  for (const std::string& l : obj) {
    if (l.rfind("v ", 0) == 0) {
      const std::vector<double> x = numbers(l, 1);
      ASSERT_EQ(x.size(), 3u) << l;
      for (int c = 0; c < 3; ++c) EXPECT_TRUE(same_bits(x[c], m.V(v, c))) << l << " column " << c;
      ++v;
    } else if (l.rfind("f ", 0) == 0) {
      EXPECT_EQ(l, "f 1 " + std::to_string(f + 2) + " " + std::to_string(f + 3));
      ++f;
    }
  }
  EXPECT_EQ(v, m.V.rows());
  EXPECT_EQ(f, m.F.rows());

  const std::vector<std::string> ply = lines((dir / "s.ply").string());
  size_t r = 0;
  while (r < ply.size() && ply[r] != "end_header") ++r;
  ASSERT_LT(r, ply.size());
  EXPECT_EQ(ply[3], "element vertex " + std::to_string(m.V.rows()));
  for (Eigen::Index k = 0; k < m.V.rows(); ++k) {
    const std::vector<double> x = numbers(ply[r + 1 + static_cast<size_t>(k)], 0);
    ASSERT_EQ(x.size(), 5u);  // x y z mean_curvature regular
    for (int c = 0; c < 3; ++c) EXPECT_TRUE(same_bits(x[c], m.V(k, c))) << ply[r + 1 + k];
    EXPECT_TRUE(same_bits(x[3], m.H(k))) << ply[r + 1 + k];
    EXPECT_EQ(x[4], 1.0) << ply[r + 1 + k];
  }
  EXPECT_EQ(ply[r + 1 + static_cast<size_t>(m.V.rows())], "3 0 1 2");
  // Shortest round trip: 0.1 is written as "0.1", not 0.10000000000000001.
  EXPECT_EQ(obj[1].substr(0, 6), "v 0.1 ");
  std::filesystem::remove_all(dir);
}

}  // namespace
