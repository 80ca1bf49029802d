#pragma once
// The outputs of a patch complex (complex/patch_complex.h) beside result.json (FORMATS.md "Patch
// complexes"): the surface files of its welded mesh (complex/complex_mesh.h), which `bpde sample`
// writes for a complex net, and the optional exports DIR/surface.step (the complex as one sewn
// shell, io/step_export.h) and DIR/view.html (the welded mesh, every patch's control net and the
// seams, io/html_view.h). The exports of a single net are in jobs/exports.h.
#include <string>

#include "bezierpde/complex/complex_mesh.h"
#include "bezierpde/complex/patch_complex.h"
#include "bezierpde/io/job.h"
#include "bezierpde/io/mesh_io.h"
#include "bezierpde/io/output_folder.h"
#include "bezierpde/io/surface_fields.h"
#include "bezierpde/jobs/exports.h"

namespace bpde {

/// The exports a job asks for (Job::export_step, Job::export_html).
Exports job_exports(const Job& job);

/// The title of a complex's view.html: "bezierpde: <problem> on a complex of <P> <kind> patches".
std::string view_title(const PatchComplex& c, const Json& report);

/// The per-vertex fields of a complex's welded mesh: the normal and K from the patch that sampled
/// the vertex first (ComplexMesh::vertex_patch), at its parameters (ComplexMesh::uv), or where
/// that patch is singular at the point nudged towards its domain's centre; H and `regular` from
/// the mesh; uv those parameters.
SurfaceFields complex_surface_fields(const PatchComplex& c, const ComplexMesh& m);
/// The same for any sampled mesh of c: `vertex_patch` and `uv` give each vertex's patch and (u, v).
SurfaceFields complex_surface_fields(const PatchComplex& c, const TriangleMesh& mesh,
                                     const Eigen::VectorXi& vertex_patch, const Eigen::MatrixX2d& uv);

/// net.obj of a complex: every control point once (row order of PatchComplex::points), then each
/// patch's control-net segments once.
std::string complex_net_obj(const PatchComplex& c);

/// The requested exports of a complex into `folder` (whose names include them): surface.step, the
/// complex as one sewn shell (write_step), and view.html, the welded mesh `m` with `fields`, the
/// report, and the seams sampled at `samples` segments per edge.
void write_complex_exports(OutputFolder& folder, const Exports& exports, const PatchComplex& c, const ComplexMesh& m,
                           const SurfaceFields& fields, const Json& report, int samples);

/// DIR's surface files of a complex sampled as `m` (surface.obj, surface.ply and surface.vtp with
/// the patch of each triangle as the cell data "patch", net.obj), all or nothing; `bpde sample`.
void write_complex_surface_files(const std::string& dir, const PatchComplex& c, const ComplexMesh& m,
                                 MeshFormat format);

}  // namespace bpde
