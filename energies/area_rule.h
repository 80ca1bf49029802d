#pragma once
// The quadrature rule of the area (energies/area_functional.h), chosen by its measured error.
//
// A = ∫ |x_u ∧ x_v| is not polynomial, so no Gauss rule is exact. For a net P and the free points
// idx the rule is chosen by refinement: q runs through q_0 = ⌈n/2⌉ + 3, q_{j+1} = q_j + ⌈q_j/3⌉
// (n the larger degree), and the first q_j is taken for which the change from q_j to q_{j+1}
//   max( |A_j - A_{j+1}| / A_{j+1},  max |G_j - G_{j+1}| / max S_{j+1} )
// (G the free rows of ∇A, S the size of their terms) is below `tolerance`. The error of the rules
// falls exponentially in q (also at degenerate corners, by the collapsed rules), so the error of
// q_j is the change measured (q_{j+1} is far more accurate).
//   The plain rules (grading 1) come first. When their change stops falling (less than ×4 in a
// step from q = 15 on: a nearly degenerate corner, area_functional.h "graded") or misses at the
// cap, the graded rules (grading 3) are run from q_0; the one that meets the tolerance is taken.
// The last rule of a sequence, q = 64, is compared with q = 86 (a finer rule, used only to measure
// the error): a rule is never compared with itself. Where the graded rule misses too, but by less
// than ×1000, the geometric rules (10 levels, area_functional.h) run from q = 11 to their cap
// q = 20 (compared with 27). A
// change still above the tolerance there leaves `ok` false (a folded or nearly singular corner,
// e.g. the circle's arcs fitted at degree 4, whose corners fold) and returns the rule with the
// smallest change, the later family on ties, with that change.
// Callers re-check at the end of a solve (the change is measured on the final net), refine again
// when the surface moved far from where the rule was chosen, choose it again during the final
// phases where it missed its tolerance at the net where it was chosen (a start that nearly folds
// at a corner), and report a rule that misses its tolerance as not converged
// (solvers/cmc/area/).
#include "bezierpde/core/eigen.h"
#include <Eigen/Core>
#include <memory>
#include <vector>

#include "bezierpde/energies/area_functional.h"
#include "bezierpde/energies/patch_assembly.h"

namespace bpde {

struct AreaRule {
  std::shared_ptr<const AreaForm> form;  ///< the rule taken (q_j)
  double change = 0.0;                   ///< the change measured from q_j to q_{j+1} (its error)
  bool ok = false;                       ///< change <= tolerance
};

/// kind: true for triangular (degree n), false for tensor (n, m). `start_q` > 0 starts the
/// sequence there, in the family of `start_grading` and `start_levels`, instead of q_0 (to check,
/// and refine, a rule already in use). With `assembly` (a surface of several patches of that kind
/// and degree, energies/patch_assembly.h) the rules are the patch's rules assembled over its
/// patches, P and idx global.
AreaRule choose_area_rule(bool triangular, int n, int m, const Eigen::MatrixX3d& P, const std::vector<int>& idx,
                          double tolerance, int start_q = 0, int start_grading = 1, int start_levels = 0,
                          const std::shared_ptr<const PatchAssembly>& assembly = nullptr);

}  // namespace bpde
