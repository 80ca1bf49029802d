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
//     Δ²w equals 1 at 2 <= i,j <= n-2, solved in the Bernstein basis (the paper's power-basis
//     solve corrupts its n = 15 column: docs/errata.md, C¹ methods §6).
//   Ritz: w minimises J(w) = ∫∫_[0,1]x[0,a] ((Δw)²/2 - w) dx dy (Δ the physical Laplacian) over
//     the same space, in the doubly integrated Legendre basis.
// The bases, the symmetry reduction, the accuracy against 90-digit references and the tables
// beside the paper's: docs/c1.md.
#include <string>

#include "bezierpde/solvers/summary.h"
#include "bezierpde/tensor/tensor_net.h"

namespace bpde {

struct ClampedPlateOptions {
  enum class Method { AdmissibleLoad, Ritz };
  double aspect = 1.0;                     ///< a: the plate is [0,1] x [0,a]; 0.01 <= a <= 100
  int degree = 11;                         ///< n: bidegree of w; 4 <= n <= 30
  Method method = Method::AdmissibleLoad;  ///< default admissible-load (the paper's method)
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
