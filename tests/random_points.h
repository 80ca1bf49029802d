#pragma once
// Shared by the test programs: reproducible random control points (rows x 3, uniform in
// [-scale, scale], row by row). The same seed gives the same points in every test.
#include "bezierpde/core/eigen.h"
#include <Eigen/Core>
#include <random>

namespace bpde::testing {

inline Eigen::MatrixX3d random_points(int rows, unsigned seed, double scale = 1.0) {
  std::mt19937 gen(seed);
  std::uniform_real_distribution<double> d(-scale, scale);
  Eigen::MatrixX3d P(rows, 3);
  for (int r = 0; r < rows; ++r)
    for (int c = 0; c < 3; ++c) P(r, c) = d(gen);
  return P;
}

}  // namespace bpde::testing
