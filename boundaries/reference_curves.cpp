#include "bezierpde/boundaries/reference_curves.h"

#include <numbers>

namespace bpde {

BoundaryData circle_three_arcs_curves(double radius, const Eigen::Vector3d& center, const Eigen::Vector3d& normal) {
  const double third = 2 * std::numbers::pi / 3;
  BoundaryData d;
  d.edges.push_back(BoundaryCurve::arc(center, normal, radius, 2 * third, 3 * third));  // P_00n -> P_n00
  d.edges.push_back(BoundaryCurve::arc(center, normal, radius, 0.0, third));            // P_n00 -> P_0n0
  d.edges.push_back(BoundaryCurve::arc(center, normal, radius, third, 2 * third));      // P_0n0 -> P_00n
  return d;
}

BoundaryData triangular_surface_curves(const std::function<Eigen::Vector3d(double, double)>& s) {
  BoundaryData d;
  d.edges.push_back(BoundaryCurve::function([s](double t) { return s(t, 0.0); }, "surface-edge"));
  d.edges.push_back(BoundaryCurve::function([s](double t) { return s(1 - t, t); }, "surface-edge"));
  d.edges.push_back(BoundaryCurve::function([s](double t) { return s(0.0, 1 - t); }, "surface-edge"));
  return d;
}

BoundaryData tensor_surface_curves(const std::function<Eigen::Vector3d(double, double)>& s) {
  BoundaryData d;
  d.edges.push_back(BoundaryCurve::function([s](double t) { return s(t, 0.0); }, "surface-edge"));
  d.edges.push_back(BoundaryCurve::function([s](double t) { return s(1.0, t); }, "surface-edge"));
  d.edges.push_back(BoundaryCurve::function([s](double t) { return s(1 - t, 1.0); }, "surface-edge"));
  d.edges.push_back(BoundaryCurve::function([s](double t) { return s(0.0, 1 - t); }, "surface-edge"));
  return d;
}

}  // namespace bpde
