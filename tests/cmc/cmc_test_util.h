#pragma once
// Shared data builders for the CMC tests.
#include <Eigen/Dense>
#include <cmath>
#include <functional>
#include <numbers>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "bezierpde/boundaries/reference_boundaries.h"
#include "bezierpde/core/bernstein.h"
#include "bezierpde/tensor/tensor_net.h"
#include "tests/random_points.h"
#include "bezierpde/triangular/triangular_net.h"

namespace bpde::testing {

using bpde::circle_three_arcs;
using bpde::fit_curve;
using bpde::inverse_stereographic;
using bpde::planar_triangle;
using bpde::sphere_square;
using bpde::sphere_triangle;
using bpde::tensor_boundary;
using bpde::triangular_boundary;

/// Checks a Hessian block against central differences of the gradient: J (3k by 3k, rows and
/// columns ordered as (point idx[a], coordinate r) -> 3a + r) against (grad(P + h e) − grad(P − h e))
/// / 2h for every listed point and coordinate, each entry within `tol` (absolute). `grad` maps a
/// #P by 3 net to its #P by 3 gradient rows.
template <class Gradient>
void expect_hessian_is_fd_of_gradient(const Eigen::MatrixXd& J, const Eigen::MatrixX3d& P, const std::vector<int>& idx,
                                      Gradient grad, double h, double tol) {
  for (size_t b = 0; b < idx.size(); ++b)
    for (int s = 0; s < 3; ++s) {
      Eigen::MatrixX3d Pp = P, Pm = P;
      Pp(idx[b], s) += h;
      Pm(idx[b], s) -= h;
      const Eigen::MatrixX3d dG = (grad(Pp) - grad(Pm)) / (2 * h);
      for (size_t a = 0; a < idx.size(); ++a)
        for (int r = 0; r < 3; ++r)
          EXPECT_NEAR(J(3 * Eigen::Index(a) + r, 3 * Eigen::Index(b) + s), dG(idx[a], r), tol)
              << "point " << idx[a] << "." << r << " by point " << idx[b] << "." << s;
    }
}

}  // namespace bpde::testing
