#pragma once
// CGAL checks of a sampled surface. This header is CGAL-free on purpose: checks/mesh_checks.cpp is
// the only translation unit of the project that includes CGAL, so its compile cost is paid once.
//
// Input: plain arrays.
//   vertices:  3*#V doubles, (x, y, z) per vertex;
//   triangles: 3*#F vertex indices, counter-clockwise in the parameter plane (so the geometric
//              normal agrees with x_u ^ x_v).
#include <optional>
#include <string_view>
#include <vector>

#include "bezierpde/core/progress.h"

namespace bpde {

struct MeshCheckReport {
  /// Number of pairs of non-adjacent triangles that intersect (CGAL::Polygon_mesh_processing::
  /// self_intersections after merging coincident vertices).
  int self_intersections = 0;
  /// True when the sampled surface (after merging coincident vertices) is a closed 2-manifold.
  bool closed = false;
  /// Enclosed volume: of the surface itself when closed, or of the surface capped by its planar
  /// boundary when that boundary is planar; empty otherwise. Sign: positive when the normals
  /// point outwards.
  std::optional<double> volume;
  /// Algebraic volume of the cone from the origin over the surface: (1/6) sum det(a, b, c) over
  /// the triangles. For a patch this is the mesh analogue of V = 1/3 int <x_u ^ x_v, x>.
  double cone_volume = 0.0;
  /// Diagnostics: vertices left after merging coincident ones (distance <= 1e-10 x bounding-box
  /// diagonal), and triangles dropped as degenerate (repeated vertex after merging, or collinear).
  int merged_vertices = 0;
  int degenerate_triangles = 0;
  /// Diagnostics: pairs of (merged, non-degenerate) triangles whose closed bounding boxes overlap,
  /// i.e. the pairs given to the exact self-intersection test (the same for every BroadPhase);
  /// 0 when the projection proof below settled the count.
  long long box_pairs = 0;
  /// Diagnostics: self_intersections is 0 by the projection proof (MeshCheckOptions::
  /// projection_proof), without the pairwise tests.
  bool embedded_by_projection = false;
};

/// How the pairs of triangles with overlapping bounding boxes are found before the exact tests.
/// Both give the same pairs, hence the same report.
enum class BroadPhase {
  kGrid,       ///< a uniform grid of cells (falls back to kCgalBoxes where it would not pay)
  kCgalBoxes,  ///< CGAL::box_self_intersection_d (the reference)
};

/// The progress stage of check_mesh (core/progress.h).
inline constexpr std::string_view kMeshCheckStage = "checking (CGAL)";

struct MeshCheckOptions {
  BroadPhase broad_phase = BroadPhase::kGrid;
  /// Called with kMeshCheckStage and the fraction done (total 1), never falling, from 0 up to
  /// before 1 (the caller ends the stage): after the merge of coincident vertices, through the
  /// exact tests of the self-intersections (by the grid's cells done; the CGAL broad phase reports
  /// only its start and end) and after the closedness. Null: no reports.
  ProgressFn progress;
  /// Try first the projection proof of no self-intersection (below); where it holds, the pairwise
  /// tests are skipped and self_intersections is 0, which they would have found too. False: always
  /// the pairwise tests (the diagnostics box_pairs then count every pair).
  bool projection_proof = true;
};

// The projection proof. Let T be the merged, non-degenerate triangles, each oriented (a, b, c),
// and f the projection that drops one coordinate axis k (f(x) = (x_{k+1}, x_{k+2}), indices mod 3,
// exact in floating point). It holds when, with exact predicates (CGAL's Epick):
//  (1) every f(a), f(b), f(c) is strictly counter-clockwise (or every one strictly clockwise);
//  (2) the algebraic boundary of T (the directed edges a -> b counted +1, b -> a counted -1) has
//      every edge with multiplicity 0 or +-1, and its edges form one closed loop through distinct
//      vertices;
//  (3) the loop's image under f is a simple polygon (distinct points, non-adjacent segments
//      disjoint, adjacent segments meeting only at their common point).
// Then no two triangles of T intersect in the sense of the exact tests (mesh_checks.cpp): for a
// point p of the plane off the images of the edges, the number of triangles whose image contains p
// equals the winding number of f(boundary) around p, by (1) and additivity of winding numbers
// (interior edges cancel); by (2) and (3) that is 0 or 1. So the images of two triangles have
// disjoint interiors; the images of a shared edge's two triangles lie on opposite sides of it; an
// interior vertex's triangles cover a neighbourhood of its image, and (3) keeps boundary vertices
// apart, so f is injective on vertices; hence the images of two triangles meet only in the image
// of a common vertex or a common edge, and since f is injective on each triangle, the triangles
// themselves meet only there: the exact tests find no intersection (a pair sharing an edge is not
// folded onto itself: its third vertices lie on opposite sides). The axes are tried in the order
// of the components of the area vector, largest first; a soup that is not one projectable disk
// (a closed surface, a folded patch, a complex whose projection overlaps) takes the pairwise tests.

/// Run the checks. Throws SizeError (from core/errors.h) for arrays whose length is not a
/// multiple of 3 or indices out of range, and NonFiniteError for non-finite coordinates.
/// An empty triangle list is valid (no intersections, not closed, no volume, cone volume 0).
/// The capped volume needs every boundary loop to be planar within 1e-8 x its diameter and the
/// rest of the surface to be a consistently oriented manifold; each loop is capped by a fan.
MeshCheckReport check_mesh(const std::vector<double>& vertices, const std::vector<int>& triangles,
                           const MeshCheckOptions& options = {});

}  // namespace bpde
