#pragma once
// view.html: one self-contained web page showing a sampled net (FORMATS.md, bezierpde extensions,
// "view.html"): the surface coloured by mean curvature with a legend, the control net,
// rotate/zoom/pan (three.js OrbitControls), toggles for the net and a wireframe, and the report's
// numbers beside it. three.js and the page's script are inlined at build time (viewer/, bundled
// by esbuild into one classic script), so the page opens from disk without a network.
//
// The data are written for WebGL as float32: positions, normals and H as base64 little-endian
// Float32Array, the triangles and net segments as Uint32Array, the regular flags as Uint8Array.
// Colours: H over [lo, hi] = the report's `mean_curvature` {min, max} (away from the corners)
// when the report has it, else the range of H over the regular vertices; values outside are
// clamped to the ends of the scale.
//
// A patch complex (complex/patch_complex.h) is shown as its welded mesh (complex/complex_mesh.h),
// its net as every patch's control net (each control point once, each patch's net lines once) and
// its seams: every edge of the complex (complex_edges: the interior seams and the boundary edges,
// each once) as a polyline of `seam_samples` segments, sampled on the first patch that has it at
// t = k / seam_samples; the data's `seams` = {edges, interior, samples, points, lines}, shown
// with the check box "patch seams".
#include <string>

#include "bezierpde/complex/complex_mesh.h"
#include "bezierpde/complex/patch_complex.h"
#include "bezierpde/core/mesh.h"
#include "bezierpde/io/json_io.h"
#include "bezierpde/io/surface_fields.h"

namespace bpde {

/// The page for `net`, its sampled `mesh` with `fields` (surface_fields of that mesh), and the
/// `report` object (FORMATS.md "Results"; may be empty). `title` is escaped for HTML.
std::string view_html(const Net& net, const TriangleMesh& mesh, const SurfaceFields& fields, const Json& report,
                      const std::string& title);
/// view_html written to `path`. Throws FileError.
void write_view_html(const std::string& path, const Net& net, const TriangleMesh& mesh, const Json& report,
                     const std::string& title);

/// The page for a patch complex, its welded mesh `m` with `fields` (per vertex of m.mesh) and its
/// seams sampled at `seam_samples` segments per edge (1..kMaxSamples, ParameterError otherwise).
std::string view_html(const PatchComplex& c, const ComplexMesh& m, const SurfaceFields& fields, const Json& report,
                      const std::string& title, int seam_samples);
/// That page written to `path`. Throws FileError.
void write_view_html(const std::string& path, const PatchComplex& c, const ComplexMesh& m, const SurfaceFields& fields,
                     const Json& report, const std::string& title, int seam_samples);

/// The three.js version inlined into the page.
std::string viewer_three_version();

}  // namespace bpde
