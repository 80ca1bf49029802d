#pragma once
// Exact polynomial test surfaces for the C¹-methods tests (Centella et al.): products zbar^a z^b with z = (u-u0) +
// i(v-v0), as monomial coefficient tables, turned into degree-(n,n) nets.
#include <complex>
#include <vector>

#include "bezierpde/tensor/power_basis.h"
#include "bezierpde/tensor/tensor_net.h"

namespace bpde::testing {

using CPoly = std::vector<std::vector<std::complex<double>>>;  // c[k][l] of u^k v^l

inline CPoly cmul(const CPoly& a, const CPoly& b) {
  CPoly r(a.size() + b.size() - 1, std::vector<std::complex<double>>(a[0].size() + b[0].size() - 1));
  for (size_t i = 0; i < a.size(); ++i)
    for (size_t j = 0; j < a[0].size(); ++j)
      for (size_t k = 0; k < b.size(); ++k)
        for (size_t l = 0; l < b[0].size(); ++l) r[i + k][j + l] += a[i][j] * b[k][l];
  return r;
}

/// zbar^a z^b with z = (u - u0) + i (v - v0).
inline CPoly zbar_z(int a, int b, double u0, double v0) {
  const std::complex<double> I(0, 1);
  const CPoly z = {{-u0 - I * v0, I}, {1.0, 0.0}}, zb = {{-u0 + I * v0, -I}, {1.0, 0.0}};
  CPoly r = {{1.0}};
  for (int k = 0; k < a; ++k) r = cmul(r, zb);
  for (int k = 0; k < b; ++k) r = cmul(r, z);
  return r;
}

/// Degree-(n,n) net of (x, y, z) = (sx * Re/Im..., ...): each coordinate is a real polynomial given
/// by its monomial table (size <= n+1 in each direction).
inline TensorNet net_from_tables(int n, const std::vector<std::vector<std::vector<double>>>& coords) {
  Eigen::MatrixX3d c = Eigen::MatrixX3d::Zero((n + 1) * (n + 1), 3);
  for (int d = 0; d < 3; ++d)
    for (size_t k = 0; k < coords[static_cast<size_t>(d)].size(); ++k)
      for (size_t l = 0; l < coords[static_cast<size_t>(d)][k].size(); ++l)
        c(static_cast<Eigen::Index>(k) * (n + 1) + static_cast<Eigen::Index>(l), d) =
            coords[static_cast<size_t>(d)][k][l];
  return from_power(n, n, c);
}

inline std::vector<std::vector<double>> re(const CPoly& p, double s = 1.0) {
  std::vector<std::vector<double>> r(p.size(), std::vector<double>(p[0].size()));
  for (size_t i = 0; i < p.size(); ++i)
    for (size_t j = 0; j < p[0].size(); ++j) r[i][j] = s * p[i][j].real();
  return r;
}
inline std::vector<std::vector<double>> im(const CPoly& p, double s = 1.0) {
  std::vector<std::vector<double>> r(p.size(), std::vector<double>(p[0].size()));
  for (size_t i = 0; i < p.size(); ++i)
    for (size_t j = 0; j < p[0].size(); ++j) r[i][j] = s * p[i][j].imag();
  return r;
}
/// Sum of two tables (any sizes).
inline std::vector<std::vector<double>> add(const std::vector<std::vector<double>>& a,
                                            const std::vector<std::vector<double>>& b) {
  const size_t R = std::max(a.size(), b.size()), C = std::max(a[0].size(), b[0].size());
  std::vector<std::vector<double>> r(R, std::vector<double>(C, 0.0));
  for (size_t i = 0; i < a.size(); ++i)
    for (size_t j = 0; j < a[i].size(); ++j) r[i][j] += a[i][j];
  for (size_t i = 0; i < b.size(); ++i)
    for (size_t j = 0; j < b[i].size(); ++j) r[i][j] += b[i][j];
  return r;
}

/// Max |a - b| over the points divided by max |b|.
inline double relative_difference(const TensorNet& a, const TensorNet& b) {
  return (a.points() - b.points()).cwiseAbs().maxCoeff() / b.points().cwiseAbs().maxCoeff();
}

}  // namespace bpde::testing
