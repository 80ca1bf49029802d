#pragma once
// Internal to solvers/cmc/: the sparse side of the area problem on a surface of several patches
// (complex_net.h). Each patch couples only its own control points, so the Hessians of A, V and D
// over the free points of a complex are sparse (a patch's block per patch, summed where points are
// shared); the correctors of a complex factor them by a sparse Cholesky (CHOLMOD, supernodal, its
// fill-reducing ordering analysed once per pattern) instead of the dense matrices of one patch.
//
// Conventions: the free points `free` (global rows, ascending) and the 3k layout y(3a + c) of
// cmc_problem.h; the global points #points x 3 (energies/patch_assembly.h).
#include "bezierpde/core/eigen.h"
#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <memory>
#include <vector>

#include "bezierpde/energies/area_functional.h"
#include "bezierpde/energies/cmc.h"
#include "bezierpde/energies/patch_assembly.h"

namespace bpde::cmc_detail {

/// What does not change during a solve: the Dirichlet Gram over the free points (⊗ Id_3), its
/// rows over all points (for ∇D and the size of its terms), and the per-patch forms.
struct SparseAreaTerms {
  /// From an assembled D_H (CmcFunctional::assembled), the free rows and the patches' kind and
  /// degree (tensor: (n, n)).
  SparseAreaTerms(const CmcFunctional& assembled, const std::vector<int>& free, bool triangular, int n);

  std::shared_ptr<const PatchAssembly> assembly;
  std::shared_ptr<const CmcFunctional> patch;  ///< the patch's D_H (its Gram and volume form)
  bool triangular = true;
  int n = 0;
  std::vector<int> free;
  /// 3k x 3k: the Gram over the free points ⊗ Id_3, on `pattern` (below).
  Eigen::SparseMatrix<double> C;
  Eigen::SparseMatrix<double, Eigen::RowMajor> Cfa, Cfa_abs;  ///< k x #points: its rows, and |C|

  /// The 3k x 3k Hessian of A by the assembled form's rule, of V, summed over the patches. Every
  /// matrix here has the same pattern: the 3 x 3 blocks of all pairs of free points that share a
  /// patch (built once; each Hessian adds the patches' dense blocks into its values through the
  /// positions kept in `scatter`), so sums of them are sums of their value arrays and the
  /// factorisation's symbolic analysis is done once.
  Eigen::SparseMatrix<double> area_hessian(const AreaForm& assembled, const Eigen::MatrixX3d& P) const;
  Eigen::SparseMatrix<double> volume_hessian(const Eigen::MatrixX3d& P) const;
  /// a + s b for two matrices of this pattern.
  Eigen::SparseMatrix<double> add(const Eigen::SparseMatrix<double>& a, double s, const Eigen::SparseMatrix<double>& b) const;

 private:
  template <class PatchHessian>
  Eigen::SparseMatrix<double> assemble(const Eigen::MatrixX3d& P, const PatchHessian& hess) const;
  Eigen::SparseMatrix<double> pattern_;      ///< all entries 0
  std::vector<std::vector<int>> local_;      ///< patch p: its free local rows
  std::vector<std::vector<int>> scatter_;    ///< patch p: value index of its entry (3i+r, 3j+s), column-major
};

/// A sparse symmetric factorisation: Cholesky (CHOLMOD supernodal where built with it), and where
/// that fails and `ldlt_fallback` is set, Eigen's simplicial LDLᵀ (the predictors, whose matrix
/// may be slightly indefinite in the soft tangential modes). ok() false when neither factors.
class SparseSymFactor {
 public:
  SparseSymFactor();
  ~SparseSymFactor();
  SparseSymFactor(const SparseSymFactor&) = delete;
  SparseSymFactor& operator=(const SparseSymFactor&) = delete;
  /// Factors M (the lower triangle is read). The symbolic analysis is kept while the pattern's
  /// size and non-zero count stay the same.
  bool compute(const Eigen::SparseMatrix<double>& M, bool ldlt_fallback = false);
  /// The same for a matrix of the pattern of the last compute() (SparseAreaTerms): the symbolic
  /// analysis is reused.
  bool refactor(const Eigen::SparseMatrix<double>& M);
  bool ok() const { return ok_; }
  /// True where the Cholesky factor succeeded (M positive definite).
  bool cholesky() const { return llt_ok_; }
  Eigen::VectorXd solve(const Eigen::VectorXd& b) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  bool ok_ = false, llt_ok_ = false, analysed_ = false;
  Eigen::Index rows_ = 0, nnz_ = 0;
};

}  // namespace bpde::cmc_detail
