#include "bezierpde/energies/tensor_gram.h"

#include <cmath>
#include <map>
#include <string>
#include <utility>

#include "bezierpde/core/bernstein.h"
#include "bezierpde/core/errors.h"

namespace bpde {
namespace {

void check_degree(int n, const char* which) {
  if (n < 1 || n > kMaxDegree)
    throw DegreeError(std::string("tensor_gram: degree ") + which + " = " + std::to_string(n) + " is outside 1.." +
                      std::to_string(kMaxDegree));
}

// 1-D derivative integrals, computed once per (a, b) pair within one Gram assembly.
class DerivativeIntegrals {
 public:
  explicit DerivativeIntegrals(int n) : n_(n) {}
  const Eigen::MatrixXd& get(int a, int b) {
    auto it = cache_.find({a, b});
    if (it != cache_.end()) return it->second;
    return cache_.emplace(std::make_pair(a, b), bernstein_derivative_integrals(n_, a, b)).first->second;
  }

 private:
  int n_;
  std::map<std::pair<int, int>, Eigen::MatrixXd> cache_;
};

}  // namespace

Eigen::MatrixXd tensor_gram(int n, int m, const std::vector<QuadraticTerm>& terms, double hu, double hv) {
  check_degree(n, "n");
  check_degree(m, "m");
  if (!(std::isfinite(hu) && std::isfinite(hv) && hu > 0 && hv > 0))
    throw ParameterError("tensor_gram: span lengths must be finite and > 0");
  for (const auto& t : terms) {
    if (t.au < 0 || t.av < 0 || t.bu < 0 || t.bv < 0)
      throw ParameterError("tensor_gram: negative derivative order in an energy term");
    if (!std::isfinite(t.w)) throw NonFiniteError("tensor_gram: non-finite energy term weight");
  }
  const int nu = n + 1, nv = m + 1, N = nu * nv;
  DerivativeIntegrals Iu(n), Iv(m);
  // Accumulate K = Σ w s kron(Ku, Kv) (unsymmetrised), then Q = (K + K^T)/2.
  Eigen::MatrixXd K = Eigen::MatrixXd::Zero(N, N);
  for (const auto& t : terms) {
    if (t.w == 0.0 || t.au > n || t.bu > n || t.av > m || t.bv > m) continue;
    const double s = t.w * std::pow(hu, 1 - t.au - t.bu) * std::pow(hv, 1 - t.av - t.bv);
    const Eigen::MatrixXd& Ku = Iu.get(t.au, t.bu);
    const Eigen::MatrixXd& Kv = Iv.get(t.av, t.bv);
    // K(i*nv + j, k*nv + l) += s Ku(i,k) Kv(j,l): block (i,k) is s Ku(i,k) * Kv.
    for (int k = 0; k < nu; ++k)
      for (int i = 0; i < nu; ++i) {
        const double c = s * Ku(i, k);
        if (c != 0.0) K.block(i * nv, k * nv, nv, nv).noalias() += c * Kv;
      }
  }
  Eigen::MatrixXd Q = 0.5 * (K + K.transpose());
  return Q;
}

Eigen::MatrixXd tensor_gram(const EnergySpec& energy, int n, int m) { return tensor_gram(n, m, energy.terms()); }

}  // namespace bpde
