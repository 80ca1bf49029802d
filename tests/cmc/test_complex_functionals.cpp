// D, V and A on complexes (energies/complex_functionals.h) against independent truths: a patch
// split into four equals the patch (values, gradients mapped back by the split's matrix S,
// Hessians Sᵀ H S); finite differences of values and gradients on a complex that is no longer one
// patch; the sparse Hessians against the dense ones; a spherical cap's area and volume against
// the closed form.
#include "bezierpde/core/eigen.h"
#include <Eigen/Dense>
#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "bezierpde/core/kron.h"
#include "bezierpde/energies/complex_functionals.h"
#include "tests/cmc/cmc_test_util.h"
#include "tests/cmc/complex_test_util.h"

namespace bpde::testing {
namespace {

// A regular, non-planar graph surface over the domain, perturbed at random: (u, v, z(u, v)) + noise.
Eigen::MatrixX3d graph_points(int N, const Eigen::MatrixX2d& uv, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> d(-0.05, 0.05);
  Eigen::MatrixX3d P(N, 3);
  for (int r = 0; r < N; ++r) {
    const double u = uv(r, 0), v = uv(r, 1);
    P.row(r) << u + d(rng), v + d(rng), 0.3 * std::sin(2 * u + v) + 0.2 * u * v + d(rng);
  }
  return P;
}

Eigen::MatrixX2d triangular_lattice(int n) {
  Eigen::MatrixX2d uv(TriangularNet::count(n), 2);
  for (int r = 0; r < uv.rows(); ++r) {
    const auto I = TriangularNet::multi_index(n, r);
    uv.row(r) << double(I[0]) / n, double(I[1]) / n;
  }
  return uv;
}

Eigen::MatrixX2d tensor_lattice(int n) {
  Eigen::MatrixX2d uv((n + 1) * (n + 1), 2);
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j <= n; ++j) uv.row(i * (n + 1) + j) << double(i) / n, double(j) / n;
  return uv;
}

std::vector<int> all_rows(int N) {
  std::vector<int> r(static_cast<std::size_t>(N));
  for (int i = 0; i < N; ++i) r[static_cast<std::size_t>(i)] = i;
  return r;
}

struct SplitCase {
  bool triangular;
  int n;
};

class ComplexSplit : public ::testing::TestWithParam<SplitCase> {
 protected:
  void SetUp() override {
    const SplitCase c = GetParam();
    P = c.triangular ? graph_points(TriangularNet::count(c.n), triangular_lattice(c.n), 7)
                     : graph_points((c.n + 1) * (c.n + 1), tensor_lattice(c.n), 7);
    split = c.triangular ? triangular_split(c.n, P) : tensor_split(c.n, P);
    f = c.triangular ? CmcFunctional::cached_triangular(c.n) : CmcFunctional::cached_tensor(c.n, c.n);
    const int q = 3 * c.n + 8;
    a = c.triangular ? AreaForm::cached_triangular(c.n, q) : AreaForm::cached_tensor(c.n, c.n, q);
    fc = complex_cmc_functional(split.complex);
    ac = complex_area_form(split.complex, q);
  }
  Eigen::MatrixX3d P;
  SplitComplex split;
  std::shared_ptr<const CmcFunctional> f, fc;
  std::shared_ptr<const AreaForm> a, ac;
};

TEST_P(ComplexSplit, ValuesEqualThePatchs) {
  const Eigen::MatrixX3d& Q = split.complex.points;
  ASSERT_EQ(split.complex.patches.size(), 4u);
  EXPECT_LT(Q.rows(), 4 * P.rows());  // shared points were merged
  EXPECT_NEAR(fc->dirichlet(Q), f->dirichlet(P), 1e-12 * f->dirichlet(P));
  EXPECT_NEAR(fc->volume(Q), f->volume(P), 1e-12 * std::abs(f->volume(P)) + 1e-14);
  EXPECT_NEAR(ac->value(Q), a->value(P), 1e-11 * a->value(P));
  EXPECT_NEAR(fc->value(Q, -0.7), f->value(P, -0.7), 1e-11 * f->dirichlet(P));
}

TEST_P(ComplexSplit, GradientsMappedBackEqualThePatchs) {
  const Eigen::MatrixX3d& Q = split.complex.points;
  const Eigen::MatrixXd St = split.S.transpose();
  const Eigen::MatrixX3d gD = f->gradient(P, 0.0), gV = f->volume_form().gradient(P), gA = a->gradient(P);
  EXPECT_LT((St * fc->gradient(Q, 0.0) - gD).cwiseAbs().maxCoeff(), 1e-11 * gD.cwiseAbs().maxCoeff());
  EXPECT_LT((St * fc->volume_form().gradient(Q) - gV).cwiseAbs().maxCoeff(), 1e-11 * gV.cwiseAbs().maxCoeff());
  EXPECT_LT((St * ac->gradient(Q) - gA).cwiseAbs().maxCoeff(), 1e-10 * gA.cwiseAbs().maxCoeff());
  // The rows of the free points of the complex by the rows route (gradient_rows) agree with the full gradient.
  const std::vector<int> free = complex_free_rows(split.complex);
  const Eigen::MatrixX3d G = fc->gradient(Q, 0.4);
  EXPECT_LT((fc->gradient_rows(Q, 0.4, free) - G(free, Eigen::all)).cwiseAbs().maxCoeff(), 1e-12 * G.cwiseAbs().maxCoeff());
  Eigen::MatrixX3d GA;
  ac->gradient_rows_and_scale(Q, free, &GA, nullptr);
  EXPECT_LT((GA - ac->gradient(Q)(free, Eigen::all)).cwiseAbs().maxCoeff(), 1e-13);
}

TEST_P(ComplexSplit, HessiansMappedBackEqualThePatchs) {
  const Eigen::MatrixX3d& Q = split.complex.points;
  const Eigen::MatrixXd S3 = kron(split.S, Eigen::Matrix3d::Identity());
  const std::vector<int> allQ = all_rows(static_cast<int>(Q.rows())), allP = all_rows(static_cast<int>(P.rows()));
  const Eigen::MatrixXd HD = f->hessian(P, 0.3, allP), HA = a->hessian(P, allP);
  EXPECT_LT((S3.transpose() * fc->hessian(Q, 0.3, allQ) * S3 - HD).cwiseAbs().maxCoeff(), 1e-10 * HD.cwiseAbs().maxCoeff());
  EXPECT_LT((S3.transpose() * ac->hessian(Q, allQ) * S3 - HA).cwiseAbs().maxCoeff(), 1e-9 * HA.cwiseAbs().maxCoeff());
}

TEST_P(ComplexSplit, SparseHessiansEqualTheDenseOnes) {
  PatchComplex c = split.complex;
  const std::vector<int> free = complex_free_rows(c);
  ASSERT_FALSE(free.empty());
  ASSERT_FALSE(c.fixed.empty());
  const Eigen::MatrixXd HD = fc->hessian(c.points, 0.0, free), HV = fc->volume_form().hessian(c.points, free);
  EXPECT_LT((Eigen::MatrixXd(dirichlet_hessian_sparse(c)) - HD).cwiseAbs().maxCoeff(), 1e-13 * HD.cwiseAbs().maxCoeff());
  EXPECT_LT((Eigen::MatrixXd(volume_hessian_sparse(c)) - HV).cwiseAbs().maxCoeff(), 1e-13 * HV.cwiseAbs().maxCoeff());
  const Eigen::MatrixXd HA = ac->hessian(c.points, free);
  const int n = GetParam().n, q = 3 * n + 8;
  const auto rule = GetParam().triangular ? AreaForm::cached_triangular(n, q) : AreaForm::cached_tensor(n, n, q);
  EXPECT_LT((Eigen::MatrixXd(area_hessian_sparse(c, *rule)) - HA).cwiseAbs().maxCoeff(), 1e-13 * HA.cwiseAbs().maxCoeff());
}

TEST_P(ComplexSplit, DerivativesMatchFiniteDifferencesOffTheSplit) {
  // Move the free points at random: the complex is no longer one patch.
  Eigen::MatrixX3d Q = split.complex.points;
  const std::vector<int> free = complex_free_rows(split.complex);
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> d(-0.03, 0.03);
  for (int r : free)
    for (int c = 0; c < 3; ++c) Q(r, c) += d(rng);
  const double H = -0.8, h = 1e-6;
  const Eigen::MatrixX3d G = fc->gradient(Q, H), GA = ac->gradient(Q);
  for (int r : free)
    for (int c = 0; c < 3; ++c) {
      Eigen::MatrixX3d Qp = Q, Qm = Q;
      Qp(r, c) += h;
      Qm(r, c) -= h;
      EXPECT_NEAR(G(r, c), (fc->value(Qp, H) - fc->value(Qm, H)) / (2 * h), 1e-7);
      EXPECT_NEAR(GA(r, c), (ac->value(Qp) - ac->value(Qm)) / (2 * h), 1e-7);
    }
  expect_hessian_is_fd_of_gradient(fc->hessian(Q, H, free), Q, free,
                                   [&](const Eigen::MatrixX3d& X) { return fc->gradient(X, H); }, 1e-5, 1e-6);
  expect_hessian_is_fd_of_gradient(ac->hessian(Q, free), Q, free,
                                   [&](const Eigen::MatrixX3d& X) { return ac->gradient(X); }, 1e-5, 1e-6);
}

INSTANTIATE_TEST_SUITE_P(Complex, ComplexSplit,
                         ::testing::Values(SplitCase{true, 4}, SplitCase{true, 7}, SplitCase{false, 3},
                                           SplitCase{false, 5}),
                         [](const auto& info) {
                           return std::string(info.param.triangular ? "triangular" : "tensor") +
                                  std::to_string(info.param.n);
                         });

// The cap of the sphere of radius 2 over the unit circle (in z = 0, bulging to +z): the unit disc
// as the image of the square [-1, 1]² by the analytic map (u √(1 − v²/2), v √(1 − u²/2)), cut
// into 3 × 3 sub-squares, each interpolated at its tensor lattice by a degree-n patch and lifted
// onto the sphere. Shared edges agree (an edge of a tensor interpolant depends on that edge's
// nodes only), so the nine patches form one complex.
PatchComplex cap_complex(int n) {
  const double R = 2.0, c = std::sqrt(R * R - 1.0);
  auto cap = [&](double s, double t) {
    const double x = s * std::sqrt(1 - t * t / 2), y = t * std::sqrt(1 - s * s / 2);
    return Eigen::Vector3d(x, y, std::sqrt(std::max(0.0, R * R - x * x - y * y)) - c);
  };
  Eigen::VectorXd t(n + 1);
  for (int k = 0; k <= n; ++k) t(k) = double(k) / n;
  const Eigen::PartialPivLU<Eigen::MatrixXd> lu(bernstein_table(n, t));
  std::vector<Eigen::MatrixX3d> nets;
  std::vector<std::vector<int>> none;
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b) {
      Eigen::MatrixX3d P((n + 1) * (n + 1), 3);
      for (int c3 = 0; c3 < 3; ++c3) {
        Eigen::MatrixXd F(n + 1, n + 1);
        for (int i = 0; i <= n; ++i)
          for (int j = 0; j <= n; ++j) F(i, j) = cap(-1 + (2 * a + 2 * t(i)) / 3, -1 + (2 * b + 2 * t(j)) / 3)(c3);
        const Eigen::MatrixXd C = lu.solve(lu.solve(F).transpose()).transpose();
        for (int i = 0; i <= n; ++i)
          for (int j = 0; j <= n; ++j) P(i * (n + 1) + j, c3) = C(i, j);
      }
      nets.push_back(P);
      none.push_back({});
    }
  return merge_nets(nets, PatchKind::tensor, n, none);
}

TEST(ComplexFunctionals, SphericalCapAreaAndVolumeConvergeToTheClosedForm) {
  const double A = 4 * std::numbers::pi * (2 - std::sqrt(3.0));  // 2πRh
  const double h = 2 - std::sqrt(3.0), V = std::numbers::pi * h * h * (6 - h) / 3;  // the cap's segment
  double last = 1.0;
  for (int n : {4, 8, 12}) {
    const PatchComplex c = cap_complex(n);
    ASSERT_EQ(c.points.rows(), 9 * (n + 1) * (n + 1) - 12 * (n + 1) + 4);  // 12 shared edges, 4 inner corners
    const double eA = std::abs(complex_area_form(c, 3 * n + 8)->value(c.points) - A) / A;
    const double eV = std::abs(complex_cmc_functional(c)->volume(c.points) - V) / V;
    EXPECT_LT(std::max(eA, eV), last / 10) << "n = " << n;
    last = std::max(eA, eV);
  }
  EXPECT_LT(last, 1e-6);
}

TEST(ComplexFunctionals, BadComplexesAreRefused) {
  SplitComplex s = triangular_split(3, graph_points(10, triangular_lattice(3), 1));
  PatchComplex c = s.complex;
  c.patches[1].degree = 4;
  EXPECT_THROW(patch_assembly(c), ParameterError);
  c = s.complex;
  c.patches[2].points.pop_back();
  EXPECT_THROW(patch_assembly(c), SizeError);
  c = s.complex;
  c.patches[0].points[0] = static_cast<int>(c.points.rows());
  EXPECT_THROW(patch_assembly(c), SizeError);
  c = s.complex;
  std::swap(c.fixed[0], c.fixed[1]);
  EXPECT_THROW(patch_assembly(c), SizeError);
  EXPECT_THROW(patch_assembly(PatchComplex{}), ParameterError);
  EXPECT_THROW(complex_cmc_functional(s.complex)->dirichlet(Eigen::MatrixX3d::Zero(3, 3)), SizeError);
}

}  // namespace
}  // namespace bpde::testing
