#include "bezierpde/core/differential_geometry.h"

#include "bezierpde/core/eigen.h"
#include <Eigen/Geometry>
#include <cmath>

namespace bpde {

FundamentalForms fundamental_forms(const SurfaceJet& jet) {
  FundamentalForms out;
  out.E = jet.xu.dot(jet.xu);
  out.F = jet.xu.dot(jet.xv);
  out.G = jet.xv.dot(jet.xv);
  const Eigen::Vector3d c = jet.xu.cross(jet.xv);
  const double cn = c.norm();
  const double scale = std::sqrt(out.E * out.G);
  if (!(scale > 0) || !(cn > 1e-14 * scale) || !std::isfinite(cn)) return out;
  out.regular = true;
  out.normal = c / cn;
  out.e = jet.xuu.dot(out.normal);
  out.f = jet.xuv.dot(out.normal);
  out.g = jet.xvv.dot(out.normal);
  const double det = cn * cn;  // EG - F^2 = |x_u ^ x_v|^2, computed without cancellation
  out.K = (out.e * out.g - out.f * out.f) / det;
  out.H = (out.e * out.G - 2.0 * out.f * out.F + out.g * out.E) / (2.0 * det);
  return out;
}

}  // namespace bpde
