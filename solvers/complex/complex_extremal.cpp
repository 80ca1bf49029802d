#include "bezierpde/solvers/complex/complex_extremal.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "bezierpde/core/errors.h"
#include "bezierpde/energies/tensor_gram.h"
#include "bezierpde/energies/triangular_gram.h"

#ifdef BPDE_HAVE_CHOLMOD
#include <Eigen/CholmodSupport>
#endif
#include <Eigen/SparseCholesky>

namespace bpde {

namespace {

using SpMat = Eigen::SparseMatrix<double>;

#ifdef BPDE_HAVE_CHOLMOD
using Factor = Eigen::CholmodSupernodalLLT<SpMat>;
#else
using Factor = Eigen::SimplicialLDLT<SpMat>;
#endif

Eigen::MatrixXd patch_gram(const ComplexPatch& patch, const EnergySpec& energy) {
  return patch.kind == PatchKind::triangular ? triangular_gram(patch.degree, energy)
                                             : tensor_gram(energy, patch.degree, patch.degree);
}

/// Free rows (complement of c.fixed) and position: row -> index in free, or -1.
std::vector<int> free_rows(const PatchComplex& c, std::vector<int>& position) {
  position.assign(c.points.rows(), -1);
  std::vector<int> free;
  for (int r = 0; r < c.points.rows(); ++r)
    if (!std::binary_search(c.fixed.begin(), c.fixed.end(), r)) {
      position[r] = static_cast<int>(free.size());
      free.push_back(r);
    }
  return free;
}

/// Reciprocal condition estimate of the (unit-diagonal) matrix A from its factor.
double rcond_estimate(const SpMat& A, const Factor& factor) {
  double lmax = 0;
  for (int k = 0; k < A.outerSize(); ++k) {
    double sum = 0;
    for (SpMat::InnerIterator it(A, k); it; ++it) sum += std::abs(it.value());
    lmax = std::max(lmax, sum);
  }
  Eigen::VectorXd y = Eigen::VectorXd::Ones(A.rows()) + 0.1 * Eigen::VectorXd::LinSpaced(A.rows(), 0, 1);
  y.normalize();
  double growth = 0;
  for (int it = 0; it < 30; ++it) {
    Eigen::VectorXd z = factor.solve(y);
    if (!z.allFinite()) return 0;
    growth = z.norm();
    if (!(growth > 0)) return 0;
    y = z / growth;
  }
  return (1.0 / growth) / lmax;
}

}  // namespace

long long complex_gram_entries(const PatchComplex& c) {
  if (c.patches.empty()) return 0;
  const long long k = static_cast<long long>(c.patches.front().points.size());
  return static_cast<long long>(c.patches.size()) * k * k;
}

SpMat complex_gram(const PatchComplex& c, const EnergySpec& energy) {
  validate(c);
  if (complex_gram_entries(c) > kMaxComplexGramEntries)
    throw SizeError("a complex of " + std::to_string(c.patches.size()) + " patches of " +
                    std::to_string(c.patches.front().points.size()) + " points has " +
                    std::to_string(complex_gram_entries(c)) + " Gram entries, more than " +
                    std::to_string(kMaxComplexGramEntries));
  const Eigen::MatrixXd Q = patch_gram(c.patches.front(), energy);  // one kind and degree
  std::vector<Eigen::Triplet<double>> triplets;
  triplets.reserve(c.patches.size() * Q.size());
  for (const ComplexPatch& patch : c.patches)
    for (int I = 0; I < Q.rows(); ++I)
      for (int J = 0; J < Q.cols(); ++J)
        if (Q(I, J) != 0) triplets.emplace_back(patch.points[I], patch.points[J], Q(I, J));
  SpMat K(c.points.rows(), c.points.rows());
  K.setFromTriplets(triplets.begin(), triplets.end());
  return K;
}

double complex_energy(const PatchComplex& c, const EnergySpec& energy) {
  const SpMat K = complex_gram(c, energy);
  return 0.5 * (c.points.transpose() * (K * c.points)).trace();
}

ComplexExtremal solve_complex_extremal(const PatchComplex& c, const EnergySpec& energy,
                                       const ComplexExtremalOptions& options) {
  if (!(options.singular_tolerance >= 0 && options.singular_tolerance < 1))
    throw ParameterError("singular_tolerance must be in [0, 1)");
  validate(c);
  const int n = c.patches.front().degree;
  if (n > kMaxComplexExtremalDegree)
    throw DegreeError("a complex extremal has degree at most " + std::to_string(kMaxComplexExtremalDegree) +
                      " (the Bernstein Gram systems lose a digit per degree), got " + std::to_string(n));
  ComplexExtremal out;
  out.complex = c;
  ScopedTimer timer(out.summary.seconds);
  const SpMat K = complex_gram(c, energy);
  std::vector<int> position;
  const std::vector<int> free = free_rows(c, position);
  if (free.empty()) {
    out.energy = 0.5 * (c.points.transpose() * (K * c.points)).trace();
    out.summary.set_converged();
    return out;
  }
  // split K into K_ff (scaled) and the right-hand side -K_fb X_b
  const int nf = static_cast<int>(free.size());
  std::vector<Eigen::Triplet<double>> tf;
  Eigen::MatrixX3d rhs = Eigen::MatrixX3d::Zero(nf, 3);
  for (int k = 0; k < K.outerSize(); ++k)
    for (SpMat::InnerIterator it(K, k); it; ++it) {
      const int i = position[it.row()], j = position[it.col()];
      if (i < 0) continue;
      if (j >= 0) tf.emplace_back(i, j, it.value());
      else rhs.row(i) -= it.value() * c.points.row(it.col());
    }
  SpMat Kff(nf, nf);
  Kff.setFromTriplets(tf.begin(), tf.end());
  Eigen::VectorXd d = Kff.diagonal();
  if ((d.array() <= 0).any())
    throw ParameterError("the energy does not determine the free control points (a zero or negative diagonal: "
                         "singular system)");
  const Eigen::VectorXd s = d.cwiseSqrt().cwiseInverse();
  const SpMat A = s.asDiagonal() * Kff * s.asDiagonal();
  Factor factor;
#ifdef BPDE_HAVE_CHOLMOD
  factor.cholmod().print = 0;  // a singular system is reported by the exception below, not on stderr
#endif
  factor.compute(A);
  const double rcond = factor.info() == Eigen::Success ? rcond_estimate(A, factor) : 0.0;
  if (!(rcond > options.singular_tolerance))
    throw ParameterError("the complex extremal's system is singular or indefinite (reciprocal condition " +
                         std::to_string(rcond) + "): the energy does not determine the free control points; a "
                         "fourth-order energy with only the boundary fixed has piecewise-affine null directions "
                         "on such layouts");
  const Eigen::MatrixX3d Xf = s.asDiagonal() * factor.solve(s.asDiagonal() * rhs);
  for (int i = 0; i < nf; ++i) out.complex.points.row(free[i]) = Xf.row(i);
  const Eigen::MatrixX3d r = Kff * Xf - rhs;
  double knorm = 0;
  for (int k = 0; k < Kff.outerSize(); ++k) {
    double sum = 0;
    for (SpMat::InnerIterator it(Kff, k); it; ++it) sum += std::abs(it.value());
    knorm = std::max(knorm, sum);
  }
  const double scale = knorm * Xf.cwiseAbs().maxCoeff() + rhs.cwiseAbs().maxCoeff() + std::numeric_limits<double>::min();
  out.summary.residual = r.cwiseAbs().maxCoeff() / scale;
  out.energy = 0.5 * (out.complex.points.transpose() * (K * out.complex.points)).trace();
  out.summary.finish(out.summary.residual < kConvergenceTolerance, Status::NumericalLimit, [&] {
    return "the extremal's relative residual " + std::to_string(out.summary.residual) + " is above " +
           std::to_string(kConvergenceTolerance) + " (rounding at degree " + std::to_string(n) + ")";
  });
  return out;
}

}  // namespace bpde
