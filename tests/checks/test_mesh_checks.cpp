// Tests of checks/mesh_checks.cpp (CGAL self-intersections, closedness, volumes).
#include <gtest/gtest.h>

#include "bezierpde/core/eigen.h"
#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <functional>
#include <limits>
#include <numbers>
#include <random>
#include <vector>

#include "bezierpde/checks/mesh_checks.h"
#include "bezierpde/core/errors.h"

namespace bpde {
namespace {

constexpr double kPi = std::numbers::pi;

struct Soup {
  std::vector<double> v;
  std::vector<int> t;
  int add_vertex(double x, double y, double z) {
    v.insert(v.end(), {x, y, z});
    return static_cast<int>(v.size() / 3 - 1);
  }
};

/// Sample x(u, v) on the (n+1) x (m+1) grid of [u0,u1] x [v0,v1], vertex index i(m+1)+j, two
/// triangles per cell, counter-clockwise in the (u, v) plane. Appends to `s` (no sharing with
/// what is already there: seams are left to the merging).
void add_grid(Soup& s, int n, int m, double u0, double u1, double v0, double v1,
              const std::function<std::array<double, 3>(double, double)>& x) {
  const int base = static_cast<int>(s.v.size() / 3);
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j <= m; ++j) {
      const auto p = x(u0 + (u1 - u0) * i / n, v0 + (v1 - v0) * j / m);
      s.add_vertex(p[0], p[1], p[2]);
    }
  auto id = [&](int i, int j) { return base + i * (m + 1) + j; };
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < m; ++j) {
      s.t.insert(s.t.end(), {id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      s.t.insert(s.t.end(), {id(i, j), id(i + 1, j + 1), id(i, j + 1)});
    }
}

std::array<double, 3> sphere(double theta, double phi) {
  return {std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta)};
}

TEST(MeshChecks, UnitCubeFromSixSampledFacesIsClosedWithVolumeOne) {
  // Six 4x4 grids, outward orientation, seams shared only geometrically.
  Soup s;
  using A = std::array<double, 3>;
  add_grid(s, 4, 4, 0, 1, 0, 1, [](double u, double v) { return A{v, u, 0}; });  // z=0, normal -z
  add_grid(s, 4, 4, 0, 1, 0, 1, [](double u, double v) { return A{u, v, 1}; });  // z=1, +z
  add_grid(s, 4, 4, 0, 1, 0, 1, [](double u, double v) { return A{u, 0, v}; });  // y=0, -y
  add_grid(s, 4, 4, 0, 1, 0, 1, [](double u, double v) { return A{v, 1, u}; });  // y=1, +y
  add_grid(s, 4, 4, 0, 1, 0, 1, [](double u, double v) { return A{0, v, u}; });  // x=0, -x
  add_grid(s, 4, 4, 0, 1, 0, 1, [](double u, double v) { return A{1, u, v}; });  // x=1, +x
  const auto r = check_mesh(s.v, s.t);
  EXPECT_TRUE(r.closed);
  ASSERT_TRUE(r.volume.has_value());
  EXPECT_NEAR(*r.volume, 1.0, 1e-13);
  EXPECT_EQ(r.self_intersections, 0);
  EXPECT_EQ(r.merged_vertices, 6 * 25 - 12 * 5 + 8);  // 98 = 6*9 + 12*3 + 8
  EXPECT_EQ(r.degenerate_triangles, 0);
  // closed surface: the cone volume is the enclosed volume too
  EXPECT_NEAR(r.cone_volume, 1.0, 1e-13);
}

TEST(MeshChecks, SmallCubeFarFromTheOriginWithAnUnreferencedFarVertex) {
  Soup s;
  using A = std::array<double, 3>;
  const double o = 1e6, h = 1e-3;
  auto f = [&](double x, double y, double z) { return A{o + h * x, o + h * y, o + h * z}; };
  add_grid(s, 3, 3, 0, 1, 0, 1, [&](double u, double v) { return f(v, u, 0); });
  add_grid(s, 3, 3, 0, 1, 0, 1, [&](double u, double v) { return f(u, v, 1); });
  add_grid(s, 3, 3, 0, 1, 0, 1, [&](double u, double v) { return f(u, 0, v); });
  add_grid(s, 3, 3, 0, 1, 0, 1, [&](double u, double v) { return f(v, 1, u); });
  add_grid(s, 3, 3, 0, 1, 0, 1, [&](double u, double v) { return f(0, v, u); });
  add_grid(s, 3, 3, 0, 1, 0, 1, [&](double u, double v) { return f(1, u, v); });
  s.add_vertex(1e300, -1e300, 0);  // not used by any triangle
  const auto r = check_mesh(s.v, s.t);
  EXPECT_TRUE(r.closed);
  EXPECT_EQ(r.self_intersections, 0);
  ASSERT_TRUE(r.volume.has_value());
  EXPECT_NEAR(*r.volume, h * h * h, 1e-6 * h * h * h);
}

TEST(MeshChecks, ReversedCubeHasNegativeVolume) {
  Soup s;
  using A = std::array<double, 3>;
  add_grid(s, 2, 2, 0, 1, 0, 1, [](double u, double v) { return A{u, v, 0}; });
  add_grid(s, 2, 2, 0, 1, 0, 1, [](double u, double v) { return A{v, u, 1}; });
  add_grid(s, 2, 2, 0, 1, 0, 1, [](double u, double v) { return A{v, 0, u}; });
  add_grid(s, 2, 2, 0, 1, 0, 1, [](double u, double v) { return A{u, 1, v}; });
  add_grid(s, 2, 2, 0, 1, 0, 1, [](double u, double v) { return A{0, u, v}; });
  add_grid(s, 2, 2, 0, 1, 0, 1, [](double u, double v) { return A{1, v, u}; });
  const auto r = check_mesh(s.v, s.t);
  EXPECT_TRUE(r.closed);
  ASSERT_TRUE(r.volume.has_value());
  EXPECT_NEAR(*r.volume, -1.0, 1e-13);
}

double sphere_volume(int n) {
  Soup s;
  add_grid(s, n, 2 * n, 0, kPi, 0, 2 * kPi, sphere);
  const auto r = check_mesh(s.v, s.t);
  EXPECT_TRUE(r.closed) << n;
  EXPECT_EQ(r.self_intersections, 0) << n;
  // poles: one degenerate triangle per cell of the first and last rows
  EXPECT_EQ(r.degenerate_triangles, 2 * 2 * n) << n;
  EXPECT_EQ(r.merged_vertices, (n - 1) * 2 * n + 2) << n;
  EXPECT_TRUE(r.volume.has_value());
  return r.volume.value_or(0);
}

TEST(MeshChecks, SampledSphereIsClosedAndConvergesToTheBallVolume) {
  const double exact = 4 * kPi / 3;
  const double v32 = sphere_volume(32), v64 = sphere_volume(64);
  EXPECT_NEAR(v32, exact, 0.01 * exact);
  EXPECT_LT(v32, exact);  // inscribed polyhedron
  EXPECT_LT(v64, exact);
  // second-order convergence: error ratio ~ 4
  const double ratio = (exact - v32) / (exact - v64);
  EXPECT_NEAR(ratio, 4.0, 0.1);
}

// MeshCheckOptions::progress: the stage kMeshCheckStage with total 1, fractions in [0, 1) that
// never fall, from 0, with many steps through the pairs' tests on a sampled surface (the grid broad
// phase), and the same report as without a callback. The CGAL broad phase reports no steps of its
// own. (BPDE_PRINT_CHECK_PROGRESS=N prints the times of the reports at N, which the phases'
// fractions in checks/mesh_checks.cpp were set from.)
TEST(MeshChecks, ProgressReportsRisingFractionsThroughTheStage) {
  const char* print = std::getenv("BPDE_PRINT_CHECK_PROGRESS");
  const int n = print ? std::atoi(print) : 120;
  Soup s;
  add_grid(s, n, 2 * n, 0, kPi, 0, 2 * kPi, sphere);
  std::vector<size_t> reports;  // per broad phase
  for (BroadPhase phase : {BroadPhase::kGrid, BroadPhase::kCgalBoxes}) {
    std::vector<double> done;
    std::vector<double> at;
    const auto t0 = std::chrono::steady_clock::now();
    MeshCheckOptions o;
    o.broad_phase = phase;
    o.progress = [&](std::string_view stage, double d, double total) {
      EXPECT_EQ(std::string(stage), std::string(kMeshCheckStage));
      EXPECT_EQ(total, 1.0);
      done.push_back(d);
      at.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
    };
    const MeshCheckReport r = check_mesh(s.v, s.t, o);
    if (print) {
      for (size_t k = 0; k < done.size(); ++k) std::printf("%.3f %.4f\n", done[k], at[k]);
      std::printf("end %.4f\n", std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
    }
    ASSERT_FALSE(done.empty());
    EXPECT_EQ(done.front(), 0.0);
    for (size_t k = 1; k < done.size(); ++k) EXPECT_GE(done[k], done[k - 1]);
    EXPECT_LT(done.back(), 1.0);  // the caller ends the stage
    EXPECT_GE(done.back(), 0.9);
    reports.push_back(done.size());
    MeshCheckOptions without;
    without.broad_phase = phase;
    const MeshCheckReport quiet = check_mesh(s.v, s.t, without);
    EXPECT_EQ(r.self_intersections, quiet.self_intersections);
    EXPECT_EQ(r.box_pairs, quiet.box_pairs);
    EXPECT_EQ(r.closed, quiet.closed);
    EXPECT_TRUE(r.closed);
  }
  EXPECT_GE(reports[0], 40u);               // the merge's steps
  EXPECT_GE(reports[0], reports[1] + 50u);  // and about a hundred through the grid's cells
}

TEST(MeshChecks, SampledTorusWithTwoSeamsIsClosed) {
  const double R = 2, rr = 0.5;
  Soup s;
  // (u, v) -> torus, oriented outwards: x_u ^ x_v points away from the tube's core circle
  add_grid(s, 96, 48, 0, 2 * kPi, 0, 2 * kPi, [&](double u, double v) {
    return std::array<double, 3>{(R + rr * std::cos(v)) * std::cos(u), (R + rr * std::cos(v)) * std::sin(u),
                                 rr * std::sin(v)};
  });
  const auto r = check_mesh(s.v, s.t);
  EXPECT_TRUE(r.closed);
  EXPECT_EQ(r.self_intersections, 0);
  ASSERT_TRUE(r.volume.has_value());
  const double exact = 2 * kPi * kPi * R * rr * rr;
  EXPECT_NEAR(std::abs(*r.volume), exact, 5e-3 * exact);  // inscribed: -0.36 %
}

TEST(MeshChecks, HemisphereCappedByItsPlanarBoundary) {
  const int n = 32;
  Soup h;
  add_grid(h, n, 4 * n, 0, kPi / 2, 0, 2 * kPi, sphere);
  const auto r = check_mesh(h.v, h.t);
  EXPECT_FALSE(r.closed);
  EXPECT_EQ(r.self_intersections, 0);
  ASSERT_TRUE(r.volume.has_value());
  // Independent truth 1: the full sphere sampled on the same rows is symmetric about z = 0, so
  // its volume is twice the capped hemisphere's.
  Soup s;
  add_grid(s, 2 * n, 4 * n, 0, kPi, 0, 2 * kPi, sphere);
  const auto full = check_mesh(s.v, s.t);
  ASSERT_TRUE(full.volume.has_value());
  EXPECT_NEAR(*r.volume, 0.5 * *full.volume, 1e-12);
  // Independent truth 2: the half ball.
  EXPECT_NEAR(*r.volume, 2 * kPi / 3, 0.005 * 2 * kPi / 3);
}

TEST(MeshChecks, ShiftedCapIsTranslationInvariant) {
  // A hemisphere of radius 1 centred at (3, -2, 5), boundary in the plane z = 5.
  const int n = 16;
  Soup h;
  add_grid(h, n, 4 * n, 0, kPi / 2, 0, 2 * kPi, [](double t, double p) {
    const auto q = sphere(t, p);
    return std::array<double, 3>{q[0] + 3, q[1] - 2, q[2] + 5};
  });
  Soup h0;
  add_grid(h0, n, 4 * n, 0, kPi / 2, 0, 2 * kPi, sphere);
  const auto r = check_mesh(h.v, h.t), r0 = check_mesh(h0.v, h0.t);
  ASSERT_TRUE(r.volume && r0.volume);
  EXPECT_NEAR(*r.volume, *r0.volume, 1e-12);
  // the cone volume is not translation invariant: it gains (1/3) <c, area vector of the cap>
  // = (1/3) * 5 * pi-ish; only check it differs
  EXPECT_GT(std::abs(r.cone_volume - r0.cone_volume), 1.0);
}

TEST(MeshChecks, TiltedOpenCylinderCappedAtBothEnds) {
  // Cylinder of radius 1 and height 2 about the axis d = (1,1,1)/sqrt3, both ends planar.
  const Eigen::Vector3d d = Eigen::Vector3d(1, 1, 1).normalized();
  const Eigen::Vector3d e1 = Eigen::Vector3d(1, -1, 0).normalized(), e2 = d.cross(e1);
  Soup s;
  add_grid(s, 64, 4, 0, 2 * kPi, 0, 2, [&](double u, double v) {
    const Eigen::Vector3d p = std::cos(u) * e1 + std::sin(u) * e2 + v * d;
    return std::array<double, 3>{p[0], p[1], p[2]};
  });
  const auto r = check_mesh(s.v, s.t);
  EXPECT_FALSE(r.closed);
  ASSERT_TRUE(r.volume.has_value());
  // the inscribed 64-gon prism
  const double exact = 2 * 0.5 * 64 * std::sin(2 * kPi / 64);
  EXPECT_NEAR(std::abs(*r.volume), exact, 1e-12);
}

TEST(MeshChecks, NonPlanarBoundaryHasNoVolume) {
  Soup s;
  add_grid(s, 8, 8, -1, 1, -1, 1, [](double u, double v) { return std::array<double, 3>{u, v, u * v}; });
  const auto r = check_mesh(s.v, s.t);
  EXPECT_FALSE(r.closed);
  EXPECT_FALSE(r.volume.has_value());
  EXPECT_EQ(r.self_intersections, 0);
}

TEST(MeshChecks, ConeVolumeOfFlatSquareAtHeightOne) {
  Soup s;
  add_grid(s, 5, 7, 0, 2, 0, 3, [](double u, double v) { return std::array<double, 3>{u, v, 1}; });
  const auto r = check_mesh(s.v, s.t);
  EXPECT_NEAR(r.cone_volume, 6.0 / 3.0, 1e-13);  // (1/3) * area * height
  EXPECT_EQ(r.self_intersections, 0);            // coplanar neighbours are not intersections
  ASSERT_TRUE(r.volume.has_value());             // planar boundary: capped volume 0
  EXPECT_NEAR(*r.volume, 0.0, 1e-13);
}

TEST(MeshChecks, TwoCrossingTrianglesIntersectOnce) {
  Soup s;
  s.add_vertex(0, 0, 0);
  s.add_vertex(2, 0, 0);
  s.add_vertex(0, 2, 0);
  s.add_vertex(0.5, 0.5, -1);
  s.add_vertex(0.5, 0.5, 1);
  s.add_vertex(3, 3, 0.2);
  s.t = {0, 1, 2, 3, 4, 5};
  EXPECT_EQ(check_mesh(s.v, s.t).self_intersections, 1);
  // moved apart: no intersection
  for (int k : {3, 4, 5}) s.v[3 * k] += 10;
  EXPECT_EQ(check_mesh(s.v, s.t).self_intersections, 0);
}

TEST(MeshChecks, FoldedStripIntersectsItself) {
  // A ribbon over the figure-eight curve (sin 2t, sin t): it crosses itself at t = 0 and t = pi.
  // 81 samples so that t = pi is not a grid line (there the two sheets would share merged
  // vertices and cross only along a shared edge, which is not an intersection).
  Soup s;
  add_grid(s, 81, 3, 0, 2 * kPi, 0, 1, [](double t, double z) {
    return std::array<double, 3>{std::sin(2 * t), std::sin(t), z};
  });
  const auto r = check_mesh(s.v, s.t);
  EXPECT_GT(r.self_intersections, 0);
  // The same ribbon over a circle is clean.
  Soup c;
  add_grid(c, 80, 3, 0, 2 * kPi, 0, 1, [](double t, double z) {
    return std::array<double, 3>{std::cos(t), std::sin(t), z};
  });
  EXPECT_EQ(check_mesh(c.v, c.t).self_intersections, 0);
}

TEST(MeshChecks, TrianglesFoldedOntoEachOtherAcrossAnEdgeIntersect) {
  Soup s;
  s.add_vertex(0, 0, 0);
  s.add_vertex(1, 0, 0);
  s.add_vertex(0, 1, 0);
  s.add_vertex(0.3, 0.8, 0);  // same side of edge (0,1) as vertex 2, coplanar
  s.t = {0, 1, 2, 1, 0, 3};
  EXPECT_EQ(check_mesh(s.v, s.t).self_intersections, 1);
  s.v[3 * 3 + 1] = -0.8;  // other side: a clean flat pair
  EXPECT_EQ(check_mesh(s.v, s.t).self_intersections, 0);
}

/// Pairs of triangles whose closed bounding boxes overlap, by testing every pair (the truth for
/// MeshCheckReport::box_pairs on a soup without coincident vertices or degenerate triangles).
long long brute_force_box_pairs(const Soup& s) {
  const std::size_t nf = s.t.size() / 3;
  std::vector<std::array<double, 6>> b(nf);
  for (std::size_t f = 0; f < nf; ++f)
    for (int a = 0; a < 3; ++a) {
      b[f][a] = std::numeric_limits<double>::infinity();
      b[f][3 + a] = -b[f][a];
      for (int k = 0; k < 3; ++k) {
        const double x = s.v[3 * static_cast<std::size_t>(s.t[3 * f + k]) + a];
        b[f][a] = std::min(b[f][a], x);
        b[f][3 + a] = std::max(b[f][3 + a], x);
      }
    }
  long long pairs = 0;
  for (std::size_t f = 0; f < nf; ++f)
    for (std::size_t g = f + 1; g < nf; ++g) {
      bool overlap = true;
      for (int a = 0; a < 3; ++a) overlap = overlap && b[f][a] <= b[g][3 + a] && b[g][a] <= b[f][3 + a];
      pairs += overlap;
    }
  return pairs;
}

TEST(MeshChecks, GridBroadPhaseFindsTheSamePairsAsCgal) {
  // A random soup of 1500 small triangles in the unit cube (many crossings, some boxes touching
  // only at a face: coordinates on a coarse lattice), the figure-eight ribbon and a sampled
  // sphere: the grid broad phase must give every box pair exactly once (brute force, on the soup)
  // and the same report as CGAL::box_self_intersection_d.
  std::mt19937 rng(7);
  std::uniform_int_distribution<int> cellpos(0, 40), offset(-3, 3);
  Soup soup;
  while (soup.t.size() < 3 * 1500) {
    const double cx = cellpos(rng), cy = cellpos(rng), cz = cellpos(rng);
    Eigen::Vector3d p[3];
    for (auto& q : p) q = Eigen::Vector3d(cx + offset(rng), cy + offset(rng), cz + offset(rng)) / 40;
    if ((p[1] - p[0]).cross(p[2] - p[0]).squaredNorm() < 1e-12) continue;  // no degenerate triangles
    for (const auto& q : p) soup.t.push_back(soup.add_vertex(q[0], q[1], q[2]));
  }
  Soup ribbon;
  add_grid(ribbon, 81, 3, 0, 2 * kPi, 0, 1, [](double t, double z) {
    return std::array<double, 3>{std::sin(2 * t), std::sin(t), z};
  });
  Soup ball;
  add_grid(ball, 24, 48, 0, kPi, 0, 2 * kPi, sphere);
  for (const Soup* s : {&soup, &ribbon, &ball}) {
    const auto grid = check_mesh(s->v, s->t);
    MeshCheckOptions reference;
    reference.broad_phase = BroadPhase::kCgalBoxes;
    const auto cgal = check_mesh(s->v, s->t, reference);
    EXPECT_EQ(grid.box_pairs, cgal.box_pairs);
    EXPECT_EQ(grid.self_intersections, cgal.self_intersections);
    EXPECT_EQ(grid.closed, cgal.closed);
    EXPECT_EQ(grid.merged_vertices, cgal.merged_vertices);
  }
  // (in the ribbon and the sphere, seam vertices merge and move by rounding: the brute force on
  // the input would test slightly different boxes; the soup's coincident points are exact)
  EXPECT_EQ(check_mesh(soup.v, soup.t).box_pairs, brute_force_box_pairs(soup));
  const auto r = check_mesh(soup.v, soup.t);
  EXPECT_GT(r.self_intersections, 100);  // the soup does cross itself
  EXPECT_GT(check_mesh(ribbon.v, ribbon.t).self_intersections, 0);
}

TEST(MeshChecks, EmptyMeshIsValid) {
  const auto r = check_mesh({}, {});
  EXPECT_EQ(r.self_intersections, 0);
  EXPECT_FALSE(r.closed);
  EXPECT_FALSE(r.volume.has_value());
  EXPECT_EQ(r.cone_volume, 0.0);
}

TEST(MeshChecks, BadInputThrowsTypedErrors) {
  const std::vector<double> v = {0, 0, 0, 1, 0, 0, 0, 1, 0};
  EXPECT_THROW(check_mesh({0, 0, 0, 1}, {0, 0, 0}), SizeError);
  EXPECT_THROW(check_mesh(v, {0, 1}), SizeError);
  EXPECT_THROW(check_mesh(v, {0, 1, 3}), SizeError);
  EXPECT_THROW(check_mesh(v, {0, -1, 2}), SizeError);
  auto bad = v;
  bad[4] = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(check_mesh(bad, {0, 1, 2}), NonFiniteError);
  bad[4] = std::numeric_limits<double>::infinity();
  EXPECT_THROW(check_mesh(bad, {0, 1, 2}), NonFiniteError);
  bad[4] = 1.7e308;
  bad[1] = -1.7e308;
  EXPECT_THROW(check_mesh(bad, {0, 1, 2}), NonFiniteError);  // bounding box overflows
  try {
    check_mesh(v, {0, 1, 7});
    FAIL();
  } catch (const SizeError& e) {
    EXPECT_NE(std::string(e.what()).find("out of range"), std::string::npos);
  }
}


// ------------------------------------------------------------------ the projection proof

MeshCheckReport pairwise(const Soup& s) {
  MeshCheckOptions o;
  o.projection_proof = false;
  return check_mesh(s.v, s.t, o);
}

TEST(ProjectionProof, AGraphIsEmbeddedByProjectionWithTheSameReport) {
  // z = sin(3x) cos(2y) over a tilted square: a graph over the (x, y) plane, normals up.
  Soup s;
  add_grid(s, 30, 30, -1, 1, -1, 1, [](double u, double v) {
    return std::array<double, 3>{u + 0.3 * v, v, std::sin(3 * u) * std::cos(2 * v)};
  });
  const auto r = check_mesh(s.v, s.t), all = pairwise(s);
  EXPECT_TRUE(r.embedded_by_projection);
  EXPECT_EQ(r.box_pairs, 0);
  EXPECT_FALSE(all.embedded_by_projection);
  EXPECT_GT(all.box_pairs, 30 * 30 * 2);  // every triangle's box meets its neighbours'
  EXPECT_EQ(r.self_intersections, 0);
  EXPECT_EQ(all.self_intersections, 0);
  EXPECT_EQ(r.closed, all.closed);
  EXPECT_EQ(r.merged_vertices, all.merged_vertices);
  EXPECT_EQ(r.volume.has_value(), all.volume.has_value());
  EXPECT_EQ(r.cone_volume, all.cone_volume);
  // the same sheet seen from below (reversed triangles) and turned onto the x axis
  Soup down;
  add_grid(down, 30, 30, -1, 1, -1, 1, [](double u, double v) {
    return std::array<double, 3>{std::sin(3 * v) * std::cos(2 * u), u, v + 0.3 * u};
  });
  EXPECT_TRUE(check_mesh(down.v, down.t).embedded_by_projection);
  EXPECT_EQ(check_mesh(down.v, down.t).self_intersections, 0);
}

TEST(ProjectionProof, AFoldedSheetIsNotClaimedAndTheExactTestsFindTheCrossing) {
  // The sheet over the prolate cycloid (t - 2 sin t, s, -2 cos t), t in [-pi, pi]: its loop
  // crosses itself at t = +-1.895 (the grid's t steps miss it), so the sheet cuts itself along a
  // line of y.
  Soup s;
  add_grid(s, 40, 4, -kPi, kPi, 0, 1, [](double t, double y) {
    return std::array<double, 3>{t - 2 * std::sin(t), y, -2 * std::cos(t)};
  });
  const auto r = check_mesh(s.v, s.t);
  EXPECT_FALSE(r.embedded_by_projection);
  EXPECT_GE(r.self_intersections, 4);  // at least one crossing pair per row of cells
  EXPECT_EQ(r.self_intersections, pairwise(s).self_intersections);
}

TEST(ProjectionProof, PositiveNormalsWithAnOverlappingBoundaryFallBackToTheExactTests) {
  // A spiral ramp (r cos t, r sin t, t / 4), r in [1, 2], t in [0, 2.5 pi]: the normal's z
  // component is r > 0 everywhere, but the projected boundary overlaps itself (the ramp turns more
  // than once). The ramp's turns are 2 pi / 4 apart in height: no intersection.
  Soup s;
  add_grid(s, 8, 60, 1, 2, 0, 2.5 * kPi, [](double r, double t) {
    return std::array<double, 3>{r * std::cos(t), r * std::sin(t), t / 4};
  });
  const auto r = check_mesh(s.v, s.t);
  EXPECT_FALSE(r.embedded_by_projection);
  EXPECT_GT(r.box_pairs, 0);  // the pairwise tests ran
  EXPECT_EQ(r.self_intersections, 0);
  // with the height (r - 1.5)(t - 1.25 pi) the first and the last quarter turn cross each other
  // along r = 1.5 (not a grid line), and the normal's z component is still r: the exact tests find
  // the crossing
  Soup cut;
  add_grid(cut, 7, 60, 1, 2, 0, 2.5 * kPi, [](double r, double t) {
    return std::array<double, 3>{r * std::cos(t), r * std::sin(t), (r - 1.5) * (t - 1.25 * kPi)};
  });
  const auto c = check_mesh(cut.v, cut.t);
  EXPECT_FALSE(c.embedded_by_projection);
  EXPECT_GE(c.self_intersections, 12);  // at least one pair per cell along the crossing line
  EXPECT_EQ(c.self_intersections, pairwise(cut).self_intersections);
}

TEST(ProjectionProof, NeverClaimsWhatTheExactTestsRefute) {
  // Jittered 6 x 6 grids (in-plane jitter up to about a cell, so that some fold over; random
  // heights): wherever the proof holds, the pairwise tests find no intersection. Both outcomes occur.
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> jitter(-1, 1);
  int claimed = 0, refused = 0;
  for (int trial = 0; trial < 300; ++trial) {
    const double amount = 0.25 * (trial % 5) / 6.0, height = 0.5 * (trial % 3);
    Soup s;
    add_grid(s, 6, 6, 0, 1, 0, 1, [&](double u, double v) {
      return std::array<double, 3>{u + amount * jitter(rng), v + amount * jitter(rng), height * jitter(rng)};
    });
    const auto r = check_mesh(s.v, s.t);
    if (r.embedded_by_projection) {
      ++claimed;
      EXPECT_EQ(pairwise(s).self_intersections, 0) << trial;
    } else {
      ++refused;
      EXPECT_EQ(r.self_intersections, pairwise(s).self_intersections) << trial;
    }
  }
  EXPECT_GT(claimed, 30);
  EXPECT_GT(refused, 30);
}

TEST(ProjectionProof, ClosedSurfacesAndTwoSheetsAreNotClaimed) {
  Soup ball;
  add_grid(ball, 12, 24, 0, kPi, 0, 2 * kPi, sphere);
  EXPECT_FALSE(check_mesh(ball.v, ball.t).embedded_by_projection);  // no boundary
  // two disjoint parallel squares: two boundary loops
  Soup two;
  add_grid(two, 3, 3, 0, 1, 0, 1, [](double u, double v) { return std::array<double, 3>{u, v, 0}; });
  add_grid(two, 3, 3, 0, 1, 0, 1, [](double u, double v) { return std::array<double, 3>{u, v, 1}; });
  const auto r = check_mesh(two.v, two.t);
  EXPECT_FALSE(r.embedded_by_projection);
  EXPECT_EQ(r.self_intersections, 0);
  // a square pierced by a separate triangle (two loops)
  Soup t;
  add_grid(t, 2, 2, 0, 1, 0, 1, [](double u, double v) { return std::array<double, 3>{u, v, 0}; });
  t.t.insert(t.t.end(), {t.add_vertex(0.1, 0.1, -0.5), t.add_vertex(0.4, 0.1, 0.5), t.add_vertex(0.1, 0.4, 0.5)});
  EXPECT_FALSE(check_mesh(t.v, t.t).embedded_by_projection);
  EXPECT_GE(check_mesh(t.v, t.t).self_intersections, 1);
  EXPECT_EQ(check_mesh(t.v, t.t).self_intersections, pairwise(t).self_intersections);
}

}  // namespace
}  // namespace bpde
