#pragma once
// §5 of Centella–Monterde–Moreno–Oset, "Two C¹-methods to generate Bézier surfaces from
// the boundary"): the C¹ boundary configurations of Figures IV–IX, as degree-(7,7) tensor nets
// whose outer two rings (boundary, i or j in {0, n}, and adjacent, i or j in {1, n−1}) are set;
// the interior is zero (the solvers ignore it).
//
// The paper prints no coordinates, only the verbal construction below; every number chosen here
// (radii, shifts, heights, the sphere piece) is ours and is stated in README.md.
//
// Shared notation: n = 7, c_k = −cos(πk/n), s_k = sin(πk/n) (k = 0..n): points equally spaced in
// angle on a unit semicircle, from −1 to +1.
//
//   cylinder-fig4   boundary and adjacent points on the half cylinder x² + z² = 1, z ≥ 0, axis y:
//                   P_ij = (−c_i, 2j/n − 1, s_i)  (equally spaced in angle and along the axis).
//   cylinder-fig5   as fig4, with the adjacent points next to the two circular boundaries
//                   (j = 1 and j = n−1, 2 <= i <= n−2) lowered by 0.5 in z. (Lowering the whole
//                   adjacent ring instead raises the tetraharmonic centre; see README.md.)
//   sphere-fig6     a degree-7 approximation of a piece of the unit sphere: tensor interpolation
//                   at the Chebyshev–Lobatto nodes of the graph (x, y, √(1 − x² − y²)) over
//                   [−½, ½]² (x = u − ½, y = v − ½); outer two rings kept. Of the pieces we tried
//                   (README.md) this one gives the paper's distances to the sphere most closely.
//   arch-fig7       four vertical semicircles over the sides of [−1,1]²:
//                   P_ij = (c_i, c_j, s_i + s_j − s_i s_j) on both rings (the boundary rows are
//                   exactly (c_i, ∓1, s_i), (∓1, c_j, s_j)); the adjacent ring follows the same
//                   "natural" pattern (a dome whose top is at the height of the arches, 1).
//   arch-fig8       same boundary; adjacent ring in the horizontal plane z = 1.25 above it:
//                   (c_i, c_j, 1.25).
//   arch2-fig9-rowK boundary: vertical semicircles (c_i, ∓1, s_i) on the sides j = 0, n and
//                   horizontal semicircles (∓(1 + s_j), c_j, 0) in z = 0 on the sides i = 0, n
//                   (bulging outwards). Adjacent ring: the neighbouring boundary point P moved by
//                   δ towards the centre of the base square, the origin: P − δ P/|P| (δ > 0
//                   interior, δ < 0 exterior); the ring's corners (1,1), ... take the mean of the
//                   two candidates from their two boundary neighbours (1,0) and (0,1).
//                   row1 δ = 0.25, row2 δ = 0.5 (interior), row3 δ = −0.25 (exterior).
#include "bezierpde/core/eigen.h"
#include <Eigen/Dense>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "bezierpde/core/bernstein.h"
#include "bezierpde/tensor/tensor_net.h"

namespace c1ex {

inline constexpr int kDegree = 7;

struct Configuration {
  std::string name;     ///< file stem, e.g. "arch-fig7"
  std::string figure;   ///< the paper's figure
  bpde::TensorNet net;  ///< outer two rings set, interior zero
};

inline double ck(int k, int n) { return -std::cos(std::numbers::pi * k / n); }
inline double sk(int k, int n) { return std::sin(std::numbers::pi * k / n); }

/// True for (i, j) in the outer two rings of a degree-(n,n) net.
inline bool in_outer_rings(int i, int j, int n) { return i <= 1 || j <= 1 || i >= n - 1 || j >= n - 1; }
inline bool on_boundary(int i, int j, int n) { return i == 0 || j == 0 || i == n || j == n; }

/// Net with the outer two rings given by f(i, j) (interior zero).
template <class F>
bpde::TensorNet rings_from(int n, F f) {
  bpde::TensorNet net(n, n);
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j <= n; ++j)
      if (in_outer_rings(i, j, n)) net.set_point(i, j, f(i, j));
  return net;
}

/// Degree-(n,n) tensor interpolant of s(u,v) at the Chebyshev–Lobatto nodes (1 − cos(kπ/n))/2.
template <class S>
bpde::TensorNet interpolate_tensor(int n, S s) {
  Eigen::MatrixXd A(n + 1, n + 1);
  std::vector<double> b(static_cast<size_t>(n + 1));
  std::vector<double> t(static_cast<size_t>(n + 1));
  for (int k = 0; k <= n; ++k) {
    t[static_cast<size_t>(k)] = 0.5 * (1 - std::cos(std::numbers::pi * k / n));
    bpde::bernstein_values(n, t[static_cast<size_t>(k)], b.data());
    for (int i = 0; i <= n; ++i) A(k, i) = b[static_cast<size_t>(i)];
  }
  const Eigen::PartialPivLU<Eigen::MatrixXd> lu(A);
  bpde::TensorNet net(n, n);
  for (int c = 0; c < 3; ++c) {
    Eigen::MatrixXd F(n + 1, n + 1);
    for (int a = 0; a <= n; ++a)
      for (int d = 0; d <= n; ++d) F(a, d) = s(t[static_cast<size_t>(a)], t[static_cast<size_t>(d)])(c);
    // A P A^T = F
    const Eigen::MatrixXd X = lu.solve(F);                          // P A^T
    const Eigen::MatrixXd P = lu.solve(X.transpose()).transpose();  // P
    for (int i = 0; i <= n; ++i)
      for (int j = 0; j <= n; ++j) {
        Eigen::Vector3d p = net.point(i, j);
        p(c) = P(i, j);
        net.set_point(i, j, p);
      }
  }
  return net;
}

/// The sphere piece of Fig. VI (our choice): the upper unit hemisphere as a graph over [−½, ½]².
inline Eigen::Vector3d sphere_piece(double u, double v) {
  const double x = u - 0.5, y = v - 0.5;
  return {x, y, std::sqrt(1 - x * x - y * y)};
}

inline bpde::TensorNet arch2_with_shift(int n, double delta) {
  auto b = [n](int i, int j) -> Eigen::Vector3d {
    if (j == 0) return {ck(i, n), -1, sk(i, n)};
    if (j == n) return {ck(i, n), 1, sk(i, n)};
    if (i == 0) return {-(1 + sk(j, n)), ck(j, n), 0};
    return {1 + sk(j, n), ck(j, n), 0};  // i == n
  };
  return rings_from(n, [&](int i, int j) -> Eigen::Vector3d {
    if (on_boundary(i, j, n)) return b(i, j);
    // candidates from the nearest boundary side(s), moved by delta towards the origin
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    int count = 0;
    auto add = [&](const Eigen::Vector3d& p) {
      sum += p - delta * p.normalized();
      ++count;
    };
    if (j == 1) add(b(i, 0));
    if (j == n - 1) add(b(i, n));
    if (i == 1) add(b(0, j));
    if (i == n - 1) add(b(n, j));
    return sum / count;
  });
}

/// All configurations of §5, in figure order.
inline std::vector<Configuration> configurations() {
  const int n = kDegree;
  std::vector<Configuration> out;
  auto cyl = [n](double lower) {
    return rings_from(n, [n, lower](int i, int j) -> Eigen::Vector3d {
      Eigen::Vector3d p(-ck(i, n), 2.0 * j / n - 1, sk(i, n));
      if ((j == 1 || j == n - 1) && i >= 2 && i <= n - 2) p.z() -= lower;
      return p;
    });
  };
  out.push_back({"cylinder-fig4", "IV", cyl(0.0)});
  out.push_back({"cylinder-fig5", "V", cyl(0.5)});
  {
    const bpde::TensorNet full = interpolate_tensor(n, sphere_piece);
    out.push_back({"sphere-fig6", "VI", rings_from(n, [&](int i, int j) { return full.point(i, j); })});
  }
  out.push_back({"arch-fig7", "VII", rings_from(n, [n](int i, int j) -> Eigen::Vector3d {
                   const double si = sk(i, n), sj = sk(j, n);
                   return {ck(i, n), ck(j, n), si + sj - si * sj};
                 })});
  out.push_back({"arch-fig8", "VIII", rings_from(n, [n](int i, int j) -> Eigen::Vector3d {
                   const double si = sk(i, n), sj = sk(j, n);
                   if (!on_boundary(i, j, n)) return {ck(i, n), ck(j, n), 1.25};
                   return {ck(i, n), ck(j, n), si + sj - si * sj};
                 })});
  out.push_back({"arch2-fig9-row1", "IX row 1", arch2_with_shift(n, 0.25)});
  out.push_back({"arch2-fig9-row2", "IX row 2", arch2_with_shift(n, 0.5)});
  out.push_back({"arch2-fig9-row3", "IX row 3", arch2_with_shift(n, -0.25)});
  return out;
}

}  // namespace c1ex
