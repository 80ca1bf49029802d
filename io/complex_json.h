#pragma once
// A patch complex as a net file (FORMATS.md "Patch complexes"): the "net" of a complex job's
// result.json, or the same object on its own, read back into a PatchComplex
// (complex/patch_complex.h) for `bpde sample`, `check`, `view` and `export`.
//
//   {"type": "complex", "patch": "triangular" | "tensor", "degree": n, "refine": r,
//    "patches": [NET, ...],
//    "layout": {"vertices": [[x, y, z], ...], "faces": [[a, b, c(, d)], ...],
//               "boundary": [{"from": a, "to": b, "loop": l, "curve": k, "range": [t0, t1]}, ...]}}
//
// The row structure (which control points the patches share) is rebuilt from the layout exactly
// as a job builds it: complex_topology(layout, n) (complex/layout.h), refined in h `refine` times
// (complex/refine.h), so patch p refines layout face ⌊p / 4^refine⌋ and its local rows are those
// of that refinement. Each patch's points are then written into its rows; a row that several
// patches share (a seam or a corner) must get the same point from each of them, to
// kComplexSeamTolerance relative to the size of the net (ParameterError otherwise: the patches
// would not meet), and keeps the point of the first patch that has it. `fixed` is the complex's
// boundary rows. layout.boundary is optional; when given, it lists every boundary edge of the
// layout once, in the direction the faces run along it (the curve pieces are recorded, not
// checked against curves: a net file has none).
//
// Limits: those of a complex job (FORMATS.md "Input limits"): `degree` 1..kMaxComplexExtremalDegree,
// `refine` 0..kMaxComplexRefine, at most kMaxComplexPatches patches and kMaxComplexGramEntries
// patches · (points per patch)², checked before the row structure is built.
#include <string>
#include <utility>
#include <vector>

#include "bezierpde/complex/layout.h"
#include "bezierpde/complex/layout_loops.h"
#include "bezierpde/complex/patch_complex.h"
#include "bezierpde/io/json_io.h"

namespace bpde {

/// A complex as a net file holds it.
struct ComplexNetFile {
  PatchComplex complex;  ///< the patches (refined), their shared rows, fixed = the boundary rows
  Layout layout;         ///< the unrefined layout (its vertices as written)
  int refine = 0;
  bool refit = false;  ///< the boundary was fitted again at every refinement (FORMATS.md `refit`)
  std::vector<LayoutBoundaryEdge> boundary;  ///< layout.boundary as written (empty when absent)
};

/// Largest gap between two patches' copies of a shared control point, relative to the diagonal of
/// the bounding box of all control points (absolute when that diagonal is below 1).
inline constexpr double kComplexSeamTolerance = 1e-9;

/// True when j is an object whose "type" is "complex".
bool is_complex_net(const Json& j);

/// The complex net `j` (path e.g. "net" or "result.json.net" names it in messages). Throws
/// ParseError (malformed: unknown fields, wrong JSON types, a patch of another type, a missing
/// field), DegreeError (degree outside 1..kMaxComplexExtremalDegree, a patch of another degree),
/// SizeError (refine outside 0..kMaxComplexRefine, a patch count other than
/// #faces · 4^refine, more than kMaxComplexPatches patches or kMaxComplexGramEntries Gram
/// entries), NonFiniteError (a non-finite coordinate), ParameterError (a layout that is not an
/// oriented manifold, patches that disagree on a shared point, a boundary list that does not
/// match the layout's boundary), each message starting with its JSON path.
ComplexNetFile complex_net_from_json(const Json& j, const std::string& path = "net");

/// The JSON object above (layout.boundary written only when c.boundary is not empty).
Json complex_net_to_json(const ComplexNetFile& c);

/// The "patch" and "degree" fields of a complex net or boundary object j: ParseError for a patch
/// other than "triangular" or "tensor", DegreeError for a degree outside
/// 1..kMaxComplexExtremalDegree.
std::pair<PatchKind, int> complex_patch_and_degree(const Json& j, const std::string& path);

/// A layout's "vertices" ([[x, y, z], ...]) and "faces" ([[a, b, c(, d)], ...]) of the object j,
/// nothing else read or checked: ParseError on wrong JSON types, NonFiniteError on a non-finite
/// coordinate, SizeError for more than kMaxComplexPatches faces.
Layout layout_vertices_and_faces_from_json(const Json& j, const std::string& path, PatchKind kind);

/// One entry of layout.boundary, {"from": a, "to": b, "loop": l, "curve": k, "range": [t0, t1]}
/// ("range" optional): ParseError on unknown fields or wrong types, ParameterError on a negative
/// loop or curve index. The edge is not checked against a layout here.
LayoutBoundaryEdge layout_boundary_edge_from_json(const Json& b, const std::string& path);

/// "triangular" or "tensor".
std::string patch_kind_name(PatchKind kind);

}  // namespace bpde
