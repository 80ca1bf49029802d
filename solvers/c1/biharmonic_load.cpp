#include "bezierpde/solvers/c1/biharmonic_load.h"

#include "bezierpde/core/eigen.h"
#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "bezierpde/core/bernstein.h"
#include "bezierpde/core/bernstein_ops.h"
#include "bezierpde/core/errors.h"
#include "bezierpde/core/interruption.h"
#include "bezierpde/core/keyed_cache.h"
#include "bezierpde/core/kron.h"
#include "bezierpde/solvers/c1/refine_mould.h"
#include "bezierpde/tensor/power_basis.h"

namespace bpde {
namespace {

using RowMat = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

void check_square_degree(const TensorNet& net, int min_degree, const char* who) {
  if (net.n() != net.m())
    throw DegreeError(std::string(who) + ": needs a net of degree [n, n], got [" + std::to_string(net.n()) + ", " +
                      std::to_string(net.m()) + "]");
  if (net.n() < min_degree)
    throw DegreeError(std::string(who) + ": needs degree n >= " + std::to_string(min_degree) + ", got " +
                      std::to_string(net.n()));
}

std::vector<int> interior_indices(int n) {
  std::vector<int> idx;
  for (int i = 2; i <= n - 2; ++i)
    for (int j = 2; j <= n - 2; ++j) idx.push_back(i * (n + 1) + j);
  return idx;
}

// The full (n+1)^2 square operator of c40 d4u + c22 d2u d2v + c04 d4v on Bernstein nets.
Eigen::MatrixXd bilaplacian_operator(int n, double c40, double c22, double c04) {
  const Eigen::MatrixXd I = Eigen::MatrixXd::Identity(n + 1, n + 1);
  const Eigen::MatrixXd T4 = derivative_at_degree(n, 4), T2 = derivative_at_degree(n, 2);
  return c40 * kron(T4, I) + c22 * kron(T2, T2) + c04 * kron(I, T4);
}

// Solution operator of Theorem 3 for degree n: interior = G * fixed.
struct LoadSolver {
  std::vector<int> interior, fixed;
  Eigen::MatrixXd G;
};

// The interior system is ill-conditioned in n (cond ~1e6 at n = 12, ~1e11 at n = 18), so G is
// computed with a long-double LU and refined (2 steps up to n ~ 20) with residuals evaluated in binary128 from
// exact matrix entries.
using MatL = MatLD;

std::shared_ptr<const LoadSolver> build_load_solver(int n) {
  auto s = std::make_shared<LoadSolver>();
  s->interior = interior_indices(n);
  s->fixed = TensorNet(n, n).fixed_indices(FixedSet::BoundaryAdjacent);
  const int n1 = n + 1, N = n1 * n1;
  const int ni = static_cast<int>(s->interior.size()), nf = static_cast<int>(s->fixed.size());
  const std::vector<quad> T4 = derivative_at_degree_rm<quad>(n, 4), T2 = derivative_at_degree_rm<quad>(n, 2);
  auto t4 = [&](int i, int k) { return T4[static_cast<size_t>(i * n1 + k)]; };
  auto t2 = [&](int i, int k) { return T2[static_cast<size_t>(i * n1 + k)]; };
  // (Op X)(i,j) = sum_k T4(i,k) X(k,j) + 2 sum_kl T2(i,k) T2(j,l) X(k,l) + sum_l T4(j,l) X(i,l).
  auto op_entry = [&](int i, int j, int k, int l) -> quad {
    return (j == l ? t4(i, k) : quad(0)) + 2 * t2(i, k) * t2(j, l) + (i == k ? t4(j, l) : quad(0));
  };
  // Interruption points (core/interruption.h): every 64 rows assembled or columns refined, and
  // before and after the LU factorisation, the one step that cannot stop (docs/robustness.md).
  constexpr int kBlock = 64;
  MatL A(ni, ni), B(ni, nf);
  for (int r = 0; r < ni; ++r) {
    if (r % kBlock == 0) check_interruption();
    const int i = s->interior[static_cast<size_t>(r)] / n1, j = s->interior[static_cast<size_t>(r)] % n1;
    for (int c = 0; c < ni; ++c)
      A(r, c) = static_cast<long double>(
          op_entry(i, j, s->interior[static_cast<size_t>(c)] / n1, s->interior[static_cast<size_t>(c)] % n1));
    for (int c = 0; c < nf; ++c)
      B(r, c) = static_cast<long double>(
          op_entry(i, j, s->fixed[static_cast<size_t>(c)] / n1, s->fixed[static_cast<size_t>(c)] % n1));
  }
  check_interruption();
  const Eigen::PartialPivLU<MatL> lu(A);
  check_interruption();
  MatL G = -lu.solve(B);
  check_interruption();
  std::vector<quad> X(static_cast<size_t>(N));
  // Refine until the correction is below 1e-18 of G (at most 8 steps; 2 suffice up to n ~ 20).
  refine_mould(
      G, n <= 8 ? 0 : 8,
      [&](const MatL& cur) {
        MatL R(ni, nf);
        for (int c = 0; c < nf; ++c) {
          if (c % kBlock == 0) check_interruption();
          mould_column(cur, c, s->interior, s->fixed, X);
          // Y = T2 X T2^T (then the other terms entrywise on the interior rows).
          std::vector<quad> XT(static_cast<size_t>(N), 0);
          for (int i = 0; i <= n; ++i)
            for (int j = 0; j <= n; ++j) {
              quad acc = 0;
              for (int l = 0; l <= n; ++l)
                if (t2(j, l) != 0) acc += X[static_cast<size_t>(i * n1 + l)] * t2(j, l);
              XT[static_cast<size_t>(i * n1 + j)] = acc;
            }
          for (int r = 0; r < ni; ++r) {
            const int i = s->interior[static_cast<size_t>(r)] / n1, j = s->interior[static_cast<size_t>(r)] % n1;
            quad acc = 0;
            for (int k = 0; k <= n; ++k) {
              if (t2(i, k) != 0) acc += 2 * t2(i, k) * XT[static_cast<size_t>(k * n1 + j)];
              if (t4(i, k) != 0) acc += t4(i, k) * X[static_cast<size_t>(k * n1 + j)];
              if (t4(j, k) != 0) acc += t4(j, k) * X[static_cast<size_t>(i * n1 + k)];
            }
            R(r, c) = static_cast<long double>(acc);
          }
        }
        return R;
      },
      [&](const MatL& R) -> MatL {
        MatL C = lu.solve(R);
        check_interruption();
        return C;
      });
  s->G = G.cast<double>();
  return s;
}

std::shared_ptr<const LoadSolver> load_solver(int n) {
  static DegreeCache<LoadSolver> cache;
  return cache.get(n, build_load_solver, "load solver");
}

}  // namespace

Eigen::MatrixXd derivative_at_degree(int n, int d) {
  if (n < 1 || d < 0) throw DegreeError("derivative_at_degree: needs n >= 1 and d >= 0");
  return derivative_at_degree_matrix<double>(n, d);  // core/bernstein_ops.h
}

TensorNet bilaplacian_load_net(const TensorNet& net, double c40, double c22, double c04) {
  check_square_degree(net, 1, "bilaplacian_load_net");
  const int n = net.n();
  const Eigen::MatrixXd T4 = derivative_at_degree(n, 4), T2 = derivative_at_degree(n, 2);
  Eigen::MatrixX3d out(net.size(), 3);
  for (int c = 0; c < 3; ++c) {
    const Eigen::Map<const RowMat> X(net.points().col(c).data(), n + 1, n + 1);
    Eigen::Map<RowMat>(out.col(c).data(), n + 1, n + 1) =
        c40 * (T4 * X) + c22 * (T2 * X * T2.transpose()) + c04 * (X * T4.transpose());
  }
  return TensorNet(n, n, std::move(out));
}

namespace {

BiharmonicLoadResult solve_biharmonic_load_untimed(const TensorNet& data) {
  check_square_degree(data, 4, "biharmonic-load");
  const int n = data.n();
  const auto solver = load_solver(n);
  require_finite_rows(data.points(), solver->fixed, "biharmonic-load data", data.m() + 1);

  const Eigen::MatrixXd xf = data.points()(solver->fixed, Eigen::all);
  const Eigen::MatrixXd xi = solver->G * xf;

  TensorNet net(n, n);
  net.points()(solver->fixed, Eigen::all) = xf;
  net.points()(solver->interior, Eigen::all) = xi;

  BiharmonicLoadResult result{net, bilaplacian_load_net(net), {}};
  // Residual: the interior of the load net against the same sums in absolute values
  // (|T4| |X| + 2 |T2| |X| |T2|^T + |X| |T4|^T), i.e. the size of the terms that cancel.
  double scale = 0.0, res = 0.0;
  {
    const Eigen::MatrixXd T4 = derivative_at_degree(n, 4).cwiseAbs(), T2 = derivative_at_degree(n, 2).cwiseAbs();
    for (int c = 0; c < 3; ++c) {
      const Eigen::Map<const RowMat> X(net.points().col(c).data(), n + 1, n + 1);
      const Eigen::MatrixXd Xa = X.cwiseAbs();
      const Eigen::MatrixXd mag = T4 * Xa + 2.0 * (T2 * Xa * T2.transpose()) + Xa * T4.transpose();
      scale = std::max(scale, mag.maxCoeff());
    }
  }
  for (int r : solver->interior) res = std::max(res, result.load.points().row(r).cwiseAbs().maxCoeff());
  Summary& summary = result.summary;
  summary.residual = scale > 0.0 ? res / scale : 0.0;
  if (summary.residual <= kConvergenceTolerance) {
    summary.set_converged();
    summary.message = "solved (Bernstein-basis LU)";
  } else {
    std::ostringstream m;
    m << "the load net does not vanish on the interior to " << kConvergenceTolerance << " (relative residual "
      << summary.residual << ")";
    summary.set_failed(Status::NumericalLimit, m.str());
  }
  return result;
}

}  // namespace

BiharmonicLoadResult solve_biharmonic_load(const TensorNet& data, const BiharmonicLoadOptions& options) {
  options.validate();
  return timed_solve([&] { return solve_biharmonic_load_untimed(data); });
}

TensorNet complete_admissible_load(const TensorNet& load) {
  check_square_degree(load, 4, "complete_admissible_load");
  const int n = load.n(), N = (n + 1) * (n + 1);
  std::vector<int> inner;  // 1 <= i,j <= n-1 : x's unknown points and the given load points
  for (int i = 1; i < n; ++i)
    for (int j = 1; j < n; ++j) inner.push_back(i * (n + 1) + j);
  const std::vector<int> ring = load.boundary_indices();
  require_finite_rows(load.points(), inner, "complete_admissible_load", load.m() + 1);
  const Eigen::MatrixXd Op = bilaplacian_operator(n, 1.0, 2.0, 1.0);
  // Unknowns: x at inner indices (x's boundary ring is 0 by Corollary 1), then R at the ring.
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(N, N);
  A.leftCols(static_cast<Eigen::Index>(inner.size())) = Op(Eigen::all, inner);
  for (size_t c = 0; c < ring.size(); ++c) A(ring[c], static_cast<Eigen::Index>(inner.size() + c)) = -1.0;
  Eigen::MatrixXd rhs = Eigen::MatrixXd::Zero(N, 3);
  rhs(inner, Eigen::all) = load.points()(inner, Eigen::all);
  const Eigen::MatrixXd sol = Eigen::PartialPivLU<Eigen::MatrixXd>(A).solve(rhs);
  TensorNet out = load;
  out.points()(ring, Eigen::all) =
      sol.middleRows(static_cast<Eigen::Index>(inner.size()), static_cast<Eigen::Index>(ring.size()));
  return out;
}

double admissibility_defect(const TensorNet& load) {
  check_square_degree(load, 4, "admissibility_defect");
  const int n = load.n();
  const Eigen::MatrixX3d p = to_factorial_power(load);
  // Rounding scale of each p_ij: i! j! (|M| |R| |M|^T)_ij, M the Bernstein-to-power matrix.
  const Eigen::MatrixXd Ma = bernstein_to_power_matrix(n).cwiseAbs();
  Eigen::MatrixXd pabs = Eigen::MatrixXd::Zero(n + 1, n + 1);
  for (int c = 0; c < 3; ++c) {
    const Eigen::Map<const RowMat> R(load.points().col(c).data(), n + 1, n + 1);
    pabs = pabs.cwiseMax(Ma * R.cwiseAbs() * Ma.transpose());
  }
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j <= n; ++j) pabs(i, j) *= factorial(i) * factorial(j);
  auto P = [&](int i, int j, int c) { return p(i * (n + 1) + j, c); };
  double defect = 0.0, scale = 0.0;
  for (int m = n - 1; m <= n; ++m)
    for (int i = 0; i <= n; ++i) {
      const int K = (n - i) / 2;
      double s1 = pabs(i, m), s2 = pabs(m, i);
      for (int l = 1; l <= K - 1; ++l) {
        s1 += (K - l) * pabs(i + 2 * l, m - 2 * l) / K;
        s2 += (K - l) * pabs(m - 2 * l, i + 2 * l) / K;
      }
      scale = std::max({scale, s1, s2});
      for (int c = 0; c < 3; ++c) {
        double rhs1 = 0.0, rhs2 = 0.0;
        for (int l = 1; l <= K - 1; ++l) {
          const double sg = ((l - 1) % 2 == 0 ? 1.0 : -1.0) * (K - l);
          rhs1 += sg * P(i + 2 * l, m - 2 * l, c);
          rhs2 += sg * P(m - 2 * l, i + 2 * l, c);
        }
        if (K > 0) {
          rhs1 /= K;
          rhs2 /= K;
        }
        defect = std::max({defect, std::abs(P(i, m, c) - rhs1), std::abs(P(m, i, c) - rhs2)});
      }
    }
  return scale > 0.0 ? defect / scale : 0.0;
}

}  // namespace bpde
