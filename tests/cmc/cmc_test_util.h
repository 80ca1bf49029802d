#pragma once
// Shared data builders for the CMC tests.
#include <Eigen/Dense>
#include <cmath>
#include <functional>
#include <numbers>
#include <random>

#include "core/bernstein.h"
#include "solvers/reference_boundaries.h"
#include "tensor/tensor_net.h"
#include "triangular/triangular_net.h"

namespace bpde::testutil {

inline Eigen::MatrixX3d random_points(int rows, unsigned seed, double scale = 1.0) {
  std::mt19937 gen(seed);
  std::uniform_real_distribution<double> d(-scale, scale);
  Eigen::MatrixX3d P(rows, 3);
  for (int r = 0; r < rows; ++r)
    for (int c = 0; c < 3; ++c) P(r, c) = d(gen);
  return P;
}

using bpde::circle_three_arcs;
using bpde::fit_curve;
using bpde::inverse_stereographic;
using bpde::planar_triangle;
using bpde::sphere_square;
using bpde::sphere_triangle;
using bpde::tensor_boundary;
using bpde::triangular_boundary;

}  // namespace bpde::testutil
