#pragma once
// D, V and A of a surface of several patches (complex/patch_complex.h), over its free coordinates.
//
// Conventions: the complex's points are #points x 3 (PatchComplex::points); its free rows are the
// rows not in PatchComplex::fixed, ascending (complex_free_rows), and the free coordinates are
// y(3a + c) = points(free[a], c). Gradients are #points x 3; Hessians over the free rows are
// 3k x 3k with entry 3a + c for (free[a], c), as the single-patch forms.
//
// Every functional is the sum of the patch's over the patches (energies/patch_assembly.h):
//   D = 1/2 Σ_p ∫ |x_u|² + |x_v|²  (the patches' Grams summed through the local -> global maps),
//   V = 1/3 Σ_p ∫ <x_u ∧ x_v, x>    (energies/volume.h per patch: for a disc the volume of the
//                                     cone from the origin over the whole surface),
//   A = Σ_p ∫ |x_u ∧ x_v|          (energies/area_functional.h per patch, one rule for all).
// The forms are the library's own forms in their assembled mode (CmcFunctional::assembled,
// VolumeForm::assembled, AreaForm::assembled), so the CMC solves use them unchanged; the sparse
// Hessians below are assembled from the same per-patch Hessians.
#include "bezierpde/core/eigen.h"
#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <memory>
#include <vector>

#include "bezierpde/complex/patch_complex.h"
#include "bezierpde/energies/area_functional.h"
#include "bezierpde/energies/cmc.h"
#include "bezierpde/energies/patch_assembly.h"
#include "bezierpde/tensor/tensor_net.h"
#include "bezierpde/triangular/triangular_net.h"

namespace bpde {

/// The local -> global maps of a complex. Throws ParameterError for an empty complex or patches
/// of different kinds or degrees, DegreeError for a degree outside 1..kMaxDegree, SizeError for a
/// map of the wrong length or a row outside the points, and for `fixed` not sorted, unique and in
/// range.
std::shared_ptr<const PatchAssembly> patch_assembly(const PatchComplex& c);
/// The rows not in c.fixed, ascending.
std::vector<int> complex_free_rows(const PatchComplex& c);
/// Patch p as a net (ParameterError when it is not of that kind).
TriangularNet triangular_patch(const PatchComplex& c, int p);
TensorNet tensor_patch(const PatchComplex& c, int p);

/// D_H = D + 2HV of the complex (CmcFunctional::assembled of the patch's cached functional).
std::shared_ptr<const CmcFunctional> complex_cmc_functional(const PatchComplex& c);
/// A of the complex with the patch rule (q, grading, levels) (AreaForm::assembled).
std::shared_ptr<const AreaForm> complex_area_form(const PatchComplex& c, int q, int grading = 1, int levels = 0);

/// The Hessians over the free rows, sparse (the per-patch blocks summed; each patch couples only
/// its own points). The dense forms are CmcFunctional::hessian(P, H, free) and
/// AreaForm::hessian(P, free) of the forms above.
Eigen::SparseMatrix<double> dirichlet_hessian_sparse(const PatchComplex& c);
Eigen::SparseMatrix<double> volume_hessian_sparse(const PatchComplex& c);
Eigen::SparseMatrix<double> area_hessian_sparse(const PatchComplex& c, const AreaForm& patch_rule);

/// The free rows of a #points x 3 gradient as the 3k vector y's layout.
Eigen::VectorXd free_vector(const Eigen::MatrixX3d& G, const std::vector<int>& free);

}  // namespace bpde
