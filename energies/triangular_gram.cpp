#include "bezierpde/energies/triangular_gram.h"

#include "bezierpde/core/eigen.h"
#include <Eigen/SparseCore>
#include <cmath>
#include <vector>
#include <string>

#include "bezierpde/core/bernstein.h"
#include "bezierpde/core/binomial.h"
#include "bezierpde/core/errors.h"
#include "bezierpde/triangular/triangular_net.h"

namespace bpde {
namespace {

void check_degree(int n, const char* who) {
  if (n < 1 || n > kMaxDegree)
    throw DegreeError(std::string(who) + ": triangular degree " + std::to_string(n) + " is outside 1.." +
                      std::to_string(kMaxDegree));
}

// One derivative step: count(n-1) by count(n), d/du (dir = 0) or d/dv (dir = 1).
Eigen::MatrixXd derivative_step(int n, int dir) {
  Eigen::MatrixXd D = Eigen::MatrixXd::Zero(TriangularNet::count(n - 1), TriangularNet::count(n));
  for (const auto& J : triangular_multi_indices(n - 1)) {
    const int r = TriangularNet::index(n - 1, J[0], J[1]);
    const int plus = dir == 0 ? TriangularNet::index(n, J[0] + 1, J[1]) : TriangularNet::index(n, J[0], J[1] + 1);
    const int minus = TriangularNet::index(n, J[0], J[1]);  // J + e3
    D(r, plus) += n;
    D(r, minus) -= n;
  }
  return D;
}

}  // namespace

std::vector<std::array<int, 3>> triangular_multi_indices(int n) {
  std::vector<std::array<int, 3>> out;
  out.reserve(static_cast<size_t>(TriangularNet::count(n)));
  for (int i = n; i >= 0; --i)
    for (int j = n - i; j >= 0; --j) out.push_back({i, j, n - i - j});
  return out;
}

Eigen::MatrixXd triangular_derivative_operator(int n, int du, int dv) {
  if (du < 0 || dv < 0) throw ParameterError("triangular_derivative_operator: negative order");
  if (du + dv > n) return Eigen::MatrixXd::Zero(0, TriangularNet::count(n));
  Eigen::MatrixXd D = Eigen::MatrixXd::Identity(TriangularNet::count(n), TriangularNet::count(n));
  int deg = n;
  for (int a = 0; a < du; ++a, --deg) D = derivative_step(deg, 0) * D;
  for (int a = 0; a < dv; ++a, --deg) D = derivative_step(deg, 1) * D;
  return D;
}

Eigen::MatrixXd triangular_product_integrals(int p, int q) {
  const auto Ip = triangular_multi_indices(p);
  const auto Iq = triangular_multi_indices(q);
  Eigen::MatrixXd M(TriangularNet::count(p), TriangularNet::count(q));
  const double area = 1.0 / ((p + q + 1.0) * (p + q + 2.0));
  for (size_t a = 0; a < Ip.size(); ++a)
    for (size_t b = 0; b < Iq.size(); ++b) {
      const auto& J = Ip[a];
      const auto& K = Iq[b];
      M(static_cast<Eigen::Index>(a), static_cast<Eigen::Index>(b)) =
          multinomial(p, J[0], J[1]) * multinomial(q, K[0], K[1]) / multinomial(p + q, J[0] + K[0], J[1] + K[1]) * area;
    }
  return M;
}

Eigen::MatrixXd triangular_derivative_integrals(int n, int au, int av, int bu, int bv) {
  if (au + av > n || bu + bv > n) return Eigen::MatrixXd::Zero(TriangularNet::count(n), TriangularNet::count(n));
  const Eigen::MatrixXd Da = triangular_derivative_operator(n, au, av);
  const Eigen::MatrixXd Db = triangular_derivative_operator(n, bu, bv);
  return Da.transpose() * triangular_product_integrals(n - au - av, n - bu - bv) * Db;
}

Eigen::MatrixXd triangular_gram(int n, const std::vector<QuadraticTerm>& terms) {
  check_degree(n, "triangular_gram");
  Eigen::MatrixXd Q = Eigen::MatrixXd::Zero(TriangularNet::count(n), TriangularNet::count(n));
  for (const auto& t : terms) {
    if (!std::isfinite(t.w)) throw NonFiniteError("triangular_gram: non-finite term weight");
    if (t.w == 0.0) continue;
    const Eigen::MatrixXd K = triangular_derivative_integrals(n, t.au, t.av, t.bu, t.bv);
    Q += 0.5 * t.w * (K + K.transpose());
  }
  return Q;
}

Eigen::MatrixXd triangular_gram(int n, const EnergySpec& energy) { return triangular_gram(n, energy.terms()); }

Eigen::MatrixXd triangular_dirichlet_gram(int n) { return triangular_gram(n, EnergySpec::dirichlet().terms()); }

Eigen::MatrixXd dirichlet_gram_closed_form(int n) {
  check_degree(n, "dirichlet_gram_closed_form");
  const auto I = triangular_multi_indices(n);
  const int N = TriangularNet::count(n);
  Eigen::MatrixXd C(N, N);
  for (int a = 0; a < N; ++a)
    for (int b = 0; b < N; ++b) {
      const auto& I0 = I[static_cast<size_t>(a)];
      const auto& I1 = I[static_cast<size_t>(b)];
      double ar[3];
      for (int r = 0; r < 3; ++r) {
        const double s = I0[r] + I1[r];
        ar[r] = (I0[r] * I1[r] == 0) ? 0.0 : I0[r] * I1[r] / (s * (s - 1));
      }
      auto brs = [&](int r, int s) {
        const double num = I0[r] * I1[s] + I0[s] * I1[r];
        if (num == 0.0) return 0.0;
        return num / ((I0[r] + I1[r]) * static_cast<double>(I0[s] + I1[s]));
      };
      const double ratio = multinomial(n, I0[0], I0[1]) * multinomial(n, I1[0], I1[1]) /
                           multinomial(2 * n, I0[0] + I1[0], I0[1] + I1[1]);
      C(a, b) = ratio * (ar[0] + ar[1] + 2 * ar[2] - brs(0, 2) - brs(1, 2));
    }
  return C;
}

Eigen::MatrixXd triangular_basis_table(int n, const Eigen::MatrixX2d& uv, int du, int dv) {
  check_degree(n, "triangular_basis_table");
  const int d = du + dv;
  if (d > n) return Eigen::MatrixXd::Zero(uv.rows(), TriangularNet::count(n));
  const int m = n - d;
  const auto I = triangular_multi_indices(m);
  std::vector<double> coef(I.size());
  for (size_t r = 0; r < I.size(); ++r) coef[r] = multinomial(m, I[r][0], I[r][1]);
  // Powers by repeated products (the tables of the area rules have ~1e4 rows; std::pow per entry
  // was most of their build time).
  std::vector<double> pu(static_cast<size_t>(m + 1)), pv(pu.size()), pw(pu.size());
  Eigen::MatrixXd T(uv.rows(), TriangularNet::count(m));
  for (Eigen::Index s = 0; s < uv.rows(); ++s) {
    const double u = uv(s, 0), v = uv(s, 1), w = 1.0 - u - v;
    pu[0] = pv[0] = pw[0] = 1.0;
    for (int e = 1; e <= m; ++e) {
      pu[e] = pu[e - 1] * u;
      pv[e] = pv[e - 1] * v;
      pw[e] = pw[e - 1] * w;
    }
    for (size_t r = 0; r < I.size(); ++r) {
      const auto& J = I[r];
      T(s, static_cast<Eigen::Index>(r)) = coef[r] * pu[J[0]] * pv[J[1]] * pw[J[2]];
    }
  }
  if (d == 0) return T;
  // The derivative operator has at most 2^d entries per row: a sparse product.
  const Eigen::SparseMatrix<double> D = triangular_derivative_operator(n, du, dv).sparseView();
  return T * D;
}

}  // namespace bpde
