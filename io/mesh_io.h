#pragma once
// Surface and control-net files (FORMATS.md "Results"): OBJ and ASCII PLY, every number written
// as the shortest decimal that reads back to the same double (std::to_chars), so files are exact.
#include <string>

#include "core/mesh.h"
#include "io/json_io.h"

namespace bpde {

/// `v x y z` per vertex (in mesh order) and `f a b c` per triangle (1-based). Throws FileError.
void write_obj(const std::string& path, const TriangleMesh& mesh);
/// ASCII PLY with double x, y, z, mean_curvature per vertex and the triangles. Throws FileError.
void write_ply(const std::string& path, const TriangleMesh& mesh);
/// The control net as OBJ lines: its points as vertices (net order) and `l a b` segments joining
/// neighbours along each parameter direction (three directions for triangular nets).
void write_net_obj(const std::string& path, const Net& net);

/// Sample any net: surface.obj, surface.ply and net.obj into `dir` (which must exist).
TriangleMesh sample_net(const Net& net, int samples);
void write_surface_files(const std::string& dir, const Net& net, const TriangleMesh& mesh);

}  // namespace bpde
