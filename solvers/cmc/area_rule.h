#pragma once
// The quadrature rule of the area (solvers/cmc/area_functional.h), chosen by its measured error.
//
// A = ∫ |x_u ∧ x_v| is not polynomial, so no Gauss rule is exact. For a net P and the free points
// idx the rule is chosen by refinement: q runs through q_0 = ⌈n/2⌉ + 3, q_{j+1} = q_j + ⌈q_j/3⌉
// (n the larger degree), and the first q_j is taken for which the change from q_j to q_{j+1}
//   max( |A_j - A_{j+1}| / A_{j+1},  max |G_j - G_{j+1}| / max S_{j+1} )
// (G the free rows of ∇A, S the size of their terms) is below `tolerance`. The error of the rules
// falls exponentially in q (also at degenerate corners, by the collapsed rules), so the error of
// q_j is the change measured (q_{j+1} is far more accurate). A change that is still above the
// tolerance at q = 64 leaves `ok` false (a nearly degenerate parametrisation) and takes q = 64.
// Callers re-check at the end of a solve (the change is measured on the final net) and refine
// again when the surface moved far from where the rule was chosen.
#include <Eigen/Core>
#include <memory>
#include <vector>

#include "bezierpde/solvers/cmc/area_functional.h"

namespace bpde {

struct AreaRule {
  std::shared_ptr<const AreaForm> form;  ///< the rule taken (q_j)
  double change = 0.0;                   ///< the change measured from q_j to q_{j+1} (its error)
  bool ok = false;                       ///< change <= tolerance
};

/// kind: true for triangular (degree n), false for tensor (n, m). `start_q` > 0 starts the
/// sequence there instead of q_0 (to check, and refine, a rule already in use).
AreaRule choose_area_rule(bool triangular, int n, int m, const Eigen::MatrixX3d& P, const std::vector<int>& idx,
                          double tolerance, int start_q = 0);

}  // namespace bpde
