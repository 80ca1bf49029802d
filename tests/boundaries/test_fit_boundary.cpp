// Fitting boundary curves to a net's boundary (boundaries/fit_boundary.h): exact reproduction of
// polynomial data, the spectral convergence of arcs against the interpolation remainder bound,
// shared corners, samples, C¹ rings from tangent fields, and the typed errors.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>

#include "bezierpde/boundaries/fit_boundary.h"
#include "bezierpde/boundaries/fit_samples.h"
#include "bezierpde/boundaries/reference_boundaries.h"
#include "bezierpde/boundaries/reference_curves.h"
#include "bezierpde/core/bernstein.h"
#include "bezierpde/core/errors.h"
#include "tests/random_points.h"

namespace {

using bpde::BoundaryCurve;
using bpde::BoundaryData;
using Eigen::Vector3d;
constexpr double kPi = std::numbers::pi;

Vector3d bezier(const Eigen::MatrixX3d& P, double t) { return BoundaryCurve::bezier(P).evaluate(t); }

// The Cauchy remainder bound of interpolation at the n+1 Chebyshev–Lobatto nodes on [0,1]: the
// node polynomial is at most 4^-n there, so |c - p| <= sqrt(2) θ^(n+1) r / ((n+1)! 4^n) for a
// circle of radius r traversed through the angle θ (two components with |c^(n+1)| <= r θ^(n+1)).
double arc_bound(int n, double theta, double r) {
  return std::sqrt(2.0) * r * std::pow(theta, n + 1) / (bpde::factorial(n + 1) * std::pow(4.0, n));
}

TEST(FitBoundary, BezierEdgesOfLowDegreeAreReproducedExactly) {
  // Tensor degree (7, 5): edges of degree 3, 5, 5 and 1 whose end points meet exactly.
  const Eigen::MatrixX3d R = bpde::testing::random_points(20, 11);
  Eigen::MatrixX3d e0 = R.topRows(4), e1 = R.middleRows(4, 6), e2 = R.middleRows(10, 6), e3(2, 3);
  e1.row(0) = e0.row(3);
  e2.row(0) = e1.row(5);
  e3.row(0) = e2.row(5);
  e3.row(1) = e0.row(0);
  BoundaryData d;
  for (const auto& e : {e0, e1, e2, e3}) d.edges.push_back(BoundaryCurve::bezier(e));
  const auto fit = bpde::fit_tensor_boundary(7, 5, d);
  for (const auto& f : fit.edges) {
    EXPECT_EQ(f.method, "elevation");
    EXPECT_LT(f.max_error, 1e-14);
  }
  for (int k = 0; k <= 20; ++k) {
    const double t = k / 20.0;
    EXPECT_LT((fit.net.evaluate(t, 0) - bezier(e0, t)).norm(), 1e-14);
    EXPECT_LT((fit.net.evaluate(1, t) - bezier(e1, t)).norm(), 1e-14);
    EXPECT_LT((fit.net.evaluate(1 - t, 1) - bezier(e2, t)).norm(), 1e-14);
    EXPECT_LT((fit.net.evaluate(0, 1 - t) - bezier(e3, t)).norm(), 1e-14);
  }
  // An edge at the net's degree (edge 1: u = 1, degree m = 5) is copied bit for bit.
  for (int s = 0; s <= 5; ++s) EXPECT_EQ(fit.net.point(7, s), Vector3d(e1.row(s).transpose()));

  // Triangular degree 6: edges of degree 6, 2, 4.
  Eigen::MatrixX3d t0 = R.topRows(7), t1 = R.middleRows(7, 3), t2 = R.middleRows(10, 5);
  t1.row(0) = t0.row(6);
  t2.row(0) = t1.row(2);
  t2.row(4) = t0.row(0);
  BoundaryData g;
  for (const auto& e : {t0, t1, t2}) g.edges.push_back(BoundaryCurve::bezier(e));
  const auto tri = bpde::fit_triangular_boundary(6, g);
  for (int k = 0; k <= 20; ++k) {
    const double t = k / 20.0;
    EXPECT_LT((tri.net.evaluate(t, 0) - bezier(t0, t)).norm(), 1e-14);
    EXPECT_LT((tri.net.evaluate(1 - t, t) - bezier(t1, t)).norm(), 1e-14);
    EXPECT_LT((tri.net.evaluate(0, 1 - t) - bezier(t2, t)).norm(), 1e-14);
  }
  // Interior points are zero: the solvers determine them.
  EXPECT_EQ(tri.net.point(2, 2), Vector3d::Zero());
}

TEST(FitBoundary, ArcErrorConvergesSpectrallyAtTheRemainderBound) {
  // A third of a circle of radius 1.5 (θ = 2π/3): the error is within a factor 2 of the bound
  // for n = 3..12 (below rounding from n = 13 on), so each degree gains a factor θ/(4(n+2)).
  const double theta = 2 * kPi / 3, r = 1.5;
  const BoundaryCurve arc = BoundaryCurve::arc(Vector3d(0, 0, 1), Vector3d(0, 1, 1), r, 0.2, 0.2 + theta);
  double previous = 1;
  for (int n = 3; n <= 12; ++n) {
    const auto f = bpde::fit_edge(arc, n);
    EXPECT_EQ(f.method, "interpolation");
    const double e = bpde::edge_error(arc, f.points);
    const double b = arc_bound(n, theta, r);
    EXPECT_LE(e, b) << n;
    EXPECT_GE(e, 0.5 * b) << n;
    EXPECT_LT(e, 0.15 * previous) << n;
    previous = e;
    // Least squares (8n+1 uniform samples) is as good to a factor 2.
    const auto ls = bpde::fit_edge(arc, n, bpde::FitMethod::LeastSquares);
    EXPECT_EQ(ls.method, "least-squares");
    EXPECT_LT(bpde::edge_error(arc, ls.points), 2 * e) << n;
  }
  EXPECT_LT(bpde::edge_error(arc, bpde::fit_edge(arc, 16).points), 1e-14);
}

TEST(FitBoundary, HelixArcErrorIsTheArcsAndItsRiseIsExact) {
  const double theta = kPi / 2;
  const BoundaryCurve h = BoundaryCurve::helix(Vector3d::Zero(), Vector3d(0, 0, 1), 1, 0, theta, 0.5);
  for (int n : {4, 6, 8, 10}) {
    const auto f = bpde::fit_edge(h, n);
    const double e = bpde::edge_error(h, f.points);
    EXPECT_LE(e, arc_bound(n, theta, 1)) << n;
    EXPECT_GE(e, 0.3 * arc_bound(n, theta, 1)) << n;
    // The rise z = 0.5 a / 2π = t/8 is linear: reproduced to rounding.
    for (double t : {0.1, 0.45, 0.8}) EXPECT_NEAR(bezier(f.points, t).z(), t / 8, 1e-15) << n;
  }
  EXPECT_LT(bpde::edge_error(h, bpde::fit_edge(h, 8).points), 3e-9);
}

TEST(FitBoundary, CornersAreSharedExactlyAndGapsAreRefused) {
  const Vector3d a(0, 0, 0), b(1, 0, 0), c(0, 1, 0), b2 = b + Vector3d(3e-12, -1e-12, 0);
  BoundaryData d;
  d.edges = {BoundaryCurve::segment(a, b), BoundaryCurve::segment(b2, c), BoundaryCurve::segment(c, a)};
  const auto fit = bpde::fit_triangular_boundary(5, d);
  // P_n00 is the corner of edges 0 and 1: the mean of the two end points, bit for bit.
  EXPECT_EQ(fit.net.point(5, 0), Vector3d(0.5 * (b + b2)));
  EXPECT_EQ(fit.net.point(0, 5), c);
  EXPECT_EQ(fit.net.point(0, 0), a);
  EXPECT_LT(fit.edges[0].max_error, 2e-12);  // the corner moved by half the gap
  // A gap of 1e-3 is bad input naming the edges and the gap.
  d.edges[1] = BoundaryCurve::segment(b + Vector3d(0, 1e-3, 0), c);
  try {
    bpde::fit_triangular_boundary(5, d);
    FAIL() << "expected ParameterError";
  } catch (const bpde::ParameterError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("edges 0 and 1 do not meet"), std::string::npos) << m;
    EXPECT_NE(m.find("0.001"), std::string::npos) << m;
  }
  // The tolerance is an option.
  bpde::BoundaryFitOptions o;
  o.corner_tolerance = 1e-2;
  EXPECT_NO_THROW(bpde::fit_triangular_boundary(5, d, o));
  o.corner_tolerance = 0;
  EXPECT_THROW(bpde::fit_triangular_boundary(5, d, o), bpde::ParameterError);
  o.corner_tolerance = 1e-2;  // the gap is allowed: only the angle is wrong
  for (double a : {-1.0, 91.0, std::nan("")}) {
    o.smooth_corner_angle = a;
    try {
      bpde::fit_triangular_boundary(5, d, o);
      ADD_FAILURE() << "expected ParameterError for " << a;
    } catch (const bpde::ParameterError& e) {
      EXPECT_NE(std::string(e.what()).find("smooth_corner_angle"), std::string::npos) << e.what();
    }
  }
}

TEST(FitBoundary, SampledPointsAreFittedByLeastSquares) {
  // 40 samples of a cubic at uneven parameters: the degree-5 fit is the cubic (elevated).
  const Eigen::MatrixX3d P = bpde::testing::random_points(4, 5);
  Eigen::MatrixX3d S(40, 3);
  std::vector<double> t(40);
  for (int i = 0; i < 40; ++i) {
    t[static_cast<size_t>(i)] = std::pow(i / 39.0, 1.5);
    S.row(i) = bezier(P, t[static_cast<size_t>(i)]).transpose();
  }
  const BoundaryCurve c = BoundaryCurve::samples(S, t);
  const auto f = bpde::fit_edge(c, 5);
  EXPECT_EQ(f.method, "least-squares");
  for (double u : {0.0, 0.3, 0.77, 1.0}) EXPECT_LT((bezier(f.points, u) - bezier(P, u)).norm(), 1e-13);
  EXPECT_LT(bpde::edge_error(c, f.points), 1e-13);
  // Chord-length parameters of uniform samples on a segment are uniform: the segment exactly.
  Eigen::MatrixX3d L(9, 3);
  for (int i = 0; i < 9; ++i) L.row(i) = Eigen::RowVector3d(1 + i / 8.0, 2 * i / 8.0, 0);
  const auto g = bpde::fit_edge(BoundaryCurve::samples(L), 4);
  for (double u : {0.1, 0.5, 0.9}) EXPECT_LT((bezier(g.points, u) - Vector3d(1 + u, 2 * u, 0)).norm(), 1e-14);
  // Samples of an arc: least squares converges like the interpolation.
  Eigen::MatrixX3d A(33, 3);
  std::vector<double> ta(33);
  for (int i = 0; i < 33; ++i) {
    ta[static_cast<size_t>(i)] = i / 32.0;
    A.row(i) << std::cos(i / 32.0), std::sin(i / 32.0), 0;
  }
  EXPECT_LT(bpde::edge_error(BoundaryCurve::samples(A, ta), bpde::fit_edge(BoundaryCurve::samples(A, ta), 6).points),
            2 * arc_bound(6, 1.0, 1.0));
  // Fewer samples than the degree needs.
  EXPECT_THROW(bpde::fit_edge(BoundaryCurve::samples(L), 9), bpde::SizeError);
}

TEST(FitBoundary, SamplesWithoutParametersRecoverTheCurveTheyCameFrom) {
  // A cubic sampled at t_k = (k/M)², given without parameters: its chord length is not t, so the
  // least squares at the chord length miss the cubic, and the orthogonal fit (fit_samples.h) finds
  // it and the parameters (unique: a polynomial reparametrisation of degree > 1 leaves degree 3).
  const Eigen::MatrixX3d P = bpde::testing::random_points(4, 7);
  const int M = 40;
  Eigen::MatrixX3d S(M + 1, 3);
  for (int k = 0; k <= M; ++k) S.row(k) = bezier(P, std::pow(static_cast<double>(k) / M, 2)).transpose();
  const BoundaryCurve chord = BoundaryCurve::samples(S, BoundaryCurve::SampleParameters::ChordLength);
  const bpde::CurveFit c = bpde::fit_edge(chord, 3);
  EXPECT_EQ(c.parameters, "chord-length");
  EXPECT_GT(bpde::edge_error(chord, c), 1e-3);
  const BoundaryCurve corrected = BoundaryCurve::samples(S);
  const bpde::CurveFit f = bpde::fit_edge(corrected, 3);
  EXPECT_EQ(f.parameters, "corrected");
  EXPECT_GT(f.corrections, 0);
  EXPECT_LT(bpde::edge_error(corrected, f), 1e-11);
  EXPECT_LT((f.points - P).cwiseAbs().maxCoeff(), 1e-9);
  for (int k = 0; k <= M; ++k) EXPECT_NEAR(f.params(k), std::pow(static_cast<double>(k) / M, 2), 1e-9) << k;
  // The report measures at the corrected parameters; at the chord length the same fit is off.
  EXPECT_GT(bpde::edge_error(corrected, f.points), 1e-3);
  // Not corrected when asked not to (C¹ data: the tangent field is given in the edge's parameter).
  EXPECT_EQ(bpde::fit_edge(corrected, 3, bpde::FitMethod::Interpolation, false).parameters, "chord-length");
  // In a net: corrected with C⁰ data; with C¹ data (tangents, given in the edge's parameter) not.
  Eigen::MatrixX3d E(21, 3);
  for (int k = 0; k <= 20; ++k) {
    const double x = std::pow(k / 20.0, 2);
    E.row(k) << x, 0.2 * x * (1 - x), 0;
  }
  auto seg = [](Vector3d a, Vector3d b) { return BoundaryCurve::segment(a, b); };
  BoundaryData data{{BoundaryCurve::samples(E), seg({1, 0, 0}, {1, 1, 0}), seg({1, 1, 0}, {0, 1, 0}),
                     seg({0, 1, 0}, {0, 0, 0})},
                    {}};
  EXPECT_EQ(bpde::fit_tensor_boundary(4, 4, data).edges[0].parameters, "corrected");
  Eigen::MatrixX3d up(5, 3);
  for (int k = 0; k < 5; ++k) up.row(k) << 0, 1, 0.1 * k * k;
  data.tangents = {BoundaryCurve::samples(up), seg({-1, 0, 0}, {-1, 0, 0}), seg({0, -1, 0}, {0, -1, 0}),
                   seg({1, 0, 0}, {1, 0, 0})};
  const auto c1 = bpde::fit_tensor_boundary(4, 4, data);
  EXPECT_EQ(c1.edges[0].parameters, "chord-length");
  EXPECT_EQ(c1.edges[0].corrections, 0);
  // Given parameters are kept.
  std::vector<double> t(M + 1);
  for (int k = 0; k <= M; ++k) t[static_cast<size_t>(k)] = static_cast<double>(k) / M;
  EXPECT_EQ(bpde::fit_edge(BoundaryCurve::samples(S, t), 3).parameters, "given");
}

TEST(FitBoundary, SamplesOfACurveWithVaryingSpeedKeepTheSpectralConvergence) {
  // A curve whose speed varies along it, sampled uniformly in its own parameter u and given
  // without parameters. Its arc length (so the chord length) is a poor polynomial parameter: the
  // chord-length fit stalls, the corrected one falls with the degree, below even the fit at the
  // true parameters (the orthogonal fit chooses them). Measured (chord length, corrected, true
  // parameters): 3.4e-2, 2.3e-5, 3.6e-3 at n = 8; 1.7e-2, 2.3e-9, 1.1e-5 at n = 12.
  auto sample = [](int M, Eigen::MatrixX3d& S, std::vector<double>& s) {
    S.resize(M + 1, 3);
    s.resize(static_cast<size_t>(M + 1));
    for (int k = 0; k <= M; ++k) {
      const double u = static_cast<double>(k) / M, a = 2.5 * u;
      S.row(k) << std::cos(a) * (1 + 0.4 * std::sin(3 * a)), std::sin(a) * (1 + 0.4 * std::sin(3 * a)), 0.3 * u * u;
      s[static_cast<size_t>(k)] = u;
    }
  };
  Eigen::MatrixX3d S;
  std::vector<double> s;
  sample(200, S, s);
  const BoundaryCurve chord = BoundaryCurve::samples(S, BoundaryCurve::SampleParameters::ChordLength);
  const BoundaryCurve corrected = BoundaryCurve::samples(S);
  const BoundaryCurve given = BoundaryCurve::samples(S, s);
  for (int n : {8, 12}) {
    const double ec = bpde::edge_error(chord, bpde::fit_edge(chord, n));
    const double ef = bpde::edge_error(corrected, bpde::fit_edge(corrected, n));
    const double eg = bpde::edge_error(given, bpde::fit_edge(given, n));
    char buf[96];
    std::snprintf(buf, sizeof buf, "%.2g %.2g %.2g", ec, ef, eg);
    RecordProperty("n" + std::to_string(n), buf);
    EXPECT_LT(ef, 2 * eg) << n;    // as good as the true parameters (orthogonal: at most their error)
    EXPECT_LT(ef, 1e-2 * ec) << n;  // and far below the chord length's
  }
  // More samples than the ladder takes (fit_samples.cpp: 2049, the rest interpolated, then 20
  // iterations over all): the same accuracy.
  sample(6000, S, s);
  const BoundaryCurve many = BoundaryCurve::samples(S);
  const bpde::CurveFit f = bpde::fit_edge(many, 12);
  EXPECT_EQ(f.parameters, "corrected");
  EXPECT_LT(bpde::edge_error(many, f), 1e-8);
}

TEST(FitBoundary, ManySamplesAreFittedAtTheHighestDegrees) {
  // 1000 and 100000 samples of a helix fitted at degree 50 and at the largest net degree: the
  // Bernstein matrix's condition (about 2^n) puts singular values below 1e-12 of the largest from
  // n = 47 on, yet n − 1 distinct inner parameters determine the fit (fit_samples.h,
  // "Conditioning"). The fit must be the helix to rounding: at these degrees the helix's
  // polynomial approximation error (3 rad, Chebyshev remainder) is far below 1e-15, so the
  // distance from the helix is the fit's numerical error alone (measured up to 1e-13).
  auto helix = [](double u) { return Vector3d(std::cos(3 * u), std::sin(3 * u), 0.9 * u); };
  for (int M : {999, 99999}) {
    Eigen::MatrixX3d S(M + 1, 3);
    std::vector<double> s(static_cast<size_t>(M + 1));
    for (int k = 0; k <= M; ++k) {
      s[static_cast<size_t>(k)] = static_cast<double>(k) / M;
      S.row(k) = helix(s[static_cast<size_t>(k)]).transpose();
    }
    const BoundaryCurve given = BoundaryCurve::samples(S, s);
    for (int n : {50, bpde::kMaxDegree}) {
      const bpde::CurveFit f = bpde::fit_edge(given, n);
      double worst = 0;
      for (int k = 0; k <= 256; ++k) worst = std::max(worst, (bezier(f.points, k / 256.0) - helix(k / 256.0)).norm());
      EXPECT_LT(worst, 1e-11) << M + 1 << " samples, degree " << n;
    }
  }
  // Without parameters (the chord length, corrected by the orthogonal fit): the fit passes the
  // samples to rounding at its parameters, and its points lie on the helix.
  Eigen::MatrixX3d S(1000, 3);
  for (int k = 0; k < 1000; ++k) S.row(k) = helix(k / 999.0).transpose();
  const BoundaryCurve corrected = BoundaryCurve::samples(S);
  for (int n : {50, bpde::kMaxDegree}) {
    const bpde::CurveFit f = bpde::fit_edge(corrected, n);
    EXPECT_LT(bpde::edge_error(corrected, f), 1e-11) << n;
    for (int k = 0; k <= 16; ++k) {
      const Vector3d x = bezier(f.points, k / 16.0);
      // On the helix: radius 1 about the z axis, and the angle 3u where u = z / 0.9.
      EXPECT_NEAR(std::hypot(x(0), x(1)), 1.0, 1e-10) << n;
      EXPECT_NEAR(std::cos(x(2) / 0.3), x(0), 1e-9) << n;
    }
  }
  // Fewer distinct inner parameters than n − 1 still do not determine the fit.
  Eigen::MatrixX3d few(51, 3);
  std::vector<double> tf(51);
  for (int k = 0; k <= 50; ++k) {
    tf[static_cast<size_t>(k)] = k / 50.0;
    few.row(k) = helix(tf[static_cast<size_t>(k)]).transpose();
  }
  EXPECT_THROW(bpde::least_squares_at(51, Eigen::Map<const Eigen::VectorXd>(tf.data(), 51), few), bpde::SizeError);
  Eigen::VectorXd twice(52);
  Eigen::MatrixX3d q2(52, 3);
  for (int k = 0; k < 52; ++k) {
    twice(k) = k < 26 ? k / 50.0 : (k - 1) / 50.0;  // 0.5 twice: 49 distinct inside (0,1)
    q2.row(k) = helix(twice(k)).transpose();
  }
  EXPECT_THROW(bpde::least_squares_at(51, twice, q2), bpde::ParameterError);
  EXPECT_NO_THROW(bpde::least_squares_at(50, twice, q2));
}

TEST(FitBoundary, TensorC1RingFromTangentFields) {
  // The boundary and the inward cross derivatives of a random polynomial patch reproduce its
  // outer two rings (interpolation of polynomials of the net's degree is exact).
  const bpde::TensorNet X(5, 4, bpde::testing::random_points(30, 3));
  BoundaryData d;
  d.edges = {BoundaryCurve::function([&](double t) { return X.evaluate(t, 0); }),
             BoundaryCurve::function([&](double t) { return X.evaluate(1, t); }),
             BoundaryCurve::function([&](double t) { return X.evaluate(1 - t, 1); }),
             BoundaryCurve::function([&](double t) { return X.evaluate(0, 1 - t); })};
  d.tangents = {BoundaryCurve::function([&](double t) { return X.derivative(t, 0, 0, 1); }),
                BoundaryCurve::function([&](double t) { return Vector3d(-X.derivative(1, t, 1, 0)); }),
                BoundaryCurve::function([&](double t) { return Vector3d(-X.derivative(1 - t, 1, 0, 1)); }),
                BoundaryCurve::function([&](double t) { return X.derivative(0, 1 - t, 1, 0); })};
  const auto fit = bpde::fit_tensor_boundary(5, 4, d);
  for (int r : X.fixed_indices(bpde::FixedSet::BoundaryAdjacent))
    EXPECT_LT((fit.net.points().row(r) - X.points().row(r)).norm(), 1e-12) << r;
  for (int r : X.free_indices(bpde::FixedSet::BoundaryAdjacent)) EXPECT_EQ(fit.net.points().row(r).norm(), 0.0);
  for (const auto& e : fit.edges) {
    ASSERT_TRUE(e.tangent_max_error);
    EXPECT_LT(*e.tangent_max_error, 1e-11);
    EXPECT_EQ(*e.tangent_method, "interpolation");
  }
  // A tangent field that disagrees at a corner shows in the reported tangent error.
  d.tangents[0] =
      BoundaryCurve::function([&](double t) { return Vector3d(X.derivative(t, 0, 0, 1) + Vector3d(0, 0, 1)); });
  const auto bad = bpde::fit_tensor_boundary(5, 4, d);
  EXPECT_GT(*bad.edges[0].tangent_max_error, 0.5);
  // Tangents for some edges only.
  d.tangents.pop_back();
  EXPECT_THROW(bpde::fit_tensor_boundary(5, 4, d), bpde::SizeError);
}

TEST(FitBoundary, TriangularC1RingFromTangentFields) {
  // Edge 0: x_v; edge 1: -x_u; edge 2: x_u - x_v (towards the opposite corner).
  const bpde::TriangularNet X(6, bpde::testing::random_points(28, 4));
  BoundaryData d;
  d.edges = {BoundaryCurve::function([&](double t) { return X.evaluate(t, 0); }),
             BoundaryCurve::function([&](double t) { return X.evaluate(1 - t, t); }),
             BoundaryCurve::function([&](double t) { return X.evaluate(0, 1 - t); })};
  d.tangents = {BoundaryCurve::function([&](double t) { return X.derivative(t, 0, 0, 1); }),
                BoundaryCurve::function([&](double t) { return Vector3d(-X.derivative(1 - t, t, 1, 0)); }),
                BoundaryCurve::function(
                    [&](double t) { return Vector3d(X.derivative(0, 1 - t, 1, 0) - X.derivative(0, 1 - t, 0, 1)); })};
  const auto fit = bpde::fit_triangular_boundary(6, d);
  for (int r : X.fixed_indices(bpde::FixedSet::BoundaryAdjacent))
    EXPECT_LT((fit.net.points().row(r) - X.points().row(r)).norm(), 1e-12) << r;
  for (int r : X.free_indices(bpde::FixedSet::BoundaryAdjacent)) EXPECT_EQ(fit.net.points().row(r).norm(), 0.0);
  for (const auto& e : fit.edges) EXPECT_LT(*e.tangent_max_error, 1e-11);
}

TEST(FitBoundary, CircleThreeArcsCurvesAreTheReferenceNet) {
  // The reference net fits edges 1 and 2 in the opposite direction: the same interpolant, whose
  // control points agree to the collocation's rounding (growing with n), the curves to 1e-15.
  // Kept as fitted (smooth_corner_angle 0): the joined corners are tested below.
  bpde::BoundaryFitOptions kept;
  kept.smooth_corner_angle = 0;
  for (int n = 3; n <= 12; ++n) {
    const auto fit = bpde::fit_triangular_boundary(n, bpde::circle_three_arcs_curves(), kept);
    const bpde::TriangularNet ref = bpde::circle_three_arcs(n);
    EXPECT_LT((fit.net.points() - ref.points()).cwiseAbs().maxCoeff(), n <= 6 ? 1e-14 : 1e-12) << n;
    for (int k = 0; k <= 16; ++k) {
      const double t = k / 16.0;
      for (const auto& uv : {Eigen::Vector2d(t, 0), Eigen::Vector2d(1 - t, t), Eigen::Vector2d(0, t)})
        EXPECT_LT((fit.net.evaluate(uv(0), uv(1)) - ref.evaluate(uv(0), uv(1))).norm(), 2e-15) << n;
    }
  }
  // Any plane, radius and center: the corners lie on that circle.
  const Vector3d c(1, 2, 3), N = Vector3d(1, 1, 0).normalized();
  const auto fit = bpde::fit_triangular_boundary(6, bpde::circle_three_arcs_curves(2.5, c, N));
  for (const Vector3d& p : {fit.net.point(6, 0), fit.net.point(0, 6), fit.net.point(0, 0)}) {
    EXPECT_NEAR((p - c).norm(), 2.5, 1e-14);
    EXPECT_NEAR((p - c).dot(N), 0.0, 1e-14);
  }
}

// The sine of the angle between the legs of a net's edges at a corner: the end leg of one edge
// and the start leg of the next, and the cosine (1 where they continue each other).
std::pair<double, double> corner_legs(const Eigen::MatrixX3d& in, const Eigen::MatrixX3d& out) {
  const Eigen::Index k = in.rows() - 1;
  const Vector3d a = (in.row(k) - in.row(k - 1)).transpose().normalized();
  const Vector3d b = (out.row(1) - out.row(0)).transpose().normalized();
  return {a.cross(b).norm(), a.dot(b)};
}

// The edges of a triangular net as Bézier polygons in the edge order of fit_boundary.h.
std::vector<Eigen::MatrixX3d> triangular_edges(const bpde::TriangularNet& net) {
  const int n = net.n();
  std::vector<Eigen::MatrixX3d> e(3, Eigen::MatrixX3d(n + 1, 3));
  for (int s = 0; s <= n; ++s) {
    e[0].row(s) = net.point(s, 0).transpose();
    e[1].row(s) = net.point(n - s, s).transpose();
    e[2].row(s) = net.point(0, n - s).transpose();
  }
  return e;
}

TEST(FitBoundary, CornersWhereTheCurveIsSmoothAreJoinedG1) {
  // The circle in three arcs: the arcs give their tangents exactly and continue each other, so
  // every corner is joined: the legs are collinear to rounding, where the plain interpolants met
  // at 180° only up to their error (0.84° at n = 4). The joined fit stays within 3x the
  // interpolation's own error (the remainder bound of arc_bound).
  bpde::BoundaryFitOptions kept;
  kept.smooth_corner_angle = 0;
  for (int n = 3; n <= 14; ++n) {
    const auto fit = bpde::fit_triangular_boundary(n, bpde::circle_three_arcs_curves());
    const auto plain = bpde::fit_triangular_boundary(n, bpde::circle_three_arcs_curves(), kept);
    const auto e = triangular_edges(fit.net), p = triangular_edges(plain.net);
    for (int c = 0; c < 3; ++c) {
      const auto [sin_joined, cos_joined] = corner_legs(e[c], e[(c + 1) % 3]);
      EXPECT_LT(sin_joined, 1e-14) << n << " corner " << c;
      EXPECT_GT(cos_joined, 0.0);
      EXPECT_EQ(fit.edges[c].end_corner, "g1");
      EXPECT_EQ(plain.edges[c].end_corner, "kept");
      // The turn reported is that of the plain fit.
      const double turn = std::asin(corner_legs(p[c], p[(c + 1) % 3]).first) * 180 / kPi;
      EXPECT_NEAR(*fit.edges[c].end_corner_turn, turn, 1e-9 * std::max(1.0, turn)) << n;
      EXPECT_NEAR(*plain.edges[c].end_corner_turn, turn, 1e-9 * std::max(1.0, turn)) << n;
      EXPECT_LT(fit.edges[c].max_error, 3 * arc_bound(n, 2 * kPi / 3, 1.0) + 1e-15) << n;
      EXPECT_LT(fit.edges[c].max_error, 3 * plain.edges[c].max_error + 1e-15) << n;
    }
    if (n == 4) {
      EXPECT_NEAR(*plain.edges[0].end_corner_turn, 0.841, 1e-3);
    }
  }

  // Samples of a smooth closed curve (no exact tangents: the estimated tier) cut into three edges
  // at uneven places: joined, and the largest edge error stays within 3x the unjoined one
  // (measured ×1.35, ×1.45, ×0.8, ×1.08 at n = 5, 7, 9, 12; an edge alone may lose more, ×14 at
  // n = 12, where its own error was far below the others').
  auto curve = [](double a) {
    return Vector3d((1 + 0.2 * std::cos(3 * a)) * std::cos(a), (1 + 0.2 * std::cos(3 * a)) * std::sin(a),
                    0.3 * std::sin(2 * a));
  };
  const double cuts[4] = {0.3, 2.0, 4.4, 0.3 + 2 * kPi};
  BoundaryData samples;
  for (int e = 0; e < 3; ++e) {
    Eigen::MatrixX3d q(61, 3);
    for (int k = 0; k <= 60; ++k) q.row(k) = curve(cuts[e] + (cuts[e + 1] - cuts[e]) * k / 60.0).transpose();
    samples.edges.push_back(BoundaryCurve::samples(q));
  }
  for (int n : {5, 7, 9, 12}) {
    const auto fit = bpde::fit_triangular_boundary(n, samples);
    const auto plain = bpde::fit_triangular_boundary(n, samples, kept);
    const auto e = triangular_edges(fit.net);
    double joined_max = 0, plain_max = 0;
    for (int c = 0; c < 3; ++c) {
      EXPECT_EQ(fit.edges[c].end_corner, "g1") << n;
      EXPECT_GT(*plain.edges[c].end_corner_turn, 1e-7) << n;  // a turn the join removed
      const auto [sin_joined, cos_joined] = corner_legs(e[c], e[(c + 1) % 3]);
      EXPECT_LT(sin_joined, 1e-14) << n;
      EXPECT_GT(cos_joined, 0.0) << n;
      // The parameters were corrected again under the constraint.
      EXPECT_EQ(fit.edges[c].parameters, "corrected");
      EXPECT_GT(*fit.edges[c].corrections, *plain.edges[c].corrections) << n;
      joined_max = std::max(joined_max, fit.edges[c].max_error);
      plain_max = std::max(plain_max, plain.edges[c].max_error);
    }
    EXPECT_LT(joined_max, 3 * plain_max) << n;
  }

  // Kept: a real corner (the three arcs of a sphere octant meet at 90°); a deliberate kink of
  // 0.5° between exact arcs (below the 2° of the estimated tier, but the tangents are exact);
  // and a degree too low to move a leg (2).
  BoundaryData octant;
  octant.edges.push_back(BoundaryCurve::arc(Vector3d::Zero(), Vector3d::UnitZ(), 1, 0, kPi / 2));
  octant.edges.push_back(BoundaryCurve::arc(Vector3d::Zero(), Vector3d::UnitX(), 1, 0, kPi / 2, Vector3d::UnitY()));
  octant.edges.push_back(BoundaryCurve::arc(Vector3d::Zero(), Vector3d::UnitY(), 1, 0, kPi / 2, Vector3d::UnitZ()));
  const auto oct = bpde::fit_triangular_boundary(6, octant);
  for (int c = 0; c < 3; ++c) {
    EXPECT_EQ(oct.edges[c].end_corner, "kept");
    EXPECT_NEAR(*oct.edges[c].end_corner_turn, 90.0, 0.5);
  }
  const double kink = 0.5 * kPi / 180;  // the second arc starts turned by 0.5°
  BoundaryData kinked;
  kinked.edges.push_back(BoundaryCurve::arc(Vector3d::Zero(), Vector3d::UnitZ(), 1, 0, 2.0));
  const Vector3d p = kinked.edges[0].end(), t = kinked.edges[0].exact_tangent(true)->normalized();
  const Vector3d t2 = std::cos(kink) * t + std::sin(kink) * Vector3d::UnitZ().cross(t);
  // A segment along t2, then a Bézier curve back to the start.
  kinked.edges.push_back(BoundaryCurve::segment(p, p + 0.8 * t2));
  Eigen::MatrixX3d back(3, 3);
  back.row(0) = (p + 0.8 * t2).transpose();
  back.row(1) = Vector3d(-1, -1, 0.5).transpose();
  back.row(2) = kinked.edges[0].start().transpose();
  kinked.edges.push_back(BoundaryCurve::bezier(back));
  const auto kf = bpde::fit_triangular_boundary(8, kinked);
  EXPECT_EQ(kf.edges[0].end_corner, "kept");
  EXPECT_NEAR(*kf.edges[0].end_corner_turn, 0.5, 1e-4);  // the fitted arc turns by 1.5e-5° less
  const auto low = bpde::fit_triangular_boundary(2, bpde::circle_three_arcs_curves());
  for (const auto& f : low.edges) EXPECT_EQ(f.end_corner, "kept");
}

// The largest distance of a Bézier polygon's points from the circle |x − c| = r in the plane
// through c normal to N, and the mean of |x − c| − r over the angle swept (the trapezoidal rule on
// 4001 points): measured on the curve, not on the fit's parameters.
std::pair<double, double> circle_deviation(const Eigen::MatrixX3d& P, const Vector3d& c, const Vector3d& N, double r) {
  constexpr int kPoints = 4000;
  double worst = 0, sum = 0, swept = 0;
  Vector3d prev = bezier(P, 0) - c;
  double dev_prev = prev.norm() - r;
  for (int k = 0; k <= kPoints; ++k) {
    const Vector3d x = bezier(P, static_cast<double>(k) / kPoints) - c;
    const double dev = std::hypot(x.norm() - r, x.dot(N));
    worst = std::max(worst, dev);
    if (k > 0) {
      const double dphi = std::atan2(prev.cross(x).norm(), prev.dot(x));
      sum += 0.5 * (dev_prev + (x.norm() - r)) * dphi;
      swept += dphi;
    }
    prev = x;
    dev_prev = x.norm() - r;
  }
  return {worst, sum / swept};
}

TEST(FitBoundary, JoinedCurvesAreFittedGeometrically) {
  // A curve's edges refitted at a joined corner have their rows' parameters corrected under the
  // constraint (the orthogonal least squares of fit_samples.h): the end legs along the tangent
  // and every other freedom of the polynomial spent on the distance to the circle, not on the
  // angle parametrisation. Measured on the circle of radius 2.5 in a tilted plane, in three arcs,
  // against the plain interpolants (smooth_corner_angle 0): the largest distance from the circle
  // falls ×63 (n = 4), ×4300 (5), ×4.9e4 (6), ×5800 (7), ×8.8e4 (8), and the mean over the angle,
  // which the area of a spanning surface follows, ×110, ×48, ×1.9e4, ×390, ×2e4. The parametric
  // least squares with the same constraint (the join before the correction) was worse than the
  // interpolants in the mean (×126 at n = 5: docs/boundaries.md). Bounds: ×20 on both, down to
  // rounding.
  const Vector3d c(1, 2, 3), N = Vector3d(1, 1, 0).normalized();
  const double r = 2.5;
  bpde::BoundaryFitOptions kept;
  kept.smooth_corner_angle = 0;
  for (int n = 4; n <= 10; ++n) {
    const auto fit = bpde::fit_triangular_boundary(n, bpde::circle_three_arcs_curves(r, c, N));
    const auto plain = bpde::fit_triangular_boundary(n, bpde::circle_three_arcs_curves(r, c, N), kept);
    const auto e = triangular_edges(fit.net), p = triangular_edges(plain.net);
    for (int k = 0; k < 3; ++k) {
      const auto [dist, mean] = circle_deviation(e[k], c, N, r);
      const auto [dist_plain, mean_plain] = circle_deviation(p[k], c, N, r);
      EXPECT_LT(dist, std::max(dist_plain / 20, 2e-14)) << n << " edge " << k;
      EXPECT_LT(std::abs(mean), std::max(std::abs(mean_plain) / 20, 2e-15)) << n << " edge " << k;
      EXPECT_EQ(fit.edges[k].end_corner, "g1");
      EXPECT_EQ(fit.edges[k].method, "geometric");
      EXPECT_EQ(fit.edges[k].parameters, "corrected");
      EXPECT_GT(*fit.edges[k].corrections, 0);
      EXPECT_FALSE(plain.edges[k].parameters.has_value());
      // The reported error is the distance from the curve to the fit (the circle's points to their
      // foot points), which on a circle is the distance of the fit from it, to first order.
      EXPECT_LE(fit.edges[k].max_error, 1.05 * dist + 4e-15) << n << " edge " << k;
      EXPECT_GE(fit.edges[k].max_error, 0.8 * dist - 4e-15) << n << " edge " << k;
    }
  }
}

// The distance from the point x to the Bézier curve P: the nearest of 4001 points of the curve,
// then golden-section search on the distance between its neighbours.
double distance_to_bezier(const Eigen::MatrixX3d& P, const Vector3d& x) {
  constexpr int kPoints = 4000;
  int best = 0;
  double d = INFINITY;
  for (int k = 0; k <= kPoints; ++k) {
    const double dk = (bezier(P, static_cast<double>(k) / kPoints) - x).norm();
    if (dk < d) d = dk, best = k;
  }
  double a = std::max(0, best - 1) / static_cast<double>(kPoints),
         b = std::min(kPoints, best + 1) / static_cast<double>(kPoints);
  const double gr = 0.5 * (std::sqrt(5.0) - 1);
  for (int it = 0; it < 80; ++it) {
    const double x1 = b - gr * (b - a), x2 = a + gr * (b - a);
    if ((bezier(P, x1) - x).norm() <= (bezier(P, x2) - x).norm())
      b = x2;
    else
      a = x1;
  }
  return std::min(d, (bezier(P, 0.5 * (a + b)) - x).norm());
}

TEST(FitBoundary, JoinedFunctionsReportTheirDistanceFromTheCurve) {
  // A smooth closed space curve given as three functions (the estimated tier: tangents from
  // finite differences), joined at its three corners and fitted geometrically: the reported
  // max_error is the largest distance from the curve's points to the fit, checked here by brute
  // force on 257 points of each edge. The largest over the edges is below the plain
  // interpolants' (measured 3.9e-3, 9.2e-5, 7.3e-7 against 1.2e-2, 4.2e-4, 2.4e-6 at n = 6, 9, 12;
  // the join without the correction: 1.5e-2, 2.5e-4, 2.4e-6); one edge alone may lose (edge 0 at
  // n = 12: 5.5e-7 against 3.7e-8, where the other edges' plain error was 1e-6 anyway).
  auto curve = [](double a) {
    return Vector3d((1 + 0.2 * std::cos(3 * a)) * std::cos(a), (1 + 0.2 * std::cos(3 * a)) * std::sin(a),
                    0.3 * std::sin(2 * a));
  };
  const double cuts[4] = {0.3, 2.0, 4.4, 0.3 + 2 * kPi};
  BoundaryData d;
  for (int e = 0; e < 3; ++e)
    d.edges.push_back(BoundaryCurve::function([=](double t) { return curve(cuts[e] + (cuts[e + 1] - cuts[e]) * t); }));
  bpde::BoundaryFitOptions kept;
  kept.smooth_corner_angle = 0;
  for (int n : {6, 9, 12}) {
    const auto fit = bpde::fit_triangular_boundary(n, d), plain = bpde::fit_triangular_boundary(n, d, kept);
    const auto e = triangular_edges(fit.net), p = triangular_edges(plain.net);
    double largest = 0, largest_plain = 0;
    for (int k = 0; k < 3; ++k) {
      EXPECT_EQ(fit.edges[k].end_corner, "g1") << n;
      EXPECT_EQ(fit.edges[k].parameters, "corrected") << n;
      double dist = 0, dist_plain = 0;
      for (int j = 0; j <= 256; ++j) {
        const Vector3d c = d.edges[k].evaluate(j / 256.0);
        dist = std::max(dist, distance_to_bezier(e[k], c));
        dist_plain = std::max(dist_plain, distance_to_bezier(p[k], c));
      }
      EXPECT_NEAR(fit.edges[k].max_error, dist, 0.02 * dist + 1e-14) << n << " edge " << k;
      largest = std::max(largest, dist);
      largest_plain = std::max(largest_plain, dist_plain);
    }
    EXPECT_LT(largest, largest_plain) << n;
  }
}

TEST(FitBoundary, GeometricFitFollowsTheCurveNotItsParametrisation) {
  // fit "geometric": the orthogonal least squares over the curve's points at 4n+1
  // Chebyshev–Lobatto nodes. Its distance from the curve (brute force, distance_to_bezier on 257
  // points) against the interpolant's, measured: a 120° arc 1.4e-8 against 1.1e-4 (n = 5),
  // 4.3e-11 against 3.5e-6 (n = 6), 2.9e-13 against 1.3e-8 (8); a catenoid's edge (the w = 0
  // edge of the tests' piece) 1.9e-6 against 9.4e-4 (5), 2.0e-8 against 3.6e-4 (6), 2.6e-10
  // against 6.3e-5 (8); a helix-like space curve 1.4e-5 against 9.2e-4 (5), 1.2e-10 against
  // 4.6e-7 (8). Bound: ×30 below the interpolant. The reported max_error is that distance.
  auto catenoid = [](double u, double v) {
    const double th = 1.2 * u + 0.4 * v, rho = 1.1 + 0.8 * v;
    return Vector3d(rho * std::cos(th), rho * std::sin(th), std::acosh(rho));
  };
  const std::vector<BoundaryCurve> curves = {
      BoundaryCurve::arc(Vector3d::Zero(), Vector3d::UnitZ(), 1, 0, 2 * kPi / 3),
      BoundaryCurve::function([=](double t) { return catenoid(1 - t, t); }),
      BoundaryCurve::function([](double t) { return Vector3d(std::cos(3 * t), std::sin(3 * t), 0.5 * t * t); })};
  for (size_t c = 0; c < curves.size(); ++c)
    for (int n : {5, 6, 8}) {
      const auto g = bpde::fit_edge(curves[c], n, bpde::FitMethod::Geometric);
      const auto p = bpde::fit_edge(curves[c], n, bpde::FitMethod::Interpolation);
      EXPECT_EQ(g.method, "geometric");
      EXPECT_EQ(g.parameters, "corrected");
      EXPECT_GT(g.corrections, 0);
      EXPECT_EQ(g.points.row(0), curves[c].evaluate(0).transpose());
      EXPECT_EQ(g.points.row(n), curves[c].evaluate(1).transpose());
      double dist = 0, dist_p = 0;
      for (int j = 0; j <= 256; ++j) {
        const Vector3d x = curves[c].evaluate(j / 256.0);
        dist = std::max(dist, distance_to_bezier(g.points, x));
        dist_p = std::max(dist_p, distance_to_bezier(p.points, x));
      }
      // the table of docs/boundaries.md, "Geometric fits" (scripts/geometric_fit_table.py)
      std::printf("geometric fit: curve %zu n = %d interpolation %.1e geometric %.1e\n", c, n, dist_p, dist);
      EXPECT_LT(dist, dist_p / 30) << c << " n = " << n;
      EXPECT_NEAR(bpde::edge_error(curves[c], g), dist, 0.02 * dist + 1e-14) << c << " n = " << n;
    }
  // In a net: every edge geometric and reported so; with C¹ data the tangent fields are given in
  // the edges' parameter, so the edges are interpolated (as the tangents are).
  bpde::BoundaryFitOptions geo;
  geo.method = bpde::FitMethod::Geometric;
  geo.smooth_corner_angle = 0;
  BoundaryData d;
  d.edges.push_back(BoundaryCurve::function([=](double t) { return catenoid(t, 0); }));
  d.edges.push_back(BoundaryCurve::function([=](double t) { return catenoid(1 - t, t); }));
  d.edges.push_back(BoundaryCurve::function([=](double t) { return catenoid(0, 1 - t); }));
  const auto fit = bpde::fit_triangular_boundary(6, d, geo);
  for (const auto& e : fit.edges) {
    EXPECT_EQ(e.method, "geometric");
    EXPECT_EQ(e.parameters, "corrected");
  }
  BoundaryData c1 = d;
  const double h = 1e-6;
  c1.tangents.push_back(
      BoundaryCurve::function([=](double t) { return Vector3d((catenoid(t, h) - catenoid(t, 0)) / h); }));
  c1.tangents.push_back(
      BoundaryCurve::function([=](double t) { return Vector3d((catenoid(1 - t - h, t) - catenoid(1 - t, t)) / h); }));
  c1.tangents.push_back(
      BoundaryCurve::function([=](double t) { return Vector3d((catenoid(h, 1 - t - h) - catenoid(0, 1 - t)) / h); }));
  const auto fit1 = bpde::fit_triangular_boundary(6, c1, geo);
  for (const auto& e : fit1.edges) {
    EXPECT_EQ(e.method, "interpolation");
    EXPECT_FALSE(e.parameters.has_value());
    EXPECT_EQ(*e.tangent_method, "interpolation");
  }
  // With the G¹ join (the circle's arcs meet smoothly): refitted under the constraint from the
  // least squares at the nodes, still reported geometric, and its correction's iterations added
  // to the edge's own; as near the circle as the joined interpolants' refit.
  bpde::BoundaryFitOptions geo_joined;
  geo_joined.method = bpde::FitMethod::Geometric;
  for (int n : {5, 8}) {
    const auto j = bpde::fit_triangular_boundary(n, bpde::circle_three_arcs_curves(), geo_joined);
    const auto i = bpde::fit_triangular_boundary(n, bpde::circle_three_arcs_curves());
    const auto own = bpde::fit_edge(curves[0], n, bpde::FitMethod::Geometric);
    for (int k = 0; k < 3; ++k) {
      EXPECT_EQ(j.edges[k].end_corner, "g1");
      EXPECT_EQ(j.edges[k].method, "geometric");
      EXPECT_EQ(i.edges[k].method, "geometric");
      EXPECT_GT(*j.edges[k].corrections, own.corrections) << n;
      EXPECT_LT(j.edges[k].max_error, 2 * i.edges[k].max_error + 1e-15) << n;
    }
  }
  // Degree 1 is the chord whatever the fit; degree 2 is corrected; at degree 64 the nodes' least
  // squares is rank deficient to the QR threshold and the interpolant (at rounding) is returned.
  EXPECT_EQ(bpde::fit_edge(curves[0], 1, bpde::FitMethod::Geometric).method, "interpolation");
  const auto q = bpde::fit_edge(curves[0], 2, bpde::FitMethod::Geometric);
  EXPECT_EQ(q.method, "geometric");
  EXPECT_LT(bpde::edge_error(curves[0], q), 0.5 * bpde::edge_error(curves[0], bpde::fit_edge(curves[0], 2)));
  const auto hd = bpde::fit_edge(curves[0], 64, bpde::FitMethod::Geometric);
  EXPECT_LT(bpde::edge_error(curves[0], hd), 1e-13) << hd.method;
}

// A corner between an exact tangent and an estimated one takes the exact direction; an exactly
// elevated Bézier curve at a joined corner has its leg projected (it moves only by rounding where
// its tangent is the other curve's). The unit circle as an arc (edge 0), samples (edge 1) and the
// cubic Bézier quarter-circle construction over the last third (edge 2: end tangents exact).
TEST(FitBoundary, MixedCornersTakeTheExactTangent) {
  const double a0 = 4 * kPi / 3, third = 2 * kPi / 3;
  auto circle = [](double a) { return Vector3d(std::cos(a), std::sin(a), 0); };
  BoundaryData d;
  d.edges.push_back(BoundaryCurve::arc(Vector3d::Zero(), Vector3d::UnitZ(), 1, a0, a0 + third));  // to angle 0
  Eigen::MatrixX3d q(41, 3);
  for (int k = 0; k <= 40; ++k) q.row(k) = circle(third * k / 40.0).transpose();
  d.edges.push_back(BoundaryCurve::samples(q));    // angle 0 to 2π/3
  const double h = 4.0 / 3 * std::tan(third / 4);  // the cubic's handle for a circular arc
  Eigen::MatrixX3d B(4, 3);
  B.row(0) = circle(third).transpose();
  B.row(1) = (circle(third) + h * Vector3d(-std::sin(third), std::cos(third), 0)).transpose();
  B.row(2) = (circle(a0) - h * Vector3d(-std::sin(a0), std::cos(a0), 0)).transpose();
  B.row(3) = circle(a0).transpose();
  d.edges.push_back(BoundaryCurve::bezier(B));  // 2π/3 to 4π/3
  const int n = 6;
  bpde::BoundaryFitOptions kept;
  kept.smooth_corner_angle = 0;
  const auto fit = bpde::fit_triangular_boundary(n, d), plain = bpde::fit_triangular_boundary(n, d, kept);
  const auto e = triangular_edges(fit.net), p = triangular_edges(plain.net);
  for (int c = 0; c < 3; ++c) {
    EXPECT_EQ(fit.edges[c].end_corner, "g1") << c;
    const auto [sn, cs] = corner_legs(e[c], e[(c + 1) % 3]);
    EXPECT_LT(sn, 1e-14) << c;
    EXPECT_GT(cs, 0.0) << c;
  }
  // The samples' legs lie along the circle's tangent at angles 0 and 2π/3 (the exact neighbours').
  const Vector3d t0 = (e[1].row(1) - e[1].row(0)).transpose(), t1 = (e[1].row(n) - e[1].row(n - 1)).transpose();
  EXPECT_LT(t0.normalized().cross(Vector3d(0, 1, 0)).norm(), 1e-14);
  EXPECT_LT(t1.normalized().cross(Vector3d(-std::sin(third), std::cos(third), 0)).norm(), 1e-14);
  // The elevated cubic is kept to rounding; the arc and the samples were fitted again.
  EXPECT_EQ(fit.edges[2].method, "elevation");
  EXPECT_LT((e[2] - p[2]).cwiseAbs().maxCoeff(), 1e-15);
  EXPECT_EQ(fit.edges[0].method, "geometric");  // the arc's interpolant, refitted geometrically
  EXPECT_EQ(plain.edges[0].method, "interpolation");
  EXPECT_GT((e[0] - p[0]).cwiseAbs().maxCoeff(), 1e-9);
  EXPECT_GT((e[1] - p[1]).cwiseAbs().maxCoeff(), 1e-9);
}

// A corner that counts as smooth but that no fit with collinear legs can take is kept: a square
// whose edges are samples of arcs bulging by 10° turns by 70° at each corner; asked to join
// corners up to 75°, the constrained fits turn a leg around (checked once with a print in the
// pass loop: single corners and pairs are dropped over several passes), every corner is kept, and
// the net is the plain fit bit for bit (no edge keeps a refit made under a dropped constraint).
TEST(FitBoundary, ACornerNoCollinearFitCanTakeIsKept) {
  const Eigen::Vector2d C[4] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
  BoundaryData d;
  for (int e = 0; e < 4; ++e) {
    const Eigen::Vector2d p = C[e], q = C[(e + 1) % 4], mid = 0.5 * (p + q), dir = (q - p).normalized();
    const Eigen::Vector2d out(dir.y(), -dir.x());  // outward for the counter-clockwise square
    const double s = 10 * kPi / 180, R = 0.5 * (q - p).norm() / std::sin(s);
    const Eigen::Vector2d c = mid - out * R * std::cos(s);
    const double a0 = std::atan2(p.y() - c.y(), p.x() - c.x());
    Eigen::MatrixX3d pts(41, 3);
    for (int k = 0; k <= 40; ++k) {
      const double a = a0 + 2 * s * k / 40.0;
      pts.row(k) << c.x() + R * std::cos(a), c.y() + R * std::sin(a), 0;
    }
    pts.row(0) << p.x(), p.y(), 0;
    pts.row(40) << q.x(), q.y(), 0;
    d.edges.push_back(BoundaryCurve::samples(pts));
  }
  bpde::BoundaryFitOptions wide, kept;
  wide.smooth_corner_angle = 75;
  kept.smooth_corner_angle = 0;
  for (int n : {3, 4, 6}) {
    const auto fit = bpde::fit_tensor_boundary(n, n, d, wide), plain = bpde::fit_tensor_boundary(n, n, d, kept);
    for (int e = 0; e < 4; ++e) {
      EXPECT_EQ(fit.edges[e].end_corner, "kept") << n;
      EXPECT_NEAR(*fit.edges[e].end_corner_turn, 70.0, 1e-3) << n;
    }
    EXPECT_EQ(fit.net.points(), plain.net.points()) << n;
  }
}

// The constrained orthogonal fit (fit_samples.h) moves the inner points only within the range of
// G and reaches the optimum there: from the orthogonal fit pushed off along two directions of a
// random subspace, it returns to the fit's sum of squares, and the change lies in the subspace.
TEST(FitBoundary, ConstrainedOrthogonalFitStaysInItsSubspace) {
  const int n = 6, M = 60;
  Eigen::MatrixX3d q(M + 1, 3);
  Eigen::VectorXd t0(M + 1);
  for (int k = 0; k <= M; ++k) {
    const double a = 2.0 * k / M;
    q.row(k) << std::cos(a) + 0.1 * std::cos(3 * a), std::sin(a), 0.2 * a * a;
  }
  double len = 0;
  t0(0) = 0;
  for (int k = 1; k <= M; ++k) t0(k) = len += (q.row(k) - q.row(k - 1)).norm();
  t0 /= len;
  const bpde::SampleFit best = bpde::fit_samples_orthogonal(n, t0, q);
  ASSERT_TRUE(best.corrected);
  auto cost = [&](const Eigen::MatrixX3d& P, const Eigen::VectorXd& t) {
    return (bpde::bernstein_table(n, t) * P - q).squaredNorm();
  };
  const double c_best = cost(best.points, best.params);
  const Eigen::MatrixXd R = bpde::testing::random_points(10, 3).reshaped(15, 2);
  const Eigen::MatrixXd G = Eigen::HouseholderQR<Eigen::MatrixXd>(R).householderQ() * Eigen::MatrixXd::Identity(15, 2);
  Eigen::MatrixX3d P = best.points;
  const Eigen::VectorXd push = G * Eigen::Vector2d(0.02, -0.03);
  for (int i = 1; i < n; ++i) P.row(i) += push.segment<3>(3 * (i - 1)).transpose();
  ASSERT_GT(cost(P, best.params), 10 * c_best);
  const bpde::SampleFit back = bpde::fit_samples_orthogonal_constrained(P, best.params, q, G);
  EXPECT_GT(back.iterations, 0);
  EXPECT_LT(cost(back.points, back.params), c_best * (1 + 1e-6));
  Eigen::VectorXd moved(15);
  for (int i = 1; i < n; ++i) moved.segment<3>(3 * (i - 1)) = (back.points.row(i) - P.row(i)).transpose();
  EXPECT_LT((moved - G * (G.transpose() * moved)).norm(), 1e-14 * std::max(1.0, moved.norm()));
  EXPECT_THROW(bpde::fit_samples_orthogonal_constrained(P, best.params, q, Eigen::MatrixXd(14, 2)), bpde::SizeError);
  Eigen::VectorXd bad = best.params;
  std::swap(bad(3), bad(4));
  EXPECT_THROW(bpde::fit_samples_orthogonal_constrained(P, bad, q, G), bpde::ParameterError);
  bad = best.params;
  bad(5) = NAN;
  EXPECT_THROW(bpde::fit_samples_orthogonal_constrained(P, bad, q, G), bpde::NonFiniteError);
}

TEST(FitBoundary, BadDataThrowTypedErrors) {
  BoundaryData d;
  d.edges = {BoundaryCurve::segment(Vector3d(0, 0, 0), Vector3d(1, 0, 0)),
             BoundaryCurve::segment(Vector3d(1, 0, 0), Vector3d(0, 1, 0)),
             BoundaryCurve::segment(Vector3d(0, 1, 0), Vector3d(0, 0, 0))};
  EXPECT_THROW(bpde::fit_tensor_boundary(3, 3, d), bpde::SizeError);  // 3 edges for a tensor net
  EXPECT_THROW(bpde::fit_triangular_boundary(0, d), bpde::DegreeError);
  EXPECT_THROW(bpde::fit_triangular_boundary(65, d), bpde::DegreeError);
  d.tangents = d.edges;
  EXPECT_THROW(bpde::fit_triangular_boundary(1, d), bpde::DegreeError);
  // Overflow in the fit is non-finite data, never a NaN net.
  BoundaryData h;
  h.edges = {BoundaryCurve::segment(Vector3d(0, 0, 0), Vector3d(1e308, 0, 0)),
             BoundaryCurve::segment(Vector3d(1e308, 0, 0), Vector3d(-1e308, 1e308, 0)),
             BoundaryCurve::segment(Vector3d(-1e308, 1e308, 0), Vector3d(0, 0, 0))};
  EXPECT_THROW(bpde::fit_triangular_boundary(4, h), bpde::NonFiniteError);
  // A helix whose rise overflows at its end point.
  h.edges[0] = BoundaryCurve::helix(Vector3d::Zero(), Vector3d(0, 0, 1), 1, 0, 1e10, 1e308);
  EXPECT_THROW(bpde::fit_triangular_boundary(4, h), bpde::NonFiniteError);
  // edge_error of a corrected fit checks the correspondence it is given, and keeps a NaN.
  const BoundaryCurve arc = BoundaryCurve::arc(Vector3d::Zero(), Vector3d::UnitZ(), 1, 0, 2.0);
  bpde::CurveFit f = bpde::fit_edge(arc, 5, bpde::FitMethod::Geometric);
  ASSERT_EQ(f.parameters, "corrected");
  bpde::CurveFit bad = f;
  bad.curve_params(2) = bad.curve_params(1);  // not increasing
  EXPECT_THROW(bpde::edge_error(arc, bad), bpde::ParameterError);
  bad = f;
  bad.params.conservativeResize(bad.params.size() - 1);  // sizes differ
  EXPECT_THROW(bpde::edge_error(arc, bad), bpde::ParameterError);
  bad = f;
  bad.params(3) = 1.5;  // outside [0, 1]
  EXPECT_THROW(bpde::edge_error(arc, bad), bpde::ParameterError);
  bad = f;
  bad.points(2, 0) = NAN;
  EXPECT_TRUE(std::isnan(bpde::edge_error(arc, bad)));
  bad.curve_params.resize(0);  // the parametric distance: NaN too
  EXPECT_TRUE(std::isnan(bpde::edge_error(arc, bad)));
}

}  // namespace
