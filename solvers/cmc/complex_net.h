#pragma once
// A surface of several patches (complex/patch_complex.h) in the role of a net for the CMC solves.
//
// Design: the CMC solves (solvers/cmc/cmc.cpp, solvers/cmc/area/) are templates on the net type,
// and everything they do with the surface goes through three kinds of calls: the forms on the
// #points x 3 point matrix (CmcFunctional, VolumeForm, AreaForm: value, gradient rows, Hessian
// over the free rows), a handful of operations on the net (its degree, points, fixed and free
// rows, a net with other points, the regularity verdict, the normal gap of the continuations'
// branch test, the area) and a rule chosen for the area. ComplexNet is a third net type for those
// templates: its forms are the library's forms in their assembled mode (energies/
// patch_assembly.h: the patch's form summed over the patches through the local -> global maps),
// and the net operations are the patches' operations combined (below). So every route, corrector
// and phase has one copy, explicitly instantiated for TriangularNet, TensorNet and ComplexNet;
// nothing in the routes knows whether it solves one patch or several. The alternative, an
// abstract "free-coordinate functional" behind CmcProblem and AreaProblem, would have changed
// every route's calls for the same effect.
//
// Conventions: points are PatchComplex::points (#points x 3); the fixed rows are PatchComplex::
// fixed (FixedSet boundary: the rows held by the boundary data); the free rows the others,
// ascending. All patches have one kind and degree n (tensor: (n, n)).
#include "bezierpde/core/eigen.h"
#include <Eigen/Core>
#include <memory>
#include <vector>

#include "bezierpde/complex/patch_complex.h"
#include "bezierpde/core/fixed_set.h"
#include "bezierpde/energies/cmc.h"
#include "bezierpde/energies/patch_assembly.h"
#include "bezierpde/solvers/cmc/cmc.h"
#include "bezierpde/solvers/cmc/area/tuning.h"

namespace bpde {

class ComplexNet {
 public:
  ComplexNet() = default;
  /// Checks the complex (energies/complex_functionals.h: patch_assembly) and builds its D_H form.
  explicit ComplexNet(PatchComplex c);
  /// The same layout with other points (#points x 3; SizeError otherwise).
  ComplexNet(const ComplexNet& like, const Eigen::MatrixX3d& points);

  const PatchComplex& complex() const { return c_; }
  bool triangular() const { return c_.patches.front().kind == PatchKind::triangular; }
  int n() const { return c_.patches.front().degree; }
  int m() const { return n(); }
  int size() const { return static_cast<int>(c_.points.rows()); }
  int patches() const { return static_cast<int>(c_.patches.size()); }
  const Eigen::MatrixX3d& points() const { return c_.points; }
  /// FixedSet boundary: PatchComplex::fixed; other sets: UnsupportedProblem.
  std::vector<int> fixed_indices(FixedSet fixed) const;
  std::vector<int> free_indices(FixedSet fixed) const;
  const std::shared_ptr<const PatchAssembly>& assembly() const { return assembly_; }
  /// D_H of the complex (CmcFunctional::assembled), shared by the nets of one layout.
  const std::shared_ptr<const CmcFunctional>& functional() const { return f_; }
  /// Patch p's points (patch_size x 3, the net's order).
  Eigen::MatrixX3d patch_points(int p) const;

 private:
  PatchComplex c_;
  std::shared_ptr<const PatchAssembly> assembly_;
  std::shared_ptr<const CmcFunctional> f_;
};

/// The sum of the patches' areas (energies/area_functional.h, area(net)).
double area(const ComplexNet& net);

/// The least squares of the mean curvature on a complex (MeanCurvatureLeastSquares::assembled,
/// cmc_mean_curvature.cpp) take at most this many free coordinates (3 per free point): their
/// Levenberg–Marquardt loop is dense (a #nodes x 3k Jacobian, a 3k x 3k normal matrix), and above it
/// the area solve's own matrices are sparse (area_impl::kSparseFromCoordinates, the same count).
inline constexpr int kMaxMeanCurvatureCoordinates = cmc_detail::area_impl::kSparseFromCoordinates;
/// Whether net's free coordinates are at most kMaxMeanCurvatureCoordinates.
bool mean_curvature_fits(const ComplexNet& net);

/// The CMC solve of a complex (cmc.h, the same routes as for one patch): functional dirichlet,
/// area or mean-curvature, H or V form, fixed set boundary. The mean-curvature functional (and the
/// area functional's mean-curvature-start) takes complexes of at most kMaxMeanCurvatureCoordinates
/// free coordinates and the solver newton (its own Levenberg–Marquardt loop; the Ceres route has one
/// residual block per node of one patch): UnsupportedProblem otherwise, and the area functional
/// skips mean-curvature-start there (its record says why; with solver ceres it minimises the least
/// squares by the newton loop, the A_H corrections after it by ceres). The regularity verdict is the
/// patches' (each on its own grid); quadrature_nodes counts the nodes of all patches.
CmcResult<ComplexNet> solve_cmc(const ComplexNet& data, const CmcOptions& options);

}  // namespace bpde
