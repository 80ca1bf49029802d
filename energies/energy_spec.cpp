#include "bezierpde/energies/energy_spec.h"

#include "bezierpde/core/eigen.h"
#include <Eigen/LU>

#include <cmath>
#include <sstream>

#include "bezierpde/core/errors.h"

namespace bpde {
namespace {

void require_finite(double x, const char* what) {
  if (!std::isfinite(x)) {
    std::ostringstream s;
    s << "energy parameter " << what << " is not finite";
    throw NonFiniteError(s.str());
  }
}

}  // namespace

EnergySpec EnergySpec::dirichlet() {
  EnergySpec e;
  e.kind_ = EnergyKind::Dirichlet;
  e.c2_ = {1, 0, 1};
  return e;
}

EnergySpec EnergySpec::second_order(double a, double b, double c) {
  require_finite(a, "a");
  require_finite(b, "b");
  require_finite(c, "c");
  EnergySpec e;
  e.kind_ = EnergyKind::SecondOrder;
  e.c2_ = {a, b, c};
  return e;
}

EnergySpec EnergySpec::biharmonic() {
  EnergySpec e;
  e.kind_ = EnergyKind::Biharmonic;
  e.c4_ = {1, 0, 2, 0, 1};
  return e;
}

EnergySpec EnergySpec::laplacian_squared() {
  EnergySpec e;
  e.kind_ = EnergyKind::LaplacianSquared;
  e.c4_ = {1, 0, 2, 0, 1};
  return e;
}

EnergySpec EnergySpec::coons() {
  EnergySpec e;
  e.kind_ = EnergyKind::Coons;
  e.c4_ = {0, 0, 1, 0, 0};
  return e;
}

EnergySpec EnergySpec::modified_biharmonic(double alpha) {
  require_finite(alpha, "alpha");
  EnergySpec e;
  e.kind_ = EnergyKind::ModifiedBiharmonic;
  e.alpha_ = alpha;
  const double a2 = alpha * alpha;
  e.c4_ = {1, 0, 2 * a2, 0, a2 * a2};
  return e;
}

EnergySpec EnergySpec::fourth_order(const std::array<double, 5>& c) {
  for (int i = 0; i < 5; ++i) require_finite(c[static_cast<size_t>(i)], "coeffs");
  EnergySpec e;
  e.kind_ = EnergyKind::FourthOrder;
  e.c4_ = c;
  return e;
}

EnergySpec EnergySpec::gnorm(double rho, double t) {
  require_finite(rho, "rho");
  require_finite(t, "t");
  if (!(rho > 0)) throw ParameterError("gnorm: rho must be > 0 (rho = |e1|/|e2|)");
  if (!std::isfinite(rho * rho) || !(rho * rho > 0))
    throw NonFiniteError("gnorm: rho^2 overflows or underflows (rho = |e1|/|e2|)");
  // e1 = rho (cos t, sin t), e2 = (1, 0) up to a rotation: det G = rho sin t, |G|_F^2 = rho^2 + 1.
  // The same relative test as gnorm(G): singular when |rho sin t| <= 1e-12 (rho^2 + 1), which
  // takes in t = 0 and t = pi (sin(pi) = 1.2e-16 in double) and every t within ~1e-12 of k pi.
  if (!(std::abs(rho * std::sin(t)) > 1e-12 * (rho * rho + 1)))
    throw ParameterError("gnorm: G is singular (sin t = 0: e1 is parallel to e2); the G-norm needs an invertible G");
  EnergySpec e;
  e.kind_ = EnergyKind::GNormRhoT;
  e.rho_ = rho;
  e.t_ = t;
  const double bc = 2 * rho * std::cos(t);
  e.c4_ = {rho * rho, bc, 1 + rho * rho, bc, 1};
  return e;
}

EnergySpec EnergySpec::gnorm(const Eigen::Matrix2d& G) {
  for (int i = 0; i < 4; ++i) require_finite(G.data()[i], "G");
  const double fro2 = G.squaredNorm();
  if (!(std::abs(G.determinant()) > 1e-12 * fro2))
    throw ParameterError("gnorm: G is singular (det G = 0); the G-norm needs an invertible G");
  EnergySpec e;
  e.kind_ = EnergyKind::GNormMatrix;
  e.G_ = G;
  const Eigen::Vector2d e1 = G.col(0), e2 = G.col(1);
  const double a = e1.squaredNorm(), c = e2.squaredNorm(), b = 2 * e1.dot(e2);
  e.c4_ = {a, b, a + c, b, c};
  e.rho_ = std::sqrt(a / c);
  e.t_ = std::atan2(e1.x() * e2.y() - e1.y() * e2.x(), e1.dot(e2));
  return e;
}

EnergySpec EnergySpec::pde_operator(const std::array<double, 5>& c) {
  EnergySpec e = fourth_order(c);
  e.kind_ = EnergyKind::Operator;
  return e;
}

std::string EnergySpec::name() const {
  switch (kind_) {
    case EnergyKind::Dirichlet:
      return "dirichlet";
    case EnergyKind::SecondOrder:
      return "second-order";
    case EnergyKind::Biharmonic:
      return "biharmonic";
    case EnergyKind::LaplacianSquared:
      return "laplacian-squared";
    case EnergyKind::Coons:
      return "coons";
    case EnergyKind::ModifiedBiharmonic:
      return "modified-biharmonic";
    case EnergyKind::FourthOrder:
      return "fourth-order";
    case EnergyKind::GNormRhoT:
    case EnergyKind::GNormMatrix:
      return "gnorm";
    case EnergyKind::Operator:
      return "operator";
  }
  return "?";
}

int EnergySpec::order() const { return (kind_ == EnergyKind::Dirichlet || kind_ == EnergyKind::SecondOrder) ? 2 : 4; }

std::vector<QuadraticTerm> EnergySpec::terms() const {
  std::vector<QuadraticTerm> t;
  if (order() == 2) {
    const auto& c = c2_;
    t.push_back({1, 0, 1, 0, c[0]});
    t.push_back({1, 0, 0, 1, c[1]});
    t.push_back({0, 1, 0, 1, c[2]});
  } else if (kind_ == EnergyKind::LaplacianSquared) {
    // 1/2|x_uu + x_vv|^2 = 1/2(|x_uu|^2 + 2<x_uu,x_vv> + |x_vv|^2)
    t.push_back({2, 0, 2, 0, 1.0});
    t.push_back({2, 0, 0, 2, 2.0});
    t.push_back({0, 2, 0, 2, 1.0});
  } else {
    const auto& c = c4_;
    t.push_back({2, 0, 2, 0, c[0]});
    t.push_back({2, 0, 1, 1, c[1]});
    t.push_back({1, 1, 1, 1, c[2]});
    t.push_back({1, 1, 0, 2, c[3]});
    t.push_back({0, 2, 0, 2, c[4]});
  }
  std::vector<QuadraticTerm> nonzero;
  for (const auto& q : t)
    if (q.w != 0.0) nonzero.push_back(q);
  return nonzero;
}

bool EnergySpec::has_explicit_solution() const {
  switch (kind_) {
    case EnergyKind::Dirichlet:
    case EnergyKind::SecondOrder:
      return false;
    case EnergyKind::Biharmonic:
    case EnergyKind::LaplacianSquared:
    case EnergyKind::Coons:
    case EnergyKind::ModifiedBiharmonic:
    case EnergyKind::GNormRhoT:
    case EnergyKind::GNormMatrix:
      return true;
    case EnergyKind::FourthOrder:
    case EnergyKind::Operator: {
      const auto& c = c4_;
      const double scale = std::abs(c[0]) + std::abs(c[1]) + std::abs(c[2]) + std::abs(c[3]) + std::abs(c[4]);
      if (!(scale > 0)) return false;
      const double tol = 1e-12 * scale;
      // Proportional to [ρ², 2ρ cos t, 1+ρ², 2ρ cos t, 1]: E != 0, A/E > 0, B == D,
      // C == A + E, |B| <= 2 sqrt(A E) (|cos t| <= 1).
      if (!(std::abs(c[4]) > tol)) return false;
      if (!(c[0] / c[4] > 0)) return false;
      if (std::abs(c[1] - c[3]) > tol) return false;
      if (std::abs(c[2] - (c[0] + c[4])) > tol) return false;
      return std::abs(c[1]) <= 2 * std::sqrt(c[0] * c[4]) * (1 + 1e-12);
    }
  }
  return false;
}

}  // namespace bpde
