// Triangular Gram matrices (triangular CMC eqs. (2)-(4)) and the volume form (eqs. (5)-(7), corrected)
// against exact Bernstein integration, closed forms and independent quadrature.
#include <gtest/gtest.h>

#include "bezierpde/core/eigen.h"
#include <Eigen/Dense>

#include "cmc_test_util.h"
#include "bezierpde/core/quadrature.h"
#include "bezierpde/energies/triangular_gram.h"
#include "bezierpde/energies/volume.h"

namespace bpde {
namespace {

double rel_diff(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b) {
  return (a - b).cwiseAbs().maxCoeff() / std::max(1e-300, b.cwiseAbs().maxCoeff());
}

TEST(TriangularGram, ClosedFormEq3MatchesDerivativeNets) {
  for (int n = 1; n <= 14; ++n) {
    const Eigen::MatrixXd A = triangular_dirichlet_gram(n);
    const Eigen::MatrixXd B = dirichlet_gram_closed_form(n);
    EXPECT_LT(rel_diff(B, A), 1e-13) << "n = " << n;
  }
}

TEST(TriangularGram, ProductIntegralsSumToArea) {
  const Eigen::MatrixXd M = triangular_product_integrals(4, 7);
  EXPECT_NEAR(M.sum(), 0.5, 1e-15);
  // ∫_T B_{n00}^n = ∫ u^n = 1/((n+1)(n+2)) with q = 0: row of (4,0,0) against (0,0,0).
  EXPECT_NEAR(triangular_product_integrals(4, 0)(0, 0), 1.0 / 30.0, 1e-16);
}

TEST(TriangularGram, DirichletAgainstQuadratureOfNetDerivatives) {
  for (int n : {1, 3, 6, 11}) {
    const Eigen::MatrixX3d P = testing::random_points(TriangularNet::count(n), 7 + n);
    const TriangularNet net(n, P);
    const QuadratureRuleTriangle q = gauss_triangle(n + 1);
    double D = 0;
    for (Eigen::Index s = 0; s < q.w.size(); ++s) {
      const double u = q.uv(s, 0), v = q.uv(s, 1);
      D += 0.5 * q.w(s) * (net.derivative(u, v, 1, 0).squaredNorm() + net.derivative(u, v, 0, 1).squaredNorm());
    }
    const double Dg = 0.5 * (P.transpose() * triangular_dirichlet_gram(n) * P).trace();
    EXPECT_NEAR(Dg, D, 1e-12 * std::abs(D)) << "n = " << n;
  }
}

TEST(TriangularGram, DirichletOfTheIdentityMapAndConstants) {
  const int n = 5;
  Eigen::MatrixX3d P(TriangularNet::count(n), 3);
  for (int r = 0; r < P.rows(); ++r) {
    const auto I = triangular_multi_indices(n)[static_cast<size_t>(r)];
    P.row(r) << double(I[0]) / n, double(I[1]) / n, 0.0;  // x = (u, v, 0)
  }
  const Eigen::MatrixXd C = triangular_dirichlet_gram(n);
  EXPECT_NEAR(0.5 * (P.transpose() * C * P).trace(), 0.5, 1e-14);  // 1/2 ∫ (1 + 1) = area
  EXPECT_LT((C * Eigen::VectorXd::Ones(C.rows())).cwiseAbs().maxCoeff(), 1e-13);
}

TEST(TriangularGram, GenericTermsAgainstQuadrature) {
  // Biharmonic and a mixed second-order energy, exact vs quadrature of net derivatives.
  const int n = 6;
  const Eigen::MatrixX3d P = testing::random_points(TriangularNet::count(n), 99);
  const TriangularNet net(n, P);
  const QuadratureRuleTriangle q = gauss_triangle(n + 1);
  double Eb = 0, E2 = 0;
  for (Eigen::Index s = 0; s < q.w.size(); ++s) {
    const double u = q.uv(s, 0), v = q.uv(s, 1);
    const Eigen::Vector3d xu = net.derivative(u, v, 1, 0), xv = net.derivative(u, v, 0, 1);
    const Eigen::Vector3d xuu = net.derivative(u, v, 2, 0), xuv = net.derivative(u, v, 1, 1),
                          xvv = net.derivative(u, v, 0, 2);
    Eb += 0.5 * q.w(s) * (xuu.squaredNorm() + 2 * xuv.squaredNorm() + xvv.squaredNorm());
    E2 += 0.5 * q.w(s) * (2 * xu.squaredNorm() + 3 * xu.dot(xv) + 0.5 * xv.squaredNorm());
  }
  const Eigen::MatrixXd Qb = triangular_gram(n, EnergySpec::biharmonic());
  const Eigen::MatrixXd Q2 = triangular_gram(n, EnergySpec::second_order(2, 3, 0.5));
  EXPECT_NEAR(0.5 * (P.transpose() * Qb * P).trace(), Eb, 1e-12 * Eb);
  EXPECT_NEAR(0.5 * (P.transpose() * Q2 * P).trace(), E2, 1e-12 * std::abs(E2));
  EXPECT_LT((Qb - Qb.transpose()).cwiseAbs().maxCoeff(), 1e-12 * Qb.cwiseAbs().maxCoeff());
}

TEST(TriangularGram, BasisTableDerivativesMatchNet) {
  const int n = 5;
  const Eigen::MatrixX3d P = testing::random_points(TriangularNet::count(n), 5);
  const TriangularNet net(n, P);
  Eigen::MatrixX2d uv(3, 2);
  uv << 0.2, 0.3, 0.6, 0.1, 0.05, 0.9;
  for (int du = 0; du <= 2; ++du)
    for (int dv = 0; dv + du <= 2; ++dv) {
      const Eigen::MatrixX3d X = triangular_basis_table(n, uv, du, dv) * P;
      for (int s = 0; s < 3; ++s)
        EXPECT_LT((X.row(s).transpose() - net.derivative(uv(s, 0), uv(s, 1), du, dv)).norm(), 1e-12);
    }
}

// ---------------------------------------------------------------- volume

double quadrature_volume_triangular(const TriangularNet& net, int q) {
  const QuadratureRuleTriangle r = gauss_triangle(q);
  double V = 0;
  for (Eigen::Index s = 0; s < r.w.size(); ++s) {
    const double u = r.uv(s, 0), v = r.uv(s, 1);
    V += r.w(s) * net.derivative(u, v, 1, 0).cross(net.derivative(u, v, 0, 1)).dot(net.evaluate(u, v));
  }
  return V / 3;
}

double quadrature_volume_tensor(const TensorNet& net, int q) {
  const QuadratureRule1D r = gauss_legendre01(q);
  double V = 0;
  for (int a = 0; a < q; ++a)
    for (int b = 0; b < q; ++b) {
      const double u = r.x(a), v = r.x(b);
      V += r.w(a) * r.w(b) * net.derivative(u, v, 1, 0).cross(net.derivative(u, v, 0, 1)).dot(net.evaluate(u, v));
    }
  return V / 3;
}

TEST(Volume, ClosedFormCorrectedEq5MatchesQuadrature) {
  for (int n = 1; n <= 6; ++n) {
    const Eigen::MatrixX3d P = testing::random_points(TriangularNet::count(n), 31 + n);
    const TriangularNet net(n, P);
    const double Vq = quadrature_volume_triangular(net, 2 * n + 2);
    const double Vf = VolumeForm::triangular(n).value(P);
    const double Vc = volume_closed_form(n, P);
    const double scale = VolumeForm::triangular(n).value_scale(P);
    EXPECT_NEAR(Vf, Vq, 1e-13 * scale) << n;
    EXPECT_NEAR(Vc, Vq, 1e-13 * scale) << n;
    EXPECT_NEAR(volume(net), Vq, 1e-13 * scale) << n;
  }
}

TEST(Volume, PrintedSignOfD13IsWrong) {
  // With + d_13 as printed in eq. (5), V of a generic net is wrong (docs/errata.md).
  const int n = 3;
  const auto I = triangular_multi_indices(n);
  const Eigen::MatrixX3d P = testing::random_points(TriangularNet::count(n), 4);
  double Vwrong = 0;
  for (size_t a = 0; a < I.size(); ++a)
    for (size_t b = 0; b < I.size(); ++b)
      for (size_t c = 0; c < I.size(); ++c) {
        int S[3];
        for (int r = 0; r < 3; ++r) S[r] = I[a][r] + I[b][r] + I[c][r];
        auto d = [&](int r, int s) {
          const double num = double(I[a][r]) * I[b][s] - double(I[b][r]) * I[a][s];
          return num == 0 ? 0.0 : num / (double(S[r]) * S[s]);
        };
        auto mult = [](int m, int i, int j) { return binomial(m, i) * binomial(m - i, j); };
        const double ratio =
            mult(n, I[a][0], I[a][1]) * mult(n, I[b][0], I[b][1]) * mult(n, I[c][0], I[c][1]) / mult(3 * n, S[0], S[1]);
        const double Cw = ratio * (d(0, 1) + d(1, 2) + d(0, 2));  // as printed
        Vwrong += Cw * P.row(Eigen::Index(a)).cross(P.row(Eigen::Index(b))).dot(P.row(Eigen::Index(c)));
      }
  Vwrong /= 6;
  const double V = VolumeForm::triangular(n).value(P);
  EXPECT_GT(std::abs(Vwrong - V), 1e-3 * VolumeForm::triangular(n).value_scale(P));
}

TEST(Volume, CoordinateFormNeedsTheCyclicAverage) {
  // Prop. 3 writes V = sum S_IJK x^1_I x^2_J x^3_K. With S the cyclic average of C it is exact and
  // S has Lemma 1's symmetries; with S = C it is off by a boundary-dependent constant, which
  // vanishes when the boundary lies in z = 0 (docs/errata.md).
  const int n = 3;
  const auto I = triangular_multi_indices(n);
  const size_t N = I.size();
  auto C = [&](size_t a, size_t b, size_t c) { return volume_coefficient(n, I[a], I[b], I[c]); };
  auto S = [&](size_t a, size_t b, size_t c) { return (C(a, b, c) + C(b, c, a) + C(c, a, b)) / 3; };
  double asym = 0, cyc = 0;
  for (size_t a = 0; a < N; ++a)
    for (size_t b = 0; b < N; ++b)
      for (size_t c = 0; c < N; ++c) {
        asym = std::max(asym, std::abs(S(a, b, c) + S(b, a, c)));
        cyc = std::max(cyc, std::abs(S(a, b, c) - S(b, c, a)));
      }
  EXPECT_LT(asym, 1e-15);
  EXPECT_LT(cyc, 1e-15);
  auto coord_form = [&](const Eigen::MatrixX3d& P, bool average) {
    double V = 0;
    for (size_t a = 0; a < N; ++a)
      for (size_t b = 0; b < N; ++b)
        for (size_t c = 0; c < N; ++c)
          V += (average ? S(a, b, c) : C(a, b, c)) * P(Eigen::Index(a), 0) * P(Eigen::Index(b), 1) *
               P(Eigen::Index(c), 2);
    return V;
  };
  const Eigen::MatrixX3d P = testing::random_points(int(N), 17);
  const double V = VolumeForm::triangular(n).value(P);
  EXPECT_NEAR(coord_form(P, true), V, 1e-14);
  EXPECT_GT(std::abs(coord_form(P, false) - V), 1e-4);
  Eigen::MatrixX3d Q = P;  // boundary in z = 0: C alone is exact too
  const TriangularNet net(n);
  for (int r : net.boundary_indices()) Q(r, 2) = 0;
  EXPECT_NEAR(coord_form(Q, false), VolumeForm::triangular(n).value(Q), 1e-14);
}

TEST(Volume, GraphOverTriangleAndSquare) {
  // Graph x = (u, v, f) with f = 0 on the boundary: V = ∫ f. f = uvw: 1/120.
  const int n = 3;
  TriangularNet t(n);
  for (int r = 0; r < t.size(); ++r) {
    const auto I = triangular_multi_indices(n)[static_cast<size_t>(r)];
    t.points().row(r) << double(I[0]) / n, double(I[1]) / n, 0.0;
  }
  t.points()(TriangularNet::index(n, 1, 1), 2) = 1.0 / 6.0;  // uvw = B_111^3 / 6
  EXPECT_NEAR(volume(t), 1.0 / 120.0, 1e-16);
  // f = u(1-u)v(1-v) = B_1^2(u) B_1^2(v) / 4: 1/36.
  TensorNet s(2, 2);
  for (int i = 0; i <= 2; ++i)
    for (int j = 0; j <= 2; ++j) s.set_point(i, j, Eigen::Vector3d(i / 2.0, j / 2.0, 0));
  s.points()(s.index(1, 1), 2) = 0.25;
  EXPECT_NEAR(volume(s), 1.0 / 36.0, 1e-16);
}

TEST(Volume, TensorAgainstQuadrature) {
  for (auto [n, m] : {std::pair{1, 1}, {2, 3}, {5, 4}, {7, 7}}) {
    const Eigen::MatrixX3d P = testing::random_points((n + 1) * (m + 1), 3 + n * m);
    const TensorNet net(n, m, P);
    const double Vq = quadrature_volume_tensor(net, 2 * std::max(n, m) + 2);
    const VolumeForm f = VolumeForm::tensor(n, m);
    EXPECT_NEAR(f.value(P), Vq, 1e-13 * f.value_scale(P)) << n << "," << m;
  }
}

// Central differences of V are exact up to rounding for a cubic (the third-order term has a
// constant third derivative and cancels only in part: error h^2 |d3V| / 6); h = 1e-4.
template <class Form>
void check_gradient_hessian(const Form& f, const Eigen::MatrixX3d& P, const std::vector<int>& idx) {
  const Eigen::MatrixX3d G = f.gradient(P);
  const double h = 1e-4;
  const double gs = G.cwiseAbs().maxCoeff();
  for (int r = 0; r < P.rows(); ++r)
    for (int c = 0; c < 3; ++c) {
      Eigen::MatrixX3d Pp = P, Pm = P;
      Pp(r, c) += h;
      Pm(r, c) -= h;
      const double fd = (f.value(Pp) - f.value(Pm)) / (2 * h);
      EXPECT_NEAR(G(r, c), fd, 1e-8 * gs) << r << "," << c;
    }
  const Eigen::MatrixXd Hs = f.hessian(P, idx);
  EXPECT_LT((Hs - Hs.transpose()).cwiseAbs().maxCoeff(), 1e-14 * Hs.cwiseAbs().maxCoeff());
  testing::expect_hessian_is_fd_of_gradient(
      Hs, P, idx, [&](const Eigen::MatrixX3d& X) { return f.gradient(X); }, h, 1e-8 * Hs.cwiseAbs().maxCoeff());
}

TEST(Volume, GradientAndHessianAgainstFiniteDifferences) {
  {
    const int n = 4;
    const Eigen::MatrixX3d P = testing::random_points(TriangularNet::count(n), 11);
    std::vector<int> all(static_cast<size_t>(P.rows()));
    for (int r = 0; r < P.rows(); ++r) all[static_cast<size_t>(r)] = r;
    check_gradient_hessian(VolumeForm::triangular(n), P, all);
  }
  {
    const Eigen::MatrixX3d P = testing::random_points(4 * 3, 12);
    std::vector<int> some = {0, 4, 5, 11};
    check_gradient_hessian(VolumeForm::tensor(3, 2), P, some);
  }
}

TEST(Volume, FastInteriorHessianMatchesQuadrature) {
  for (int n : {3, 4, 7, 12}) {
    const VolumeForm f = VolumeForm::triangular(n);
    const Eigen::MatrixX3d P = testing::random_points(f.size(), 50 + n);
    for (FixedSet fs : {FixedSet::Boundary, FixedSet::BoundaryAdjacent}) {
      if (fs == FixedSet::BoundaryAdjacent && n < 6) continue;
      const std::vector<int> idx = TriangularNet(n).free_indices(fs);
      const Eigen::MatrixXd A = f.hessian(P, idx), B = f.hessian_quadrature(P, idx);
      EXPECT_LE((A - B).cwiseAbs().maxCoeff(), 1e-13 * B.cwiseAbs().maxCoeff()) << n;
      const Eigen::MatrixX3d G = f.gradient(P), Gr = f.gradient_rows(P, idx);
      for (size_t a = 0; a < idx.size(); ++a)
        EXPECT_LT((Gr.row(Eigen::Index(a)) - G.row(idx[a])).norm(), 1e-13 * G.cwiseAbs().maxCoeff());
    }
  }
  for (auto [n, m] : {std::pair{2, 2}, {3, 5}, {6, 4}, {9, 9}}) {
    const VolumeForm f = VolumeForm::tensor(n, m);
    const Eigen::MatrixX3d P = testing::random_points(f.size(), 60 + n + m);
    const std::vector<int> idx = TensorNet(n, m).free_indices(FixedSet::Boundary);
    const Eigen::MatrixXd A = f.hessian(P, idx), B = f.hessian_quadrature(P, idx);
    EXPECT_LE((A - B).cwiseAbs().maxCoeff(), 1e-13 * B.cwiseAbs().maxCoeff()) << n << "," << m;
    const Eigen::MatrixX3d G = f.gradient(P), Gr = f.gradient_rows(P, idx);
    for (size_t a = 0; a < idx.size(); ++a)
      EXPECT_LT((Gr.row(Eigen::Index(a)) - G.row(idx[a])).norm(), 1e-13 * G.cwiseAbs().maxCoeff());
  }
}

TEST(Volume, InteriorGradientIsEq10WithoutTheSpuriousThird) {
  // For interior I: dV/dP_I = ∫ B_I x_u ∧ x_v = 1/2 sum_JK C_IJK P_J ∧ P_K (eqs. (7), (10)).
  const int n = 4;
  const auto I = triangular_multi_indices(n);
  const Eigen::MatrixX3d P = testing::random_points(TriangularNet::count(n), 21);
  const Eigen::MatrixX3d G = VolumeForm::triangular(n).gradient(P);
  const TriangularNet net(n, P);
  for (int r : net.free_indices(FixedSet::Boundary)) {
    Eigen::Vector3d s = Eigen::Vector3d::Zero();
    for (size_t b = 0; b < I.size(); ++b)
      for (size_t c = 0; c < I.size(); ++c)
        s += 0.5 * volume_coefficient(n, I[static_cast<size_t>(r)], I[b], I[c]) *
             P.row(Eigen::Index(b)).transpose().cross(P.row(Eigen::Index(c)).transpose());
    EXPECT_LT((G.row(r).transpose() - s).norm(), 1e-13 * G.cwiseAbs().maxCoeff());
  }
}

}  // namespace
}  // namespace bpde
