// STEP export (io/step_export.h): the exact patch of each kind of net, read back by OpenCASCADE's
// STEPControl_Reader and compared with the net's own evaluation; and the triangular net's exact
// tensor form (triangular/tensor_form.h) against closed forms.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <random>

#include "bezierpde/core/errors.h"
#include "bezierpde/io/step_export.h"
#include "bezierpde/triangular/tensor_form.h"

using namespace bpde;
namespace fs = std::filesystem;

namespace {

fs::path scratch(const std::string& name) {
  const fs::path d = fs::temp_directory_path() / ("bpde_step_" + std::to_string(::getpid()));
  fs::create_directories(d);
  return d / name;
}

Eigen::MatrixX3d random_points(int rows, unsigned seed) {
  std::mt19937 g(seed);
  std::uniform_real_distribution<double> d(-2.0, 3.0);
  Eigen::MatrixX3d P(rows, 3);
  for (int r = 0; r < rows; ++r) P.row(r) << d(g), d(g), d(g);
  return P;
}

TriangularNet random_triangular(int n, unsigned seed) {
  TriangularNet t(n);
  t.points() = random_points((n + 1) * (n + 2) / 2, seed);
  return t;
}

Eigen::MatrixX2d grid(double u0, double u1, double v0, double v1, int N) {
  Eigen::MatrixX2d uv((N + 1) * (N + 1), 2);
  for (int a = 0; a <= N; ++a)
    for (int b = 0; b <= N; ++b) uv.row(a * (N + 1) + b) << u0 + (u1 - u0) * a / N, v0 + (v1 - v0) * b / N;
  return uv;
}

// max |read - expected| over the grid, relative to the largest |expected|
template <class Eval>
double relative_error(const StepReadBack& r, const Eigen::MatrixX2d& uv, Eval&& expected) {
  double err = 0, scale = 0;
  for (Eigen::Index k = 0; k < uv.rows(); ++k) {
    const Eigen::Vector3d x = expected(uv(k, 0), uv(k, 1));
    err = std::max(err, (r.points.row(k).transpose() - x).norm());
    scale = std::max(scale, x.norm());
  }
  return err / scale;
}

}  // namespace

TEST(TensorForm, EvaluatesTheTriangleThroughTheDuffyMap) {
  for (int n = 1; n <= 9; ++n) {
    const TriangularNet t = random_triangular(n, 40u + n);
    const TensorNet q = tensor_form(t);
    ASSERT_EQ(q.n(), n);
    ASSERT_EQ(q.m(), n);
    for (int a = 0; a <= 8; ++a)
      for (int b = 0; b <= 8; ++b) {
        const double s = a / 8.0, tt = b / 8.0;
        EXPECT_LT((q.evaluate(s, tt) - t.evaluate(s, (1 - s) * tt)).norm(), 1e-13) << n << " " << s << " " << tt;
      }
    // the edge s = 1 is collapsed onto P_{n00}, bit for bit; the corners are the triangle's
    for (int b = 0; b <= n; ++b) EXPECT_EQ(q.point(n, b), t.point(n, 0));
    EXPECT_EQ(q.point(0, 0), t.point(0, 0));  // P_{00n}
    EXPECT_EQ(q.point(0, n), t.point(0, n));  // P_{0n0}
  }
}

TEST(TensorForm, ClosedFormForTheLinearPatch) {
  // P_I = (i/n, j/n, 0) is the patch (u, v, 0) (linear precision); its tensor form is
  // (s, (1-s)t, 0), whose Bernstein coefficients at degree (n, n) are (i/n, (n-i) b/n^2, 0).
  for (int n = 1; n <= 12; ++n) {
    TriangularNet t(n);
    for (int i = 0; i <= n; ++i)
      for (int j = 0; j <= n - i; ++j) t.set_point(i, j, Eigen::Vector3d(double(i) / n, double(j) / n, 0));
    const TensorNet q = tensor_form(t);
    for (int i = 0; i <= n; ++i)
      for (int b = 0; b <= n; ++b) {
        EXPECT_NEAR(q.point(i, b)(0), double(i) / n, 1e-15);
        EXPECT_NEAR(q.point(i, b)(1), double((n - i) * b) / (n * n), 1e-15) << n << " " << i << " " << b;
        EXPECT_EQ(q.point(i, b)(2), 0.0);
      }
  }
}

TEST(StepExport, TensorNetReadsBackAsTheSameBezierSurface) {
  const TensorNet t(4, 3, random_points(5 * 4, 7));
  const fs::path p = scratch("tensor.step");
  write_step(p.string(), Net(t));
  const Eigen::MatrixX2d uv = grid(0, 1, 0, 1, 12);
  const StepReadBack r = read_step(p.string(), uv);
  EXPECT_EQ(r.faces, 1);
  EXPECT_TRUE(r.surface == "bezier" || r.surface == "bspline") << r.surface;
  EXPECT_EQ(r.u_degree, 4);
  EXPECT_EQ(r.v_degree, 3);
  EXPECT_DOUBLE_EQ(r.u0, 0.0);
  EXPECT_DOUBLE_EQ(r.u1, 1.0);
  EXPECT_DOUBLE_EQ(r.v0, 0.0);
  EXPECT_DOUBLE_EQ(r.v1, 1.0);
  EXPECT_LT(relative_error(r, uv, [&](double u, double v) { return t.evaluate(u, v); }), 1e-12);
}

TEST(StepExport, BSplineNetReadsBackWithItsKnots) {
  const std::vector<double> U = {0, 0, 0, 0.25, 0.25, 0.7, 1, 1, 1}, V = {-1, -1, -1, -1, 0.5, 2, 2, 2, 2};
  const BSplineNet b(2, 3, U, V, random_points(6 * 5, 11));
  const fs::path p = scratch("bspline.step");
  write_step(p.string(), Net(b));
  const Eigen::MatrixX2d uv = grid(0, 1, -1, 2, 15);
  const StepReadBack r = read_step(p.string(), uv);
  EXPECT_EQ(r.faces, 1);
  EXPECT_EQ(r.surface, "bspline");
  EXPECT_EQ(r.u_degree, 2);
  EXPECT_EQ(r.v_degree, 3);
  EXPECT_DOUBLE_EQ(r.u0, 0.0);
  EXPECT_DOUBLE_EQ(r.u1, 1.0);
  EXPECT_DOUBLE_EQ(r.v0, -1.0);
  EXPECT_DOUBLE_EQ(r.v1, 2.0);
  EXPECT_LT(relative_error(r, uv, [&](double u, double v) { return b.evaluate(u, v); }), 1e-12);
}

TEST(StepExport, BSplineKnotOfFullMultiplicityIsLoweredWhereTheSurfaceIsContinuous) {
  // Interior knots of multiplicity degree + 1 (0.5 in u at degree 1, 0.3 in v at degree 2), which
  // OpenCASCADE refuses: where the control points on either side are equal, the knot is written
  // once less and the surface reads back the same.
  const std::vector<double> U = {0, 0, 0.5, 0.5, 1, 1}, V = {0, 0, 0, 0.3, 0.3, 0.3, 1, 1, 1};
  const int nu = 4, nv = 6;
  Eigen::MatrixX3d P = random_points(nu * nv, 21);
  for (int j = 0; j < nv; ++j) P.row(2 * nv + j) = P.row(1 * nv + j);  // rows u = 1, 2 equal
  for (int i = 0; i < nu; ++i) P.row(i * nv + 3) = P.row(i * nv + 2);  // columns v = 2, 3 equal
  const BSplineNet b(1, 2, U, V, P);
  const fs::path p = scratch("bspline_full_multiplicity.step");
  write_step(p.string(), Net(b));
  const Eigen::MatrixX2d uv = grid(0, 1, 0, 1, 20);  // holds u = 0.5 and v = 0.3 on either side
  const StepReadBack r = read_step(p.string(), uv);
  EXPECT_EQ(r.faces, 1);
  EXPECT_EQ(r.surface, "bspline");
  EXPECT_EQ(r.u_degree, 1);
  EXPECT_EQ(r.v_degree, 2);
  EXPECT_LT(relative_error(r, uv, [&](double u, double v) { return b.evaluate(u, v); }), 1e-12);
  // the surface jumps where the control points differ: one face cannot hold it (exit 2)
  P.row(2 * nv + 4) += Eigen::RowVector3d(0, 0, 1);
  const fs::path q = scratch("bspline_jump.step");
  fs::remove(q);
  EXPECT_THROW(write_step(q.string(), Net(BSplineNet(1, 2, U, V, P))), UnsupportedProblem);
  EXPECT_FALSE(fs::exists(q));
  Eigen::MatrixX3d Q = random_points(nu * nv, 22);
  for (int j = 0; j < nv; ++j) Q.row(2 * nv + j) = Q.row(1 * nv + j);  // continuous in u, a jump in v
  EXPECT_THROW(write_step(q.string(), Net(BSplineNet(1, 2, U, V, Q))), UnsupportedProblem);
}

TEST(StepExport, TriangularNetReadsBackAsTheDegenerateTensorPatch) {
  for (int n : {1, 4, 7}) {
    const TriangularNet t = random_triangular(n, 100u + n);
    const fs::path p = scratch("tri" + std::to_string(n) + ".step");
    write_step(p.string(), Net(t));
    const Eigen::MatrixX2d uv = grid(0, 1, 0, 1, 12);
    const StepReadBack r = read_step(p.string(), uv);
    EXPECT_EQ(r.faces, 1);
    EXPECT_EQ(r.u_degree, n);
    EXPECT_EQ(r.v_degree, n);
    EXPECT_LT(relative_error(r, uv, [&](double s, double tt) { return t.evaluate(s, (1 - s) * tt); }), 1e-12) << n;
    // the collapsed edge s = 1 is the corner P_{n00}
    const Eigen::MatrixX2d edge = (Eigen::MatrixX2d(3, 2) << 1, 0, 1, 0.5, 1, 1).finished();
    const StepReadBack e = read_step(p.string(), edge);
    for (int k = 0; k < 3; ++k)
      EXPECT_LT((e.points.row(k).transpose() - t.point(n, 0)).norm(), 1e-12 * (1 + t.point(n, 0).norm()));
  }
}

TEST(StepExport, RefusesDegreesOpenCascadeCannotHoldAndUnwritablePaths) {
  EXPECT_THROW(write_step(scratch("big.step").string(), Net(TensorNet(26, 2))), DegreeError);
  EXPECT_THROW(write_step(scratch("big_tri.step").string(), Net(TriangularNet(26))), DegreeError);
  EXPECT_FALSE(fs::exists(scratch("big.step")));
  EXPECT_NO_THROW(write_step(scratch("max.step").string(), Net(TensorNet(25, 25, random_points(26 * 26, 3)))));
  EXPECT_THROW(write_step("/nonexistent-dir/x.step", Net(TensorNet(2, 2))), FileError);
  EXPECT_THROW(read_step(scratch("missing.step").string(), Eigen::MatrixX2d(0, 2)), FileError);
}

TEST(StepExport, KeepsTwelveDigitsAtAnyScale) {
  // the file's numbers are relative to the net's size, whatever its unit
  for (double scale : {1e-4, 1.0, 1e5}) {
    const TensorNet t(3, 3, scale * random_points(16, 5));
    const fs::path p = scratch("scaled.step");
    write_step(p.string(), Net(t));
    const Eigen::MatrixX2d uv = grid(0, 1, 0, 1, 6);
    const StepReadBack r = read_step(p.string(), uv);
    EXPECT_LT(relative_error(r, uv, [&](double u, double v) { return t.evaluate(u, v); }), 1e-12) << scale;
  }
}

TEST(StepExport, PluginIsFoundBesideTheLibraryOrWhereTheEnvironmentSays) {
  const std::vector<std::string> candidates = step_plugin_candidates();
  ASSERT_FALSE(candidates.empty());
  const std::string loaded = step_plugin_path();
  EXPECT_TRUE(fs::is_regular_file(loaded));
  EXPECT_NE(std::find(candidates.begin(), candidates.end(), loaded), candidates.end());
  // the environment variable replaces the search (the loaded plugin stays loaded)
  ASSERT_EQ(setenv("BPDE_STEP_PLUGIN", "/nonexistent/plugin.so", 1), 0);
  EXPECT_EQ(step_plugin_candidates(), std::vector<std::string>{"/nonexistent/plugin.so"});
  ASSERT_EQ(unsetenv("BPDE_STEP_PLUGIN"), 0);
  EXPECT_EQ(step_plugin_candidates(), candidates);
}
