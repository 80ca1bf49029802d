#pragma once
// The quadratic energies of FORMATS.md ("ENERGY"), as data.
//
// Every energy is  E(x) = integral over the domain of  1/2 * sum_t w_t <d^{a_t} x, d^{b_t} x>,
// a list of QuadraticTerm {a = (au, av), b = (bu, bv), w}. Its Hessian (Gram matrix, per coordinate)
// is therefore  Q = sum_t w_t * sym(K_{a_t b_t}),  K_ab[I,J] = integral d^a B_I * d^b B_J,
// and E = 1/2 sum_c P_c^T Q P_c. energies/ builds Q for each kind of net from these terms.
//
//  name                  integrand (FORMATS.md)                             Euler–Lagrange operator
//  dirichlet             1/2(|x_u|^2 + |x_v|^2)                              -(x_uu + x_vv)
//  second-order [a,b,c]  1/2(a|x_u|^2 + b<x_u,x_v> + c|x_v|^2)               -(a x_uu + b x_uv + c x_vv)
//  biharmonic            1/2(|x_uu|^2 + 2|x_uv|^2 + |x_vv|^2)                [1,0,2,0,1]
//  laplacian-squared     1/2|x_uu + x_vv|^2                                  [1,0,2,0,1]
//  coons                 1/2|x_uv|^2                                         [0,0,1,0,0]
//  modified-biharmonic α 1/2(|x_uu|^2 + 2α²|x_uv|^2 + α⁴|x_vv|^2)           [1,0,2α²,0,α⁴]
//  fourth-order [a..e]   1/2(a|x_uu|^2 + b<x_uu,x_uv> + c|x_uv|^2
//                            + d<x_uv,x_vv> + e|x_vv|^2)  (Sun–Zhu)         [a,b,c,d,e]
//  gnorm ρ,t             fourth-order [ρ², 2ρcos t, 1+ρ², 2ρcos t, 1]  (Arnal–Monterde–Ugail eq. (1))
//  gnorm G               fourth-order [|e1|², 2<e1,e2>, |e1|²+|e2|², 2<e1,e2>, |e2|²],
//                        e1 = (g11, g21), e2 = (g12, g22) the columns of G
//                        (docs/errata.md, explicit PDE solutions §2)
//  operator [A..E]       for pde only: A∂⁴u + B∂³u∂v + C∂²u∂²v + D∂u∂³v + E∂⁴v; energy fourth-order [A..E]
//
// The operator [A..E] of a fourth-order energy means A x_uuuu + B x_uuuv + C x_uuvv + D x_uvvv +
// E x_vvvv = 0 (Arnal–Monterde–Ugail eq. (2); docs/errata.md, explicit PDE solutions eq. (2)).
#include "bezierpde/core/eigen.h"
#include <Eigen/Core>
#include <array>
#include <string>
#include <vector>

namespace bpde {

/// One term 1/2 * w * <d^a x, d^b x> of an integrand; d^a = d^{au}/du^{au} d^{av}/dv^{av}.
struct QuadraticTerm {
  int au = 0, av = 0;
  int bu = 0, bv = 0;
  double w = 0.0;
};

enum class EnergyKind {
  Dirichlet,
  SecondOrder,
  Biharmonic,
  LaplacianSquared,
  Coons,
  ModifiedBiharmonic,
  FourthOrder,
  GNormRhoT,
  GNormMatrix,
  Operator,
};

class EnergySpec {
 public:
  /// Constructors validate their parameters: every number finite (NonFiniteError); for a G
  /// matrix, |det G| > 1e-12 * |G|_F^2 (ParameterError "singular G"); rho > 0 (ParameterError);
  /// for (rho, t) the same relative test, |rho sin t| > 1e-12 (rho^2 + 1) (ParameterError "singular
  /// G": t = 0, pi, ... make e1 parallel to e2).
  static EnergySpec dirichlet();
  static EnergySpec second_order(double a, double b, double c);
  static EnergySpec biharmonic();
  static EnergySpec laplacian_squared();
  static EnergySpec coons();
  static EnergySpec modified_biharmonic(double alpha);
  static EnergySpec fourth_order(const std::array<double, 5>& coeffs);
  static EnergySpec gnorm(double rho, double t);
  static EnergySpec gnorm(const Eigen::Matrix2d& G);
  static EnergySpec pde_operator(const std::array<double, 5>& coeffs);

  EnergyKind kind() const { return kind_; }
  /// The FORMATS.md name: "dirichlet", "second-order", ..., "gnorm", "operator".
  std::string name() const;
  /// 2 for dirichlet and second-order, 4 otherwise.
  int order() const;
  /// Second-order coefficients [a, b, c] (order 2 only).
  const std::array<double, 3>& second_order_coeffs() const { return c2_; }
  /// Euler–Lagrange operator [A..E] (order 4 only). For laplacian-squared: [1,0,2,0,1].
  const std::array<double, 5>& operator_coeffs() const { return c4_; }
  /// The integrand as quadratic terms (see the header comment).
  std::vector<QuadraticTerm> terms() const;
  /// Parameters as given (alpha, rho, t, G), for reports.
  double alpha() const { return alpha_; }
  double rho() const { return rho_; }
  double t() const { return t_; }
  const Eigen::Matrix2d& G() const { return G_; }

  /// True when Arnal–Monterde–Ugail give a closed form for this operator: Coons, biharmonic,
  /// laplacian-squared, modified biharmonic, G-norm, and any [A..E] proportional to a G-norm
  /// operator [ρ², 2ρcos t, 1+ρ², 2ρcos t, 1] (that is, B = D and C = A + E after scaling).
  bool has_explicit_solution() const;

 private:
  EnergyKind kind_ = EnergyKind::Dirichlet;
  std::array<double, 3> c2_{1, 0, 1};
  std::array<double, 5> c4_{0, 0, 0, 0, 0};
  double alpha_ = 0, rho_ = 0, t_ = 0;
  Eigen::Matrix2d G_ = Eigen::Matrix2d::Identity();
};

}  // namespace bpde
