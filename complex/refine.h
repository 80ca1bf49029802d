#pragma once
// Exact refinement of a patch complex (complex/patch_complex.h): in h (each patch split into four
// by de Casteljau subdivision) and in p (degree elevation). The refined complex describes the
// same surface; shared edges stay shared.
//
// h: a triangular patch with domain corners A = (0,0), B = (1,0), C = (0,1) is split at its edge
//    midpoints AB, BC, CA into the four patches (A, AB, CA), (AB, B, BC), (CA, BC, C) and the
//    middle one (BC, CA, AB), each given as (its x(0,0), x(1,0), x(0,1)); the middle one is turned
//    by 180° in the domain but keeps the orientation. Their control points are the blossom of
//    the patch at their corners (P'_{ijk} = b[B'^i, C'^j, A'^k] for the sub-triangle (A', B', C')),
//    i.e. de Casteljau subdivision. The midpoint split keeps every sub-triangle similar to the
//    patch's domain (no angle degenerates under repeated refinement), unlike a split at the
//    centroid. A tensor patch is split at u = 1/2 and v = 1/2 into the four quarters
//    [0,½]²,[½,1]×[0,½],[½,1]²,[0,½]×[½,1] (in that order), each by the 1-D subdivision in u and v.
//    Patch 4p + k of the result is the k-th part of patch p.
// p: every patch elevated by r degrees (TriangularNet::elevated, TensorNet::elevated); patch p
//    stays patch p.
//
// Row sharing: every refined control point has an abscissa in its parent's domain (the Greville
// point: (i B' + j C' + k A')/n' for a sub-triangle; (u0 + i h/n', v0 + j h/n') for a
// quarter). Points with one abscissa inside a parent are one row; a point on a parent's edge is
// keyed by that complex edge and its position along it, so both parents of a seam use one row
// there, and a point at a parent's corner is the corner's row. A shared row takes its value from
// the first patch that has it (both values are the same polynomial data, equal up to rounding).
// A refined row is fixed when it lies on a complex edge all of whose rows are fixed, or is a
// fixed corner row; inner rows are free.
#include "bezierpde/complex/patch_complex.h"

namespace bpde {

/// Most refinement levels in h of a job (4^r patches per patch).
inline constexpr int kMaxComplexRefine = 5;

/// Each patch split into four (above). Validates c; SizeError when the result would have more
/// than kMaxComplexPatches patches.
PatchComplex refine_h(const PatchComplex& c);

/// Every patch's degree raised by r >= 0 (DegreeError beyond kMaxDegree). Validates c.
PatchComplex refine_p(const PatchComplex& c, int r);

}  // namespace bpde
