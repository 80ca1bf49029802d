#pragma once
// The uniformly loaded clamped rectangular plate (Centella, Monterde, Moreno, Oset,
// "Two C¹-methods to generate Bézier surfaces from the boundary", §6 and its two tables;
// FORMATS.md `bpde plate`).
//
// Problem: D Δ²w = p on [0,1] x [0,a] with p/D = 1, w = ∂w/∂n = 0 on the edges.
// Discretisation: w is a bidegree-(n,n) Bézier patch in (u,v) in [0,1]^2 with x = u, y = a·v,
// whose outer two rings of control points are zero (so w and ∇w vanish on the edges). In (u,v)
//   Δ² = ∂⁴_u + (2/a²) ∂²_u∂²_v + (1/a⁴) ∂⁴_v.
// Methods:
//   AdmissibleLoad (the paper's method, Theorem 3 with load 1): the degree-(n,n) Bernstein net of
//     Δ²w equals 1 at 2 <= i,j <= n-2. Square system solved in the Bernstein basis (NOTES.md: the
//     paper's power-basis solve has condition ~1e18 and corrupts its n = 15 column), restricted
//     to the nets symmetric under i -> n-i and j -> n-j (the problem is, and the solution is
//     unique). Reproduces every printed digit of the paper at n = 7, 9, 11.
//   Ritz: w minimises J(w) = ∫∫_[0,1]x[0,a] ((Δw)²/2 - w) dx dy (Δ the physical Laplacian) over
//     the same space. Basis: φ_k(u) φ_l(v) with φ_k'' = P_k(2u-1) (Legendre), k = 2..n-2, i.e.
//     the doubly integrated Legendre polynomials, which vanish with their derivative at 0 and 1;
//     ∫φ_k''φ_l'' is diagonal. Only even k, l (the symmetric modes; the odd ones decouple exactly
//     and carry no load). Gauss–Legendre quadrature with n+2 points (exact). Cholesky solve.
//     Converges to the literature value 0.00126532 (square).
// Both are the exact value of their discrete problem to better than 1e-9 relative for
// 4 <= n <= 30 (tests/c1 compares with 90-digit references).
#include <string>

#include "solvers/summary.h"
#include "tensor/tensor_net.h"

namespace bpde {

struct ClampedPlateOptions {
  enum class Method { AdmissibleLoad, Ritz };
  double aspect = 1.0;                       ///< a: the plate is [0,1] x [0,a]; 0.01 <= a <= 100
  int degree = 11;                           ///< n: bidegree of w; 4 <= n <= 30
  Method method = Method::AdmissibleLoad;    ///< default admissible-load (the paper's method)
  /// Throws NonFiniteError (aspect NaN/inf), ParameterError (aspect outside [0.01, 100]) or
  /// DegreeError (degree outside 4..30).
  void validate() const;
};

/// "admissible-load" or "ritz" -> Method; anything else throws ParameterError naming the value.
ClampedPlateOptions::Method parse_plate_method(const std::string& name);

struct ClampedPlateResult {
  double center_deflection = 0.0;  ///< w(1/2, 1/2), i.e. at (x, y) = (1/2, a/2)
  double energy = 0.0;             ///< J(w) = ∫∫ ((Δw)²/2 - w) dx dy over the physical plate
  TensorNet net;                   ///< degree (n,n), points (u_i, a·v_j, w_ij): the deflection patch
                                   ///< (the Bernstein x,y of the map (u,v) -> (u, a v))
  TensorNet load;                  ///< admissible-load only: points (i/n, a·j/n, R_ij), the
                                   ///< degree-(n,n) Bernstein net of Δ²w (1 at the interior);
                                   ///< for ritz, the same net of the Ritz solution's Δ²w
  Summary summary;                 ///< residual: admissible-load max |R_ij - 1| over the interior;
                                   ///< ritz ||K c - f|| / ||f|| of the Galerkin system
};

/// Solve the plate problem (validates the options first).
ClampedPlateResult solve_clamped_plate(const ClampedPlateOptions& options);

}  // namespace bpde
