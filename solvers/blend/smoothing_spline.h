#pragma once
// Discrete smoothing PDE splines (Pasadas, Rodríguez, "Blending surfaces by smoothing
// PDE splines", §3 eq. (6), §5 Definition 2, Theorem 6 / eq. (8), §6).
//
// Given a k×l partition of Ω = [0,1]², the space X_h of Bogner–Fox–Schmit C¹ bicubic fields
// (solvers/blend/bfs_element.h), ε > 0 and a > 0, the discrete PDE spline σ ∈ X_h (three independent
// coordinates) minimises
//     J(v) = Σ_i |v(a_i) - β_i|² + ε ( |v|_L² - 2 (f, v)_0 )                              (6)
// over H_h = {v ∈ X_h : τ v = y}, where
//   - (u, v)_L = ∫_Ω u_xx v_xx + 2a u_xy v_xy + a² u_yy v_yy   (docs/errata.md: the splitting of
//     the operator ∂⁴_x + 2a ∂²_x∂²_y + a² ∂⁴_y that §6 uses);
//   - τ v = (v(x_i, 0), v_y(x_i, 0), v(x_i, 1), v_y(x_i, 1)), x_i = i/k, i = 0..k: the boundary
//     nodes are the partition's nodes on y = 0 and y = 1 (docs/errata.md reading of §6; x is not
//     periodic and the sides x = 0, x = 1 carry natural conditions);
//   - A = {a_1..a_m} ⊂ Ω the approximation points, β their data (A may be empty);
//   - f the load (0 unless given).
// Optimality (Theorem 6, eq. (8)): with C = AᵀA + εR, D the constraint matrix and
// F = Aᵀβ + ε((ω_r, f)_0) (the paper prints F without the ε; eq. (8) has it),
//     [ C  D ] [α]   [F]
//     [ Dᵀ 0 ] [λ] = [y].
// The KKT matrix is symmetric indefinite: it is solved by sparse LU. The cross-check eliminates
// the constrained dofs (τ fixes dofs directly: u and u_y at the boundary nodes) and solves the
// reduced SPD system C_ff α_f = F_f - C_fc y by sparse Cholesky (LDLᵀ).
//
// What the discrete spline reproduces (docs/errata.md, smoothing PDE splines): with A = ∅ and f = 0, exactly the data
// of U ∈ span{1, x, y, xy}; as ε → 0, σ(a_i) → β_i with an error linear in ε.
#include "bezierpde/core/eigen.h"
#include <Eigen/Core>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "bezierpde/core/differential_geometry.h"
#include "bezierpde/core/mesh.h"
#include "bezierpde/solvers/blend/bfs_element.h"
#include "bezierpde/solvers/summary.h"
#include "bezierpde/tensor/bspline_net.h"

namespace bpde {

/// The data of a discrete smoothing PDE spline (the FORMATS.md blend config, io/blend_config.h).
struct SmoothingSplineProblem {
  int k = 8;             ///< intervals in x
  int l = 4;             ///< intervals in y
  double a = 1.0;        ///< operator ∂⁴_x + 2a ∂²_x∂²_y + a² ∂⁴_y; 1e-6 <= a <= 1e6
  double epsilon = 1.0;  ///< ε > 0
  /// Prescribed values and ∂/∂y at the k+1 nodes x_i = i/k of the edges y = 0 and y = 1, each
  /// (k+1) by 3, row i for node x_i.
  Eigen::MatrixX3d y0_value, y0_dy, y1_value, y1_dy;
  /// Approximation points A (m by 2, rows (x, y) in [0,1]²) and their data β (m by 3). m may be 0.
  Eigen::MatrixX2d points;
  Eigen::MatrixX3d data;
  /// Load f of eq. (6); empty means f = 0. Integrated with a load_quadrature² Gauss rule per
  /// element.
  std::function<Eigen::Vector3d(double, double)> load;

  /// Throws ParameterError (k, l out of 1..BfsSpace::kMaxPartition, ε <= 0, a outside
  /// [1e-6, 1e6] (beyond, the discrete problem is numerically singular), a point
  /// outside [0,1]²), SizeError (edge arrays not (k+1) by 3, points/data row counts differ) or
  /// NonFiniteError (NaN/inf anywhere), naming the field.
  void validate() const;
};

struct SmoothingSplineOptions {
  enum class Method {
    kKktLu,       ///< the Lagrange-multiplier system of eq. (8), sparse LU (indefinite)
    kElimination  ///< eliminate the constrained dofs, sparse Cholesky of the SPD reduced system
                  ///< (CHOLMOD supernodal, fill-reducing ordering; default: docs/performance.md)
  };
  Method method = Method::kElimination;  ///< default kElimination
  /// kElimination with CHOLMOD: let CHOLMOD's supernodal factorisation run its OpenMP threads
  /// (CHOLMOD 3: a fixed 4 per parallel region, for the copy and assembly loops of large
  /// supernodes; the dense kernels are the BLAS's). Default false: on the blend systems the threads
  /// cost more CPU than they save (docs/performance_measurements.md "Blend"). While a factorisation runs with
  /// false, OpenMP's max-active-levels is 0 process-wide (restored after it).
  bool threaded_factorization = false;
  int load_quadrature = 6;         ///< Gauss points per direction and element for (f, ω)_0; 1..50
  /// Throws ParameterError for an option out of range.
  void validate() const;
};

/// A C¹ bicubic (BFS) vector field on [0,1]²: the discrete PDE spline.
class SmoothingSpline {
 public:
  /// coefficients: space.num_dofs() by 3, in the dof order of BfsSpace (SizeError otherwise).
  SmoothingSpline(BfsSpace space, Eigen::MatrixX3d coefficients);

  const BfsSpace& space() const { return space_; }
  const Eigen::MatrixX3d& coefficients() const { return coef_; }

  /// σ(x, y) and its derivatives ∂^(dx+dy)σ/∂x^dx ∂y^dy; (x, y) ∈ [0,1]² (ParameterError
  /// otherwise). Orders up to 3 in each variable are nonzero (bicubic on each element).
  Eigen::Vector3d evaluate(double x, double y, int dx = 0, int dy = 0) const;
  /// Position and derivatives up to order two, with (u, v) = (x, y).
  SurfaceJet jet(double x, double y) const;

  /// The (N+1)² vertices at (x, y) = (a/N, b/N), index a(N+1) + b (FORMATS.md tensor order),
  /// 2N² triangles counter-clockwise in the (x, y) plane, and the mean curvature at every vertex
  /// (FORMATS.md sign; at a singular point it is taken at a point nudged towards (½, ½); never
  /// NaN). Throws ParameterError unless 1 <= N <= kMaxSamples (core/mesh.h).
  TriangleMesh sample(int N) const;

  /// The same surface as a FORMATS.md "bspline" net of degree (3, 3) (BfsSpace::to_bspline).
  BfsSpace::BSplineForm to_bspline() const { return space_.to_bspline(coef_); }
  /// The same, as the project's B-spline net class (what `bpde blend` writes as "net").
  BSplineNet to_bspline_net() const;

 private:
  BfsSpace space_;
  Eigen::MatrixX3d coef_;
};

struct SmoothingSplineResult {
  SmoothingSpline spline;
  /// J(σ) of eq. (6), summed over the coordinates.
  double functional = 0.0;
  /// Σ |σ(a_i) - β_i|² and |σ|_L² (summed over the coordinates). |σ|_L² is summed element by
  /// element as squares of the second derivatives at the Gauss points of the exact 4×4 rule
  /// (BfsSpace::element_form_factor), equal to tr(αᵀRα) of the assembled R up to rounding.
  double data_misfit = 0.0;
  double energy = 0.0;
  /// max_i |σ(a_i) - β_i| (0 when A is empty).
  double max_data_error = 0.0;
  /// Lagrange multipliers λ of eq. (8) (4(k+1) by 3, rows in the order of the constrained dofs:
  /// for each node i, u(x_i,0), u_y(x_i,0), u(x_i,1), u_y(x_i,1)). With either method they are
  /// the rows of F - Cα at the constrained dofs (first block row of eq. (8)).
  Eigen::MatrixX3d multipliers;
  /// converged: the stationarity residual on the free dofs is <= kConvergenceTolerance (1e-11)
  /// relative to the size of its terms (max |(Cα - F)_free| / max(|C||α| + |F|)_free), and τσ = y
  /// to the same relative tolerance. residual holds that stationarity value. Otherwise status
  /// NotUnique (the system of eq. (8) is singular) or NumericalLimit (the solve is inaccurate).
  Summary summary;
};

/// Assemble once, factor once, solve for several data sets with the same partition, a, ε and
/// approximation points.
class SmoothingSplineSolver {
 public:
  /// Uses k, l, a, epsilon and points of the problem (validated) and the options.
  SmoothingSplineSolver(const SmoothingSplineProblem& problem, const SmoothingSplineOptions& options = {});
  ~SmoothingSplineSolver();
  SmoothingSplineSolver(const SmoothingSplineSolver&) = delete;
  SmoothingSplineSolver& operator=(const SmoothingSplineSolver&) = delete;

  /// Solve with the edges, data and load of `problem` (which must have the same k, l, a, ε and
  /// points as the constructor's: ParameterError otherwise).
  SmoothingSplineResult solve(const SmoothingSplineProblem& problem) const;

  const BfsSpace& space() const;
  /// The matrices of eq. (8): R = ((ω_r, ω_s)_L), C = AᵀA + εR (num_dofs square, both
  /// triangles) and the indices of the constrained dofs in the order of the multipliers. R is not
  /// kept by the solver (the energy is summed element by element) and C only as its lower
  /// triangle: both are built on demand here, at the cost of an assembly (docs/performance.md).
  Eigen::SparseMatrix<double> form_matrix() const;
  Eigen::SparseMatrix<double> system_matrix() const;
  const std::vector<int>& constrained_dofs() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

/// One-shot: validate, assemble, factor and solve.
SmoothingSplineResult solve_smoothing_spline(const SmoothingSplineProblem& problem,
                                             const SmoothingSplineOptions& options = {});

}  // namespace bpde
