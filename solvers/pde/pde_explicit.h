#pragma once
// Explicit (closed-form) polynomial solutions of the fourth-order PDEs of Arnal, Monterde, Ugail,
// "Explicit polynomial solutions of fourth order linear elliptic PDEs for boundary based smooth
// surface generation", with the corrections of docs/errata.md (explicit PDE solutions):
//
//   A x_uuuu + B x_uuuv + C x_uuvv + D x_uvvv + E x_vvvv = 0   (eq. (2); B, D on x_uuuv, x_uvvv)
//
// on a tensor net of degree (n, n) with the outer ring of control points prescribed. Route, with
// x = sum a_kl/(k! l!) u^k v^l (eq. (4)):
//   1. boundary -> a_{i0}, a_{0j} (eq. (5)-(6));
//   2. anti-diagonals s = k + l from n+1 down to 2 (a_kl = 0 for k + l > n+1): a_{1,s-1},
//      a_{s-1,1} from the edges u = 1 and v = 1 (eq. (7); the a_{i1} formula uses P_{ln}), then
//      the interior a_kl (k, l >= 2) in closed form:
//      - Coons [0,0,C,0,0] (x_uuvv = 0, §5.2.1): a_kl = 0;
//      - orthogonal (B = D = 0, C^2 >= 4AE > 0): Prop. 4 eq. (21) with G_{-1} = 0, G_0 = 1 (§5.1),
//        covering biharmonic (§5.2.3), modified biharmonic (§5.2.2, exponent ⌊k/2⌋) and the
//        rho case (§5.2.4);
//      - G-norm [rho^2, 2 rho cos t, 1 + rho^2, 2 rho cos t, 1] with cos t != 0: Lemma 1
//        (eq. (11)-(12)) and Prop. 2 (eq. (13)); an anti-diagonal whose M_s is below
//        singular_tolerance is solved numerically from system (9) (corrected: D a_{m-3,3});
//   3. back to Bernstein form (§6), via tensor/power_basis.h; the prescribed ring is copied exactly.
// The formulas as implemented, and how the degenerate cases (rho -> 1, sin t -> 0, rho > 1) are
// evaluated: docs/pde_accuracy.md, "How the solvers work".
//
// Accepted operators: those with EnergySpec::has_explicit_solution(), and also any [A..E]
// proportional to the Coons operator [0,0,1,0,0] or to a modified biharmonic one [1,0,2a²,0,a⁴]
// (a != 0). Anything else throws UnsupportedProblem suggesting method "lu" (solvers/pde/pde_lu.h).
// A singular anti-diagonal system means the solution is not unique (e.g. rho = 1, t = 0: kernel
// u^2 v^2 (u - v)): converged = false, and the Summary says so.
//
// Measured errors against exact solutions: docs/pde_accuracy.md.
#include "bezierpde/core/eigen.h"
#include <Eigen/Core>
#include <string>

#include "bezierpde/energies/energy_spec.h"
#include "bezierpde/solvers/pde/pde_lu.h"  // PdeSolution
#include "bezierpde/solvers/requirements.h"
#include "bezierpde/solvers/summary.h"
#include "bezierpde/tensor/tensor_net.h"

namespace bpde {

struct PdeExplicitOptions {
  /// An anti-diagonal's closed-form denominator M_s smaller than this, relative to the size of its
  /// terms, sends that anti-diagonal to the numerical solve of system (9). Default 1e-8.
  double singular_tolerance = 1e-8;
  /// Relative threshold below which that numerical solve calls the system singular. Default 1e-10.
  double rank_tolerance = 1e-10;
  /// Throws ParameterError unless both are finite and in (0, 1).
  void validate() const;
};

/// The FORMATS.md "pde" problem with method "explicit": tensor nets with n = m >= 2, a
/// fourth-order operator with a closed form (EnergySpec::has_explicit_solution) and "boundary"
/// data; for other operators the method is refused with a message suggesting "lu".
inline SolverRequirements pde_explicit_requirements(const EnergySpec& op) {
  SolverRequirements r = pde_lu_requirements(op);
  r.methods.clear();
  r.square = true;
  if (op.order() == 4 && op.has_explicit_solution())
    r.methods = {"explicit"};
  else
    r.method_reason =
        "operator " + op.name() +
        " has no explicit solution (the explicit solutions cover Coons, biharmonic, laplacian-squared, modified "
        "biharmonic and G-norm operators); use \"method\": \"lu\"";
  return r;
}

/// Which closed form applies, and its normalised parameters.
struct ExplicitOperator {
  enum class Family { Coons, Orthogonal, GNorm } family = Family::Coons;
  /// Normalised coefficients (E = 1 for Orthogonal and GNorm; C = 1 for Coons).
  double A = 0, B = 0, C = 1, D = 0, E = 0;
  /// G-norm parameters (GNorm and, when C = A + E, Orthogonal): rho > 0, t in [0, pi].
  double rho = 1, t = 0;
};

/// Classify the operator of `op` (order 4). Throws UnsupportedProblem (message suggests "lu") for
/// operators without a closed form, and for second-order energies.
ExplicitOperator classify_explicit_operator(const EnergySpec& op);

/// Lemma 1 (eq. (12)): the fundamental sequences of
///   rho^2 x_l + 2 rho cos t x_{l+1} + (1+rho^2) x_{l+2} + 2 rho cos t x_{l+3} + x_{l+4} = 0
/// with initial values the unit vectors: row 0 = A_l, 1 = B_l, 2 = C_l, 3 = D_l, l = 0..N.
/// closed_form = true uses eq. (12) (requires sin t != 0 and 1 + rho^4 + 2 rho^2 cos 2t != 0, else
/// ParameterError); false runs the recurrence.
Eigen::MatrixXd lemma1_sequences(double rho, double t, int N, bool closed_form);

/// The factorial-scaled monomial coefficients a_kl (eq. (4)) of the explicit solution,
/// (n+1)^2 x 3, row k*(n+1)+l. `summary` receives converged / message (not unique).
Eigen::MatrixX3d explicit_pde_coefficients(const TensorNet& data, const ExplicitOperator& op,
                                           const PdeExplicitOptions& options, Summary& summary);

/// Solve by the explicit route. data: a degree (n, n) net, n >= 1 (DegreeError if n != m), whose
/// outer ring is prescribed. converged = false with a message if the solution is not unique.
PdeSolution solve_pde_explicit(const TensorNet& data, const EnergySpec& op, const PdeExplicitOptions& options = {});

}  // namespace bpde
