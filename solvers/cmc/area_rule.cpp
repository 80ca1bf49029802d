#include "bezierpde/solvers/cmc/area_rule.h"

#include <algorithm>
#include <cmath>
#include <limits>

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

int next_q(int q) { return q + (q + 2) / 3; }

std::shared_ptr<const AreaForm> form_for(bool triangular, int n, int m, int q, int grading) {
  return triangular ? AreaForm::cached_triangular(n, q, grading) : AreaForm::cached_tensor(n, m, q, grading);
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

// One sequence of rules of one grading from q: the first whose change to the next is below the
// tolerance, or (ok false) the cap q = 64 with its change to q = 86 (never a rule compared with
// itself). `stall` (the plain sequence) stops early, ok false, when the change stops falling.
AreaRule sequence(bool triangular, int n, int m, const Eigen::MatrixX3d& P, const std::vector<int>& idx,
                  double tolerance, int q, int grading, bool stall) {
  q = std::min(q, kMaxAreaPoints);
  std::shared_ptr<const AreaForm> cur = form_for(triangular, n, m, q, grading);
  AreaRule r;
  double prev = std::numeric_limits<double>::infinity();
  while (true) {
    const int qn = next_q(q);  // may pass the cap: it only measures the error of q
    std::shared_ptr<const AreaForm> next = form_for(triangular, n, m, qn, grading);
    r.form = cur;
    r.change = change_between(*cur, *next, P, idx);
    r.ok = r.change <= tolerance;
    if (r.ok || q >= kMaxAreaPoints) return r;
    if (stall && q >= kStallFrom && r.change > kStallRatio * prev) return r;
    prev = r.change;
    q = std::min(qn, kMaxAreaPoints);
    cur = form_for(triangular, n, m, q, grading);
  }
}

}  // namespace

AreaRule choose_area_rule(bool triangular, int n, int m, const Eigen::MatrixX3d& P, const std::vector<int>& idx,
                          double tolerance, int start_q, int start_grading) {
  const int deg = std::max(n, m);
  const int q0 = (deg + 1) / 2 + 3;
  const int g0 = start_q > 0 ? start_grading : 1;
  const AreaRule first = sequence(triangular, n, m, P, idx, tolerance, start_q > 0 ? start_q : q0, g0, g0 == 1);
  if (first.ok || g0 != 1) return first;
  // The plain rule stalls (a nearly degenerate corner) or misses at the cap: the graded sequence.
  const AreaRule graded = sequence(triangular, n, m, P, idx, tolerance, q0, kGrading, false);
  return graded.ok || !(first.change < graded.change) ? graded : first;
}

}  // namespace bpde
