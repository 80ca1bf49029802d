#pragma once
// C¹ continuity of a triangular patch complex on a planar domain (complex/planar_domain.h), and
// the energies measured on that domain.
//
// With a domain triangle for every patch, the complex is a piecewise polynomial map of a planar
// triangulation (a spline in S⁰_n). It is C¹ as a map of the domain exactly when, across every
// interior seam, the classical smoothness conditions hold (Farin; Lai–Schumaker, "Spline
// Functions on Triangulations", ch. 2): for patches p and q sharing the edge E1E2, with D the
// vertex of q opposite it and (β_B, β_C, β_A) D's barycentric coordinates in p's domain triangle
// (weights of p's x(1,0), x(0,1), x(0,0), i.e. of the multi-index slots i, j, k),
//
//     Q_J = Σ_s β_s P_{I + e_s},   J = (a at E1, n-1-a at E2, 1 at D),  I = (a at E1, n-1-a at E2,
//                                  0 at p's opposite vertex),  a = 0..n-1,
//
// n conditions per seam, the same for x, y and z. They involve the edge's rows and the rows one
// step off it on either side: near the edge's ends these are rows of the other edges at the
// vertex, so each vertex of valence N couples all its edges (a vertex's ring is the affine image
// of the domain's star). Where a condition involves fixed (boundary) rows only, the boundary data
// must meet it.
//
// Energies on the domain: the energy's integrand (energies/energy_spec.h) is read in the domain
// coordinates y = (s, t) and integrated over the domain triangle; pulled back through the patch's
// affine map y = y0 + J (u, v) (J = [y1 - y0, y2 - y0]), ∂_s and ∂_t become the rows of
// J^{-T} (∂_u, ∂_v) and dy = |det J| du dv, so each patch's Gram is a combination of the
// reference integrals ∫_T d^a B_I d^b B_J (energies/triangular_gram.h). The Dirichlet energy on a
// similarity image of the reference triangle is the reference one.
#include "bezierpde/core/eigen.h"
#include <Eigen/Sparse>
#include <map>
#include <tuple>
#include <vector>

#include "bezierpde/complex/patch_complex.h"
#include "bezierpde/complex/planar_domain.h"
#include "bezierpde/energies/energy_spec.h"

namespace bpde {

/// The C¹ conditions above as rows of a sparse matrix (#conditions x #points; the same for the
/// three coordinates): C X = 0 holds exactly when the complex is C¹ on the domain. Seams in the
/// order of complex_edges(), a = 0..n-1 within a seam (row n·seam + a). ParameterError when c is
/// not triangular, domain.size() != #patches, or two patches' triangles disagree on their shared
/// edge (by more than 1e-9 of the domain's diameter).
Eigen::SparseMatrix<double> c1_constraints(const PatchComplex& c, const std::vector<DomainTriangle>& domain);

/// max over the conditions and coordinates of |(C X)_row| / (max_k |C_row,k| · max|X|): the C¹
/// defect relative to the size of the control points (0 for a C¹ complex, up to rounding).
double c1_residual(const PatchComplex& c, const std::vector<DomainTriangle>& domain);

/// The per-patch Grams of an energy measured on domain triangles (above), for one degree; the
/// reference integrals are computed once per derivative pair.
class DomainGrams {
 public:
  DomainGrams(int n, const EnergySpec& energy);
  /// The Gram of a patch with this domain triangle (count(n) square, symmetric).
  Eigen::MatrixXd gram(const DomainTriangle& T);

 private:
  int n_;
  std::vector<QuadraticTerm> terms_;
  std::map<std::tuple<int, int, int, int>, Eigen::MatrixXd> integrals_;
};

}  // namespace bpde
