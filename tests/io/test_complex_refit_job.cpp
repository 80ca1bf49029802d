// The "refit" field of a complex boundary (io/complex_job.h, FORMATS.md "Patch complexes"): with
// refine, the boundary is fitted again on the refined layout and boundary_fit reports those fits.
#include "bezierpde/core/eigen.h"
#include <gtest/gtest.h>

#include <algorithm>

#include "bezierpde/core/errors.h"
#include "bezierpde/io/complex_job.h"
#include "bezierpde/io/json_io.h"

using namespace bpde;

namespace {

Json circle_boundary(int refine, const Json& refit) {
  Json j = parse_json(R"({"type": "complex", "patch": "triangular", "degree": 3,
      "loops": [[{"type": "circle", "center": [0, 0, 0], "normal": [0, 0, 1], "radius": 1}]]})", "test");
  j["refine"] = refine;
  if (!refit.is_null()) j["refit"] = refit;
  return j;
}

double largest_error(const ComplexJobData& d) {
  double e = 0;
  for (const EdgeFit& f : d.coarse.fits) e = std::max(e, f.max_error);
  return e;
}

}  // namespace

TEST(ComplexRefitJob, RefitFitsTheRefinedBoundaryAndReportsIt) {
  const ComplexJobData coarse = complex_from_json(circle_boundary(2, nullptr), "boundary", FitMethod::Interpolation);
  const ComplexJobData refit = complex_from_json(circle_boundary(2, true), "boundary", FitMethod::Interpolation);
  EXPECT_FALSE(coarse.refit);
  EXPECT_TRUE(refit.refit);
  ASSERT_EQ(refit.coarse.fits.size(), coarse.coarse.fits.size());  // one entry per layout boundary edge
  // two halvings at degree 3: the error falls by about 2^8 (measured 253)
  EXPECT_GT(largest_error(coarse) / largest_error(refit), 128.0);
  EXPECT_LT(largest_error(coarse) / largest_error(refit), 512.0);
  EXPECT_EQ(refit.complex.patches.size(), coarse.complex.patches.size());
  EXPECT_EQ(refit.complex.fixed, coarse.complex.fixed);
  EXPECT_EQ(complex_to_json(refit, refit.complex)["refit"], true);
  // without refine, refit changes nothing
  const ComplexJobData none = complex_from_json(circle_boundary(0, true), "boundary", FitMethod::Interpolation);
  EXPECT_EQ(none.complex.points, complex_from_json(circle_boundary(0, false), "boundary", FitMethod::Interpolation).complex.points);
  EXPECT_THROW(complex_from_json(circle_boundary(1, 1), "boundary", FitMethod::Interpolation), ParseError);
}
