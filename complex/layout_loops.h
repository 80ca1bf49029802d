#pragma once
// Patch complexes from boundary loops (boundaries/boundary_curves.h): automatic layouts for a
// disc (one loop) and an annulus (two loops), and layouts given by the user.
//
// Loops: a loop is a list of curves, each starting where the previous one ends and the last
// ending where the first starts (a loop of one curve is closed by itself: a circle, closed
// samples). The first loop is the outer one. Every loop runs with the surface on its left seen
// from the side the normals point to: the outer loop counter-clockwise, an annulus's inner loop
// the other way round (two coaxial circles spanned by a tube: one with normal +N, one with -N).
//
// Automatic layouts. Every junction of two curves is a layout vertex (a real corner must be one;
// a smooth junction may be one here, below); where a loop has fewer curves than the layout needs,
// curves are cut into pieces of equal parameter length (the longest first: for a circle, arcs of
// equal angle). Each layout boundary edge is one piece of one curve, fitted at degree n by
// fit_edge (boundaries/fit_boundary.h: Bézier curves and segments exactly, arcs and circles by
// the method asked, Chebyshev interpolation by default, samples by least squares).
//   disc, triangular: a fan of M triangles around a centre vertex, one per curve (M = N) for
//     N >= 3 curves, else M = 6 (the loop's curves cut into 6 pieces of equal parameter: a fan of
//     3 puts 120° arcs on its patches, and the area solve of the spherical cap over one circle
//     then stops at a nearly degenerate parametrisation; with 6 it converges to the exact cap).
//   disc, tensor: an O-grid: M boundary edges (M = max(N, 4), made even by one more cut), a ring
//     of M quads, and inside it one quad (M = 4) or M/2 quads around a centre vertex (M >= 6).
//   annulus: both loops cut into the same number M = max(N_outer, N_inner, 4) of edges, paired by
//     the cyclic shift of the inner loop's vertices nearest the outer's; a ring of M quads, or of
//     M pairs of triangles (each quad cut along its diagonal from its first outer to its first
//     inner vertex). The pairing runs the inner loop the other way round: outer point i faces
//     inner point s − i. An inner loop given the same way round as the outer one is refused
//     (LoopOrientationError naming loop 1) rather than reversed: its ring would be twisted (the
//     patches' normals flip), and a reversed loop would no longer be the curves and parameter
//     ranges the user gave (the layout's `boundary` names them). The test: 4 points per edge on
//     each loop (4M in all, at equal parameter steps of the pieces); when the best cyclic pairing
//     of the two point lists in the same direction (o_i with q_{s+i}) is nearer, in the sum of
//     squared distances, than the best pairing in opposite directions (o_i with q_{s-i}), the
//     inner loop runs the same way. (Two coaxial circles: the right pairing joins points straight
//     across the tube, the wrong one crosses it.)
// Why these: in all of them every boundary vertex belongs to two patches, so no patch has a
// corner where the boundary is smooth (its corner angle there would be 180° and x_u ∥ x_v; the
// single-patch problem of FORMATS.md).  For
// quads, "M quads meeting at a centre" needs the boundary vertices every other one at a patch
// corner of a single quad, which is wrong on a smooth loop; the O-grid keeps two quads at every
// boundary vertex and gives the inside regular quads.
// Interior positions: the centre vertex is the mean of the boundary edges' control points; the
// O-grid's inner ring is halfway from the centre to the boundary vertices; inner edges are the
// straight segments between their vertices, and each patch's inner points the discrete Coons
// fill of its edges (tensor: P_ij = linear in i + linear in j - bilinear in the corners;
// triangular: the mean of the three linear interpolations between opposite edge points). A
// solve (solvers/complex) replaces them.
//
// User layouts: vertices (positions of the inner vertices; a boundary vertex's position is taken
// from the curves), faces, and for each layout boundary edge the loop, curve and parameter range
// of the curve it follows, in the direction the faces run along it.
#include "bezierpde/core/eigen.h"
#include <Eigen/Core>
#include <vector>

#include "bezierpde/boundaries/fit_boundary.h"
#include "bezierpde/complex/layout.h"
#include "bezierpde/complex/patch_complex.h"
#include "bezierpde/core/errors.h"

namespace bpde {

/// A loop whose curves do not meet (the gap is named).
class LoopNotClosedError : public ParameterError {
 public:
  using ParameterError::ParameterError;
};
/// A loop whose curves meet, but not in the given order or direction.
class CurvesOutOfOrderError : public ParameterError {
 public:
  using ParameterError::ParameterError;
};
/// An annulus whose inner loop runs the same way round as the outer one (above).
class LoopOrientationError : public ParameterError {
 public:
  using ParameterError::ParameterError;
};
/// A user layout whose boundary does not match the loops (an edge without a curve, a curve piece
/// used twice or not at all, a piece that runs against its edge, ends that do not meet).
class LayoutMismatchError : public ParameterError {
 public:
  using ParameterError::ParameterError;
};

using Loop = std::vector<BoundaryCurve>;

struct LoopOptions {
  FitMethod method = FitMethod::Interpolation;  ///< fit_edge's method for curves that are not Bézier
  double corner_tolerance = 1e-8;  ///< relative gap allowed between consecutive curves (> 0)
};

/// The piece of a loop's curve that a layout boundary edge follows.
struct CurvePiece {
  int loop = 0, curve = 0;
  double t0 = 0, t1 = 1;
};

/// A layout boundary edge from vertex a to vertex b (the faces' direction) and its curve piece.
struct LayoutBoundaryEdge {
  int a = 0, b = 0;
  CurvePiece piece;
};

struct LoopComplex {
  Layout layout;
  PatchComplex complex;                    ///< fixed = the boundary rows
  std::vector<LayoutBoundaryEdge> boundary;
  std::vector<EdgeFit> fits;               ///< per boundary edge (EdgeFit::edge its index)
};

/// Checks that each loop is closed and in order (LoopNotClosedError, CurvesOutOfOrderError,
/// SizeError for an empty loop or no loops).
void check_loops(const std::vector<Loop>& loops, double corner_tolerance = 1e-8);

/// One loop: a disc (above). Two loops: an annulus. SizeError for other counts; the errors of
/// check_loops and of the fits; DegreeError for n outside 1..kMaxDegree.
LoopComplex loop_complex(PatchKind kind, int n, const std::vector<Loop>& loops, const LoopOptions& options = {});

/// A user layout: faces as in complex/layout.h; `boundary` names one piece per layout boundary
/// edge. The pieces of each curve must cover [0,1] without gaps or overlaps (LayoutMismatchError),
/// the edge's vertices must be the piece's ends in order, and the layout must be valid
/// (validate_layout).
LoopComplex layout_complex(const Layout& layout, int n, const std::vector<Loop>& loops,
                           const std::vector<LayoutBoundaryEdge>& boundary, const LoopOptions& options = {});

/// The boundary of `refined` (coarse.complex refined `refine` times by refine_h, complex/refine.h)
/// fitted again on the refined layout, so that the boundary error falls with h: every coarse
/// layout boundary edge, the piece [t0, t1] of its curve, is split with its patches into 2^refine
/// edges, the k-th following the piece [t0 + k (t1 − t0)/2^refine, t0 + (k + 1)(t1 − t0)/2^refine],
/// and each is fitted on its own at the complex's degree by fit_edge (options.method), its inner
/// rows set to the fit and each boundary vertex row to the mean of the fits' ends there (the curve
/// point, for fits that keep the ends). The inner rows of `refined` are kept (the subdivided
/// start). Returns one EdgeFit per coarse boundary edge (the order of coarse.boundary): the
/// method of its pieces' fits and the largest of their max_error. refine = 0 refits nothing and
/// returns coarse.fits. Needs the loops the coarse complex was made from.
std::vector<EdgeFit> refit_boundary(PatchComplex& refined, const LoopComplex& coarse, int refine,
                                    const std::vector<Loop>& loops, const LoopOptions& options = {});

/// Sets the rows of c that are not fixed, except the corner rows (kept as they are): the inner
/// rows of each edge on the segment between its end rows, then each patch's inner rows by the
/// discrete Coons fill of the header.
void coons_fill(PatchComplex& c);

}  // namespace bpde
