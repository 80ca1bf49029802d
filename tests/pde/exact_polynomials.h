#pragma once
// Test helper: exact polynomial solutions of homogeneous constant-coefficient PDEs, as Bernstein
// nets, computed in long double.
//
// For L = sum_j c_j d^{p-j}_u d^j_v (p = 2 or 4), p(u,v) = (u + mu v)^k solves L p = 0 whenever
// mu is a root of sum_j c_j mu^j = 0; for a double root mu, u (u + mu v)^(k-1) does too. The real
// and imaginary parts of these, k <= deg, span exact solutions of total degree <= deg, which lie
// in bidegree (deg, deg) and are exactly representable at any bidegree (n, m) >= (deg, deg).
#include <cmath>
#include <complex>
#include <random>
#include <vector>

#include "bezierpde/solvers/pde/pde_lu.h"
#include "bezierpde/tensor/tensor_net.h"

namespace bpde::testing {

using cld = std::complex<long double>;

struct Root {
  cld mu;
  bool double_root = false;
};

inline long double binom_ld(int n, int k) {
  if (k < 0 || k > n) return 0;
  long double r = 1;
  for (int i = 1; i <= k; ++i) r = r * (n - k + i) / i;
  return r;
}

/// Monomial coefficients c[k][l] (of u^k v^l) of a random real combination of the basis above,
/// one set per coordinate. Each basis function is scaled by (1 + |mu|)^-k.
inline std::vector<std::vector<std::vector<long double>>> exact_monomials(const std::vector<Root>& roots, int deg,
                                                                          unsigned seed) {
  std::mt19937 gen(seed);
  std::uniform_real_distribution<double> U(-1.0, 1.0);
  std::vector<std::vector<std::vector<long double>>> c(
      3, std::vector<std::vector<long double>>(deg + 1, std::vector<long double>(deg + 1, 0.0L)));
  auto add = [&](const std::vector<cld>& f, int k, int shift_u) {
    // f[j]: coefficient of u^(k - j + shift_u - ...) handled by caller: here f[j] multiplies
    // u^(k-j) v^j times u^shift_u.
    for (int co = 0; co < 3; ++co) {
      const long double wr = U(gen), wi = U(gen);
      for (int j = 0; j <= k; ++j) {
        const int ku = k - j + shift_u;
        c[co][ku][j] += wr * f[j].real() + wi * f[j].imag();
      }
    }
  };
  for (const Root& r : roots) {
    const long double scale = 1.0L / (1.0L + std::abs(r.mu));
    for (int k = 0; k <= deg; ++k) {
      std::vector<cld> f(k + 1);
      for (int j = 0; j <= k; ++j) f[j] = binom_ld(k, j) * std::pow(r.mu, j) * std::pow(scale, k);
      add(f, k, 0);
      if (r.double_root && k >= 1) {
        std::vector<cld> g(k);
        for (int j = 0; j <= k - 1; ++j) g[j] = binom_ld(k - 1, j) * std::pow(r.mu, j) * std::pow(scale, k - 1);
        add(g, k - 1, 1);
      }
    }
  }
  return c;
}

/// The Bernstein net of degree (n, m) of those monomials (deg <= min(n, m)).
inline TensorNet exact_net(const std::vector<std::vector<std::vector<long double>>>& c, int n, int m) {
  const int deg = static_cast<int>(c[0].size()) - 1;
  TensorNet net(n, m);
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j <= m; ++j)
      for (int co = 0; co < 3; ++co) {
        long double s = 0;
        for (int k = 0; k <= std::min(i, deg); ++k)
          for (int l = 0; l <= std::min(j, deg); ++l)
            s += binom_ld(i, k) * binom_ld(j, l) / (binom_ld(n, k) * binom_ld(m, l)) * c[co][k][l];
        net.points()(net.index(i, j), co) = static_cast<double>(s);
      }
  return net;
}

inline TensorNet exact_solution(const std::vector<Root>& roots, int n, unsigned seed) {
  return exact_net(exact_monomials(roots, n, seed), n, n);
}

/// Same net with only the boundary ring kept (the rest set to 0).
inline TensorNet boundary_only(const TensorNet& net, bool u_rows_only = false) {
  TensorNet out(net.n(), net.m());
  for (int i = 0; i <= net.n(); ++i)
    for (int j = 0; j <= net.m(); ++j) {
      const bool keep = u_rows_only ? (i == 0 || i == net.n()) : (i == 0 || i == net.n() || j == 0 || j == net.m());
      if (keep) out.set_point(i, j, net.point(i, j));
    }
  return out;
}

/// max_ij |P_ij - Q_ij| / max_ij |Q_ij|.
inline double relative_error(const TensorNet& P, const TensorNet& Q) {
  return (P.points() - Q.points()).rowwise().norm().maxCoeff() / Q.points().rowwise().norm().maxCoeff();
}

/// The data-rounding floor: rounding the prescribed points to double (relative 2^-53) moves the
/// free points by up to |S|_inf * 2^-53 * max|x_B| (S = the mould's boundary-to-free map). No
/// method that reads double data can beat it reliably; relative to max|P_exact|.
inline double floor_error(const PdeMould& mould, const TensorNet& exact) {
  double xb = 0;
  for (int idx : mould.fixed_indices()) xb = std::max(xb, exact.points().row(idx).cwiseAbs().maxCoeff());
  return std::ldexp(1.0, -53) * mould.interior_from_boundary().cwiseAbs().rowwise().sum().maxCoeff() * xb /
         exact.points().rowwise().norm().maxCoeff();
}

/// Tolerance for exact recovery: 50 x the floor plus 1e-14. A wrong formula gives O(1) errors.
inline double floor_tolerance(double floor) { return 50 * floor + 1e-14; }

// Roots of the common operators (mu with sum_j c_j mu^j = 0, one of each conjugate pair).
inline std::vector<Root> biharmonic_roots() { return {{cld(0, 1), true}}; }
inline std::vector<Root> modified_biharmonic_roots(double alpha) { return {{cld(0, 1.0L / alpha), true}}; }
/// The G-norm operator [rho^2, 2 rho cos t, 1+rho^2, 2 rho cos t, 1] as an `operator` energy: the
/// same coefficients as EnergySpec::gnorm(rho, t), also for the degenerate t = 0, pi (e1 parallel
/// to e2), which EnergySpec::gnorm refuses as a singular G but which stays a valid PDE operator.
inline EnergySpec gnorm_operator(double rho, double t) {
  const double bc = 2 * rho * std::cos(t);
  return EnergySpec::pde_operator({rho * rho, bc, 1 + rho * rho, bc, 1});
}
/// G-norm [rho^2, 2 rho cos t, 1+rho^2, 2 rho cos t, 1]: (1 + mu^2)(rho^2 + 2 rho cos t mu + mu^2).
inline std::vector<Root> gnorm_roots(double rho, double t) {
  const cld r2 = -static_cast<long double>(rho) * std::exp(cld(0, t));
  if (std::abs(std::sin(t)) < 1e-15) return {{cld(0, 1), false}, {cld(r2.real(), 0), true}};
  return {{cld(0, 1), false}, {r2, false}};
}

/// Generic data: the grid (i/n, j/m, 0) perturbed by up to 0.1 in u, v and 0.5 in z, from `seed`.
inline TensorNet perturbed_grid_net(int n, int m, unsigned seed) {
  std::mt19937 gen(seed);
  std::uniform_real_distribution<double> U(-1.0, 1.0);
  TensorNet net(n, m);
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j <= m; ++j)
      net.set_point(i, j, Eigen::Vector3d(double(i) / n + 0.1 * U(gen), double(j) / m + 0.1 * U(gen), 0.5 * U(gen)));
  return net;
}

}  // namespace bpde::testing
