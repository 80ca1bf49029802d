#include "bezierpde/solvers/pde/pde_residual.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "bezierpde/core/errors.h"

namespace bpde {

namespace {
constexpr double kNaturalFloor = 1e-8;
}  // namespace

std::vector<PdeTerm> pde_operator_terms(const EnergySpec& op) {
  std::vector<PdeTerm> t;
  if (op.order() == 2) {
    const auto& c = op.second_order_coeffs();
    const int d[3][2] = {{2, 0}, {1, 1}, {0, 2}};
    for (int k = 0; k < 3; ++k)
      if (c[static_cast<size_t>(k)] != 0.0) t.push_back({d[k][0], d[k][1], c[static_cast<size_t>(k)]});
  } else {
    const auto& c = op.operator_coeffs();
    for (int k = 0; k < 5; ++k)
      if (c[static_cast<size_t>(k)] != 0.0) t.push_back({4 - k, k, c[static_cast<size_t>(k)]});
  }
  return t;
}

double pde_residual(const TensorNet& net, const EnergySpec& op, int samples) {
  return pde_residual(net, pde_operator_terms(op), samples);
}

double pde_residual(const TensorNet& net, const std::vector<PdeTerm>& terms, int samples) {
  if (samples < 1) throw ParameterError("pde_residual: samples must be >= 1, got " + std::to_string(samples));
  const Eigen::VectorXd t = Eigen::VectorXd::LinSpaced(samples + 1, 0.0, 1.0);
  const Eigen::Index rows = t.size() * t.size();
  Eigen::MatrixX3d Lx = Eigen::MatrixX3d::Zero(rows, 3);
  Eigen::VectorXd scale = Eigen::VectorXd::Zero(rows);
  const double pmax = net.points().rowwise().norm().maxCoeff();
  double natural = 0;  // sum_k |c_k| (n)_du (m)_dv max|P|: the size a derivative of this net can have
  for (const PdeTerm& term : terms) {
    if (term.du > net.n() || term.dv > net.m() || term.c == 0.0) continue;  // the derivative vanishes
    double falling = 1;
    for (int q = 0; q < term.du; ++q) falling *= net.n() - q;
    for (int q = 0; q < term.dv; ++q) falling *= net.m() - q;
    natural += std::abs(term.c) * falling * pmax;
    const Eigen::MatrixX3d d = net.evaluate_grid(t, t, term.du, term.dv);
    Lx += term.c * d;
    scale += std::abs(term.c) * d.rowwise().norm();
  }
  const double num = Lx.rowwise().norm().maxCoeff();
  const double den = std::max(scale.maxCoeff(), kNaturalFloor * natural);
  if (!(den > 0.0)) return 0.0;
  return num / den;
}

void check_pde_degree_limit(int n, int m, const char* method, Summary& summary) {
  if (!summary.converged || std::max(n, m) <= kMaxPdeDegree) return;
  summary.set_failed(Status::NumericalLimit, "numerical limit: degree [" + std::to_string(n) + ", " +
                                                 std::to_string(m) + "] exceeds " + std::to_string(kMaxPdeDegree) +
                                                 ", past which double-precision boundary data no longer "
                                                 "determine the interior (docs/pde_accuracy.md); method \"" +
                                                 method + "\" returned its computed net, which is not reliable");
}

}  // namespace bpde
