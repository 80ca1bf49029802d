// STEP export of a patch complex (io/step_export.h write_step(path, PatchComplex)): one face per
// patch sewn into one shell, read back by OpenCASCADE and checked with BRepCheck_Analyzer; the
// free edges of the shell are exactly the complex's boundary edges.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "bezierpde/complex/patch_complex.h"
#include "bezierpde/complex/refine.h"
#include "bezierpde/io/complex_job.h"
#include "bezierpde/io/step_export.h"
#include "bezierpde/solvers/complex/complex_extremal.h"

using namespace bpde;
namespace fs = std::filesystem;

namespace {

fs::path scratch(const std::string& name) {
  const fs::path d = fs::temp_directory_path() / ("bpde_step_complex_" + std::to_string(::getpid()));
  fs::create_directories(d);
  return d / name;
}

const char* kCircle = R"({"type": "circle", "center": [0, 0, 0], "normal": [0, 0, 1], "radius": 1})";
const char* kInnerCircle = R"({"type": "circle", "center": [0, 0, 0.3], "normal": [0, 0, -1], "radius": 0.4})";

/// The complex of a job's "boundary" (io/complex_job.h), its inside solved for the Dirichlet
/// extremal (as a job's result holds it).
PatchComplex solved_complex(const std::string& patch, int degree, int refine, const std::string& loops) {
  const Json j = parse_json(R"({"type": "complex", "patch": ")" + patch + R"(", "degree": )" + std::to_string(degree) +
                                R"(, "refine": )" + std::to_string(refine) + R"(, "loops": )" + loops + "}",
                            "boundary");
  const ComplexJobData data = complex_from_json(j, "boundary", FitMethod::Interpolation);
  return solve_complex_extremal(data.complex, EnergySpec::dirichlet()).complex;
}

int boundary_edges(const PatchComplex& c) {
  int k = 0;
  for (const ComplexEdge& e : complex_edges(c)) k += e.boundary() ? 1 : 0;
  return k;
}

void expect_one_sewn_shell(const PatchComplex& c, const std::string& name) {
  SCOPED_TRACE(name);
  const fs::path path = scratch(name + ".step");
  write_step(path.string(), c);
  const StepTopology t = read_step_topology(path.string());
  const int P = static_cast<int>(c.patches.size());
  const int edges = static_cast<int>(complex_edges(c).size()), boundary = boundary_edges(c);
  EXPECT_TRUE(t.valid);
  EXPECT_EQ(t.shells, 1);
  EXPECT_EQ(t.solids, 0);
  EXPECT_EQ(t.faces, P);
  EXPECT_EQ(t.free_edges, boundary);
  const bool triangular = c.patches.front().kind == PatchKind::triangular;
  // a triangular patch's tensor form collapses one edge to a point
  EXPECT_EQ(t.degenerate_edges, triangular ? P : 0);
  EXPECT_EQ(t.edges, edges + t.degenerate_edges);  // the sewn shell has each complex edge once
}

}  // namespace

TEST(StepComplex, TriangularFanIsOneValidShellWithTheBoundaryFree) {
  const PatchComplex c = solved_complex("triangular", 4, 0, std::string("[[") + kCircle + "]]");
  ASSERT_EQ(c.patches.size(), 6u);  // the fan of 6 around the centre (complex/layout_loops.h)
  ASSERT_EQ(boundary_edges(c), 6);
  expect_one_sewn_shell(c, "fan");
}

TEST(StepComplex, RefinedTriangularFan) {
  const PatchComplex c = solved_complex("triangular", 3, 1, std::string("[[") + kCircle + "]]");
  ASSERT_EQ(c.patches.size(), 24u);
  ASSERT_EQ(boundary_edges(c), 12);
  expect_one_sewn_shell(c, "fan_refined");
}

TEST(StepComplex, TensorOGrid) {
  const PatchComplex c = solved_complex("tensor", 4, 0, std::string("[[") + kCircle + "]]");
  ASSERT_EQ(c.patches.size(), 5u);  // a ring of 4 quads around one
  ASSERT_EQ(boundary_edges(c), 4);
  expect_one_sewn_shell(c, "ogrid");
}

TEST(StepComplex, TensorAnnulusHasTwoBoundaryLoopsFree) {
  const PatchComplex c =
      solved_complex("tensor", 3, 1, std::string("[[") + kCircle + "], [" + kInnerCircle + "]]");
  ASSERT_EQ(c.patches.size(), 16u);  // a ring of 4 quads refined once
  ASSERT_EQ(boundary_edges(c), 16);  // 8 on each loop
  expect_one_sewn_shell(c, "annulus");
}

TEST(StepComplex, DegreeAboveOpenCascadesLimitIsRefused) {
  const Json j = parse_json(std::string(R"({"type": "complex", "patch": "triangular", "degree": 2, "loops": [[)") +
                                kCircle + "]]}",
                            "boundary");
  const PatchComplex c = refine_p(complex_from_json(j, "boundary", FitMethod::Interpolation).complex, 24);
  EXPECT_THROW(write_step(scratch("deg26.step").string(), c), DegreeError);
  EXPECT_FALSE(fs::exists(scratch("deg26.step")));
}
