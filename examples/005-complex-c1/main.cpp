// 005-complex-c1: C¹ continuity across the seams of a triangular patch complex on its planar
// domain (solvers/complex/complex_c1.h, docs/c1.md "C¹ patch complexes"): the largest angle between
// the patches' normals across the seams with C⁰ and with C¹, the C¹ defect, and the energy the C¹
// conditions cost, for two closed boundary loops over the unit circle (the planar circle; a saddle
// z = 0.4 cos 2θ + 0.2 sin 3θ) on the automatic fans of 6, 3 and 5 triangles, in p (the degree of
// the fit and the solve) and in h (the fan refined).
//
// Usage: example_005_complex_c1
// Prints one Markdown table (docs/c1.md holds its output).
#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>
#include <vector>

#include "bezierpde/complex/complex_mesh.h"
#include "bezierpde/complex/layout_loops.h"
#include "bezierpde/complex/planar_domain.h"
#include "bezierpde/complex/refine.h"
#include "bezierpde/core/errors.h"
#include "bezierpde/solvers/complex/complex_c1.h"
#include "bezierpde/solvers/complex/complex_extremal.h"
#include "examples/common/generated.h"  // GeneratedSection

using namespace bpde;

namespace {

struct Case {
  const char* name;
  double a2, a3;  // z = a2 cos 2θ + a3 sin 3θ over (cos θ, sin θ)
  int curves;     // the loop in that many curves: the fan has 6 triangles for 1, else one per curve
};

Loop loop_of(const Case& c) {
  Loop loop;
  for (int k = 0; k < c.curves; ++k)
    loop.push_back(BoundaryCurve::function([c, k](double t) {
      const double a = 2 * std::numbers::pi * (k + t) / c.curves;
      return Eigen::Vector3d(std::cos(a), std::sin(a), c.a2 * std::cos(2 * a) + c.a3 * std::sin(3 * a));
    }));
  return loop;
}

std::string fmt(const char* f, double x) {
  char b[64];
  std::snprintf(b, sizeof b, f, x);
  return b;
}

/// A seam angle or defect at rounding level: "< 1e-10" below the floor (0 included), else 2 digits.
std::string small(double x, double floor) { return x < floor ? "< " + fmt("%.0e", floor) : fmt("%.1e", x); }

void row(const Case& k, const EnergySpec& energy, int n, int refine) {
  const LoopComplex lc = loop_complex(PatchKind::triangular, n, {loop_of(k)});
  std::vector<DomainTriangle> D = layout_domain(lc.layout, layout_domain_positions(lc.layout));
  PatchComplex c = lc.complex;
  for (int r = 0; r < refine; ++r) c = refine_h(c), D = refine_domain_h(D);
  std::printf("| %s | %d | %s | %d | %d | %zu |", k.name, static_cast<int>(lc.layout.faces.size()),
              energy.name().c_str(), n, refine, c.patches.size());
  // C0: the job's default (each patch's energy in its reference triangle), then on the domain
  std::string c0_reference = "singular", c0_domain = "singular", e0 = "";
  double E0 = NAN;
  try {
    c0_reference = fmt("%.4f", seam_angle_max(solve_complex_extremal(c, energy).complex));
  } catch (const ParameterError&) {
  }
  ComplexExtremalOptions o;
  o.domain = D;
  try {
    const ComplexExtremal r = solve_complex_extremal(c, energy, o);
    c0_domain = fmt("%.4f", seam_angle_max(r.complex));
    E0 = r.energy;
    e0 = fmt("%.6g", E0);
  } catch (const ParameterError&) {
  }
  o.continuity = Continuity::C1;
  const ComplexExtremal r = solve_complex_extremal(c, energy, o);
  std::printf(" %s | %s |", c0_reference.c_str(), c0_domain.c_str());
  if (!r.summary.converged) {
    std::printf(" %s | %s | %s | | |\n", to_string(r.summary.status), fmt("%.1e", r.c1_residual).c_str(), e0.c_str());
    return;
  }
  std::printf(" %s | %s | %s | %.6g | %s |\n", small(seam_angle_max(r.complex), 1e-10).c_str(),
              small(r.c1_residual, 1e-13).c_str(), e0.c_str(), r.energy,
              std::isnan(E0) ? "" : fmt("%.2f", 100 * (r.energy / E0 - 1)).c_str());
}

}  // namespace

int main() {
  const std::vector<Case> cases{
      {"circle", 0, 0, 1}, {"saddle", 0.4, 0.2, 1}, {"saddle", 0.4, 0.2, 3}, {"saddle", 0.4, 0.2, 5}};
  examples::GeneratedSection section("complex-c1-seams");
  std::printf(
      "| boundary | fan | energy | n | refine | patches | C0 seam angle (°), reference energies | C0 seam angle (°), "
      "domain energies | C1 seam angle (°) | C1 defect | energy C0 | energy C1 | C1 cost (%%) |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  for (std::size_t i = 0; i < cases.size(); ++i) {
    const Case& k = cases[i];
    const bool full = i < 2;  // the fans of 3 and 5: the degrees only
    for (int n : {2, 3, 4, 5, 6, 8}) row(k, EnergySpec::dirichlet(), n, 0);
    if (full)
      for (int refine : {1, 2}) row(k, EnergySpec::dirichlet(), 5, refine);
    for (int n : {4, 5, 6, 8}) row(k, EnergySpec::laplacian_squared(), n, 0);
    if (full) row(k, EnergySpec::laplacian_squared(), 5, 1);
  }
  return 0;
}
