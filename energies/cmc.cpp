#include "bezierpde/energies/cmc.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <mutex>
#include <string>
#include <utility>

#include "bezierpde/core/bernstein.h"
#include "bezierpde/core/columns3.h"
#include "bezierpde/core/errors.h"
#include "bezierpde/core/keyed_cache.h"
#include "bezierpde/core/kron.h"
#include "bezierpde/energies/patch_assembly.h"
#include "bezierpde/energies/triangular_gram.h"
#include "bezierpde/tensor/tensor_net.h"
#include "bezierpde/triangular/triangular_net.h"

namespace bpde {
namespace {

// kron(A, B) for the tensor index i*(m+1) + j.

// Functionals kept by cached_triangular and cached_tensor (each; least recently used evicted).
constexpr std::size_t kFunctionalCacheSize = 16;

}  // namespace

CmcFunctional CmcFunctional::triangular(int n) {
  CmcFunctional f;
  f.volume_ = VolumeForm::triangular(n);  // validates n
  f.gram_ = triangular_dirichlet_gram(n);
  f.abs_gram_ = f.gram_.cwiseAbs();
  return f;
}

CmcFunctional CmcFunctional::tensor(int n, int m) {
  CmcFunctional f;
  f.volume_ = VolumeForm::tensor(n, m);  // validates n, m
  const Eigen::MatrixXd Ku = bernstein_derivative_integrals(n, 1, 1);
  const Eigen::MatrixXd Mu = bernstein_product_integrals(n, n);
  const Eigen::MatrixXd Kv = bernstein_derivative_integrals(m, 1, 1);
  const Eigen::MatrixXd Mv = bernstein_product_integrals(m, m);
  f.gram_ = kron(Ku, Mv) + kron(Mu, Kv);
  f.abs_gram_ = f.gram_.cwiseAbs();
  return f;
}

std::shared_ptr<const CmcFunctional> CmcFunctional::cached_triangular(int n) {
  static KeyedCache<int, CmcFunctional> cache(kFunctionalCacheSize);
  return cache.get(n, [](int d) { return triangular(d); });
}

std::shared_ptr<const CmcFunctional> CmcFunctional::cached_tensor(int n, int m) {
  static KeyedCache<std::pair<int, int>, CmcFunctional> cache(kFunctionalCacheSize);
  return cache.get({n, m}, [](const std::pair<int, int>& d) { return tensor(d.first, d.second); });
}

struct CmcFunctional::DenseGram {
  std::once_flag once;
  Eigen::MatrixXd M;
};

namespace {

// An assembled functional over at most this many points also keeps its Gram dense and uses the
// dense products (the solves of small complexes stay those of one patch, bit for bit; 500 points
// are the 1500 coordinates from which the complex solves turn sparse, solvers/cmc/area/tuning.h).
constexpr int kDenseAssembledGramPoints = 500;

// Σ_p S_pᵀ M S_p (#global square, sparse).
Eigen::SparseMatrix<double> assembled_sparse(const PatchAssembly& a, const Eigen::MatrixXd& M) {
  std::vector<Eigen::Triplet<double>> t;
  t.reserve(a.maps.size() * static_cast<std::size_t>(M.size()));
  for (const std::vector<int>& map : a.maps)
    for (std::size_t j = 0; j < map.size(); ++j)
      for (std::size_t i = 0; i < map.size(); ++i) {
        const double v = M(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j));
        if (v != 0.0) t.emplace_back(map[i], map[j], v);
      }
  Eigen::SparseMatrix<double> S(a.size, a.size);
  S.setFromTriplets(t.begin(), t.end());
  return S;
}

}  // namespace

CmcFunctional CmcFunctional::assembled(std::shared_ptr<const CmcFunctional> patch,
                                       std::shared_ptr<const PatchAssembly> assembly) {
  if (!patch || !assembly) throw ParameterError("CmcFunctional::assembled: needs a patch functional and an assembly");
  CmcFunctional f;
  f.volume_ = VolumeForm::assembled(std::shared_ptr<const VolumeForm>(patch, &patch->volume_), assembly);
  f.sgram_ = assembled_sparse(*assembly, patch->gram_);
  f.sabs_gram_ = assembled_sparse(*assembly, patch->abs_gram_);
  f.dense_ = std::make_shared<DenseGram>();
  if (assembly->size <= kDenseAssembledGramPoints) {  // small: the dense products, as one patch
    f.gram_ = assembled_matrix(*assembly, patch->gram_);
    f.abs_gram_ = assembled_matrix(*assembly, patch->abs_gram_);
  }
  return f;
}

const Eigen::MatrixXd& CmcFunctional::gram() const {
  if (gram_.size() > 0 || !assembly()) return gram_;
  std::call_once(dense_->once, [this] { dense_->M = Eigen::MatrixXd(sgram_); });
  return dense_->M;
}

std::size_t CmcFunctional::memory_bytes() const {
  return volume_.memory_bytes() + sizeof(double) * static_cast<std::size_t>(gram_.size()) +
         (sizeof(double) + sizeof(int)) * static_cast<std::size_t>(sgram_.nonZeros() + sabs_gram_.nonZeros());
}

double CmcFunctional::dirichlet(const Eigen::MatrixX3d& P) const {
  if (P.rows() != size()) throw SizeError("CmcFunctional: wrong number of points");
  if (gram_.size() == 0) return 0.5 * (P.transpose() * Eigen::MatrixX3d(sgram_ * P)).trace();
  return 0.5 * (P.transpose() * gram_ * P).trace();
}

double CmcFunctional::value(const Eigen::MatrixX3d& P, double H) const {
  return dirichlet(P) + 2.0 * H * volume_.value(P);
}

Eigen::MatrixX3d CmcFunctional::gradient(const Eigen::MatrixX3d& P, double H) const {
  if (P.rows() != size()) throw SizeError("CmcFunctional: wrong number of points");
  Eigen::MatrixX3d G = gram_.size() == 0 ? Eigen::MatrixX3d(sgram_ * P) : Eigen::MatrixX3d(gram_ * P);
  if (H != 0.0) G += 2.0 * H * volume_.gradient(P);
  return G;
}

Eigen::MatrixXd CmcFunctional::hessian(const Eigen::MatrixX3d& P, double H, const std::vector<int>& idx) const {
  const Eigen::Index k = static_cast<Eigen::Index>(idx.size());
  Eigen::MatrixXd Hs = Eigen::MatrixXd::Zero(3 * k, 3 * k);
  if (H != 0.0) Hs = 2.0 * H * volume_.hessian(P, idx);
  const Eigen::MatrixXd& C = gram();
  for (Eigen::Index a = 0; a < k; ++a)
    for (Eigen::Index b = 0; b < k; ++b) {
      const double c = C(idx[static_cast<size_t>(a)], idx[static_cast<size_t>(b)]);
      for (int r = 0; r < 3; ++r) Hs(3 * a + r, 3 * b + r) += c;
    }
  return Hs;
}

Eigen::MatrixX3d CmcFunctional::gradient_rows(const Eigen::MatrixX3d& P, double H, const std::vector<int>& idx) const {
  if (P.rows() != size()) throw SizeError("CmcFunctional: wrong number of points");
  const Eigen::MatrixX3d CP = gram_.size() == 0 ? Eigen::MatrixX3d(sgram_ * P) : times(gram_, P);
  Eigen::MatrixX3d G = CP(idx, Eigen::all);
  if (H != 0.0) G += 2.0 * H * volume_.gradient_rows(P, idx);
  return G;
}

double CmcFunctional::residual(const Eigen::MatrixX3d& P, double H, const std::vector<int>& idx, Eigen::MatrixX3d* Fout,
                               double* scale) const {
  if (P.rows() != size()) throw SizeError("CmcFunctional: wrong number of points");
  const Eigen::Index k = static_cast<Eigen::Index>(idx.size());
  const Eigen::MatrixX3d CP = gram_.size() == 0 ? Eigen::MatrixX3d(sgram_ * P) : times(gram_, P);
  const Eigen::MatrixX3d CS =
      gram_.size() == 0 ? Eigen::MatrixX3d(sabs_gram_ * P.cwiseAbs()) : times(abs_gram_, P.cwiseAbs());
  Eigen::MatrixX3d F = CP(idx, Eigen::all), S = CS(idx, Eigen::all);
  if (H != 0.0) {
    Eigen::MatrixX3d GV, SV;
    volume_.gradient_rows_and_scale(P, idx, &GV, &SV);
    F += 2.0 * H * GV;
    S += 2.0 * std::abs(H) * SV;
  }
  if (Fout) *Fout = F;
  const double num = k == 0 ? 0.0 : F.cwiseAbs().maxCoeff();
  const double den = k == 0 ? 0.0 : S.maxCoeff();
  if (scale) *scale = den;
  if (!std::isfinite(num)) return std::numeric_limits<double>::infinity();
  if (den == 0.0) return num == 0.0 ? 0.0 : std::numeric_limits<double>::infinity();
  return num / den;
}

CmcEnergies cmc_energies(const TriangularNet& net, double H) {
  if (!std::isfinite(H)) throw NonFiniteError("cmc energy: H must be a finite number");
  const auto f = CmcFunctional::cached_triangular(net.n());
  CmcEnergies e;
  e.D = f->dirichlet(net.points());
  e.V = f->volume(net.points());
  e.DH = e.D + 2.0 * H * e.V;
  return e;
}

CmcEnergies cmc_energies(const TensorNet& net, double H) {
  if (!std::isfinite(H)) throw NonFiniteError("cmc energy: H must be a finite number");
  const auto f = CmcFunctional::cached_tensor(net.n(), net.m());
  CmcEnergies e;
  e.D = f->dirichlet(net.points());
  e.V = f->volume(net.points());
  e.DH = e.D + 2.0 * H * e.V;
  return e;
}

namespace {

void check_sampling(int N, double margin) {
  if (N < 1) throw ParameterError("mean_curvature_stats: samples must be >= 1");
  if (!(margin >= 0.0 && margin < 0.5)) throw ParameterError("mean_curvature_stats: corner_margin must be in [0, 0.5)");
}

}  // namespace

MeanCurvatureStats mean_curvature_stats(const TriangleMesh& mesh, SampleLayout layout, int N, double corner_margin,
                                        bool skip_singular) {
  check_sampling(N, corner_margin);
  const Eigen::Index expected =
      layout == SampleLayout::TensorGrid ? Eigen::Index(N + 1) * (N + 1) : Eigen::Index(N + 1) * (N + 2) / 2;
  if (mesh.H.size() != expected || (mesh.regular.size() != 0 && mesh.regular.size() != expected))
    throw SizeError("mean_curvature_stats: the mesh has " + std::to_string(mesh.H.size()) + " samples, expected " +
                    std::to_string(expected) + " for N = " + std::to_string(N));
  const bool use_flags = skip_singular && mesh.regular.size() == expected;
  MeanCurvatureStats s;
  double sum = 0;
  auto take = [&](Eigen::Index id, double u, double v) {
    if (use_flags && !mesh.regular(id)) return;
    const double h = mesh.H(id);
    if (skip_singular && !std::isfinite(h)) return;
    if (s.count == 0 || h < s.min) {
      s.min = h;
      s.at_min = {u, v};
    }
    if (s.count == 0 || h > s.max) {
      s.max = h;
      s.at_max = {u, v};
    }
    sum += h;
    ++s.count;
  };
  Eigen::Index id = 0;
  if (layout == SampleLayout::TriangularGrid) {
    const double lim = 1.0 - corner_margin + 1e-12;
    for (int a = 0; a <= N; ++a)
      for (int b = 0; b <= N - a; ++b, ++id) {
        const double u = static_cast<double>(a) / N, v = static_cast<double>(b) / N;
        const double w = 1.0 - u - v;
        if (u > lim || v > lim || w > lim) continue;
        take(id, u, v);
      }
  } else {
    const double lim = corner_margin - 1e-12;
    for (int a = 0; a <= N; ++a)
      for (int b = 0; b <= N; ++b, ++id) {
        const double u = static_cast<double>(a) / N, v = static_cast<double>(b) / N;
        if (std::min(u, 1 - u) < lim && std::min(v, 1 - v) < lim) continue;
        take(id, u, v);
      }
  }
  if (s.count > 0) s.mean = sum / s.count;
  return s;
}

MeanCurvatureStats mean_curvature_stats(const TriangularNet& net, int N, double corner_margin) {
  check_sampling(N, corner_margin);
  return mean_curvature_stats(sample_mesh(net, N), SampleLayout::TriangularGrid, N, corner_margin);
}

MeanCurvatureStats mean_curvature_stats(const TensorNet& net, int N, double corner_margin) {
  check_sampling(N, corner_margin);
  return mean_curvature_stats(sample_mesh(net, N), SampleLayout::TensorGrid, N, corner_margin);
}

}  // namespace bpde
