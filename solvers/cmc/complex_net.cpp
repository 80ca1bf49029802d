// ComplexNet (complex_net.h): the net operations of the CMC solves on a complex, each the patches'
// operations combined, and the public solve of a PatchComplex (complex_cmc.h).
#include "bezierpde/solvers/cmc/complex_net.h"

#include "bezierpde/core/eigen.h"
#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>
#include <utility>

#include "bezierpde/core/errors.h"
#include "bezierpde/energies/area_functional.h"
#include "bezierpde/energies/complex_functionals.h"
#include "bezierpde/energies/energy_spec.h"
#include "bezierpde/solvers/cmc/area/area_problem.h"
#include "bezierpde/solvers/cmc/area/tuning.h"
#include "bezierpde/solvers/cmc/cmc_problem.h"
#include "bezierpde/solvers/cmc/complex_cmc.h"
#include "bezierpde/solvers/complex/complex_extremal.h"

namespace bpde {
namespace {

template <class F>
void for_each_patch(const PatchComplex& c, F&& f) {
  for (int p = 0; p < static_cast<int>(c.patches.size()); ++p) {
    if (c.patches[static_cast<std::size_t>(p)].kind == PatchKind::triangular)
      f(triangular_patch(c, p));
    else
      f(tensor_patch(c, p));
  }
}

}  // namespace

ComplexNet::ComplexNet(PatchComplex c) : c_(std::move(c)) {
  assembly_ = patch_assembly(c_);
  if (!c_.points.allFinite()) throw NonFiniteError("complex: the points must be finite");
  f_ = complex_cmc_functional(c_);
}

ComplexNet::ComplexNet(const ComplexNet& like, const Eigen::MatrixX3d& points)
    : c_(like.c_), assembly_(like.assembly_), f_(like.f_) {
  if (points.rows() != c_.points.rows()) throw SizeError("complex: wrong number of points");
  c_.points = points;
}

std::vector<int> ComplexNet::fixed_indices(FixedSet fixed) const {
  if (fixed != FixedSet::Boundary)
    throw UnsupportedProblem("cmc on a complex: the fixed set is \"boundary\" (the complex's fixed rows)");
  return c_.fixed;
}

std::vector<int> ComplexNet::free_indices(FixedSet fixed) const {
  fixed_indices(fixed);
  return complex_free_rows(c_);
}

bool mean_curvature_fits(const ComplexNet& net) {
  return 3 * static_cast<long long>(complex_free_rows(net.complex()).size()) <= kMaxMeanCurvatureCoordinates;
}

Eigen::MatrixX3d ComplexNet::patch_points(int p) const { return bpde::patch_points(*assembly_, p, c_.points); }

double area(const ComplexNet& net) {
  double A = 0.0;
  for_each_patch(net.complex(), [&](const auto& patch) { A += area(patch); });
  return A;
}

namespace cmc_detail {

void check_degree(const ComplexNet& net, FixedSet fixed) {
  net.fixed_indices(fixed);
  const int need = net.triangular() ? 3 : 2;
  if (net.n() < need)
    throw DegreeError("cmc: the patches of a complex need degree >= " + std::to_string(need) + " (got " +
                      std::to_string(net.n()) + ")");
}

std::shared_ptr<const CmcFunctional> functional_for(const ComplexNet& net) { return net.functional(); }

ComplexNet make_net(const ComplexNet& data, const Eigen::MatrixX3d& P) { return ComplexNet(data, P); }

DirichletFactor dirichlet_solve_sparse(CmcProblem& p, const std::vector<int>& fixed_idx, const PatchComplex& c) {
  // K = Σ_p S_pᵀ C_p S_p over all points (complex_extremal.h), split into K_ff and K_fx.
  const Eigen::SparseMatrix<double> K = complex_gram(c, EnergySpec::dirichlet());
  std::vector<int> position(static_cast<std::size_t>(K.rows()), -1);
  for (int a = 0; a < p.k(); ++a) position[static_cast<std::size_t>(p.free[static_cast<std::size_t>(a)])] = a;
  std::vector<Eigen::Triplet<double>> tf;
  tf.reserve(static_cast<std::size_t>(K.nonZeros()));
  Eigen::MatrixX3d rhs = Eigen::MatrixX3d::Zero(p.k(), 3);
  for (int col = 0; col < K.outerSize(); ++col)
    for (Eigen::SparseMatrix<double>::InnerIterator it(K, col); it; ++it) {
      const int i = position[static_cast<std::size_t>(it.row())], j = position[static_cast<std::size_t>(col)];
      if (i < 0) continue;
      if (j >= 0) tf.emplace_back(i, j, it.value());
      else rhs.row(i) -= it.value() * p.P.row(col);
    }
  Eigen::SparseMatrix<double> Kff(p.k(), p.k());
  Kff.setFromTriplets(tf.begin(), tf.end());
  auto factor = std::make_shared<SparseSymFactor>();
  if (!factor->compute(Kff, /*ldlt_fallback=*/true)) return dirichlet_solve(p, fixed_idx);
  DirichletFactor f;
  f.sparse = factor;
  p.P(p.free, Eigen::all) = f.solve(rhs);
  return f;
}

DirichletFactor dirichlet_solve(CmcProblem& p, const std::vector<int>& fixed_idx, const ComplexNet& net) {
  const bool sparse = 3 * p.k() > area_impl::kSparseFromCoordinates && complex_gram_entries(net.complex()) <= kMaxComplexGramEntries;
  return sparse ? dirichlet_solve_sparse(p, fixed_idx, net.complex()) : dirichlet_solve(p, fixed_idx);
}

namespace {

// The patches' verdicts combined: ok when every patch is; the smallest ratio; the first fold.
Regularity combine(const ComplexNet& net, bool final_check) {
  Regularity r;
  r.min_ratio = std::numeric_limits<double>::infinity();
  for_each_patch(net.complex(), [&](const auto& patch) {
    const double A = area(patch);
    const Regularity q = final_check ? final_regularity(patch, A) : regularity(patch, A);
    r.min_ratio = std::min(r.min_ratio, q.min_ratio);
    r.flipped = r.flipped || q.flipped;
    if (!q.ok && r.ok) {
      r.fold_u = q.fold_u;
      r.fold_v = q.fold_v;
      r.fold_min_ratio = q.fold_min_ratio;
      r.fold_corner_angle = q.fold_corner_angle;
    }
    r.ok = r.ok && q.ok;
  });
  return r;
}

}  // namespace

Regularity regularity(const ComplexNet& net, double) { return combine(net, false); }
Regularity final_regularity(const ComplexNet& net, double) { return combine(net, true); }

double normal_gap(const ComplexNet& a, const ComplexNet& b) {
  double g = 0.0;
  for (int p = 0; p < a.patches(); ++p) {
    const double gp = a.triangular() ? normal_gap(TriangularNet(a.n(), a.patch_points(p)), TriangularNet(b.n(), b.patch_points(p)))
                                     : normal_gap(TensorNet(a.n(), a.n(), a.patch_points(p)),
                                                  TensorNet(b.n(), b.n(), b.patch_points(p)));
    g = std::max(g, gp);
  }
  return g;
}

}  // namespace cmc_detail

CmcResult<PatchComplex> solve_cmc(const PatchComplex& data, const CmcOptions& options) {
  const CmcResult<ComplexNet> r = solve_cmc(ComplexNet(data), options);
  CmcResult<PatchComplex> out;
  out.net = r.net.complex();
  out.H = r.H;
  out.D = r.D;
  out.V = r.V;
  out.DH = r.DH;
  out.A = r.A;
  out.energy = r.energy;
  out.functional = r.functional;
  out.quadrature_points = r.quadrature_points;
  out.quadrature_grading = r.quadrature_grading;
  out.quadrature_levels = r.quadrature_levels;
  out.quadrature_nodes = r.quadrature_nodes;
  out.continuation_steps = r.continuation_steps;
  out.summary = r.summary;
  out.routes = r.routes;
  out.parametrisation = r.parametrisation;
  return out;
}

MeanCurvatureStats mean_curvature_stats(const PatchComplex& c, int N, double corner_margin) {
  MeanCurvatureStats s;
  double sum = 0.0;
  for_each_patch(c, [&](const auto& patch) {
    const MeanCurvatureStats q = mean_curvature_stats(patch, N, corner_margin);
    if (q.count == 0) return;
    s.min = s.count == 0 ? q.min : std::min(s.min, q.min);
    s.max = s.count == 0 ? q.max : std::max(s.max, q.max);
    s.count += q.count;
    sum += q.mean * q.count;
  });
  if (s.count > 0) s.mean = sum / s.count;
  return s;
}

}  // namespace bpde
