#pragma once
// Extremals of the quadratic energies (energies/energy_spec.h) on a patch complex
// (complex/patch_complex.h): the minimiser of the summed energy
//
//     E(X) = Σ_patches 1/2 Σ_c P_{p,c}^T Q_p P_{p,c},    P_p = S_p X  (the patch's rows of X),
//
// over the free rows of X (the complement of PatchComplex::fixed), the fixed rows held. Each patch
// contributes its exact Gram matrix Q_p in its own reference domain (tensor_gram(energy, n, n) or
// triangular_gram(n, energy)); the global Gram K = Σ_p S_p^T Q_p S_p is sparse (rows couple only
// within a patch), and the optimality condition is the sparse symmetric system
//
//     K_ff X_f = -K_fb X_b        (the same matrix for x, y, z),
//
// factored once by a supernodal sparse Cholesky (CHOLMOD; Eigen's SimplicialLDLT where the build
// has no CHOLMOD) after Jacobi scaling to a unit diagonal. Cost: assembly O(#patches · N_p²),
// the factorisation of a matrix whose sparsity is that of the layout's patches.
//
// The energy depends on each patch's parametrisation (its reference triangle or square), not on
// the surface alone: the complex's extremal is the minimiser of that sum, the surface the
// parametrisations together describe. With C⁰ data (only the boundary rows fixed) a fourth-order
// energy is singular when a continuous piecewise-affine function vanishing on the fixed rows
// exists (a triangular complex with an inner vertex; a quad O-grid): ParameterError, like a
// singular single-patch extremal.
//
// Singularity test: a failed factorisation, or a reciprocal condition estimate of the scaled K_ff
// below ComplexExtremalOptions::singular_tolerance: λ_min by 30 steps of inverse iteration with the
// factor, λ_max bounded by the largest absolute row sum (Gershgorin).
// Summary::residual: ‖K_ff X_f + K_fb X_b‖_∞ / (‖K_ff‖_∞ ‖X_f‖_∞ + ‖K_fb X_b‖_∞ + tiny), converged
// when it is below kConvergenceTolerance (else NumericalLimit).
//
// On a planar domain (ComplexExtremalOptions::domain, complex/planar_domain.h, one triangle per
// patch) each patch's Gram is the energy measured on its domain triangle (solvers/complex/
// complex_c1.h), so E is the energy of the map of the planar domain the complex describes.
// Continuity::C1 (triangular complexes on a domain) minimises E subject to the C¹ conditions
// C X = 0 across every seam (complex_c1.h): the linear equality-constrained quadratic problem,
// solved by the augmented Lagrangian method on the Jacobi-scaled system with unit-norm condition
// rows, (A + ρ ĈᵀĈ) y_k = b - Ĉᵀλ_k + ρ Ĉᵀd, λ_{k+1} = λ_k + ρ (Ĉ y_k - d), ρ = kC1Penalty: one
// CHOLMOD factorisation, a solve per step. It needs neither independent conditions (the
// conditions at a vertex are linearly dependent) nor K_ff regular (only K positive on the
// conditions' null space; C¹ removes the piecewise-affine null directions of C⁰). The steps stop
// when the conditions' residual is at rounding level or falls by less than a tenth in a step (at
// most 200 steps); the stationarity A y + Ĉᵀλ = b holds after each
// step. Conditions that the boundary data contradict (degree too low for C¹ with that boundary)
// leave a residual: c1_residual (complex_c1.h) above kC1Tolerance is Status::Incompatible, the
// returned complex the last iterate.
#include "bezierpde/core/eigen.h"
#include <Eigen/Sparse>

#include <vector>

#include "bezierpde/complex/patch_complex.h"
#include "bezierpde/complex/planar_domain.h"
#include "bezierpde/energies/energy_spec.h"
#include "bezierpde/solvers/summary.h"

namespace bpde {

/// Largest degree of a complex extremal: the per-patch Bernstein Grams lose about a digit per
/// degree, as for the single triangular patch (solvers/extremal.h, kMaxTriangularExtremalDegree).
inline constexpr int kMaxComplexExtremalDegree = 20;

/// Most entries of the per-patch Gram matrices together (#patches · (points per patch)²; SizeError
/// beyond): the assembly holds them all at once, 16 bytes each (320 MB at the limit). A 256-patch
/// tensor complex of degree 4 has 1.6·10⁵, 4096 triangular patches of degree 8 8.2·10⁶.
inline constexpr long long kMaxComplexGramEntries = 20'000'000;

/// #patches · (points per patch)² of c (the Gram entries of its assembly).
long long complex_gram_entries(const PatchComplex& c);

/// Penalty ρ of the augmented Lagrangian steps (scaled system, unit-diagonal A, unit-norm rows).
inline constexpr double kC1Penalty = 1e3;
/// Largest C¹ defect (c1_residual) of a converged C¹ extremal.
inline constexpr double kC1Tolerance = 1e-10;

struct ComplexExtremalOptions {
  double singular_tolerance = 1e-13;  ///< in [0, 1): ParameterError otherwise
  /// C1 needs a triangular complex and `domain`; ParameterError otherwise.
  Continuity continuity = Continuity::C0;
  /// Empty (each patch's energy on its reference domain) or one domain triangle per patch.
  std::vector<DomainTriangle> domain;
};

struct ComplexExtremal {
  PatchComplex complex;  ///< the input with its free rows replaced by the extremal
  double energy = 0;     ///< E at the extremal
  Summary summary;
  double c1_residual = 0;  ///< Continuity::C1: the C¹ defect of the result (complex_c1.h); else 0
  int c1_steps = 0;        ///< Continuity::C1: augmented Lagrangian steps
};

/// The global Gram K (#points square, symmetric, both triangles stored). Validates c. With a
/// domain (one triangle per patch of a triangular complex, else ParameterError), the energy is
/// measured on it.
Eigen::SparseMatrix<double> complex_gram(const PatchComplex& c, const EnergySpec& energy,
                                         const std::vector<DomainTriangle>& domain = {});

/// E(X) of the complex's points (on the domain when one is given).
double complex_energy(const PatchComplex& c, const EnergySpec& energy, const std::vector<DomainTriangle>& domain = {});

/// The extremal above. Throws the errors of validate(c); DegreeError beyond
/// kMaxComplexExtremalDegree; SizeError beyond kMaxComplexGramEntries; ParameterError for a singular or indefinite K_ff (naming why) or bad options. A complex with no
/// free rows is returned as it is (converged).
ComplexExtremal solve_complex_extremal(const PatchComplex& c, const EnergySpec& energy,
                                       const ComplexExtremalOptions& options = {});

}  // namespace bpde
