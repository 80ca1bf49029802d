#pragma once
// First and second fundamental forms and curvatures from the derivatives of a parametrisation.
//
// Conventions (FORMATS.md, "Orientation and curvature"):
//   N = x_u ^ x_v / |x_u ^ x_v|,  E,F,G = <x_u,x_u>, <x_u,x_v>, <x_v,x_v>,
//   e,f,g = <x_uu,N>, <x_uv,N>, <x_vv,N>,
//   K = (eg - f^2)/(EG - F^2),  H = (eG - 2fF + gE) / (2(EG - F^2)).
// So z = u^2 + v^2 has H = +2 at the origin.
#include "bezierpde/core/eigen.h"
#include <Eigen/Core>
#include <cmath>

namespace bpde {

/// Position and derivatives up to order two of a surface at one parameter point.
struct SurfaceJet {
  Eigen::Vector3d x = Eigen::Vector3d::Zero();
  Eigen::Vector3d xu = Eigen::Vector3d::Zero(), xv = Eigen::Vector3d::Zero();
  Eigen::Vector3d xuu = Eigen::Vector3d::Zero(), xuv = Eigen::Vector3d::Zero(), xvv = Eigen::Vector3d::Zero();
};

/// Differential geometry at one point. When the parametrisation is singular there
/// (|x_u ^ x_v| <= 1e-14 (|x_u| |x_v|), or a zero derivative) `regular` is false and the normal,
/// second fundamental form and curvatures are set to 0: they are never NaN.
struct FundamentalForms {
  bool regular = false;
  Eigen::Vector3d normal = Eigen::Vector3d::Zero();
  double E = 0, F = 0, G = 0;  ///< first fundamental form
  double e = 0, f = 0, g = 0;  ///< second fundamental form
  double K = 0;                ///< Gaussian curvature
  double H = 0;                ///< mean curvature
};

FundamentalForms fundamental_forms(const SurfaceJet& jet);

}  // namespace bpde

namespace bpde {

/// Mean curvature for sampled files: H of `jet` when it is regular; otherwise the H of
/// geometry_at(h) (the point nudged by the fraction h towards the domain's centre) for
/// h = 1e-7, 1e-5, 1e-3, 1e-2, the first regular one; 0 if none is. Never NaN.
template <class GeometryAt>
double mean_curvature_robust(const SurfaceJet& jet, GeometryAt&& geometry_at) {
  FundamentalForms f = fundamental_forms(jet);
  if (f.regular) return f.H;
  for (double h : {1e-7, 1e-5, 1e-3, 1e-2}) {
    f = geometry_at(h);
    if (f.regular) return f.H;
  }
  return 0.0;
}

}  // namespace bpde

namespace bpde {

/// Mean curvature at every sample from the sampled derivatives (one row per sample), with the
/// fallback of mean_curvature_robust: geometry_at(k, h) evaluates sample k nudged by the
/// fraction h towards the domain's centre. If `regular` is given it is resized to #samples and
/// set to 1 where the sample itself is regular with a finite H (fundamental_forms), else 0.
template <class GeometryAt>
Eigen::VectorXd sampled_mean_curvature(const Eigen::MatrixX3d& X, const Eigen::MatrixX3d& Xu,
                                       const Eigen::MatrixX3d& Xv, const Eigen::MatrixX3d& Xuu,
                                       const Eigen::MatrixX3d& Xuv, const Eigen::MatrixX3d& Xvv,
                                       GeometryAt&& geometry_at,
                                       Eigen::Matrix<unsigned char, Eigen::Dynamic, 1>* regular = nullptr) {
  Eigen::VectorXd H(X.rows());
  if (regular) regular->resize(X.rows());
  for (Eigen::Index k = 0; k < X.rows(); ++k) {
    const SurfaceJet j{X.row(k).transpose(),   Xu.row(k).transpose(),  Xv.row(k).transpose(),
                       Xuu.row(k).transpose(), Xuv.row(k).transpose(), Xvv.row(k).transpose()};
    const FundamentalForms f = fundamental_forms(j);
    const bool ok = f.regular && std::isfinite(f.H);
    if (regular) (*regular)(k) = ok ? 1 : 0;
    H(k) = f.regular ? f.H : mean_curvature_robust(j, [&](double h) { return geometry_at(k, h); });
  }
  return H;
}

}  // namespace bpde

namespace bpde {

/// Position and derivatives up to order two of any surface type with evaluate(u, v) and
/// derivative(u, v, du, dv) (tensor, triangular and B-spline nets).
template <class Surface>
SurfaceJet surface_jet(const Surface& s, double u, double v) {
  SurfaceJet j;
  j.x = s.evaluate(u, v);
  j.xu = s.derivative(u, v, 1, 0);
  j.xv = s.derivative(u, v, 0, 1);
  j.xuu = s.derivative(u, v, 2, 0);
  j.xuv = s.derivative(u, v, 1, 1);
  j.xvv = s.derivative(u, v, 0, 2);
  return j;
}

}  // namespace bpde
