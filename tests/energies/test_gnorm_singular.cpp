// gnorm (rho, t) with e1 parallel to e2 is a singular G: the same relative test as for
// a G matrix, |det G| <= 1e-12 |G|_F^2, with det G = rho sin t and |G|_F^2 = rho^2 + 1.
#include <gtest/gtest.h>

#include <cmath>

#include "bezierpde/core/errors.h"
#include "bezierpde/energies/energy_spec.h"

using namespace bpde;

TEST(GnormSingular, ParallelAxesAreASingularG) {
  const double pi = std::acos(-1.0);
  for (double t : {0.0, pi, -pi, 2 * pi, 1e-13, pi - 1e-13})
    for (double rho : {0.5, 1.0, 2.0}) EXPECT_THROW(EnergySpec::gnorm(rho, t), ParameterError) << rho << " " << t;
  // Near-singular but above the relative tolerance: accepted, as G matrices are.
  EXPECT_NO_THROW(EnergySpec::gnorm(2.0, 1e-9));
  EXPECT_NO_THROW(EnergySpec::gnorm(2.0, pi - 1e-9));
  // The matrix form of the same G agrees: e1 = rho (cos t, sin t), e2 = (1, 0).
  Eigen::Matrix2d G;
  G << 2.0, 1.0, 0.0, 0.0;  // t = 0: columns (2, 0) and (1, 0)
  EXPECT_THROW(EnergySpec::gnorm(G), ParameterError);
  // rho^2 overflowing is not a usable operator either.
  EXPECT_THROW(EnergySpec::gnorm(1e200, 1.0), NonFiniteError);
}
