#include "bezierpde/solvers/complex/complex_c1.h"

#include <Eigen/Dense>
#include <algorithm>
#include <array>
#include <cmath>
#include <string>

#include "bezierpde/core/errors.h"
#include "bezierpde/energies/triangular_gram.h"
#include "bezierpde/triangular/triangular_net.h"

namespace bpde {

namespace {

/// Domain-triangle row of the corner of multi-index slot s: slot 0 (i) is x(1,0), slot 1 (j)
/// x(0,1), slot 2 (k) x(0,0).
constexpr std::array<int, 3> kSlotRow{1, 2, 0};

int local_index(int n, const std::array<int, 3>& I) { return TriangularNet::index(n, I[0], I[1]); }

/// Global row of the corner of slot s of patch p.
int corner_row(const ComplexPatch& patch, int s) {
  std::array<int, 3> I{0, 0, 0};
  I[s] = patch.degree;
  return patch.points[local_index(patch.degree, I)];
}

/// Polynomial in (∂_u, ∂_v) of ∂_s^a ∂_t^b: coefficient k of ∂_u^k ∂_v^(a+b-k).
std::vector<double> pulled_back(int a, int b, const Eigen::Matrix2d& M) {
  std::vector<double> p{1.0};
  auto times = [&](double du, double dv) {
    std::vector<double> q(p.size() + 1, 0.0);
    for (std::size_t k = 0; k < p.size(); ++k) {
      q[k + 1] += du * p[k];
      q[k] += dv * p[k];
    }
    p = q;
  };
  for (int r = 0; r < a; ++r) times(M(0, 0), M(0, 1));
  for (int r = 0; r < b; ++r) times(M(1, 0), M(1, 1));
  return p;
}

}  // namespace

Eigen::SparseMatrix<double> c1_constraints(const PatchComplex& c, const std::vector<DomainTriangle>& domain) {
  validate(c);
  if (c.patches.front().kind != PatchKind::triangular)
    throw ParameterError("C1 conditions on a planar domain take triangular complexes");
  if (domain.size() != c.patches.size())
    throw ParameterError("the planar domain has " + std::to_string(domain.size()) + " triangles for " +
                         std::to_string(c.patches.size()) + " patches");
  double diameter = 0;
  for (const DomainTriangle& T : domain) diameter = std::max(diameter, T.cwiseAbs().maxCoeff());
  const int n = c.patches.front().degree;
  std::vector<Eigen::Triplet<double>> t;
  int row = 0;
  for (const ComplexEdge& edge : complex_edges(c)) {
    if (edge.sides.size() != 2) continue;
    const int p = edge.sides[0].patch, q = edge.sides[1].patch;
    const ComplexPatch &P = c.patches[p], &Q = c.patches[q];
    const int e1 = edge.rows.front(), e2 = edge.rows.back();
    std::array<int, 3> ps{-1, -1, -1}, qs{-1, -1, -1};  // slots of E1, E2, opposite
    for (int s = 0; s < 3; ++s) {
      const int rp = corner_row(P, s), rq = corner_row(Q, s);
      (rp == e1 ? ps[0] : rp == e2 ? ps[1] : ps[2]) = s;
      (rq == e1 ? qs[0] : rq == e2 ? qs[1] : qs[2]) = s;
    }
    for (int k = 0; k < 2; ++k)
      if ((domain[p].row(kSlotRow[ps[k]]) - domain[q].row(kSlotRow[qs[k]])).norm() > 1e-9 * (diameter + 1e-300))
        throw ParameterError("the domain triangles of patches " + std::to_string(p) + " and " + std::to_string(q) +
                             " disagree on their shared edge");
    // D's barycentric coordinates in p's triangle, per slot
    const DomainTriangle& T = domain[p];
    Eigen::Matrix2d J;
    J.col(0) = (T.row(1) - T.row(0)).transpose();
    J.col(1) = (T.row(2) - T.row(0)).transpose();
    const Eigen::Vector2d D = domain[q].row(kSlotRow[qs[2]]).transpose();
    const Eigen::Vector2d uv = J.lu().solve(D - T.row(0).transpose());
    const std::array<double, 3> beta{uv(0), uv(1), 1 - uv(0) - uv(1)};
    for (int a = 0; a < n; ++a, ++row) {
      std::array<int, 3> Jq{0, 0, 0}, Ip{0, 0, 0};
      Jq[qs[0]] = a, Jq[qs[1]] = n - 1 - a, Jq[qs[2]] = 1;
      Ip[ps[0]] = a, Ip[ps[1]] = n - 1 - a;
      t.emplace_back(row, Q.points[local_index(n, Jq)], 1.0);
      for (int s = 0; s < 3; ++s) {
        std::array<int, 3> I = Ip;
        ++I[s];
        t.emplace_back(row, P.points[local_index(n, I)], -beta[s]);
      }
    }
  }
  Eigen::SparseMatrix<double> C(row, c.points.rows());
  C.setFromTriplets(t.begin(), t.end());
  return C;
}

double c1_residual(const PatchComplex& c, const std::vector<DomainTriangle>& domain) {
  const Eigen::SparseMatrix<double, Eigen::RowMajor> C = c1_constraints(c, domain);
  const double size = c.points.cwiseAbs().maxCoeff();
  if (!(size > 0)) return 0;
  const Eigen::MatrixX3d R = C * c.points;
  double worst = 0;
  for (int r = 0; r < C.rows(); ++r) {
    double coeff = 0;
    for (Eigen::SparseMatrix<double, Eigen::RowMajor>::InnerIterator it(C, r); it; ++it)
      coeff = std::max(coeff, std::abs(it.value()));
    worst = std::max(worst, R.row(r).cwiseAbs().maxCoeff() / (coeff * size));
  }
  return worst;
}

DomainGrams::DomainGrams(int n, const EnergySpec& energy) : n_(n), terms_(energy.terms()) {}

Eigen::MatrixXd DomainGrams::gram(const DomainTriangle& T) {
  Eigen::Matrix2d J;
  J.col(0) = (T.row(1) - T.row(0)).transpose();
  J.col(1) = (T.row(2) - T.row(0)).transpose();
  const double det = J.determinant();
  if (!(std::abs(det) > 0)) throw ParameterError("a degenerate domain triangle");
  const Eigen::Matrix2d M = J.inverse().transpose();
  const int N = TriangularNet::count(n_);
  Eigen::MatrixXd Q = Eigen::MatrixXd::Zero(N, N);
  for (const QuadraticTerm& term : terms_) {
    if (term.w == 0) continue;
    const std::vector<double> ca = pulled_back(term.au, term.av, M), cb = pulled_back(term.bu, term.bv, M);
    const int da = term.au + term.av, db = term.bu + term.bv;
    for (int k = 0; k <= da; ++k)
      for (int l = 0; l <= db; ++l) {
        const double w = term.w * ca[k] * cb[l] * std::abs(det);
        if (w == 0) continue;
        const auto key = std::make_tuple(k, da - k, l, db - l);
        auto it = integrals_.find(key);
        if (it == integrals_.end())
          it = integrals_.emplace(key, triangular_derivative_integrals(n_, k, da - k, l, db - l)).first;
        Q += 0.5 * w * (it->second + it->second.transpose());
      }
  }
  return Q;
}

}  // namespace bpde
