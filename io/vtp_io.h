#pragma once
// surface.vtp: the sampled surface as VTK XML PolyData (VTK file format 1.0), so that ParaView
// opens it with its fields ready (FORMATS.md, bezierpde extensions, "surface.vtp").
//
// Points: the mesh vertices (mesh order). Polys: the triangles (connectivity, offsets 3, 6, ...).
// PointData (the fields of io/surface_fields.h):
//   Normals (3 components, the active normals), mean_curvature (the active scalars),
//   gaussian_curvature, uv (2 components: the parameters (u, v), the active texture coordinates),
//   regular (UInt8, 1 where x_u ^ x_v does not vanish).
// MeshFormat::Ascii writes Float64 values with 17 significant digits and Int32 indices in ASCII;
// MeshFormat::Binary writes Float32 values and Int32 indices inline as base64 (format="binary",
// header_type="UInt64": each array is preceded by its byte count as a little-endian UInt64).
#include <cstdint>
#include <string>
#include <vector>

#include "bezierpde/core/mesh.h"
#include "bezierpde/io/mesh_io.h"
#include "bezierpde/io/surface_fields.h"

namespace bpde {

/// Write `mesh` with `fields` (surface_fields of the same mesh) to `path`. Throws FileError.
/// `text`, if given, is the SharedNumberText of the same mesh and fields (io/mesh_io.h).
/// `patch` (a patch complex's mesh, complex/complex_mesh.h): one patch id per triangle, written
/// as the Int32 CellData array "patch" (the active cell scalars).
/// The bytes write_vtp writes (for a file written through io/output_folder.h).
std::string vtp_text(const TriangleMesh& mesh, const SurfaceFields& fields, MeshFormat format = MeshFormat::Ascii,
                     const SharedNumberText* text = nullptr, const std::vector<std::int32_t>* patch = nullptr);
void write_vtp(const std::string& path, const TriangleMesh& mesh, const SurfaceFields& fields,
               MeshFormat format = MeshFormat::Ascii, const SharedNumberText* text = nullptr,
               const std::vector<std::int32_t>* patch = nullptr);

}  // namespace bpde
