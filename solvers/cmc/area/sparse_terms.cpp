// The sparse side of the area problem on a complex (sparse_terms.h).
#include "bezierpde/solvers/cmc/area/sparse_terms.h"

#include <Eigen/SparseCholesky>
#ifdef BPDE_HAVE_CHOLMOD
#include <Eigen/CholmodSupport>
#endif
#include <algorithm>
#include <cmath>
#include <utility>

#include "bezierpde/core/errors.h"

namespace bpde::cmc_detail {
namespace {

using SpMat = Eigen::SparseMatrix<double>;


}  // namespace

SparseAreaTerms::SparseAreaTerms(const CmcFunctional& assembled, const std::vector<int>& free_rows, bool tri,
                                 int degree)
    : assembly(assembled.assembly()), triangular(tri), n(degree), free(free_rows) {
  if (!assembly) throw ParameterError("SparseAreaTerms: needs an assembled functional");
  const int ps = assembly->patch_size;
  patch = triangular ? CmcFunctional::cached_triangular(n) : CmcFunctional::cached_tensor(n, n);
  if (patch->size() != ps) throw SizeError("SparseAreaTerms: the patch functional does not fit the assembly");
  const Eigen::MatrixXd& G = patch->gram();
  const std::vector<int> where = positions(*assembly, free);
  const Eigen::Index k = static_cast<Eigen::Index>(free.size());
  // The pattern: every 3 x 3 block of two free points of one patch (explicit zeros included).
  std::vector<Eigen::Triplet<double>> tp, tr;
  std::vector<int> local, pos;
  local_.resize(static_cast<std::size_t>(assembly->patches()));
  std::vector<std::vector<int>> positions_of(local_.size());
  for (int p = 0; p < assembly->patches(); ++p) {
    local_rows(*assembly, p, where, local, pos);
    local_[static_cast<std::size_t>(p)] = local;
    positions_of[static_cast<std::size_t>(p)] = pos;
    const std::vector<int>& map = assembly->maps[static_cast<std::size_t>(p)];
    for (std::size_t i = 0; i < local.size(); ++i) {
      for (std::size_t j = 0; j < local.size(); ++j)
        for (int r = 0; r < 3; ++r)
          for (int c = 0; c < 3; ++c) tp.emplace_back(3 * pos[i] + r, 3 * pos[j] + c, 0.0);
      for (int j = 0; j < ps; ++j) {
        const double v = G(local[i], j);
        if (v != 0.0) tr.emplace_back(pos[i], map[static_cast<std::size_t>(j)], v);
      }
    }
  }
  pattern_.resize(3 * k, 3 * k);
  pattern_.setFromTriplets(tp.begin(), tp.end());
  pattern_.makeCompressed();
  // Where each patch entry lands in the value array.
  scatter_.resize(local_.size());
  for (std::size_t p = 0; p < local_.size(); ++p) {
    const std::vector<int>& ps_ = positions_of[p];
    const int kp = static_cast<int>(ps_.size());
    std::vector<int>& sc = scatter_[p];
    sc.resize(static_cast<std::size_t>(9 * kp * kp));
    for (int j = 0; j < kp; ++j)
      for (int s = 0; s < 3; ++s) {
        const int col = 3 * ps_[static_cast<std::size_t>(j)] + s;
        const int* rows = pattern_.innerIndexPtr() + pattern_.outerIndexPtr()[col];
        const int len = pattern_.outerIndexPtr()[col + 1] - pattern_.outerIndexPtr()[col];
        for (int i = 0; i < kp; ++i)
          for (int r = 0; r < 3; ++r) {
            const int row = 3 * ps_[static_cast<std::size_t>(i)] + r;
            const int at = static_cast<int>(std::lower_bound(rows, rows + len, row) - rows);
            sc[static_cast<std::size_t>((3 * j + s) * 3 * kp + 3 * i + r)] = pattern_.outerIndexPtr()[col] + at;
          }
      }
  }
  C = assemble(Eigen::MatrixX3d(), [&](const Eigen::MatrixX3d&, const std::vector<int>& l) {
    const Eigen::Index kp = static_cast<Eigen::Index>(l.size());
    Eigen::MatrixXd B = Eigen::MatrixXd::Zero(3 * kp, 3 * kp);
    for (Eigen::Index i = 0; i < kp; ++i)
      for (Eigen::Index j = 0; j < kp; ++j)
        for (int c = 0; c < 3; ++c) B(3 * i + c, 3 * j + c) = G(l[static_cast<std::size_t>(i)], l[static_cast<std::size_t>(j)]);
    return B;
  });
  Cfa.resize(k, assembly->size);
  Cfa.setFromTriplets(tr.begin(), tr.end());
  Cfa_abs = Cfa.cwiseAbs();
}

template <class PatchHessian>
SpMat SparseAreaTerms::assemble(const Eigen::MatrixX3d& P, const PatchHessian& hess) const {
  SpMat K = pattern_;
  double* v = K.valuePtr();
  for (std::size_t p = 0; p < local_.size(); ++p) {
    const std::vector<int>& l = local_[p];
    if (l.empty()) continue;
    const Eigen::MatrixXd Hp = hess(P.size() ? patch_points(*assembly, static_cast<int>(p), P) : Eigen::MatrixX3d(), l);
    const int* sc = scatter_[p].data();
    const Eigen::Index m = Hp.size();
    const double* h = Hp.data();  // column-major, as the scatter
    for (Eigen::Index e = 0; e < m; ++e) v[sc[e]] += h[e];
  }
  return K;
}

SpMat SparseAreaTerms::area_hessian(const AreaForm& assembled, const Eigen::MatrixX3d& P) const {
  const std::shared_ptr<const AreaForm> rule =
      triangular ? AreaForm::cached_triangular(n, assembled.points_per_direction(), assembled.grading(), assembled.levels())
                 : AreaForm::cached_tensor(n, n, assembled.points_per_direction(), assembled.grading(), assembled.levels());
  return assemble(P, [&](const Eigen::MatrixX3d& Pp, const std::vector<int>& l) { return rule->hessian(Pp, l); });
}

SpMat SparseAreaTerms::volume_hessian(const Eigen::MatrixX3d& P) const {
  return assemble(P, [&](const Eigen::MatrixX3d& Pp, const std::vector<int>& l) {
    return patch->volume_form().hessian(Pp, l);
  });
}

SpMat SparseAreaTerms::add(const SpMat& a, double s, const SpMat& b) const {
  SpMat r = a;
  Eigen::Map<Eigen::VectorXd>(r.valuePtr(), r.nonZeros()) += s * Eigen::Map<const Eigen::VectorXd>(b.valuePtr(), b.nonZeros());
  return r;
}

// ---- SparseSymFactor

struct SparseSymFactor::Impl {
#ifdef BPDE_HAVE_CHOLMOD
  Eigen::CholmodSupernodalLLT<SpMat, Eigen::Lower> llt;
  Impl() { llt.cholmod().print = 0; }  // a failed factor is reported by info(), not on stderr
#else
  Eigen::SimplicialLLT<SpMat, Eigen::Lower> llt;
#endif
  Eigen::SimplicialLDLT<SpMat, Eigen::Lower> ldlt;
  bool use_ldlt = false;
};

SparseSymFactor::SparseSymFactor() : impl_(std::make_unique<Impl>()) {}
SparseSymFactor::~SparseSymFactor() = default;

bool SparseSymFactor::compute(const SpMat& M, bool ldlt_fallback) {
  ok_ = llt_ok_ = false;
  impl_->use_ldlt = false;
  impl_->llt.analyzePattern(M);
  analysed_ = true;
  rows_ = M.rows();
  nnz_ = M.nonZeros();
  impl_->llt.factorize(M);
  if (impl_->llt.info() == Eigen::Success) {
    ok_ = llt_ok_ = true;
    return true;
  }
  if (!ldlt_fallback) return false;
  impl_->ldlt.compute(M);
  if (impl_->ldlt.info() != Eigen::Success) return false;
  impl_->use_ldlt = true;
  ok_ = true;
  return true;
}

bool SparseSymFactor::refactor(const SpMat& M) {
  if (!analysed_ || M.rows() != rows_ || M.nonZeros() != nnz_) return compute(M);
  ok_ = llt_ok_ = false;
  impl_->use_ldlt = false;
  impl_->llt.factorize(M);
  ok_ = llt_ok_ = impl_->llt.info() == Eigen::Success;
  return ok_;
}

Eigen::VectorXd SparseSymFactor::solve(const Eigen::VectorXd& b) const {
  if (!ok_) return Eigen::VectorXd::Constant(b.size(), std::nan(""));
  return impl_->use_ldlt ? Eigen::VectorXd(impl_->ldlt.solve(b)) : Eigen::VectorXd(impl_->llt.solve(b));
}

}  // namespace bpde::cmc_detail
