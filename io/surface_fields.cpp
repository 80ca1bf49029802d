#include "bezierpde/io/surface_fields.h"

#include "bezierpde/core/eigen.h"
#include <Eigen/Geometry>
#include <cmath>
#include <string>

#include "bezierpde/core/differential_geometry.h"
#include "bezierpde/core/errors.h"

namespace bpde {

int sampled_resolution(const Net& net, const TriangleMesh& mesh) {
  const long nv = static_cast<long>(mesh.V.rows());
  if (std::holds_alternative<TriangularNet>(net)) {
    // (N+1)(N+2)/2 = nv
    const long N = std::lround((std::sqrt(8.0 * static_cast<double>(nv) + 1.0) - 3.0) / 2.0);
    if (N >= 1 && (N + 1) * (N + 2) / 2 == nv) return static_cast<int>(N);
  } else {
    const long N = std::lround(std::sqrt(static_cast<double>(nv))) - 1;
    if (N >= 1 && (N + 1) * (N + 1) == nv) return static_cast<int>(N);
  }
  throw InternalError("surface fields: a mesh of " + std::to_string(nv) + " vertices is not a sampling of a " +
                      net_kind(net) + " net");
}

Eigen::MatrixX2d sample_parameters(const Net& net, int N) {
  if (std::holds_alternative<TriangularNet>(net)) {
    Eigen::MatrixX2d uv((N + 1) * (N + 2) / 2, 2);
    int k = 0;
    for (int a = 0; a <= N; ++a)
      for (int b = 0; b <= N - a; ++b, ++k) uv.row(k) << static_cast<double>(a) / N, static_cast<double>(b) / N;
    return uv;
  }
  double u0 = 0, u1 = 1, v0 = 0, v1 = 1;
  const bool bspline = std::holds_alternative<BSplineNet>(net);
  if (bspline) {
    const auto& b = std::get<BSplineNet>(net);
    u0 = b.u_min(), u1 = b.u_max(), v0 = b.v_min(), v1 = b.v_max();
  }
  Eigen::VectorXd tu(N + 1), tv(N + 1);
  for (int a = 0; a <= N; ++a) {  // the formulas of sample_mesh, so that the parameters are bit-equal
    tu(a) = bspline ? u0 + (u1 - u0) * a / N : static_cast<double>(a) / N;
    tv(a) = bspline ? v0 + (v1 - v0) * a / N : static_cast<double>(a) / N;
  }
  Eigen::MatrixX2d uv((N + 1) * (N + 1), 2);
  for (int a = 0; a <= N; ++a)
    for (int b = 0; b <= N; ++b) uv.row(a * (N + 1) + b) << tu(a), tv(b);
  return uv;
}

SurfaceFields surface_fields(const Net& net, const TriangleMesh& mesh) {
  const int N = sampled_resolution(net, mesh);
  const Eigen::Index nv = mesh.V.rows();
  SurfaceFields out;
  out.uv = sample_parameters(net, N);
  out.normal.setZero(nv, 3);
  out.H.setZero(nv);
  out.K.setZero(nv);
  out.regular.setZero(nv);
  // The jets at the vertices, tabulated as sample_mesh tabulates them: one Bernstein table per
  // derivative for tensor and triangular nets, one B-spline basis table per direction and
  // derivative for bspline nets.
  auto classify = [&](Eigen::Index k, const SurfaceJet& jet) {
    const double cross = jet.xu.cross(jet.xv).norm(), scale = jet.xu.norm() * jet.xv.norm();
    if (!(scale > 0) || !(cross >= kRegularSine * scale)) return;
    const FundamentalForms f = fundamental_forms(jet);
    if (!f.regular || !std::isfinite(f.K) || !std::isfinite(f.H)) return;
    out.regular(k) = 1;
    out.normal.row(k) = f.normal.transpose();
    out.K(k) = f.K;
    out.H(k) = k < mesh.H.size() && std::isfinite(mesh.H(k)) ? mesh.H(k) : f.H;
  };
  auto tabulated = [&](const Eigen::MatrixX3d& Xu, const Eigen::MatrixX3d& Xv, const Eigen::MatrixX3d& Xuu,
                       const Eigen::MatrixX3d& Xuv, const Eigen::MatrixX3d& Xvv) {
    for (Eigen::Index k = 0; k < nv; ++k) {
      SurfaceJet jet;
      jet.xu = Xu.row(k).transpose(), jet.xv = Xv.row(k).transpose();
      jet.xuu = Xuu.row(k).transpose(), jet.xuv = Xuv.row(k).transpose(), jet.xvv = Xvv.row(k).transpose();
      classify(k, jet);
    }
  };
  if (const auto* t = std::get_if<TensorNet>(&net)) {
    Eigen::VectorXd g(N + 1);
    for (int a = 0; a <= N; ++a) g(a) = static_cast<double>(a) / N;
    tabulated(t->evaluate_grid(g, g, 1, 0), t->evaluate_grid(g, g, 0, 1), t->evaluate_grid(g, g, 2, 0),
              t->evaluate_grid(g, g, 1, 1), t->evaluate_grid(g, g, 0, 2));
  } else if (const auto* tr = std::get_if<TriangularNet>(&net)) {
    const int n = tr->n();
    auto D = [&](int du, int dv) -> Eigen::MatrixX3d {
      if (du + dv > n) return Eigen::MatrixX3d::Zero(nv, 3);
      return TriangularNet::basis_matrix(n - du - dv, out.uv) * tr->derivative_points(du, dv);
    };
    tabulated(D(1, 0), D(0, 1), D(2, 0), D(1, 1), D(0, 2));
  } else {
    // the grid products of sample_mesh(BSplineNet): basis tables of the sample parameters in each
    // direction, Bu (P Bv^T) per coordinate
    const auto& b = std::get<BSplineNet>(net);
    Eigen::VectorXd tu(N + 1), tv(N + 1);
    for (int a = 0; a <= N; ++a) tu(a) = out.uv(a * (N + 1), 0), tv(a) = out.uv(a, 1);
    using RowMat = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
    auto grid = [&](int du, int dv) {
      const Eigen::MatrixXd Bu = BSplineNet::basis_table(b.p(), b.knots_u(), tu, du);
      const Eigen::MatrixXd Bv = BSplineNet::basis_table(b.q(), b.knots_v(), tv, dv);
      Eigen::MatrixX3d X((N + 1) * (N + 1), 3);
      for (int c = 0; c < 3; ++c) {
        const Eigen::Map<const RowMat, 0, Eigen::OuterStride<>> Pc(b.points().col(c).data(), b.nu(), b.nv(),
                                                                   Eigen::OuterStride<>(b.nv()));
        Eigen::Map<RowMat>(X.col(c).data(), N + 1, N + 1) = Bu * (Pc * Bv.transpose());
      }
      return X;
    };
    tabulated(grid(1, 0), grid(0, 1), grid(2, 0), grid(1, 1), grid(0, 2));
  }
  // Irregular vertices, ring by ring: first those with a regular neighbour get the mean over their
  // regular neighbours; then those next to a vertex filled in an earlier ring get the mean over
  // those, and so on, so that no irregular vertex inside a wide degenerate corner keeps 0.
  Eigen::Matrix<std::uint8_t, Eigen::Dynamic, 1> known = out.regular;
  for (Eigen::Index filled = 1; filled > 0;) {
    filled = 0;
    Eigen::VectorXd count = Eigen::VectorXd::Zero(nv), Hs = Eigen::VectorXd::Zero(nv), Ks = Eigen::VectorXd::Zero(nv);
    Eigen::MatrixX3d Ns = Eigen::MatrixX3d::Zero(nv, 3);
    for (Eigen::Index t = 0; t < mesh.F.rows(); ++t)
      for (int a = 0; a < 3; ++a)
        for (int b = 0; b < 3; ++b) {
          const int i = mesh.F(t, a), j = mesh.F(t, b);
          if (known(i) || !known(j)) continue;
          // a neighbour shared by two triangles counts twice: a weight, not an error
          count(i) += 1;
          Hs(i) += out.H(j);
          Ks(i) += out.K(j);
          Ns.row(i) += out.normal.row(j);
        }
    for (Eigen::Index k = 0; k < nv; ++k) {
      if (known(k) || !(count(k) > 0)) continue;
      out.H(k) = Hs(k) / count(k);
      out.K(k) = Ks(k) / count(k);
      const double len = Ns.row(k).norm();
      if (len > 0) out.normal.row(k) = Ns.row(k) / len;
      known(k) = 1;
      ++filled;
    }
  }
  for (Eigen::Index k = 0; k < nv; ++k)
    if (!(out.normal.row(k).norm() > 0)) out.normal.row(k) << 0, 0, 1;
  return out;
}

}  // namespace bpde
