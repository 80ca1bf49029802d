// D_H = D + 2HV (triangular CMC Prop. 4, eq. (11)): value, gradient and Hessian.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include "bezierpde/core/eigen.h"
#include <Eigen/Dense>

#include "cmc_test_util.h"
#include "bezierpde/core/errors.h"
#include "bezierpde/core/quadrature.h"
#include "bezierpde/energies/cmc.h"
#include "bezierpde/energies/triangular_gram.h"

namespace bpde {
namespace {

TEST(CmcFunctional, ValueGradientHessianAgainstFiniteDifferences) {
  const double H = -1.3;
  for (int kind = 0; kind < 2; ++kind) {
    const CmcFunctional f = kind == 0 ? CmcFunctional::triangular(5) : CmcFunctional::tensor(3, 4);
    const Eigen::MatrixX3d P = testing::random_points(f.size(), 40 + kind);
    EXPECT_NEAR(f.value(P, H), f.dirichlet(P) + 2 * H * f.volume(P), 1e-14 * std::abs(f.value(P, H)));
    const Eigen::MatrixX3d G = f.gradient(P, H);
    const double h = 1e-4, gs = G.cwiseAbs().maxCoeff();
    for (int r = 0; r < f.size(); ++r)
      for (int c = 0; c < 3; ++c) {
        Eigen::MatrixX3d Pp = P, Pm = P;
        Pp(r, c) += h;
        Pm(r, c) -= h;
        EXPECT_NEAR(G(r, c), (f.value(Pp, H) - f.value(Pm, H)) / (2 * h), 1e-8 * gs);
      }
    std::vector<int> idx;
    for (int r = 0; r < f.size(); r += 2) idx.push_back(r);
    const Eigen::MatrixXd J = f.hessian(P, H, idx);
    testing::expect_hessian_is_fd_of_gradient(
        J, P, idx, [&](const Eigen::MatrixX3d& X) { return f.gradient(X, H); }, h, 1e-8 * J.cwiseAbs().maxCoeff());
  }
}

TEST(CmcFunctional, JacobianBlockOfEq11) {
  // dF_I/dP_L = C_IL Id - 2H [sum_K C_ILK P_K]_x for interior I, L (docs/errata.md).
  const int n = 5;
  const double H = 0.7;
  const CmcFunctional f = CmcFunctional::triangular(n);
  const auto I = triangular_multi_indices(n);
  const Eigen::MatrixX3d P = testing::random_points(f.size(), 77);
  const std::vector<int> idx = TriangularNet(n).free_indices(FixedSet::Boundary);
  const Eigen::MatrixXd J = f.hessian(P, H, idx);
  for (size_t a = 0; a < idx.size(); ++a)
    for (size_t b = 0; b < idx.size(); ++b) {
      Eigen::Vector3d s = Eigen::Vector3d::Zero();
      for (size_t k = 0; k < I.size(); ++k)
        s += volume_coefficient(n, I[static_cast<size_t>(idx[a])], I[static_cast<size_t>(idx[b])], I[k]) *
             P.row(Eigen::Index(k)).transpose();
      Eigen::Matrix3d X;
      X << 0, -s(2), s(1), s(2), 0, -s(0), -s(1), s(0), 0;
      const Eigen::Matrix3d expect = f.gram()(idx[a], idx[b]) * Eigen::Matrix3d::Identity() - 2 * H * X;
      EXPECT_LT((J.block<3, 3>(3 * Eigen::Index(a), 3 * Eigen::Index(b)) - expect).cwiseAbs().maxCoeff(),
                1e-13 * J.cwiseAbs().maxCoeff());
    }
}

TEST(CmcFunctional, TensorGramIsDirichlet) {
  const TensorNet net(3, 2, testing::random_points(12, 8));
  const CmcFunctional f = CmcFunctional::tensor(3, 2);
  const QuadratureRule1D r = gauss_legendre01(4);
  double D = 0;
  for (int a = 0; a < 4; ++a)
    for (int b = 0; b < 4; ++b)
      D += 0.5 * r.w(a) * r.w(b) *
           (net.derivative(r.x(a), r.x(b), 1, 0).squaredNorm() + net.derivative(r.x(a), r.x(b), 0, 1).squaredNorm());
  EXPECT_NEAR(f.dirichlet(net.points()), D, 1e-13 * D);
}

TEST(CmcFunctional, EnergiesOfANet) {
  // x = (u, v, 1) on the triangle: D = 1/2 (1 + 1) area = 1/2; x_u ^ x_v = e3, <e3, x> = 1, so
  // V = 1/3 area = 1/6. On the square with z = 2: D = 1, V = 2/3.
  TriangularNet t(3);
  for (int r = 0; r < t.size(); ++r) {
    const auto I = triangular_multi_indices(3)[static_cast<size_t>(r)];
    t.points().row(r) << I[0] / 3.0, I[1] / 3.0, 1.0;
  }
  const CmcEnergies e = cmc_energies(t, -2.0);
  EXPECT_NEAR(e.D, 0.5, 1e-14);
  EXPECT_NEAR(e.V, 1.0 / 6.0, 1e-15);
  EXPECT_NEAR(e.DH, 0.5 - 4.0 / 6.0, 1e-14);
  EXPECT_THROW(cmc_energies(t, std::nan("")), NonFiniteError);
  TensorNet q(1, 1);
  q.set_point(0, 0, {0, 0, 2});
  q.set_point(1, 0, {1, 0, 2});
  q.set_point(0, 1, {0, 1, 2});
  q.set_point(1, 1, {1, 1, 2});
  const CmcEnergies eq = cmc_energies(q, 1.0);
  EXPECT_NEAR(eq.D, 1.0, 1e-14);
  EXPECT_NEAR(eq.V, 2.0 / 3.0, 1e-15);
}

TEST(CmcFunctional, MeanCurvatureStatsOfAParaboloid) {
  // z = u^2 + v^2 over the unit square: H(0,0) = 2 (FORMATS.md); check the range is sensible.
  TensorNet net(2, 2);
  for (int i = 0; i <= 2; ++i)
    for (int j = 0; j <= 2; ++j) {
      // u^2 has Bernstein coefficients (0, 0, 1); u has (0, 1/2, 1).
      const double zi[3] = {0, 0, 1};
      net.set_point(i, j, Eigen::Vector3d(i / 2.0, j / 2.0, zi[i] + zi[j]));
    }
  const MeanCurvatureStats s = mean_curvature_stats(net, 20, 0.0);
  EXPECT_NEAR(s.max, 2.0, 1e-12);
  EXPECT_GT(s.min, 0.0);
  EXPECT_EQ(s.count, 21 * 21);
  const MeanCurvatureStats s2 = mean_curvature_stats(net, 20, 0.1);
  EXPECT_LT(s2.count, s.count);
  EXPECT_LT(s2.max, 2.0);
  EXPECT_THROW(mean_curvature_stats(net, 0), ParameterError);
}

// The statistics come from the one tabulated sampling (sample_mesh); check them against the
// per-point de Casteljau geometry of every qualifying sample, on a generic tensor and triangular
// net, and the mesh overload against the net overload (the report uses the former).
TEST(CmcFunctional, MeanCurvatureStatsMatchPerPointGeometry) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> U(-0.2, 0.2);
  TensorNet t(7, 6);
  for (int i = 0; i <= 7; ++i)
    for (int j = 0; j <= 6; ++j) t.set_point(i, j, Eigen::Vector3d(i / 7.0 + U(rng), j / 6.0 + U(rng), U(rng)));
  TriangularNet tr(6);
  for (int r = 0; r < tr.size(); ++r) tr.points().row(r) << U(rng), U(rng), U(rng);
  for (int r = 0; r < tr.size(); ++r) tr.points()(r, 0) += 5.0 * r / tr.size();
  const int N = 17;
  auto direct = [&](auto&& geometry_at, auto&& loop) {
    MeanCurvatureStats s;
    double sum = 0;
    loop([&](double u, double v) {
      const FundamentalForms g = geometry_at(u, v);
      if (!g.regular) return;
      s.min = s.count ? std::min(s.min, g.H) : g.H;
      s.max = s.count ? std::max(s.max, g.H) : g.H;
      sum += g.H;
      ++s.count;
    });
    s.mean = sum / s.count;
    return s;
  };
  const MeanCurvatureStats et = direct([&](double u, double v) { return t.geometry(u, v); },
                                       [&](auto&& f) {
                                         for (int a = 0; a <= N; ++a)
                                           for (int b = 0; b <= N; ++b) {
                                             const double u = double(a) / N, v = double(b) / N;
                                             if (std::min(u, 1 - u) < 0.1 - 1e-12 && std::min(v, 1 - v) < 0.1 - 1e-12)
                                               continue;
                                             f(u, v);
                                           }
                                       });
  const MeanCurvatureStats er = direct([&](double u, double v) { return tr.geometry(u, v); },
                                       [&](auto&& f) {
                                         for (int a = 0; a <= N; ++a)
                                           for (int b = 0; b <= N - a; ++b) {
                                             const double u = double(a) / N, v = double(b) / N;
                                             if (u > 0.9 + 1e-12 || v > 0.9 + 1e-12 || 1 - u - v > 0.9 + 1e-12)
                                               continue;
                                             f(u, v);
                                           }
                                       });
  for (const auto& [got, want] :
       {std::pair{mean_curvature_stats(t, N, 0.1), et}, std::pair{mean_curvature_stats(tr, N, 0.1), er},
        std::pair{mean_curvature_stats(sample_mesh(t, N), SampleLayout::TensorGrid, N, 0.1), et},
        std::pair{mean_curvature_stats(sample_mesh(tr, N), SampleLayout::TriangularGrid, N, 0.1), er}}) {
    ASSERT_GT(want.count, 0);
    EXPECT_EQ(got.count, want.count);
    const double scale = std::max(std::abs(want.min), std::abs(want.max));
    EXPECT_NEAR(got.min, want.min, 1e-10 * scale);
    EXPECT_NEAR(got.max, want.max, 1e-10 * scale);
    EXPECT_NEAR(got.mean, want.mean, 1e-10 * scale);
  }
  // A mesh of the wrong size for N is refused.
  EXPECT_THROW(mean_curvature_stats(sample_mesh(t, N), SampleLayout::TensorGrid, N + 1, 0.1), SizeError);
  EXPECT_THROW(mean_curvature_stats(sample_mesh(t, N), SampleLayout::TriangularGrid, N, 0.1), SizeError);
}

}  // namespace
}  // namespace bpde
