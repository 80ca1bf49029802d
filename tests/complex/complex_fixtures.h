#pragma once
// Layouts and complexes with a known surface, for the complex tests.
#include "bezierpde/core/eigen.h"
#include <Eigen/Dense>
#include <functional>

#include "bezierpde/complex/layout.h"
#include "bezierpde/complex/patch_complex.h"
#include "bezierpde/core/binomial.h"
#include "bezierpde/tensor/tensor_net.h"
#include "bezierpde/triangular/triangular_net.h"

namespace bpde::test {

using SurfaceFn = std::function<Eigen::Vector3d(double, double)>;

/// k x k unit squares over [0,k]^2 in the plane z = 0: tensor faces (a, b, c, d) counter-clockwise;
/// triangular faces (a, b, d) and (c, d, b), each with its right angle at its first vertex (the
/// patch's x(0,0)), so every patch is a similarity image of its reference domain.
inline Layout grid_layout(PatchKind kind, int k) {
  Layout L;
  L.kind = kind;
  L.vertices.resize((k + 1) * (k + 1), 3);
  for (int i = 0; i <= k; ++i)
    for (int j = 0; j <= k; ++j) L.vertices.row(i * (k + 1) + j) << i, j, 0;
  for (int i = 0; i < k; ++i)
    for (int j = 0; j < k; ++j) {
      const int a = i * (k + 1) + j, b = a + k + 1, c = b + 1, d = a + 1;
      if (kind == PatchKind::tensor) {
        L.faces.push_back({a, b, c, d});
      } else {
        L.faces.push_back({a, b, d});
        L.faces.push_back({c, d, b});
      }
    }
  return L;
}

/// The layout face's map from the patch domain: affine (triangles) or bilinear (quads).
inline Eigen::Vector2d face_map(const Layout& L, int f, double u, double v) {
  const auto& face = L.faces[f];
  auto X = [&](int k) { return Eigen::Vector2d(L.vertices(face[k], 0), L.vertices(face[k], 1)); };
  if (face.size() == 3) return X(0) + u * (X(1) - X(0)) + v * (X(2) - X(0));
  return (1 - u) * (1 - v) * X(0) + u * (1 - v) * X(1) + u * v * X(2) + (1 - u) * v * X(3);
}

inline double bern(int n, int i, double t) {
  return static_cast<double>(binomial(n, i)) * std::pow(t, i) * std::pow(1 - t, n - i);
}

/// Sets every patch of c (built by complex_topology(L, n)) to the interpolant of F∘(face map) at
/// the degree-n lattice: exact when F∘map is a polynomial of that degree.
inline void set_from_function(PatchComplex& c, const Layout& L, const SurfaceFn& F) {
  const int n = c.patches.front().degree;
  for (int f = 0; f < static_cast<int>(c.patches.size()); ++f) {
    const int N = patch_point_count(L.kind, n);
    Eigen::MatrixXd B(N, N);
    Eigen::MatrixX3d values(N, 3);
    for (int r = 0; r < N; ++r) {
      double u, v;
      if (L.kind == PatchKind::triangular) {
        const MultiIndex I = TriangularNet::multi_index(n, r);
        u = double(I[0]) / n, v = double(I[1]) / n;
        Eigen::MatrixX2d uv(1, 2);
        uv << u, v;
        B.row(r) = TriangularNet::basis_matrix(n, uv).row(0);
      } else {
        u = double(r / (n + 1)) / n, v = double(r % (n + 1)) / n;
        for (int q = 0; q < N; ++q) B(r, q) = bern(n, q / (n + 1), u) * bern(n, q % (n + 1), v);
      }
      const Eigen::Vector2d X = face_map(L, f, u, v);
      values.row(r) = F(X(0), X(1)).transpose();
    }
    set_patch_points(c, f, B.partialPivLu().solve(values));
  }
}

/// The point of the complex's patch f at (u, v).
inline Eigen::Vector3d patch_point(const PatchComplex& c, int f, double u, double v) {
  return c.patches[f].kind == PatchKind::triangular ? triangular_net(c, f).evaluate(u, v)
                                                    : tensor_net(c, f).evaluate(u, v);
}

}  // namespace bpde::test
