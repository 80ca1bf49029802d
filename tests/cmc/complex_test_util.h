#pragma once
// Complexes built by hand for the tests of energies/complex_functionals.h and the solves on
// complexes: a patch split into four sub-patches (triangular: the midpoint split, the middle
// triangle turned by 180° so that every sub-patch keeps the orientation; tensor: the quadrants),
// with the linear map S from the patch's points to the complex's, and complexes from patches
// computed one by one whose shared points are merged by position.
#include "bezierpde/core/eigen.h"
#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "bezierpde/boundaries/reference_boundaries.h"
#include "bezierpde/complex/patch_complex.h"
#include "bezierpde/core/bernstein.h"
#include "bezierpde/tensor/tensor_net.h"
#include "bezierpde/triangular/triangular_net.h"

namespace bpde::testing {

/// The complex of a split and S (#complex points x #patch points): complex points = S P.
struct SplitComplex {
  PatchComplex complex;
  Eigen::MatrixXd S;
};

/// Rows of the stacked sub-patch matrices that are equal (to 1e-12) become one global row.
inline SplitComplex merge_rows(const std::vector<Eigen::MatrixXd>& subs, PatchKind kind, int n,
                               const std::vector<int>& patch_boundary) {
  SplitComplex out;
  std::vector<Eigen::RowVectorXd> rows;
  for (const Eigen::MatrixXd& Sp : subs) {
    ComplexPatch cp{kind, n, {}};
    for (Eigen::Index r = 0; r < Sp.rows(); ++r) {
      int g = -1;
      for (std::size_t q = 0; q < rows.size() && g < 0; ++q)
        if ((rows[q] - Sp.row(r)).cwiseAbs().maxCoeff() < 1e-12) g = static_cast<int>(q);
      if (g < 0) {
        g = static_cast<int>(rows.size());
        rows.push_back(Sp.row(r));
      }
      cp.points.push_back(g);
    }
    out.complex.patches.push_back(cp);
  }
  out.S.resize(static_cast<Eigen::Index>(rows.size()), subs.front().cols());
  for (std::size_t q = 0; q < rows.size(); ++q) out.S.row(static_cast<Eigen::Index>(q)) = rows[q];
  // A point of the complex is on the outer boundary when it depends on the patch's boundary only.
  for (std::size_t q = 0; q < rows.size(); ++q) {
    double inner = 0.0;
    for (Eigen::Index c = 0; c < out.S.cols(); ++c)
      if (!std::binary_search(patch_boundary.begin(), patch_boundary.end(), static_cast<int>(c)))
        inner += std::abs(rows[q](c));
    if (inner < 1e-13) out.complex.fixed.push_back(static_cast<int>(q));
  }
  out.complex.points = Eigen::MatrixX3d::Zero(out.S.rows(), 3);
  return out;
}

/// The midpoint split of a degree-n triangular patch: sub-triangle (O, O + e1, O + e2) in (u, v),
/// the sub-patch's points by interpolation at its lattice (exact: the restriction has degree n).
inline SplitComplex triangular_split(int n, const Eigen::MatrixX3d& P) {
  const int N = TriangularNet::count(n);
  Eigen::MatrixX2d lattice(N, 2);
  for (int r = 0; r < N; ++r) {
    const auto I = TriangularNet::multi_index(n, r);
    lattice.row(r) << double(I[0]) / n, double(I[1]) / n;
  }
  const Eigen::MatrixXd Bsub = TriangularNet::basis_matrix(n, lattice);
  const Eigen::PartialPivLU<Eigen::MatrixXd> lu(Bsub);
  const double h = 0.5;
  const std::vector<std::array<double, 6>> tris = {
      {0, 0, h, 0, 0, h}, {h, 0, h, 0, 0, h}, {0, h, h, 0, 0, h}, {h, h, -h, 0, 0, -h}};
  std::vector<Eigen::MatrixXd> subs;
  for (const auto& t : tris) {
    Eigen::MatrixX2d uv(N, 2);
    for (int r = 0; r < N; ++r)
      uv.row(r) << t[0] + lattice(r, 0) * t[2] + lattice(r, 1) * t[4], t[1] + lattice(r, 0) * t[3] + lattice(r, 1) * t[5];
    subs.push_back(lu.solve(TriangularNet::basis_matrix(n, uv)));
  }
  std::vector<int> bnd = TriangularNet(n).boundary_indices();
  std::sort(bnd.begin(), bnd.end());
  SplitComplex s = merge_rows(subs, PatchKind::triangular, n, bnd);
  s.complex.points = s.S * P;
  return s;
}

/// The quadrant split of a degree-(n, n) tensor patch.
inline SplitComplex tensor_split(int n, const Eigen::MatrixX3d& P) {
  Eigen::VectorXd t(n + 1);
  for (int k = 0; k <= n; ++k) t(k) = double(k) / n;
  const Eigen::MatrixXd T = bernstein_table(n, t);
  const Eigen::PartialPivLU<Eigen::MatrixXd> lu(T);
  std::vector<Eigen::MatrixXd> subs;
  for (double u0 : {0.0, 0.5})
    for (double v0 : {0.0, 0.5}) {
      const Eigen::MatrixXd Su = lu.solve(bernstein_table(n, (u0 + 0.5 * t.array()).matrix()));
      const Eigen::MatrixXd Sv = lu.solve(bernstein_table(n, (v0 + 0.5 * t.array()).matrix()));
      Eigen::MatrixXd S((n + 1) * (n + 1), (n + 1) * (n + 1));
      for (int i = 0; i <= n; ++i)
        for (int j = 0; j <= n; ++j)
          for (int k = 0; k <= n; ++k)
            for (int l = 0; l <= n; ++l) S(i * (n + 1) + j, k * (n + 1) + l) = Su(i, k) * Sv(j, l);
      subs.push_back(S);
    }
  std::vector<int> bnd = TensorNet(n, n).boundary_indices();
  std::sort(bnd.begin(), bnd.end());
  SplitComplex s = merge_rows(subs, PatchKind::tensor, n, bnd);
  s.complex.points = s.S * P;
  return s;
}

/// A complex from nets of one kind and degree given one by one: points within `tol` of each other
/// are one point of the complex; the rows listed in `fixed_local[p]` of patch p are fixed.
inline PatchComplex merge_nets(const std::vector<Eigen::MatrixX3d>& nets, PatchKind kind, int n,
                               const std::vector<std::vector<int>>& fixed_local, double tol = 1e-9) {
  PatchComplex c;
  std::vector<Eigen::RowVector3d> pts;
  for (std::size_t p = 0; p < nets.size(); ++p) {
    ComplexPatch cp{kind, n, {}};
    for (Eigen::Index r = 0; r < nets[p].rows(); ++r) {
      int g = -1;
      for (std::size_t q = 0; q < pts.size() && g < 0; ++q)
        if ((pts[q] - nets[p].row(r)).norm() < tol) g = static_cast<int>(q);
      if (g < 0) {
        g = static_cast<int>(pts.size());
        pts.push_back(nets[p].row(r));
      }
      cp.points.push_back(g);
    }
    c.patches.push_back(cp);
  }
  c.points.resize(static_cast<Eigen::Index>(pts.size()), 3);
  for (std::size_t q = 0; q < pts.size(); ++q) c.points.row(static_cast<Eigen::Index>(q)) = pts[q];
  for (std::size_t p = 0; p < nets.size(); ++p)
    for (int r : fixed_local[p]) c.fixed.push_back(c.patches[p].points[static_cast<std::size_t>(r)]);
  std::sort(c.fixed.begin(), c.fixed.end());
  c.fixed.erase(std::unique(c.fixed.begin(), c.fixed.end()), c.fixed.end());
  return c;
}

}  // namespace bpde::testing

namespace bpde::testing {

/// The unit circle (z = 0) as the outer edges of a fan of K degree-n triangular patches around a
/// free centre: patch k has P_00n at the centre (row 0), P_n00 at the circle's point of angle
/// 2πk/K and P_0n0 at 2π(k+1)/K (counter-clockwise seen from +z: x_u ∧ x_v points to +z), its
/// edge w = 0 the degree-n fit (fit_curve, Chebyshev–Lobatto interpolation) of the arc between.
/// Rows: the centre, the K radial edges (centre excluded, vertex last), the arcs' inner points,
/// the patches' inner points. Fixed: the arcs with their vertices. Free rows hold 0.
inline PatchComplex circle_fan(int K, int n) {
  PatchComplex c;
  const int radial0 = 1, arc0 = 1 + K * n, inner0 = arc0 + K * (n - 1);
  const int inner = (n - 1) * (n - 2) / 2;
  c.points = Eigen::MatrixX3d::Zero(inner0 + K * inner, 3);
  auto radial = [&](int k, int r) { return r == 0 ? 0 : radial0 + (k % K) * n + (r - 1); };
  for (int k = 0; k < K; ++k) {
    const double a0 = 2 * std::numbers::pi * k / K, a1 = 2 * std::numbers::pi * (k + 1) / K;
    const Eigen::MatrixX3d arc =
        fit_curve(n, [&](double t) { return Eigen::Vector3d(std::cos(a0 + (a1 - a0) * t), std::sin(a0 + (a1 - a0) * t), 0); });
    ComplexPatch p{PatchKind::triangular, n, std::vector<int>(static_cast<std::size_t>(TriangularNet::count(n)))};
    int next_inner = inner0 + k * inner;
    for (int r = 0; r < TriangularNet::count(n); ++r) {
      const auto I = TriangularNet::multi_index(n, r);  // (weight of vertex k, of vertex k + 1, of the centre)
      int g;
      if (I[1] == 0) g = radial(k, I[0]);
      else if (I[0] == 0) g = radial(k + 1, I[1]);
      else if (I[2] == 0) g = arc0 + k * (n - 1) + (I[1] - 1);
      else g = next_inner++;
      p.points[static_cast<std::size_t>(r)] = g;
      if (I[2] == 0) {
        c.points.row(g) = arc.row(I[1]);
        c.fixed.push_back(g);
      }
    }
    c.patches.push_back(p);
  }
  std::sort(c.fixed.begin(), c.fixed.end());
  c.fixed.erase(std::unique(c.fixed.begin(), c.fixed.end()), c.fixed.end());
  return c;
}

}  // namespace bpde::testing

namespace bpde::testing {

/// A ring of K degree-(n, n) tensor patches between the unit circles at z = ∓h: patch k spans the
/// angles 2πk/K … 2π(k+1)/K along u and z = −h … h along v (x_u ∧ x_v points outwards), its points
/// the interpolant (tensor lattice) of the cylinder (cos θ, sin θ, z) whose edges v = 0 and v = 1
/// are fitted arcs of the circles; those rows are fixed.
inline PatchComplex circle_ring(int K, int n, double h) {
  Eigen::VectorXd t(n + 1);
  for (int k = 0; k <= n; ++k) t(k) = double(k) / n;
  const Eigen::PartialPivLU<Eigen::MatrixXd> lu(bernstein_table(n, t));
  std::vector<Eigen::MatrixX3d> nets;
  std::vector<std::vector<int>> fixed;
  for (int k = 0; k < K; ++k) {
    const double a0 = 2 * std::numbers::pi * k / K, a1 = 2 * std::numbers::pi * (k + 1) / K;
    Eigen::MatrixX3d P((n + 1) * (n + 1), 3);
    for (int c = 0; c < 3; ++c) {
      Eigen::MatrixXd F(n + 1, n + 1);
      for (int i = 0; i <= n; ++i)
        for (int j = 0; j <= n; ++j) {
          const double a = a0 + (a1 - a0) * t(i);
          F(i, j) = c == 0 ? std::cos(a) : c == 1 ? std::sin(a) : -h + 2 * h * t(j);
        }
      const Eigen::MatrixXd C = lu.solve(lu.solve(F).transpose()).transpose();
      for (int i = 0; i <= n; ++i)
        for (int j = 0; j <= n; ++j) P(i * (n + 1) + j, c) = C(i, j);
    }
    nets.push_back(P);
    std::vector<int> f;
    for (int i = 0; i <= n; ++i) {
      f.push_back(i * (n + 1));
      f.push_back(i * (n + 1) + n);
    }
    fixed.push_back(f);
  }
  return merge_nets(nets, PatchKind::tensor, n, fixed);
}

}  // namespace bpde::testing
