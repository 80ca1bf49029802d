#include "bezierpde/solvers/complex/complex_extremal.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "bezierpde/core/errors.h"
#include "bezierpde/core/interruption.h"
#include "bezierpde/energies/tensor_gram.h"
#include "bezierpde/energies/triangular_gram.h"
#include "bezierpde/solvers/complex/complex_c1.h"

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

/// ‖A‖_∞ (largest absolute row sum).
double inf_norm(const SpMat& A) {
  Eigen::VectorXd sums = Eigen::VectorXd::Zero(A.rows());
  for (int k = 0; k < A.outerSize(); ++k)
    for (SpMat::InnerIterator it(A, k); it; ++it) sums(it.row()) += std::abs(it.value());
  return A.rows() ? sums.maxCoeff() : 0.0;
}

/// The C¹ extremal (complex_extremal.h): augmented Lagrangian steps on the scaled system.
void solve_c1(const PatchComplex& c, const SpMat& K, const std::vector<int>& free, const std::vector<int>& position,
              const ComplexExtremalOptions& options, ComplexExtremal& out) {
  const int n = c.patches.front().degree;
  const SpMat C = c1_constraints(c, options.domain);
  const int nf = static_cast<int>(free.size());
  // K_ff, -K_fb X_b; C_f, d = -C_b X_b
  std::vector<Eigen::Triplet<double>> tk, tc;
  Eigen::MatrixX3d rhs = Eigen::MatrixX3d::Zero(nf, 3), d = Eigen::MatrixX3d::Zero(C.rows(), 3);
  for (int k = 0; k < K.outerSize(); ++k)
    for (SpMat::InnerIterator it(K, k); it; ++it) {
      const int i = position[it.row()], j = position[it.col()];
      if (i < 0) continue;
      if (j >= 0) tk.emplace_back(i, j, it.value());
      else rhs.row(i) -= it.value() * c.points.row(it.col());
    }
  for (int k = 0; k < C.outerSize(); ++k)
    for (SpMat::InnerIterator it(C, k); it; ++it) {
      const int j = position[it.col()];
      if (j >= 0) tc.emplace_back(it.row(), j, it.value());
      else d.row(it.row()) -= it.value() * c.points.row(it.col());
    }
  SpMat Kff(nf, nf), Cf(C.rows(), nf);
  Kff.setFromTriplets(tk.begin(), tk.end());
  Cf.setFromTriplets(tc.begin(), tc.end());
  Eigen::MatrixX3d Xf = Eigen::MatrixX3d::Zero(nf, 3);
  if (nf > 0) {
    const Eigen::VectorXd diag = Kff.diagonal();
    if ((diag.array() <= 0).any())
      throw ParameterError("the energy does not determine the free control points (a zero or negative diagonal: "
                           "singular system)");
    const Eigen::VectorXd s = diag.cwiseSqrt().cwiseInverse();
    const SpMat A = s.asDiagonal() * Kff * s.asDiagonal();
    SpMat Cs = Cf * s.asDiagonal();
    // unit-norm rows; rows with no free entry (conditions on the boundary data alone) stay zero
    Eigen::VectorXd rownorm = Eigen::VectorXd::Zero(Cs.rows());
    for (int k = 0; k < Cs.outerSize(); ++k)
      for (SpMat::InnerIterator it(Cs, k); it; ++it) rownorm(it.row()) += it.value() * it.value();
    Eigen::VectorXd rscale(Cs.rows());
    for (int r = 0; r < Cs.rows(); ++r) rscale(r) = rownorm(r) > 0 ? 1 / std::sqrt(rownorm(r)) : 0.0;
    const SpMat Ch = rscale.asDiagonal() * Cs;
    const Eigen::MatrixX3d dh = rscale.asDiagonal() * d;
    const SpMat Ct = Ch.transpose();
    const SpMat Arho = A + kC1Penalty * SpMat(Ct * Ch);
    Factor factor;
#ifdef BPDE_HAVE_CHOLMOD
    factor.cholmod().print = 0;
#endif
    check_interruption();  // core/interruption.h: around the factorisation and between the steps
    factor.compute(Arho);
    check_interruption();
    const double rcond = factor.info() == Eigen::Success ? rcond_estimate(Arho, factor) : 0.0;
    if (!(rcond > options.singular_tolerance))
      throw ParameterError("the C1 complex extremal's system is singular (reciprocal condition " + std::to_string(rcond) +
                           "): the energy does not determine the control points the C1 conditions leave free");
    const Eigen::MatrixX3d b = s.asDiagonal() * rhs;
    Eigen::MatrixX3d lambda = Eigen::MatrixX3d::Zero(Ch.rows(), 3), y;
    double last = INFINITY;
    for (int step = 0; step < 200; ++step) {
      check_interruption();
      y = factor.solve(b - Ct * lambda + kC1Penalty * (Ct * dh));
      const Eigen::MatrixX3d r = Ch * y - dh;
      lambda += kC1Penalty * r;
      out.c1_steps = step + 1;
      const double defect = r.cwiseAbs().maxCoeff();
      if (!(defect > 1e-15 * (y.cwiseAbs().maxCoeff() + dh.cwiseAbs().maxCoeff())) || !(defect < 0.9 * last)) break;
      last = defect;
    }
    Xf = s.asDiagonal() * y;
    // stationarity K_ff X_f + C_fᵀ μ = rhs, μ = R λ
    const Eigen::MatrixX3d mu = rscale.asDiagonal() * lambda;
    const Eigen::MatrixX3d r = Kff * Xf + SpMat(Cf.transpose()) * mu - rhs;
    const double scale = inf_norm(Kff) * Xf.cwiseAbs().maxCoeff() + rhs.cwiseAbs().maxCoeff() +
                         inf_norm(SpMat(Cf.transpose())) * mu.cwiseAbs().maxCoeff() + std::numeric_limits<double>::min();
    out.summary.residual = r.cwiseAbs().maxCoeff() / scale;
  }
  for (int i = 0; i < nf; ++i) out.complex.points.row(free[i]) = Xf.row(i);
  out.c1_residual = c1_residual(out.complex, options.domain);
  out.energy = 0.5 * (out.complex.points.transpose() * (K * out.complex.points)).trace();
  if (!(out.c1_residual <= kC1Tolerance)) {
    out.summary.set_failed(Status::Incompatible,
                           "the C1 conditions across the seams contradict the boundary data at degree " + std::to_string(n) +
                               " (C1 defect " + std::to_string(out.c1_residual) +
                               "): no C1 complex of this degree takes this boundary (raise the degree, or use C0)");
    return;
  }
  out.summary.finish(out.summary.residual < kConvergenceTolerance, Status::NumericalLimit, [&] {
    return "the C1 extremal's relative residual " + std::to_string(out.summary.residual) + " is above " +
           std::to_string(kConvergenceTolerance) + " (rounding at degree " + std::to_string(n) + ")";
  });
}

}  // namespace

long long complex_gram_entries(const PatchComplex& c) {
  if (c.patches.empty()) return 0;
  const long long k = static_cast<long long>(c.patches.front().points.size());
  return static_cast<long long>(c.patches.size()) * k * k;
}

SpMat complex_gram(const PatchComplex& c, const EnergySpec& energy, const std::vector<DomainTriangle>& domain) {
  validate(c);
  if (!domain.empty() && (domain.size() != c.patches.size() || c.patches.front().kind != PatchKind::triangular))
    throw ParameterError("a planar domain takes one triangle per patch of a triangular complex (" +
                         std::to_string(domain.size()) + " for " + std::to_string(c.patches.size()) + " patches)");
  if (complex_gram_entries(c) > kMaxComplexGramEntries)
    throw SizeError("a complex of " + std::to_string(c.patches.size()) + " patches of " +
                    std::to_string(c.patches.front().points.size()) + " points has " +
                    std::to_string(complex_gram_entries(c)) + " Gram entries, more than " +
                    std::to_string(kMaxComplexGramEntries));
  Eigen::MatrixXd Q = patch_gram(c.patches.front(), energy);  // one kind and degree
  std::vector<Eigen::Triplet<double>> triplets;
  triplets.reserve(c.patches.size() * Q.size());
  DomainGrams grams(c.patches.front().degree, energy);
  for (std::size_t p = 0; p < c.patches.size(); ++p) {
    const ComplexPatch& patch = c.patches[p];
    if (!domain.empty()) Q = grams.gram(domain[p]);
    for (int I = 0; I < Q.rows(); ++I)
      for (int J = 0; J < Q.cols(); ++J)
        if (Q(I, J) != 0) triplets.emplace_back(patch.points[I], patch.points[J], Q(I, J));
  }
  SpMat K(c.points.rows(), c.points.rows());
  K.setFromTriplets(triplets.begin(), triplets.end());
  return K;
}

double complex_energy(const PatchComplex& c, const EnergySpec& energy, const std::vector<DomainTriangle>& domain) {
  const SpMat K = complex_gram(c, energy, domain);
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
  const bool c1 = options.continuity == Continuity::C1;
  if (c1 && (options.domain.empty() || c.patches.front().kind != PatchKind::triangular))
    throw ParameterError("C1 continuity takes a triangular complex with a planar domain (one triangle per patch)");
  const SpMat K = complex_gram(c, energy, options.domain);
  std::vector<int> position;
  const std::vector<int> free = free_rows(c, position);
  if (c1) {
    solve_c1(c, K, free, position, options, out);
    return out;
  }
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
  check_interruption();  // core/interruption.h: around the factorisation
  factor.compute(A);
  check_interruption();
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
