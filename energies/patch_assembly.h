#pragma once
// Sums of per-patch forms over a surface of several patches that share control points
// (complex/patch_complex.h): E(P) = sum_p E_patch(P(map_p)), with map_p the local row -> global row
// map of patch p. All patches have one kind and degree, so one per-patch form (its tables) serves
// every patch.
//
// Conventions: P is the #global x 3 point matrix; gradients are #global x 3 (rows: global points),
// the rows of a gradient over a list idx of global rows are k x 3 in idx's order, and Hessians over
// idx use entry 3a + c for (idx[a], coordinate c), as the single-patch forms (energies/volume.h,
// energies/area_functional.h). A point shared by several patches receives the sum of their
// contributions (gradient rows, Hessian blocks): the derivative of the sum.
//
// Used by VolumeForm::assembled, AreaForm::assembled and CmcFunctional::assembled (which keep
// one implementation of every form: the patch's) and by energies/complex_functionals.h (sparse
// Hessians).
#include "bezierpde/core/eigen.h"
#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <functional>
#include <vector>

namespace bpde {

struct PatchAssembly {
  int size = 0;                        ///< number of global points
  int patch_size = 0;                  ///< control points of one patch
  std::vector<std::vector<int>> maps;  ///< patch p: local row -> global row
  int patches() const { return static_cast<int>(maps.size()); }
};

/// The local net of patch p: patch_size x 3 rows P(maps[p]).
Eigen::MatrixX3d patch_points(const PatchAssembly& a, int p, const Eigen::MatrixX3d& P);

/// The local rows of patch p that are among the global rows idx, and their positions in idx
/// (where: global row -> position in idx, or -1; size a.size).
void local_rows(const PatchAssembly& a, int p, const std::vector<int>& where, std::vector<int>& local,
                std::vector<int>& pos);
/// global row -> position in idx (or -1). SizeError when a row of idx is outside 0..size-1.
std::vector<int> positions(const PatchAssembly& a, const std::vector<int>& idx);

/// Rows idx of a summed row quantity (a gradient or its scale): rows(p, Pp, local) gives the k_p x 3
/// rows of patch p at its local rows `local`; they are added into the rows of idx they belong to.
using PatchRowsFn = std::function<Eigen::MatrixX3d(const Eigen::MatrixX3d& Pp, const std::vector<int>& local)>;
Eigen::MatrixX3d assembled_rows(const PatchAssembly& a, const Eigen::MatrixX3d& P, const std::vector<int>& idx,
                                const PatchRowsFn& rows);

/// The 3k x 3k Hessian over idx as triplets: hess(Pp, local) gives patch p's 3k_p x 3k_p Hessian
/// over its local rows `local` (the patch forms' convention); its entries are added at the
/// positions of those rows in idx. Entries that are exactly 0 are left out.
using PatchHessianFn = std::function<Eigen::MatrixXd(const Eigen::MatrixX3d& Pp, const std::vector<int>& local)>;
std::vector<Eigen::Triplet<double>> assembled_hessian_triplets(const PatchAssembly& a, const Eigen::MatrixX3d& P,
                                                               const std::vector<int>& idx,
                                                               const PatchHessianFn& hess);
/// The same as a sparse matrix (duplicates summed) and as a dense one.
Eigen::SparseMatrix<double> assembled_hessian_sparse(const PatchAssembly& a, const Eigen::MatrixX3d& P,
                                                     const std::vector<int>& idx, const PatchHessianFn& hess);
Eigen::MatrixXd assembled_hessian_dense(const PatchAssembly& a, const Eigen::MatrixX3d& P,
                                        const std::vector<int>& idx, const PatchHessianFn& hess);

/// A per-patch N_p x N_p matrix (a Gram) summed into #global x #global.
Eigen::MatrixXd assembled_matrix(const PatchAssembly& a, const Eigen::MatrixXd& patch_matrix);

}  // namespace bpde
