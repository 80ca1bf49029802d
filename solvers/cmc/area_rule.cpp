#include "bezierpde/solvers/cmc/area_rule.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace bpde {
namespace {

// Larger rules cost more than they gain: a change still above the tolerance at 64 points per
// direction means a nearly singular corner.
constexpr int kMaxAreaPoints = 64;

std::shared_ptr<const AreaForm> form_for(bool triangular, int n, int m, int q) {
  return triangular ? AreaForm::cached_triangular(n, q) : AreaForm::cached_tensor(n, m, q);
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

}  // namespace

AreaRule choose_area_rule(bool triangular, int n, int m, const Eigen::MatrixX3d& P, const std::vector<int>& idx,
                          double tolerance, int start_q) {
  const int deg = std::max(n, m);
  int q = start_q > 0 ? start_q : (deg + 1) / 2 + 3;
  std::shared_ptr<const AreaForm> cur = form_for(triangular, n, m, std::min(q, kMaxAreaPoints));
  AreaRule r;
  while (true) {
    const int qn = std::min(kMaxAreaPoints, q + (q + 2) / 3);
    std::shared_ptr<const AreaForm> next = form_for(triangular, n, m, qn);
    r.form = cur;
    r.change = change_between(*cur, *next, P, idx);
    r.ok = r.change <= tolerance;
    if (r.ok) return r;
    if (qn == kMaxAreaPoints) {
      r.form = next;
      return r;
    }
    q = qn;
    cur = next;
  }
}

}  // namespace bpde
