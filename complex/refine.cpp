#include "bezierpde/complex/refine.h"

#include <algorithm>
#include <array>
#include <map>
#include <string>
#include <tuple>

#include "bezierpde/core/bernstein.h"
#include "bezierpde/core/errors.h"
#include "bezierpde/tensor/tensor_net.h"
#include "bezierpde/triangular/triangular_net.h"

namespace bpde {

namespace {

/// A refined patch before its rows are assigned: its parent, degree, local points and each
/// point's abscissa (a, b) on the parent's lattice of resolution D.
struct Part {
  int parent = 0, degree = 1;
  Eigen::MatrixX3d points;
  std::vector<std::array<int, 2>> abscissa;
};

/// The blossom b[p_1, ..., p_n] of a degree-n triangular net at the barycentric points p_l
/// (weights of u, v, w).
Eigen::Vector3d triangular_blossom(const Eigen::MatrixX3d& P, int n, const std::vector<Eigen::Vector3d>& p) {
  Eigen::MatrixX3d Q = P;
  for (int d = n; d >= 1; --d) {
    const Eigen::Vector3d& w = p[n - d];
    Eigen::MatrixX3d R(TriangularNet::count(d - 1), 3);
    for (int i = 0; i <= d - 1; ++i)
      for (int j = 0; i + j <= d - 1; ++j)
        R.row(TriangularNet::index(d - 1, i, j)) = w(0) * Q.row(TriangularNet::index(d, i + 1, j)) +
                                                   w(1) * Q.row(TriangularNet::index(d, i, j + 1)) +
                                                   w(2) * Q.row(TriangularNet::index(d, i, j));
    Q = std::move(R);
  }
  return Q.row(0).transpose();
}

/// (n+1) x (n+1) matrix S with S P the Bernstein coefficients of the restriction of the curve P
/// to [a, b]: row i is the blossom at (a^(n-i), b^i).
Eigen::MatrixXd subdivision_matrix(int n, double a, double b) {
  Eigen::MatrixXd S(n + 1, n + 1);
  for (int i = 0; i <= n; ++i) {
    Eigen::MatrixXd Q = Eigen::MatrixXd::Identity(n + 1, n + 1);  // rows: control points
    for (int d = n; d >= 1; --d) {
      const double t = (n - d) < n - i ? a : b;
      for (int k = 0; k < d; ++k) Q.row(k) = (1 - t) * Q.row(k) + t * Q.row(k + 1);
    }
    S.row(i) = Q.row(0);
  }
  return S;
}

std::vector<Part> split_triangular(const PatchComplex& c, int p) {
  const int n = c.patches[p].degree;
  const TriangularNet net = triangular_net(c, p);
  // domain points in half units: A, B, C, AB, BC, CA
  const std::array<Eigen::Vector2i, 6> q{Eigen::Vector2i(0, 0), Eigen::Vector2i(2, 0), Eigen::Vector2i(0, 2),
                                         Eigen::Vector2i(1, 0), Eigen::Vector2i(1, 1), Eigen::Vector2i(0, 1)};
  const std::array<std::array<int, 3>, 4> subs{{{0, 3, 5}, {3, 1, 4}, {5, 4, 2}, {4, 5, 3}}};
  std::vector<Part> parts;
  for (const auto& sub : subs) {
    Part part{p, n, Eigen::MatrixX3d(net.size(), 3), std::vector<std::array<int, 2>>(net.size())};
    std::array<Eigen::Vector3d, 3> bary;  // A', B', C' as (u, v, w)
    for (int k = 0; k < 3; ++k) {
      const Eigen::Vector2d uv = q[sub[k]].cast<double>() / 2.0;
      bary[k] = Eigen::Vector3d(uv(0), uv(1), 1 - uv(0) - uv(1));
    }
    for (int r = 0; r < net.size(); ++r) {
      const MultiIndex I = TriangularNet::multi_index(n, r);
      std::vector<Eigen::Vector3d> args;
      args.insert(args.end(), I[0], bary[1]);
      args.insert(args.end(), I[1], bary[2]);
      args.insert(args.end(), I[2], bary[0]);
      part.points.row(r) = triangular_blossom(net.points(), n, args).transpose();
      const Eigen::Vector2i X = I[0] * q[sub[1]] + I[1] * q[sub[2]] + I[2] * q[sub[0]];
      part.abscissa[r] = {X(0), X(1)};
    }
    parts.push_back(std::move(part));
  }
  return parts;
}

std::vector<Part> split_tensor(const PatchComplex& c, int p) {
  const int n = c.patches[p].degree;
  const TensorNet net = tensor_net(c, p);
  const Eigen::MatrixXd S0 = subdivision_matrix(n, 0, 0.5), S1 = subdivision_matrix(n, 0.5, 1);
  const std::array<std::array<int, 2>, 4> quarters{{{0, 0}, {1, 0}, {1, 1}, {0, 1}}};
  std::vector<Part> parts;
  for (const auto& [qu, qv] : quarters) {
    const Eigen::MatrixXd& Su = qu ? S1 : S0;
    const Eigen::MatrixXd& Sv = qv ? S1 : S0;
    Part part{p, n, Eigen::MatrixX3d(net.size(), 3), std::vector<std::array<int, 2>>(net.size())};
    for (int c3 = 0; c3 < 3; ++c3) {
      const Eigen::MatrixXd G = net.points().col(c3).reshaped<Eigen::RowMajor>(n + 1, n + 1);  // G(i, j) = P_ij
      const Eigen::MatrixXd H = Su * G * Sv.transpose();
      part.points.col(c3) = H.reshaped<Eigen::RowMajor>();
    }
    for (int i = 0; i <= n; ++i)
      for (int j = 0; j <= n; ++j) part.abscissa[i * (n + 1) + j] = {qu * n + i, qv * n + j};
    parts.push_back(std::move(part));
  }
  return parts;
}

/// Assigns rows to the parts (the header's row sharing) on the parent lattice of resolution D.
PatchComplex assemble(const PatchComplex& c, const std::vector<Part>& parts, int D) {
  const std::vector<ComplexEdge> edges = complex_edges(c);
  std::map<std::pair<int, int>, std::pair<int, bool>> side_of;
  std::vector<bool> edge_fixed(edges.size());
  for (int k = 0; k < static_cast<int>(edges.size()); ++k) {
    for (const ComplexEdge::Side& s : edges[k].sides) side_of[{s.patch, s.edge}] = {k, s.reversed};
    edge_fixed[k] = std::all_of(edges[k].rows.begin(), edges[k].rows.end(),
                                [&](int r) { return std::binary_search(c.fixed.begin(), c.fixed.end(), r); });
  }
  const PatchKind kind = c.patches.front().kind;
  const int n_old = c.patches.front().degree;
  std::map<std::tuple<int, int, int, int>, int> rows;
  std::vector<Eigen::Vector3d> points;
  std::vector<int> fixed;
  PatchComplex out;
  for (const Part& part : parts) {
    ComplexPatch patch{kind, part.degree, std::vector<int>(part.abscissa.size())};
    for (std::size_t r = 0; r < part.abscissa.size(); ++r) {
      const auto [a, b] = part.abscissa[r];
      const auto [e, s] = patch_lattice_edge(kind, D, a, b);
      std::tuple<int, int, int, int> key{2, part.parent, a, b};
      bool is_fixed = false;
      if (e >= 0 && (s == 0 || s == D)) {
        const int corner = c.patches[part.parent].points[patch_edge_local_rows(kind, n_old, e)[s == 0 ? 0 : n_old]];
        key = {0, corner, 0, 0};
        is_fixed = std::binary_search(c.fixed.begin(), c.fixed.end(), corner);
      } else if (e >= 0) {
        const auto [edge, reversed] = side_of.at({part.parent, e});
        key = {1, edge, reversed ? D - s : s, 0};
        is_fixed = edge_fixed[edge];
      }
      auto [it, added] = rows.emplace(key, static_cast<int>(points.size()));
      if (added) {
        points.push_back(part.points.row(r).transpose());
        if (is_fixed) fixed.push_back(it->second);
      }
      patch.points[r] = it->second;
    }
    out.patches.push_back(std::move(patch));
  }
  out.points.resize(points.size(), 3);
  for (std::size_t k = 0; k < points.size(); ++k) out.points.row(k) = points[k].transpose();
  std::sort(fixed.begin(), fixed.end());
  out.fixed = std::move(fixed);
  return out;
}

}  // namespace

PatchComplex refine_h(const PatchComplex& c) {
  validate(c);
  if (4 * c.patches.size() > static_cast<std::size_t>(kMaxComplexPatches))
    throw SizeError("refining " + std::to_string(c.patches.size()) + " patches in h gives more than " +
                    std::to_string(kMaxComplexPatches));
  std::vector<Part> parts;
  for (int p = 0; p < static_cast<int>(c.patches.size()); ++p) {
    std::vector<Part> sub = c.patches[p].kind == PatchKind::triangular ? split_triangular(c, p) : split_tensor(c, p);
    parts.insert(parts.end(), sub.begin(), sub.end());
  }
  return assemble(c, parts, 2 * c.patches.front().degree);
}

PatchComplex refine_p(const PatchComplex& c, int r) {
  validate(c);
  const int n = c.patches.front().degree;
  if (r < 0 || n + r > kMaxDegree)
    throw DegreeError("degree elevation by " + std::to_string(r) + " from " + std::to_string(n) + " outside 0.." +
                      std::to_string(kMaxDegree - n));
  const int m = n + r;
  std::vector<Part> parts;
  for (int p = 0; p < static_cast<int>(c.patches.size()); ++p) {
    Part part{p, m, {}, {}};
    if (c.patches[p].kind == PatchKind::triangular) {
      part.points = triangular_net(c, p).elevated(r).points();
      for (int k = 0; k < TriangularNet::count(m); ++k) {
        const MultiIndex I = TriangularNet::multi_index(m, k);
        part.abscissa.push_back({I[0], I[1]});
      }
    } else {
      part.points = tensor_net(c, p).elevated(r, r).points();
      for (int k = 0; k < (m + 1) * (m + 1); ++k) part.abscissa.push_back({k / (m + 1), k % (m + 1)});
    }
    parts.push_back(std::move(part));
  }
  return assemble(c, parts, m);
}

}  // namespace bpde
