// solvers/complex/complex_c1.h and the C1 option of solvers/complex/complex_extremal.h: C¹
// continuity of a triangular complex on a planar domain (complex/planar_domain.h).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "bezierpde/complex/complex_mesh.h"
#include "bezierpde/complex/layout_loops.h"
#include "bezierpde/complex/planar_domain.h"
#include "bezierpde/complex/refine.h"
#include "bezierpde/core/errors.h"
#include "bezierpde/energies/triangular_gram.h"
#include "bezierpde/solvers/complex/complex_c1.h"
#include "bezierpde/solvers/complex/complex_extremal.h"
#include "tests/complex/complex_fixtures.h"

using namespace bpde;
using namespace bpde::test;

namespace {

/// A fan of m triangles around the origin, its boundary the regular m-gon on the unit circle in
/// z = 0; faces (i, i+1, centre) as the automatic layouts make them.
Layout fan_layout(int m) {
  Layout L;
  L.kind = PatchKind::triangular;
  L.vertices = Eigen::MatrixX3d::Zero(m + 1, 3);
  for (int i = 0; i < m; ++i) {
    const double a = 2 * std::numbers::pi * i / m;
    L.vertices.row(i) << std::cos(a), std::sin(a), 0;
    L.faces.push_back({i, (i + 1) % m, m});
  }
  return L;
}

/// The layout's own xy as the domain.
std::vector<DomainTriangle> xy_domain(const Layout& L) { return layout_domain(L, L.vertices.leftCols(2)); }

/// The complex of L at degree n with every row on F (exact for polynomials of degree <= n).
PatchComplex on_function(const Layout& L, int n, const SurfaceFn& F) {
  PatchComplex c = complex_topology(L, n);
  set_from_function(c, L, F);
  return c;
}

/// Re z³ over z = x + iy: harmonic, cubic.
Eigen::Vector3d harmonic_cubic(double x, double y) { return {x, y, x * x * x - 3 * x * y * y}; }

/// A saddle-shaped closed curve over the unit circle: (cos θ, sin θ, 0.4 cos 2θ + 0.2 sin 3θ).
Loop saddle_loop() {
  return {BoundaryCurve::function([](double t) {
    const double a = 2 * std::numbers::pi * t;
    return Eigen::Vector3d(std::cos(a), std::sin(a), 0.4 * std::cos(2 * a) + 0.2 * std::sin(3 * a));
  })};
}

ComplexExtremalOptions c1_options(const std::vector<DomainTriangle>& domain) {
  ComplexExtremalOptions o;
  o.continuity = Continuity::C1;
  o.domain = domain;
  return o;
}

}  // namespace

TEST(PlanarDomain, AutomaticFanIsTheRegularPolygonAndAnnulusRingIsPositive) {
  const LoopComplex fan = loop_complex(PatchKind::triangular, 3, {saddle_loop()});
  const Eigen::MatrixX2d P = layout_domain_positions(fan.layout);
  const int m = static_cast<int>(fan.layout.faces.size());
  ASSERT_EQ(m, 6);
  EXPECT_LT(P.row(m).norm(), 1e-14);  // the centre
  for (int i = 0; i < m; ++i) EXPECT_NEAR(P.row(i).norm(), 1.0, 1e-14);
  for (int i = 0; i < m; ++i) EXPECT_NEAR((P.row((i + 1) % m) - P.row(i)).norm(), 1.0, 1e-14);  // hexagon side
  const Loop top{BoundaryCurve::circle({0, 0, 0.5}, {0, 0, 1}, 1.0)};
  const Loop bottom{BoundaryCurve::circle({0, 0, -0.5}, {0, 0, -1}, 1.0)};
  const LoopComplex ring = loop_complex(PatchKind::triangular, 3, {top, bottom});
  const std::vector<DomainTriangle> D = layout_domain(ring.layout, layout_domain_positions(ring.layout));
  double area = 0;
  for (const DomainTriangle& T : D) {
    const double a = 0.5 * ((T(1, 0) - T(0, 0)) * (T(2, 1) - T(0, 1)) - (T(1, 1) - T(0, 1)) * (T(2, 0) - T(0, 0)));
    EXPECT_GT(a, 0.01);
    area += a;
  }
  // the ring between the inscribed M-gons of radius 1 and 1/2 (M = 4 edges per loop)
  EXPECT_NEAR(area, 0.5 * 4 * std::sin(std::numbers::pi / 2) * (1 - 0.25), 1e-12);
  EXPECT_THROW(layout_domain_positions(grid_layout(PatchKind::tensor, 2)), ParameterError);
}

TEST(ComplexC1, ConditionsVanishExactlyOnAGlobalPolynomialAndNotOnAKink) {
  const Layout L = fan_layout(5);
  const auto D = xy_domain(L);
  // any global polynomial of degree <= n is C1 (not only harmonic ones)
  const PatchComplex c = on_function(L, 4, [](double x, double y) {
    return Eigen::Vector3d(x + 0.3 * y * y, y - x * y * x, 0.7 * x * x * y * y - y * y * y + 0.2 * x);
  });
  EXPECT_EQ(c1_constraints(c, D).rows(), 5 * 4);  // 5 seams, n conditions each
  EXPECT_LT(c1_residual(c, D), 1e-14);
  // moving one inner row of a seam (a C0 change) breaks C1 by about that much
  PatchComplex bent = c;
  int seam_row = -1;
  for (const ComplexEdge& e : complex_edges(c))
    if (!e.boundary() && seam_row < 0) seam_row = e.rows[2];
  ASSERT_FALSE(std::binary_search(c.fixed.begin(), c.fixed.end(), seam_row));
  bent.points(seam_row, 2) += 0.01;
  EXPECT_GT(c1_residual(bent, D), 1e-3);  // 0.01 / max|X| times a coefficient of order 1
  EXPECT_THROW(c1_constraints(c, std::vector<DomainTriangle>(D.begin(), D.end() - 1)), ParameterError);
}

TEST(ComplexC1, DomainGramsMeasureTheEnergyOnTheDomainTriangle) {
  // a similarity image of the reference triangle: the Dirichlet Gram is the reference one
  DomainTriangle T;
  T << 1, 2, 1 + 2 * std::cos(0.4), 2 + 2 * std::sin(0.4), 1 - 2 * std::sin(0.4), 2 + 2 * std::cos(0.4);
  DomainGrams dirichlet(5, EnergySpec::dirichlet());
  EXPECT_LT((dirichlet.gram(T) - triangular_gram(5, EnergySpec::dirichlet())).cwiseAbs().maxCoeff(), 1e-11);
  // 1/2 ∫ (Δf)² over a general triangle for f = s² + 3st - t³/6 + ... with Δf = 2 - t: exact integral
  DomainTriangle S;
  S << 0.2, -0.1, 1.5, 0.3, 0.4, 1.2;
  const Layout L{PatchKind::triangular,
                 (Eigen::MatrixX3d(3, 3) << 0.2, -0.1, 0, 1.5, 0.3, 0, 0.4, 1.2, 0).finished(),
                 {{0, 1, 2}}};
  const int n = 4;
  PatchComplex c =
      on_function(L, n, [](double s, double t) { return Eigen::Vector3d(s * s + 3 * s * t - t * t * t / 6, 0, 0); });
  DomainGrams lap(n, EnergySpec::laplacian_squared());
  const Eigen::VectorXd P = c.points.col(0);
  Eigen::VectorXd local(P.size());
  for (int r = 0; r < P.size(); ++r) local(r) = P(c.patches[0].points[r]);
  const double E = 0.5 * local.dot(lap.gram(S) * local);
  // ∫_S (2 - t)² by the exact quadrature of a quadratic on a triangle (edge midpoints)
  const Eigen::Vector2d A(0.2, -0.1), B(1.5, 0.3), C(0.4, 1.2);
  const double area = 0.5 * ((B - A).x() * (C - A).y() - (B - A).y() * (C - A).x());
  double integral = 0;
  for (const Eigen::Vector2d& m :
       {Eigen::Vector2d((A + B) / 2), Eigen::Vector2d((B + C) / 2), Eigen::Vector2d((C + A) / 2)})
    integral += area / 3 * (2 - m.y()) * (2 - m.y());
  EXPECT_NEAR(E, 0.5 * integral, 1e-12);
}

TEST(ComplexC1, LaplacianSquaredC1ExtremalReproducesAHarmonicCubicAtAnExtraordinaryCentre) {
  // Re z³ is harmonic: the laplacian-squared energy on the domain is 0 there, and a C1 complex
  // with that energy 0 is harmonic on the whole domain, so it is the unique minimiser. The fan of
  // 5 makes the centre a vertex of valence 5; h refinement adds regular vertices.
  const Layout L = fan_layout(5);
  for (int refine : {0, 1}) {
    for (int n : {4, 5}) {
      PatchComplex exact = on_function(L, n, harmonic_cubic);
      std::vector<DomainTriangle> D = xy_domain(L);
      for (int r = 0; r < refine; ++r) exact = refine_h(exact), D = refine_domain_h(D);
      PatchComplex start = exact;
      for (int r = 0; r < start.points.rows(); ++r)
        if (!std::binary_search(start.fixed.begin(), start.fixed.end(), r)) start.points.row(r).setZero();
      const ComplexExtremal e = solve_complex_extremal(start, EnergySpec::laplacian_squared(), c1_options(D));
      EXPECT_TRUE(e.summary.converged) << "n = " << n << ": " << e.summary.message;
      EXPECT_LT((e.complex.points - exact.points).cwiseAbs().maxCoeff(), 1e-9) << "n = " << n << ", refine " << refine;
      EXPECT_LT(e.c1_residual, 1e-12);
      EXPECT_LT(std::abs(e.energy), 1e-10);
    }
  }
}

TEST(ComplexC1, SaddleLoopSeamsCloseWithC1AndStayOpenWithC0) {
  for (const EnergySpec& energy : {EnergySpec::dirichlet(), EnergySpec::laplacian_squared()}) {
    const LoopComplex lc = loop_complex(PatchKind::triangular, 6, {saddle_loop()});
    const std::vector<DomainTriangle> D = layout_domain(lc.layout, layout_domain_positions(lc.layout));
    ComplexExtremalOptions c0;
    c0.domain = D;
    const bool second_order = energy.order() == 2;
    const ComplexExtremal e1 = solve_complex_extremal(lc.complex, energy, c1_options(D));
    ASSERT_TRUE(e1.summary.converged) << energy.name() << ": " << e1.summary.message;
    EXPECT_LT(e1.c1_residual, 1e-10);
    EXPECT_LE(e1.c1_steps, 10);  // the augmented Lagrangian steps (3 to 7 measured)
    EXPECT_LT(seam_angle_max(e1.complex), 1e-8) << energy.name();
    if (second_order) {  // C0 with a fourth-order energy is singular on a fan (piecewise-affine null directions)
      const ComplexExtremal e0 = solve_complex_extremal(lc.complex, energy, c0);
      ASSERT_TRUE(e0.summary.converged) << e0.summary.message;
      EXPECT_GT(seam_angle_max(e0.complex), 1e-3);
      EXPECT_GT(c1_residual(e0.complex, D), 1e-4);
      // the constrained minimum costs energy, the unconstrained one is below it
      EXPECT_GT(e1.energy, e0.energy * (1 + 1e-6));
    } else {
      EXPECT_THROW(solve_complex_extremal(lc.complex, energy, c0), ParameterError);
    }
  }
}

TEST(ComplexC1, DegreeTooLowForTheBoundaryIsIncompatible) {
  // at n = 2 each seam has one inner point; its C1 conditions at the boundary vertex and at the
  // centre over-determine it, so a generic boundary has no C1 complex
  const LoopComplex lc = loop_complex(PatchKind::triangular, 2, {saddle_loop()});
  const std::vector<DomainTriangle> D = layout_domain(lc.layout, layout_domain_positions(lc.layout));
  const ComplexExtremal e = solve_complex_extremal(lc.complex, EnergySpec::dirichlet(), c1_options(D));
  EXPECT_FALSE(e.summary.converged);
  EXPECT_EQ(e.summary.status, Status::Incompatible);
  EXPECT_GT(e.c1_residual, 1e-6);
  // compatible data at the same degree (a global quadratic) has its C1 complex
  const Layout L = fan_layout(6);
  const PatchComplex q =
      on_function(L, 2, [](double x, double y) { return Eigen::Vector3d(x, y, x * x - y * y + x * y); });
  const ComplexExtremal eq = solve_complex_extremal(q, EnergySpec::dirichlet(), c1_options(xy_domain(L)));
  EXPECT_TRUE(eq.summary.converged) << eq.summary.message;
  EXPECT_LT((eq.complex.points - q.points).cwiseAbs().maxCoeff(), 1e-10);
}

TEST(ComplexC1, RefinementKeepsAC1ComplexC1) {
  const LoopComplex lc = loop_complex(PatchKind::triangular, 5, {saddle_loop()});
  const std::vector<DomainTriangle> D = layout_domain(lc.layout, layout_domain_positions(lc.layout));
  const ComplexExtremal e = solve_complex_extremal(lc.complex, EnergySpec::dirichlet(), c1_options(D));
  ASSERT_TRUE(e.summary.converged) << e.summary.message;
  EXPECT_LT(c1_residual(refine_h(e.complex), refine_domain_h(D)), 1e-12);
  EXPECT_LT(c1_residual(refine_p(e.complex, 2), D), 1e-12);
}

TEST(ComplexC1, RefusesTensorComplexesAndAMissingDomain) {
  const Layout L = grid_layout(PatchKind::tensor, 2);
  const PatchComplex c = complex_topology(L, 3);
  ComplexExtremalOptions o;
  o.continuity = Continuity::C1;
  EXPECT_THROW(solve_complex_extremal(c, EnergySpec::dirichlet(), o), ParameterError);
  const Layout T = fan_layout(4);
  EXPECT_THROW(solve_complex_extremal(complex_topology(T, 3), EnergySpec::dirichlet(), o), ParameterError);
}

TEST(ComplexC1, AnnulusRingAndATutteDomainWithInnerVertices) {
  // two coaxial circles spanned by a tube: the ring of triangles between two concentric circles
  const Loop top{BoundaryCurve::circle({0, 0, 0.5}, {0, 0, 1}, 1.0)};
  const Loop bottom{BoundaryCurve::circle({0, 0, -0.5}, {0, 0, -1}, 1.0)};
  const LoopComplex ring = loop_complex(PatchKind::triangular, 5, {top, bottom});
  const std::vector<DomainTriangle> D = layout_domain(ring.layout, layout_domain_positions(ring.layout));
  ComplexExtremalOptions c0;
  c0.domain = D;
  const ComplexExtremal e0 = solve_complex_extremal(ring.complex, EnergySpec::dirichlet(), c0);
  const ComplexExtremal e1 = solve_complex_extremal(ring.complex, EnergySpec::dirichlet(), c1_options(D));
  ASSERT_TRUE(e0.summary.converged) << e0.summary.message;
  ASSERT_TRUE(e1.summary.converged) << e1.summary.message;
  EXPECT_GT(seam_angle_max(e0.complex), 1e-3);
  EXPECT_LT(seam_angle_max(e1.complex), 1e-8);
  EXPECT_LT(e1.c1_residual, 1e-10);
  EXPECT_GT(e1.energy, e0.energy);
  // a 3 x 3 grid of triangle pairs: 4 inner vertices placed by Tutte's embedding
  const Layout grid = grid_layout(PatchKind::triangular, 3);
  const Eigen::MatrixX2d P = layout_domain_positions(grid);
  for (int v : {5, 6, 9, 10}) EXPECT_LT(P.row(v).norm(), 1.0);  // inside the unit circle
  PatchComplex c = complex_topology(grid, 5);
  set_from_function(c, grid, [](double x, double y) { return Eigen::Vector3d(x, y, std::sin(x) * std::cos(y)); });
  const ComplexExtremal g = solve_complex_extremal(c, EnergySpec::biharmonic(), c1_options(layout_domain(grid, P)));
  ASSERT_TRUE(g.summary.converged) << g.summary.message;
  EXPECT_LT(seam_angle_max(g.complex), 1e-8);
}
