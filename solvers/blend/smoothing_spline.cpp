#include "bezierpde/solvers/blend/smoothing_spline.h"

#include "bezierpde/core/eigen.h"
#include <Eigen/SparseCholesky>
#include <Eigen/SparseLU>
#ifdef BPDE_HAVE_CHOLMOD
#include <Eigen/CholmodSupport>
#include <dlfcn.h>

#include <mutex>
#endif
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include "bezierpde/core/errors.h"
#include "bezierpde/core/interruption.h"

namespace bpde {

namespace {

void require_finite(const Eigen::MatrixXd& M, const std::string& name) {
  for (Eigen::Index r = 0; r < M.rows(); ++r)
    for (Eigen::Index c = 0; c < M.cols(); ++c)
      if (!std::isfinite(M(r, c)))
        throw NonFiniteError(name + "[" + std::to_string(r) + "][" + std::to_string(c) + "] is not finite");
}

void require_edge(const Eigen::MatrixX3d& M, int k, const std::string& name) {
  if (M.rows() != k + 1)
    throw SizeError(name + ": " + std::to_string(M.rows()) + " points, expected k+1 = " + std::to_string(k + 1) +
                    " (one per node x_i = i/k)");
  require_finite(M, name);
}

std::string sci(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.2e", v);
  return buf;
}

#ifdef BPDE_HAVE_CHOLMOD
/// While alive, the OpenMP parallel regions of CHOLMOD run on the calling thread alone.
/// CHOLMOD 3's supernodal factorisation opens a parallel region of a fixed CHOLMOD_OMP_NUM_THREADS
/// (4, compiled in: neither OMP_NUM_THREADS nor cholmod_common changes it) around the copy and
/// assembly loops of every large supernode; on the blend systems that costs CPU in waking and
/// waiting threads and, with 2 cores, wall time too (docs/performance_measurements.md "Blend").
/// max-active-levels 0 makes every parallel region inactive (one thread). The OpenMP runtime is
/// the one CHOLMOD links (found through CHOLMOD's own library, so it also works when this
/// library was loaded with RTLD_LOCAL, e.g. by Python); without one this does nothing. The
/// setting is process-wide: nested guards (concurrent solves) share it under a mutex, the first
/// saves the previous value and the last restores it.
class SerialCholmodOpenMP {
 public:
  SerialCholmodOpenMP() {
    std::lock_guard<std::mutex> lock(state().mutex);
    State& s = state();
    if (s.users++ == 0 && s.resolve()) {
      s.saved = s.get();
      s.set(0);
    }
  }
  ~SerialCholmodOpenMP() {
    std::lock_guard<std::mutex> lock(state().mutex);
    State& s = state();
    if (--s.users == 0 && s.set) s.set(s.saved);
  }
  SerialCholmodOpenMP(const SerialCholmodOpenMP&) = delete;
  SerialCholmodOpenMP& operator=(const SerialCholmodOpenMP&) = delete;

 private:
  struct State {
    std::mutex mutex;
    int users = 0, saved = 0;
    bool resolved = false;
    int (*get)() = nullptr;
    void (*set)(int) = nullptr;
    bool resolve() {
      if (!resolved) {
        resolved = true;
        Dl_info info;
        if (dladdr(reinterpret_cast<void*>(&cholmod_factorize_p), &info) && info.dli_fname) {
          if (void* h = dlopen(info.dli_fname, RTLD_LAZY | RTLD_NOLOAD)) {  // already loaded: no new reference
            get = reinterpret_cast<int (*)()>(dlsym(h, "omp_get_max_active_levels"));
            set = reinterpret_cast<void (*)(int)>(dlsym(h, "omp_set_max_active_levels"));
            dlclose(h);
          }
        }
        if (!get || !set) get = nullptr, set = nullptr;
      }
      return set != nullptr;
    }
  };
  static State& state() {
    static State s;
    return s;
  }
};
#endif

}  // namespace

void SmoothingSplineProblem::validate() const {
  if (k < 1 || l < 1 || k > BfsSpace::kMaxPartition || l > BfsSpace::kMaxPartition)
    throw ParameterError("partition: k and l must be integers in 1.." + std::to_string(BfsSpace::kMaxPartition) +
                         " (got [" + std::to_string(k) + ", " + std::to_string(l) + "])");
  if (!std::isfinite(a)) throw NonFiniteError("a is not finite");
  if (!(a > 0)) throw ParameterError("a must be > 0 (the operator must be strongly elliptic)");
  if (a < 1e-6 || a > 1e6)
    throw ParameterError(
        "a must be in [1e-6, 1e6]: beyond, the terms of (u,v)_L differ by more "
        "than 1e12 and the discrete problem is numerically singular");
  if (!std::isfinite(epsilon)) throw NonFiniteError("epsilon is not finite");
  if (!(epsilon > 0)) throw ParameterError("epsilon must be > 0");
  require_edge(y0_value, k, "edges.y0.value");
  require_edge(y0_dy, k, "edges.y0.dy");
  require_edge(y1_value, k, "edges.y1.value");
  require_edge(y1_dy, k, "edges.y1.dy");
  if (points.rows() != data.rows())
    throw SizeError("points has " + std::to_string(points.rows()) + " entries but data has " +
                    std::to_string(data.rows()));
  require_finite(points, "points");
  require_finite(data, "data");
  for (Eigen::Index i = 0; i < points.rows(); ++i)
    if (points(i, 0) < 0 || points(i, 0) > 1 || points(i, 1) < 0 || points(i, 1) > 1)
      throw ParameterError("points[" + std::to_string(i) + "] = (" + std::to_string(points(i, 0)) + ", " +
                           std::to_string(points(i, 1)) + ") is outside [0,1]^2");
}

void SmoothingSplineOptions::validate() const {
  if (load_quadrature < 1 || load_quadrature > 50)
    throw ParameterError("SmoothingSplineOptions.load_quadrature must be in 1..50");
  if (method != Method::kKktLu && method != Method::kElimination)
    throw ParameterError("SmoothingSplineOptions.method is not a known method");
}

// ------------------------------------------------------------------ SmoothingSpline
SmoothingSpline::SmoothingSpline(BfsSpace space, Eigen::MatrixX3d coefficients)
    : space_(space), coef_(std::move(coefficients)) {
  if (coef_.rows() != space_.num_dofs())
    throw SizeError("SmoothingSpline: " + std::to_string(coef_.rows()) + " coefficient rows, expected " +
                    std::to_string(space_.num_dofs()));
  require_finite(coef_, "SmoothingSpline coefficients");
}

Eigen::Vector3d SmoothingSpline::evaluate(double x, double y, int dx, int dy) const {
  return space_.evaluate(coef_, x, y, dx, dy);
}

SurfaceJet SmoothingSpline::jet(double x, double y) const {
  std::array<int, 16> idx;
  std::array<double, 16> v[6];
  const int orders[6][2] = {{0, 0}, {1, 0}, {0, 1}, {2, 0}, {1, 1}, {0, 2}};
  for (int o = 0; o < 6; ++o) space_.basis_at(x, y, orders[o][0], orders[o][1], idx, v[o]);
  Eigen::Vector3d r[6];
  for (int o = 0; o < 6; ++o) {
    r[o].setZero();
    for (int c = 0; c < 16; ++c) r[o] += v[o][c] * coef_.row(idx[c]).transpose();
  }
  SurfaceJet j;
  j.x = r[0];
  j.xu = r[1];
  j.xv = r[2];
  j.xuu = r[3];
  j.xuv = r[4];
  j.xvv = r[5];
  return j;
}

BSplineNet SmoothingSpline::to_bspline_net() const {
  BfsSpace::BSplineForm b = to_bspline();
  return BSplineNet(3, 3, std::move(b.knots_x), std::move(b.knots_y), std::move(b.points));
}

TriangleMesh SmoothingSpline::sample(int N) const {
  if (N < 1 || N > kMaxSamples) throw ParameterError(samples_limit_message("samples", N));
  // The spline is exactly its bicubic B-spline net over [0,1]^2 (BfsSpace::to_bspline): sample
  // that, by the tabulated basis values and derivatives of tensor/bspline_net.h (one table per
  // direction and order, then small products), not point by point.
  return sample_mesh(to_bspline_net(), N);
}

// ------------------------------------------------------------------ solver
struct SmoothingSplineSolver::Impl {
  SmoothingSplineProblem key;  // k, l, a, epsilon, points
  SmoothingSplineOptions options;
  BfsSpace space{1, 1};
  // R is not stored (docs/performance_measurements.md "Blend"): the energy σᵀRσ is summed element by element
  // as Σ_e |B c_e|² with the square root B of the one element matrix K = BᵀB of the uniform
  // partition (BfsSpace::element_form_factor), and form_matrix() assembles R on demand.
  // C = εR + AᵀA is assembled as its lower triangle (rows >= columns) and kept only as its blocks
  // C_ff (lower triangle, what the factor reads), C_fc and C_cc: C itself is freed before the
  // factorisation, the peak of the memory.
  Eigen::Matrix<double, 16, 16> K;  // element matrix of (·,·)_L
  Eigen::Matrix<double, 48, 16> B, B_abs;  // K = BᵀB, and |B|
  Eigen::SparseMatrix<double> A, C;
  std::vector<int> constrained, free_dofs;
  std::vector<int> position;  // dof -> index in free_dofs, or -1
  Eigen::SparseLU<Eigen::SparseMatrix<double>, Eigen::COLAMDOrdering<int>> lu;
#ifdef BPDE_HAVE_CHOLMOD
  // Supernodal sparse Cholesky (CHOLMOD) of C_ff, which is built in its fill-reducing order
  // (order_free_dofs): CHOLMOD factors it in place, without permuted copies; measured against
  // SimplicialLDLT and the KKT LU in docs/performance_measurements.md ("Blend").
  Eigen::CholmodSupernodalLLT<Eigen::SparseMatrix<double>> ldlt;
#else
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> ldlt;  // AMD ordering
#endif
  Eigen::SparseMatrix<double> Cff, Cfc, Ccc;  // blocks of C: free-free (lower), free-constrained, constrained
  double kkt_scale = 1.0;
  bool factored = false;
  std::string factor_message;

  // ---- construction
  /// K, B, A = (ω_j(a_i)) (m by n) and the lower triangle of C = AᵀA + εR (into C).
  void assemble(const SmoothingSplineProblem& problem);
  /// The lower triangle of C (num_dofs square) for the key's a, ε and points.
  Eigen::SparseMatrix<double> assemble_system() const;
  /// C_ff (lower triangle, rows and columns in the order of free_dofs), C_fc and C_cc from C;
  /// then frees C.
  void split_system();
  /// Σ over elements of |M c_e|² (c_e: the 16 by 3 rows of c of element e), i.e. tr(cᵀ R c) for
  /// M = B, without R (a sum of squares).
  /// With abs, of |M| |c_e| for M = |B| (the rounding scale), |c| taken on the fly.
  double element_sum(const Eigen::Matrix<double, 48, 16>& M, const Eigen::MatrixX3d& c, bool abs = false) const;
  /// S·x and |S|·|x| for a symmetric S stored as its lower triangle.
  static void symmetric_products(const Eigen::SparseMatrix<double>& S, const Eigen::MatrixX3d& x, Eigen::MatrixX3d& Sx,
                                 Eigen::MatrixX3d& Sabs_x);
  /// The constrained dofs (per node i: u(x_i,0), u_y(x_i,0), u(x_i,1), u_y(x_i,1)) and the rest
  /// (free_dofs increasing, position its inverse).
  void split_dofs();
  /// With CHOLMOD, for the elimination route: free_dofs and position in a fill-reducing order of
  /// the reduced system, so that C_ff is built already permuted and CHOLMOD factors it in the
  /// natural order (no permuted transposes of C_ff beside the factor). The order is that of the
  /// nodes: nested dissection of the node grid by grid lines (node (i, j) couples with the 3 x 3
  /// nodes around it; less fill than METIS_NodeND, AMD or CHOLMOD's NESDIS here, and no METIS
  /// run), followed by CHOLMOD's weighted postorder of its elimination tree, each node's free dofs
  /// kept together (they have the same couplings); docs/performance_measurements.md "Blend".
  void order_free_dofs();
  /// The KKT matrix of eq. (8), equilibrated, by sparse LU.
  void factor_kkt();
  /// The reduced SPD system C_ff on the free dofs by sparse Cholesky (and C_fc for the right-hand side).
  void factor_reduced();

  // ---- solve
  /// ParameterError unless problem has the partition, a, ε and points that were factored.
  void check_same_problem(const SmoothingSplineProblem& problem) const;
  /// y: the boundary values τσ of the problem in the order of the constrained dofs.
  Eigen::MatrixX3d boundary_values(const SmoothingSplineProblem& problem) const;
  /// α from the factorisation (the right-hand side F of eq. (8) and y).
  Eigen::MatrixX3d solve_linear(const Eigen::MatrixX3d& F, const Eigen::MatrixX3d& y) const;
  struct Residuals {
    Eigen::MatrixX3d g;   ///< Cα - F at the constrained dofs (the order of constrained); the free
                          ///< rows are reduced to their maximum at once (not stored: memory)
    double stationarity;  ///< max |g_free| / max (|C||α| + |F|)_free
    double constraint;    ///< max |α_c - y| / max(|y|, |α|)
  };
  Residuals residuals(const Eigen::MatrixX3d& alpha, const Eigen::MatrixX3d& F, const Eigen::MatrixX3d& y) const;
  /// J of eq. (6) for a field c, and its parts.
  struct Functional {
    double J = 0, misfit = 0, max_error = 0, energy = 0;
  };
  Functional functional(const SmoothingSplineProblem& problem, const Eigen::MatrixX3d& load,
                        const Eigen::MatrixX3d& c) const;
  /// The verdict on a finite α from the factored system (sets converged, status, message, residual).
  void judge(const SmoothingSplineProblem& problem, const Eigen::MatrixX3d& alpha, const Functional& J,
             const Functional& J0, const Residuals& res, Summary& summary) const;
  /// SmoothingSplineSolver::solve without the timing.
  SmoothingSplineResult solve(const SmoothingSplineProblem& problem) const;
};

void SmoothingSplineSolver::Impl::assemble(const SmoothingSplineProblem& problem) {
  K = space.element_form(SecondOrderForm::from_a(problem.a));
  B = space.element_form_factor(SecondOrderForm::from_a(problem.a));
  B_abs = B.cwiseAbs();
  std::vector<Eigen::Triplet<double>> trip;
  for (Eigen::Index i = 0; i < problem.points.rows(); ++i) {
    std::array<int, 16> idx;
    std::array<double, 16> val;
    space.basis_at(problem.points(i, 0), problem.points(i, 1), 0, 0, idx, val);
    for (int c = 0; c < 16; ++c)
      if (val[c] != 0) trip.emplace_back(static_cast<int>(i), idx[c], val[c]);
  }
  A.resize(problem.points.rows(), space.num_dofs());
  A.setFromTriplets(trip.begin(), trip.end());
  C = assemble_system();
}

Eigen::SparseMatrix<double> SmoothingSplineSolver::Impl::assemble_system() const {
  const int n = space.num_dofs();
  const SmoothingSplineProblem& problem = key;
  // The lower triangle of C = εR + AᵀA, summed in place into its final pattern: column dof c of
  // node (i, j) couples with the dofs r >= c of the at most 9 nodes around (i, j) (the nodes of
  // larger index: 4 dofs each; its own node: dofs d..3). The 16 dofs of a point's element are
  // coupled in R already, so the points insert no entry.
  const int L1 = space.l() + 1;
  Eigen::VectorXi count(n);
  for (int i = 0; i <= space.k(); ++i)
    for (int j = 0; j <= space.l(); ++j) {
      int later = 0;  // neighbour nodes of larger index
      for (int di = -1; di <= 1; ++di)
        for (int dj = -1; dj <= 1; ++dj) {
          const int ii = i + di, jj = j + dj;
          if (ii < 0 || ii > space.k() || jj < 0 || jj > space.l()) continue;
          if (ii * L1 + jj > i * L1 + j) ++later;
        }
      for (int d = 0; d < 4; ++d) count(space.dof(i, j, d)) = 4 * later + (4 - d);
    }
  Eigen::SparseMatrix<double> C(n, n);
  C.reserve(count);
  for (int i = 0; i < space.k(); ++i)
    for (int j = 0; j < space.l(); ++j) {
      const auto idx = space.element_dofs(i, j);
      for (int c = 0; c < 16; ++c)
        for (int r = 0; r < 16; ++r)
          if (idx[r] >= idx[c]) C.coeffRef(idx[r], idx[c]) += K(r, c);
    }
  // R's entries summed in the order of BfsSpace::assemble_form, then scaled: the same numbers as
  // the lower triangle of εR from the assembled R.
  C.makeCompressed();
  C *= problem.epsilon;
  for (Eigen::Index i = 0; i < problem.points.rows(); ++i) {
    std::array<int, 16> idx;
    std::array<double, 16> val;
    space.basis_at(problem.points(i, 0), problem.points(i, 1), 0, 0, idx, val);
    for (int c = 0; c < 16; ++c) {
      if (val[c] == 0) continue;
      for (int r = 0; r < 16; ++r)
        if (val[r] != 0 && idx[r] >= idx[c]) C.coeffRef(idx[r], idx[c]) += val[r] * val[c];
    }
  }
  C.makeCompressed();
  return C;
}

double SmoothingSplineSolver::Impl::element_sum(const Eigen::Matrix<double, 48, 16>& M, const Eigen::MatrixX3d& c,
                                                bool abs) const {
  double sum = 0;
  Eigen::Matrix<double, 16, 3> ce;
  for (int i = 0; i < space.k(); ++i)
    for (int j = 0; j < space.l(); ++j) {
      const auto idx = space.element_dofs(i, j);
      if (abs)
        for (int r = 0; r < 16; ++r) ce.row(r) = c.row(idx[r]).cwiseAbs();
      else
        for (int r = 0; r < 16; ++r) ce.row(r) = c.row(idx[r]);
      sum += M.lazyProduct(ce).squaredNorm();  // coefficient-based: no packing for a 48x16 by 16x3 product
    }
  return sum;
}

void SmoothingSplineSolver::Impl::symmetric_products(const Eigen::SparseMatrix<double>& S, const Eigen::MatrixX3d& x,
                                                     Eigen::MatrixX3d& Cx, Eigen::MatrixX3d& Cabs_x) {
  Cx = Eigen::MatrixX3d::Zero(x.rows(), 3);
  Cabs_x = Eigen::MatrixX3d::Zero(x.rows(), 3);
  for (int col = 0; col < S.outerSize(); ++col)
    for (Eigen::SparseMatrix<double>::InnerIterator it(S, col); it; ++it) {
      const Eigen::Index row = it.row();
      const double v = it.value(), av = std::abs(v);
      Cx.row(row) += v * x.row(col);
      Cabs_x.row(row) += av * x.row(col).cwiseAbs();
      if (row != col) {
        Cx.row(col) += v * x.row(row);
        Cabs_x.row(col) += av * x.row(row).cwiseAbs();
      }
    }
}

void SmoothingSplineSolver::Impl::split_dofs() {
  const int n = space.num_dofs();
  for (int i = 0; i <= space.k(); ++i)
    for (int j : {0, space.l()})
      for (int d : {0, 2}) constrained.push_back(space.dof(i, j, d));
  position.assign(n, -1);
  std::vector<bool> is_c(n, false);
  for (int c : constrained) is_c[c] = true;
  for (int r = 0; r < n; ++r)
    if (!is_c[r]) {
      position[r] = static_cast<int>(free_dofs.size());
      free_dofs.push_back(r);
    }
}

void SmoothingSplineSolver::Impl::factor_kkt() {
  const int n = space.num_dofs();
  const int nc = static_cast<int>(constrained.size());
  std::vector<Eigen::Triplet<double>> t;
  t.reserve(2 * C.nonZeros() + 2 * nc);
  for (int col = 0; col < C.outerSize(); ++col)
    for (Eigen::SparseMatrix<double>::InnerIterator it(C, col); it; ++it) {
      t.emplace_back(static_cast<int>(it.row()), col, it.value());
      if (it.row() != col) t.emplace_back(col, static_cast<int>(it.row()), it.value());  // C is its lower triangle
    }
  // Equilibrate: D is scaled by s = max |C_ij| so that the LU pivots see blocks of one size
  // (the constraint rows then read s·α_c = s·y).
  kkt_scale = std::max(C.coeffs().cwiseAbs().maxCoeff(), std::numeric_limits<double>::min());
  for (int c = 0; c < nc; ++c) {
    t.emplace_back(constrained[c], n + c, kkt_scale);
    t.emplace_back(n + c, constrained[c], kkt_scale);
  }
  Eigen::SparseMatrix<double> K(n + nc, n + nc);
  K.setFromTriplets(t.begin(), t.end());
  K.makeCompressed();
  // Interruption points (core/interruption.h) between the analysis and the factorisation.
  check_interruption();
  lu.analyzePattern(K);
  check_interruption();
  lu.factorize(K);
  check_interruption();
  factored = lu.info() == Eigen::Success;
  if (!factored) factor_message = "the KKT matrix of eq. (8) is singular: " + lu.lastErrorMessage();
}

void SmoothingSplineSolver::Impl::order_free_dofs() {
#ifdef BPDE_HAVE_CHOLMOD
  const int L1 = space.l() + 1, nn = space.num_nodes();
  cholmod_common& cm = ldlt.cholmod();
  cm.print = 0;  // no CHOLMOD messages on stdout (see the factorisation)
  // The lower triangle of the node graph, pattern only: node c = i (l+1) + j and the nodes
  // (i, j), (i, j+1), (i+1, j-1), (i+1, j), (i+1, j+1) that exist (increasing indices).
  cholmod_sparse* G = cholmod_allocate_sparse(nn, nn, 5 * static_cast<size_t>(nn), 1, 1, -1, CHOLMOD_PATTERN, &cm);
  if (!G) return;  // out of memory: keep the increasing order (CHOLMOD then reports the failure)
  int* Gp = static_cast<int*>(G->p);
  int* Gi = static_cast<int*>(G->i);
  int q = 0;
  for (int i = 0; i <= space.k(); ++i)
    for (int j = 0; j <= space.l(); ++j) {
      Gp[i * L1 + j] = q;
      Gi[q++] = i * L1 + j;
      if (j < space.l()) Gi[q++] = i * L1 + j + 1;
      if (i < space.k())
        for (int jj = j - 1; jj <= j + 1; ++jj)
          if (jj >= 0 && jj <= space.l()) Gi[q++] = (i + 1) * L1 + jj;
    }
  Gp[nn] = q;
  // Nested dissection of the node grid (George's, on the grid itself): a line of nodes across the
  // longer side of a box separates its two halves (the couplings reach the 3 x 3 neighbours
  // only); the halves first, recursively down to single nodes, the separator last.
  std::vector<int> nd;
  nd.reserve(nn);
  std::function<void(int, int, int, int)> dissect = [&](int i0, int i1, int j0, int j1) {
    if (i0 > i1 || j0 > j1) return;
    if (i0 == i1 && j0 == j1) {
      nd.push_back(i0 * L1 + j0);
    } else if (i1 - i0 >= j1 - j0) {
      const int m = (i0 + i1) / 2;
      dissect(i0, m - 1, j0, j1);
      dissect(m + 1, i1, j0, j1);
      for (int j = j0; j <= j1; ++j) nd.push_back(m * L1 + j);
    } else {
      const int m = (j0 + j1) / 2;
      dissect(i0, i1, j0, m - 1);
      dissect(i0, i1, m + 1, j1);
      for (int i = i0; i <= i1; ++i) nd.push_back(i * L1 + m);
    }
  };
  dissect(0, space.k(), 0, space.l());
  // CHOLMOD follows it with the weighted postorder of its elimination tree (better supernodes).
  const int supernodal = cm.supernodal;
  cm.nmethods = 1;
  cm.method[0].ordering = CHOLMOD_GIVEN;
  cm.postorder = 1;
  cm.supernodal = CHOLMOD_SIMPLICIAL;  // only the order is wanted here
  cholmod_factor* Lg = cholmod_analyze_p(G, nd.data(), nullptr, 0, &cm);
  cm.supernodal = supernodal;
  cholmod_free_sparse(&G, &cm);
  if (!Lg) return;
  const int* perm = static_cast<const int*>(Lg->Perm);
  std::vector<int> order;
  order.reserve(free_dofs.size());
  for (int t = 0; t < nn; ++t)
    for (int d = 0; d < 4; ++d) {
      const int dof = 4 * perm[t] + d;  // BfsSpace::dof: 4 (i (l+1) + j) + d
      if (position[dof] >= 0) order.push_back(dof);
    }
  cholmod_free_factor(&Lg, &cm);
  free_dofs.swap(order);
  for (int r = 0; r < static_cast<int>(free_dofs.size()); ++r) position[free_dofs[r]] = r;
#endif
}

void SmoothingSplineSolver::Impl::split_system() {
  const int n = space.num_dofs();
  const int nc = static_cast<int>(constrained.size());
  const int nf = static_cast<int>(free_dofs.size());
  std::vector<Eigen::Triplet<double>> tc, tcc;
  std::vector<int> cpos(n, -1);
  for (int c = 0; c < nc; ++c) cpos[constrained[c]] = c;
  // C holds its lower triangle (row >= column). A free-free entry goes to the lower triangle of
  // C_ff in the order of free_dofs (column min(p_r, p_c), row max), built directly in compressed
  // storage (counts, then entries, then each column sorted); a free-constrained entry is
  // C_fc(row, column) or, read through the symmetry, C_fc(column, row).
  std::vector<int> start(nf + 1, 0);
  for (int col = 0; col < C.outerSize(); ++col)
    for (Eigen::SparseMatrix<double>::InnerIterator it(C, col); it; ++it) {
      const int r = position[it.row()], c = position[col];
      if (r >= 0 && c >= 0) ++start[std::min(r, c) + 1];
    }
  for (int c = 0; c < nf; ++c) start[c + 1] += start[c];
  Cff = Eigen::SparseMatrix<double>(nf, nf);  // lower triangle only
  Cff.resizeNonZeros(start[nf]);
  std::copy(start.begin(), start.end(), Cff.outerIndexPtr());
  int* inner = Cff.innerIndexPtr();
  double* value = Cff.valuePtr();
  for (int col = 0; col < C.outerSize(); ++col)
    for (Eigen::SparseMatrix<double>::InnerIterator it(C, col); it; ++it) {
      const int r = position[it.row()], c = position[col];
      if (r >= 0 && c >= 0) {
        const int dst = start[std::min(r, c)]++;
        inner[dst] = std::max(r, c);
        value[dst] = it.value();
      } else if (r >= 0) {
        tc.emplace_back(r, cpos[col], it.value());
      } else if (c >= 0) {
        tc.emplace_back(c, cpos[it.row()], it.value());
      } else {
        tcc.emplace_back(cpos[it.row()], cpos[col], it.value());
        if (it.row() != col) tcc.emplace_back(cpos[col], cpos[it.row()], it.value());
      }
    }
  // Freed: the factorisation is the peak of the memory. (Not `C = SparseMatrix()`: Eigen's copy
  // assignment from an empty matrix keeps C's value and index arrays allocated; it did so here
  // until this was measured, docs/performance_measurements.md "Blend".)
  Eigen::SparseMatrix<double>().swap(C);
  const int* outer = Cff.outerIndexPtr();
  for (int c = 0; c < nf; ++c)  // insertion sort of each column by row (at most 36 entries)
    for (int p = outer[c] + 1; p < outer[c + 1]; ++p) {
      const int row = inner[p];
      const double v = value[p];
      int q = p;
      for (; q > outer[c] && inner[q - 1] > row; --q) {
        inner[q] = inner[q - 1];
        value[q] = value[q - 1];
      }
      inner[q] = row;
      value[q] = v;
    }
  Cfc.resize(nf, nc);
  Cfc.setFromTriplets(tc.begin(), tc.end());
  Ccc.resize(nc, nc);
  Ccc.setFromTriplets(tcc.begin(), tcc.end());
}

void SmoothingSplineSolver::Impl::factor_reduced() {
#ifdef BPDE_HAVE_CHOLMOD
  // C_ff is in its fill-reducing, postordered order already (order_free_dofs): the natural
  // ordering and no postorder keep it, and CHOLMOD then factors the lower triangle we pass as it
  // is (for any other ordering it factors two permuted transposes of it).
  cholmod_common& cm = ldlt.cholmod();
  cm.print = 0;  // CHOLMOD prints its warnings (a matrix not positive definite) on stdout; the
                 // solver reports them through its Summary (bpde's stdout carries JSON only)
  cm.nmethods = 1;
  cm.method[0].ordering = CHOLMOD_NATURAL;
  cm.postorder = 0;
  {
    std::unique_ptr<SerialCholmodOpenMP> serial;
    if (!options.threaded_factorization) serial = std::make_unique<SerialCholmodOpenMP>();
    // Interruption points (core/interruption.h) between the analysis and the factorisation.
    check_interruption();
    ldlt.analyzePattern(Cff);
    check_interruption();
    ldlt.factorize(Cff);
  }
#else
  check_interruption();
  ldlt.compute(Cff);
#endif
  check_interruption();
#ifdef BPDE_HAVE_CHOLMOD
  factored = ldlt.info() == Eigen::Success;  // a Cholesky factor exists only for SPD matrices
#else
  factored = ldlt.info() == Eigen::Success && (ldlt.vectorD().array() > 0).all();
#endif
  if (!factored)
    factor_message =
        "the reduced system is numerically singular (epsilon or a too small for the data "
        "term?)";
}

void SmoothingSplineSolver::Impl::check_same_problem(const SmoothingSplineProblem& problem) const {
  if (problem.k != key.k || problem.l != key.l || problem.a != key.a || problem.epsilon != key.epsilon ||
      problem.points.rows() != key.points.rows() || problem.points != key.points)
    throw ParameterError(
        "SmoothingSplineSolver::solve: the problem's partition, a, epsilon or points differ from "
        "the factored ones");
}

Eigen::MatrixX3d SmoothingSplineSolver::Impl::boundary_values(const SmoothingSplineProblem& problem) const {
  Eigen::MatrixX3d y(static_cast<Eigen::Index>(constrained.size()), 3);
  for (int i = 0, c = 0; i <= space.k(); ++i) {
    y.row(c++) = problem.y0_value.row(i);
    y.row(c++) = problem.y0_dy.row(i);
    y.row(c++) = problem.y1_value.row(i);
    y.row(c++) = problem.y1_dy.row(i);
  }
  return y;
}

Eigen::MatrixX3d SmoothingSplineSolver::Impl::solve_linear(const Eigen::MatrixX3d& F, const Eigen::MatrixX3d& y) const {
  const int n = space.num_dofs();
  const int nc = static_cast<int>(constrained.size());
  // (The arrays here are n by 3 and live beside the factor: each is allocated only when the
  // previous ones are freed; the solve is the peak of the memory, docs/performance_measurements.md "Blend".)
  if (options.method == SmoothingSplineOptions::Method::kKktLu) {
    Eigen::MatrixX3d alpha(n, 3);
    Eigen::MatrixXd rhs(n + nc, 3);
    rhs.topRows(n) = F;
    rhs.bottomRows(nc) = kkt_scale * y;
    const Eigen::MatrixXd z = lu.solve(rhs);
    alpha = z.topRows(n);
    // The constrained dofs are data: the LU returns them to rounding, the contract bit-exact. The
    // stationarity residual is then measured at the data themselves.
    for (int c = 0; c < nc; ++c) alpha.row(constrained[c]) = y.row(c);
    return alpha;
  }
  const int nf = static_cast<int>(free_dofs.size());
  Eigen::MatrixXd af;
  {
    Eigen::MatrixXd Ff(nf, 3);
    for (int r = 0; r < nf; ++r) Ff.row(r) = F.row(free_dofs[r]);
    Ff -= Cfc * y;  // the product into a temporary first (no noalias): the numbers of Ff - Cfc y
    af = ldlt.solve(Ff);
  }
  Eigen::MatrixX3d alpha(n, 3);
  for (int r = 0; r < nf; ++r) alpha.row(free_dofs[r]) = af.row(r);
  for (int c = 0; c < nc; ++c) alpha.row(constrained[c]) = y.row(c);
  return alpha;
}

SmoothingSplineSolver::Impl::Residuals SmoothingSplineSolver::Impl::residuals(const Eigen::MatrixX3d& alpha,
                                                                              const Eigen::MatrixX3d& F,
                                                                              const Eigen::MatrixX3d& y) const {
  const int nc = static_cast<int>(constrained.size());
  const int nf = static_cast<int>(free_dofs.size());
  // Cα - F and |C||α| + |F| from the blocks of C (C and |C| are not stored): free rows
  // C_ff α_f + C_fc α_c, constrained rows C_fcᵀ α_f + C_cc α_c.
  Eigen::MatrixX3d af(nf, 3), ac(nc, 3);
  for (int r = 0; r < nf; ++r) af.row(r) = alpha.row(free_dofs[r]);
  for (int c = 0; c < nc; ++c) ac.row(c) = alpha.row(constrained[c]);
  Eigen::MatrixX3d gf, sf;
  symmetric_products(Cff, af, gf, sf);
  gf += Cfc * ac;
  sf += Cfc.cwiseAbs() * ac.cwiseAbs();
  const Eigen::MatrixX3d gc = Cfc.transpose() * af + Ccc * ac;
  Residuals res{Eigen::MatrixX3d(nc, 3), 0.0, 0.0};
  for (int c = 0; c < nc; ++c) res.g.row(c) = gc.row(c) - F.row(constrained[c]);
  double gmax = 0, smax = 0;
  for (int r = 0; r < nf; ++r) {
    gmax = std::max(gmax, (gf.row(r) - F.row(free_dofs[r])).cwiseAbs().maxCoeff());
    smax = std::max(smax, (sf.row(r) + F.row(free_dofs[r]).cwiseAbs()).maxCoeff());
  }
  res.stationarity = smax > 0 ? gmax / smax : gmax;
  double cmax = 0;
  for (int c = 0; c < nc; ++c) cmax = std::max(cmax, (alpha.row(constrained[c]) - y.row(c)).cwiseAbs().maxCoeff());
  const double cscale = std::max(y.cwiseAbs().maxCoeff(), alpha.cwiseAbs().maxCoeff());
  res.constraint = cscale > 0 ? cmax / cscale : cmax;
  return res;
}

SmoothingSplineSolver::Impl::Functional SmoothingSplineSolver::Impl::functional(const SmoothingSplineProblem& problem,
                                                                                const Eigen::MatrixX3d& load,
                                                                                const Eigen::MatrixX3d& c) const {
  Functional f;
  const Eigen::MatrixX3d r = A * c - problem.data;
  f.misfit = r.squaredNorm();
  f.max_error = r.rows() ? r.rowwise().norm().maxCoeff() : 0.0;
  f.energy = element_sum(B, c);  // tr(cᵀ R c), element by element
  const double load_term = load.rows() ? (load.transpose() * c).trace() : 0.0;  // load empty: f = 0
  f.J = f.misfit + problem.epsilon * (f.energy - 2 * load_term);
  return f;
}

void SmoothingSplineSolver::Impl::judge(const SmoothingSplineProblem& problem, const Eigen::MatrixX3d& alpha,
                                        const Functional& J, const Functional& J0, const Residuals& res,
                                        Summary& summary) const {
  summary.residual = res.stationarity;
  // σ must do at least as well as the feasible field with the free dofs at 0; |σ|_L² >= 0; and
  // without load 0 <= J(σ) <= J0.
  const double en_abs = element_sum(B_abs, alpha, true);  // the rounding scale of the energy's sum
  if (J.J > J0.J + 1e-9 * (std::abs(J0.J) + std::abs(J.J)) || J.energy < -1e-10 * en_abs ||
      (!problem.load && J.J < -1e-9 * J0.J)) {
    summary.set_failed(Status::NumericalLimit,
                       "the linear solve is inaccurate: J(sigma) exceeds J of a feasible field, or J < 0 "
                       "(ill-conditioned: epsilon or a too small or too large?)");
    return;
  }
  if (res.stationarity <= kConvergenceTolerance && res.constraint <= kConvergenceTolerance) {
    summary.message = options.method == SmoothingSplineOptions::Method::kKktLu
                          ? "solved the KKT system of eq. (8) by sparse LU"
                          : "solved the reduced SPD system by sparse Cholesky";
    summary.set_converged();
  } else {
    summary.set_failed(Status::NumericalLimit, "the linear solve is inaccurate: stationarity residual " +
                                                   sci(res.stationarity) + ", constraint residual " +
                                                   sci(res.constraint) +
                                                   " (ill-conditioned: epsilon or a too small or too large?)");
  }
}

SmoothingSplineSolver::~SmoothingSplineSolver() = default;

SmoothingSplineSolver::SmoothingSplineSolver(const SmoothingSplineProblem& problem,
                                             const SmoothingSplineOptions& options)
    : impl_(std::make_unique<Impl>()) {
  problem.validate();
  options.validate();
  Impl& m = *impl_;
  m.key.k = problem.k;
  m.key.l = problem.l;
  m.key.a = problem.a;
  m.key.epsilon = problem.epsilon;
  m.key.points = problem.points;
  m.options = options;
  m.space = BfsSpace(problem.k, problem.l);
  check_interruption();  // core/interruption.h: between the stages
  m.assemble(problem);
  check_interruption();
  m.split_dofs();
  if (options.method == SmoothingSplineOptions::Method::kKktLu) m.factor_kkt();
  if (options.method == SmoothingSplineOptions::Method::kElimination) m.order_free_dofs();
  check_interruption();
  m.split_system();  // frees C
  if (options.method == SmoothingSplineOptions::Method::kElimination) m.factor_reduced();
}

const BfsSpace& SmoothingSplineSolver::space() const { return impl_->space; }
Eigen::SparseMatrix<double> SmoothingSplineSolver::form_matrix() const {
  return impl_->space.assemble_form(SecondOrderForm::from_a(impl_->key.a));
}
Eigen::SparseMatrix<double> SmoothingSplineSolver::system_matrix() const {
  const Eigen::SparseMatrix<double> L = impl_->assemble_system();
  Eigen::SparseMatrix<double> full = L.selfadjointView<Eigen::Lower>();
  return full;
}
const std::vector<int>& SmoothingSplineSolver::constrained_dofs() const { return impl_->constrained; }

SmoothingSplineResult SmoothingSplineSolver::Impl::solve(const SmoothingSplineProblem& problem) const {
  Summary summary;
  problem.validate();
  const Impl& m = *this;
  m.check_same_problem(problem);
  const BfsSpace& V = m.space;
  const int n = V.num_dofs();
  const int nc = static_cast<int>(m.constrained.size());

  // right-hand sides (Fload stays empty without a load: f = 0)
  Eigen::MatrixX3d Fload;
  if (problem.load) Fload = V.assemble_load(problem.load, m.options.load_quadrature);
  Eigen::MatrixX3d F = m.A.transpose() * problem.data;
  if (problem.load) F += problem.epsilon * Fload;
  const Eigen::MatrixX3d y = m.boundary_values(problem);

  Eigen::MatrixX3d alpha;
  if (!m.factored) {
    summary.set_failed(Status::NotUnique, m.factor_message);
    alpha = Eigen::MatrixX3d::Zero(n, 3);
  } else {
    check_interruption();
    alpha = m.solve_linear(F, y);
  }
  check_interruption();

  const Residuals res = m.residuals(alpha, F, y);
  // The feasible field with the free dofs at 0: σ must do at least as well.
  Eigen::MatrixX3d v0 = Eigen::MatrixX3d::Zero(n, 3);
  for (int c = 0; c < nc; ++c) v0.row(m.constrained[c]) = y.row(c);
  const Functional J0 = m.functional(problem, Fload, v0);
  if (!std::isfinite(J0.J))
    throw NonFiniteError("the boundary data, data, load or epsilon are too large: the functional of eq. (6) overflows");
  Functional J;
  if (alpha.allFinite()) J = m.functional(problem, Fload, alpha);
  if (m.factored) {
    if (!alpha.allFinite() || !std::isfinite(J.J)) {
      summary.set_failed(Status::NumericalLimit,
                         "the linear solve produced non-finite values (ill-conditioned: epsilon or a too small "
                         "or too large?)");
      alpha.setZero();
      J = m.functional(problem, Fload, alpha);
    } else {
      m.judge(problem, alpha, J, J0, res, summary);
    }
  }
  SmoothingSplineResult result{SmoothingSpline(V, std::move(alpha)), J.J, J.misfit, J.energy, J.max_error, {}, {}};
  result.multipliers.resize(nc, 3);
  for (int c = 0; c < nc; ++c) result.multipliers.row(c) = -res.g.row(c);
  if (!result.multipliers.allFinite()) result.multipliers.setZero();
  if (!std::isfinite(summary.residual)) summary.residual = 0.0;
  summary.iterations = 0;
  result.summary = summary;
  return result;
}

SmoothingSplineResult SmoothingSplineSolver::solve(const SmoothingSplineProblem& problem) const {
  return timed_solve([&] { return impl_->solve(problem); });
}

SmoothingSplineResult solve_smoothing_spline(const SmoothingSplineProblem& problem,
                                             const SmoothingSplineOptions& options) {
  return timed_solve([&] {
    SmoothingSplineSolver solver(problem, options);
    return solver.solve(problem);
  });
}

}  // namespace bpde
