#include "bezierpde/energies/area_rule.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

namespace bpde {
namespace {

// Larger rules cost more than they gain: a change still above the tolerance at 64 points per
// direction (compared with the next rule, 86) means a folded or nearly singular corner.
constexpr int kMaxAreaPoints = 64;
// The plain rule is given up for the graded one once its change falls less than ×4 in a step from
// q >= 15 on (exponential convergence falls ≥ 10× a step there until it reaches rounding, ~1e-15).
constexpr int kStallFrom = 15;
constexpr double kStallRatio = 0.25;
constexpr int kGrading = 3;
// The geometric rules (area_functional.h): kGeometricLevels + 1 radial pieces (the innermost
// [0, 0.3^10 = 5.9e-6]), q from kGeometricQ0 to the cap kMaxGeometricPoints (26 400 nodes on a
// triangular net, 35 200 on a tensor net: about the graded q = 64's 24 576 and 32 768), that cap
// compared with q = 27.
constexpr int kGeometricLevels = 10;
constexpr int kGeometricQ0 = 11;
constexpr int kMaxGeometricPoints = 20;
// They are tried only where the graded rule missed by less than this factor of the tolerance: they
// gained 3 orders or less on the nets measured (docs/cmc_algorithm.md, "The area functional A_H"), and a start that folds at a corner misses by far more (1.7e-4 on a wavy curve), where
// building them (66 000 nodes for the q = 27 that measures the cap on a tensor net) only costs.
constexpr double kGeometricGate = 1e3;

int next_q(int q) { return q + (q + 2) / 3; }

// The patch's rule, assembled over the patches of a complex where `assembly` is given.
std::shared_ptr<const AreaForm> form_for(bool triangular, int n, int m, int q, int grading, int levels,
                                         const std::shared_ptr<const PatchAssembly>& assembly) {
  auto patch = triangular ? AreaForm::cached_triangular(n, q, grading, levels)
                          : AreaForm::cached_tensor(n, m, q, grading, levels);
  if (!assembly) return patch;
  return std::make_shared<const AreaForm>(AreaForm::assembled(std::move(patch), assembly));
}

double change_between(const AreaForm& a, const AreaForm& b, const Eigen::MatrixX3d& P, const std::vector<int>& idx) {
  const double Aa = a.value(P), Ab = b.value(P);
  Eigen::MatrixX3d Ga, Gb, Sb;
  a.gradient_rows_and_scale(P, idx, &Ga, nullptr);
  b.gradient_rows_and_scale(P, idx, &Gb, &Sb);
  if (!std::isfinite(Aa) || !std::isfinite(Ab) || !Ga.allFinite() || !Gb.allFinite())
    return std::numeric_limits<double>::infinity();
  double c = Ab > 0 ? std::abs(Aa - Ab) / Ab : std::abs(Aa - Ab);
  if (!idx.empty()) {
    const double s = Sb.maxCoeff();
    const double d = (Ga - Gb).cwiseAbs().maxCoeff();
    c = std::max(c, s > 0 ? d / s : d);
  }
  return c;
}

// One sequence of rules of one family (grading, levels) from q: the first whose change to the next
// is below the tolerance, or (ok false) the cap (q = 64, compared with q = 86; geometric: q = 20,
// compared with 27; never a rule compared with itself). `stall` (the plain sequence) stops early,
// ok false, when the change stops falling.
AreaRule sequence(bool triangular, int n, int m, const Eigen::MatrixX3d& P, const std::vector<int>& idx,
                  double tolerance, int q, int grading, int levels, bool stall,
                  const std::shared_ptr<const PatchAssembly>& assembly) {
  const int cap = levels > 0 ? kMaxGeometricPoints : kMaxAreaPoints;
  q = std::min(q, cap);
  std::shared_ptr<const AreaForm> cur = form_for(triangular, n, m, q, grading, levels, assembly);
  AreaRule r;
  double prev = std::numeric_limits<double>::infinity();
  while (true) {
    const int qn = next_q(q);  // may pass the cap: it only measures the error of q
    std::shared_ptr<const AreaForm> next = form_for(triangular, n, m, qn, grading, levels, assembly);
    r.form = cur;
    r.change = change_between(*cur, *next, P, idx);
    r.ok = r.change <= tolerance;
    if (r.ok || q >= cap) return r;
    if (stall && q >= kStallFrom && r.change > kStallRatio * prev) return r;
    prev = r.change;
    q = std::min(qn, cap);
    cur = form_for(triangular, n, m, q, grading, levels, assembly);
  }
}

}  // namespace

AreaRule choose_area_rule(bool triangular, int n, int m, const Eigen::MatrixX3d& P, const std::vector<int>& idx,
                          double tolerance, int start_q, int start_grading, int start_levels,
                          const std::shared_ptr<const PatchAssembly>& assembly) {
  const int deg = std::max(n, m);
  const int q0 = (deg + 1) / 2 + 3;
  // The families in order: plain (0), graded (1), geometric (2); a start refines within its own
  // family and goes on to the later ones only where it misses.
  const int f0 = start_q <= 0 ? 0 : start_levels > 0 ? 2 : start_grading > 1 ? 1 : 0;
  AreaRule best;
  best.change = std::numeric_limits<double>::infinity();
  for (int f = f0; f <= 2; ++f) {
    if (f == 2 && f0 < 2 && !(best.change <= kGeometricGate * tolerance)) break;
    const int q = f == f0 && start_q > 0 ? start_q : f == 2 ? kGeometricQ0 : q0;
    // The plain rule stalls (a nearly degenerate corner) or misses at the cap: the graded
    // sequence; where that misses too, the geometric one.
    const AreaRule r = f == 0   ? sequence(triangular, n, m, P, idx, tolerance, q, 1, 0, true, assembly)
                       : f == 1 ? sequence(triangular, n, m, P, idx, tolerance, q, kGrading, 0, false, assembly)
                                : sequence(triangular, n, m, P, idx, tolerance, q, 1, kGeometricLevels, false, assembly);
    if (r.ok) return r;
    // Not met: the later family unless an earlier one measured a smaller change (as before the
    // geometric rules: the graded rule kept unless the plain one was better).
    if (!best.form || !(best.change < r.change)) best = r;
  }
  return best;
}

}  // namespace bpde
