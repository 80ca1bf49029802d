#pragma once
// Shared data builders for the CMC tests.
#include "bezierpde/core/eigen.h"
#include <Eigen/Dense>
#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <functional>
#include <numbers>
#include <optional>
#include <ostream>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "bezierpde/boundaries/reference_boundaries.h"
#include "bezierpde/core/bernstein.h"
#include "bezierpde/solvers/cmc/cmc.h"
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

// The full net interpolating s(u, v) at the tensor Chebyshev–Lobatto nodes (every point, so the
// boundary and the next ring carry C¹ data of s).
inline TensorNet tensor_interpolant(int n, const std::function<Eigen::Vector3d(double, double)>& s) {
  Eigen::MatrixXd A(n + 1, n + 1);
  std::vector<double> b(static_cast<size_t>(n + 1));
  std::vector<double> t(static_cast<size_t>(n + 1));
  for (int k = 0; k <= n; ++k) {
    t[static_cast<size_t>(k)] = 0.5 * (1 - std::cos(std::numbers::pi * k / n));
    bernstein_values(n, t[static_cast<size_t>(k)], b.data());
    for (int i = 0; i <= n; ++i) A(k, i) = b[static_cast<size_t>(i)];
  }
  const Eigen::PartialPivLU<Eigen::MatrixXd> lu(A);
  TensorNet net(n, n);
  for (int c = 0; c < 3; ++c) {
    Eigen::MatrixXd S(n + 1, n + 1);
    for (int a = 0; a <= n; ++a)
      for (int d = 0; d <= n; ++d) S(a, d) = s(t[static_cast<size_t>(a)], t[static_cast<size_t>(d)])(c);
    const Eigen::MatrixXd P = lu.solve(lu.solve(S).transpose()).transpose();  // A P Aᵀ = S
    for (int i = 0; i <= n; ++i)
      for (int j = 0; j <= n; ++j) {
        Eigen::Vector3d x = net.point(i, j);
        x(c) = P(i, j);
        net.set_point(i, j, x);
      }
  }
  return net;
}

/// max over the triangular sample grid u = a/N, v = b/N (every sample, corners included) of
/// | |x - c| - R |: the distance to the sphere of radius R about c.
inline double sphere_distance(const TriangularNet& net, const Eigen::Vector3d& c, double R, int N = 40) {
  double d = 0;
  for (int a = 0; a <= N; ++a)
    for (int b = 0; b <= N - a; ++b)
      d = std::max(d, std::abs((net.evaluate(double(a) / N, double(b) / N) - c).norm() - R));
  return d;
}

/// The helicoid piece (s cos t, s sin t, t), s = 0.3 + 0.7u in [0.3, 1], t = 1.2v in [0, 1.2]: a
/// minimal surface in a non-conformal parametrisation.
inline Eigen::Vector3d helicoid(double u, double v) {
  const double s = 0.3 + 0.7 * u, t = 1.2 * v;
  return Eigen::Vector3d(s * std::cos(t), s * std::sin(t), t);
}

/// max |x sin z − y cos z| over a 31 × 31 grid: the distance-like defect from the helicoid.
inline double helicoid_off(const TensorNet& net) {
  double e = 0;
  for (int a = 0; a <= 30; ++a)
    for (int b = 0; b <= 30; ++b) {
      const Eigen::Vector3d x = net.evaluate(a / 30.0, b / 30.0);
      e = std::max(e, std::abs(x(0) * std::sin(x(2)) - x(1) * std::cos(x(2))));
    }
  return e;
}

/// The catenoid piece (θ, ρ) = (1.2u, 1.1 + 0.8v) ↦ (ρ cos θ, ρ sin θ, acosh ρ) on the square: a
/// minimal surface in a radial, not conformal, parametrisation.
inline Eigen::Vector3d catenoid_square(double u, double v) {
  const double th = 1.2 * u, rho = 1.1 + 0.8 * v;
  return Eigen::Vector3d(rho * std::cos(th), rho * std::sin(th), std::acosh(rho));
}

/// max |√(x² + y²) − cosh z| over a 31 × 31 grid: the distance-like defect from the catenoid.
inline double catenoid_off(const TensorNet& net) {
  double e = 0;
  for (int a = 0; a <= 30; ++a)
    for (int b = 0; b <= 30; ++b) {
      const Eigen::Vector3d x = net.evaluate(a / 30.0, b / 30.0);
      e = std::max(e, std::abs(std::hypot(x(0), x(1)) - std::cosh(x(2))));
    }
  return e;
}

/// Options of a cmc solve in H mode with the given functional (the other options at their defaults).
inline CmcOptions cmc_options(CmcFunctionalKind functional, double H) {
  CmcOptions o;
  o.H = H;
  o.functional = functional;
  return o;
}

/// The larger cap of H (|H| < 1) over the unit circle in three arcs at degree n, moved by t: the
/// sphere of radius 1/|H| with its centre √(R² − 1) above the circle's plane (plus t). V0 is the
/// cap's volume plus that of the flat disk (V_flat, the Dirichlet extremal's: V shifts by the same
/// constant for every surface with the boundary when the origin moves), checked against π t_z / 3.
struct LargerCapOffTheOrigin {
  TriangularNet data;
  double Vflat, V0, R;
  Eigen::Vector3d centre;
};
inline LargerCapOffTheOrigin larger_cap_off_the_origin(int n, double H, const Eigen::Vector3d& t) {
  const double R = 1 / std::abs(H), hb = R + std::sqrt(R * R - 1);
  LargerCapOffTheOrigin c{circle_three_arcs(n), 0.0, 0.0, R, Eigen::Vector3d(0, 0, std::sqrt(R * R - 1)) + t};
  for (Eigen::Index i = 0; i < c.data.points().rows(); ++i) c.data.points().row(i) += t.transpose();
  c.Vflat = solve_cmc(c.data, cmc_options(CmcFunctionalKind::Dirichlet, 0.0)).V;
  // π z/3 for the exact disk; the degree-n arcs enclose it to 2e-10 at n = 8 (measured 4.7e-10 on V)
  EXPECT_NEAR(std::abs(c.Vflat), std::numbers::pi * t.z() / 3, 1e-8);
  c.V0 = c.Vflat + std::numbers::pi * hb * hb * (3 * R - hb) / 3;
  return c;
}

}  // namespace bpde::testing

namespace bpde {
/// Failure output of the area routes' typed records by their names.
inline void PrintTo(AreaRoute r, std::ostream* os) { *os << to_string(r); }
inline void PrintTo(SoftModeEnd e, std::ostream* os) { *os << to_string(e); }
inline void PrintTo(Status s, std::ostream* os) { *os << to_string(s); }
}  // namespace bpde

namespace bpde::testing {
/// The route an area result comes from (none: no route was kept, the solve failed in every route).
inline std::optional<AreaRoute> kept_route(const AreaRouteLog& log) {
  const AreaRouteRecord* k = log.kept();
  return k ? std::optional<AreaRoute>(k->route) : std::nullopt;
}
}  // namespace bpde::testing
