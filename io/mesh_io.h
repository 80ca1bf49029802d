#pragma once
// Surface and control-net files (FORMATS.md "Results"): OBJ, PLY (ASCII, every number written as
// the shortest decimal that reads back to the same double (std::to_chars), so files are exact; or
// binary little-endian float32) and VTK XML PolyData (io/vtp_io.h).
#include <array>
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "bezierpde/core/mesh.h"
#include "bezierpde/core/progress.h"
#include "bezierpde/io/json_io.h"
#include "bezierpde/io/surface_fields.h"

namespace bpde {

/// The decimal text (std::to_chars: the shortest that reads back to the same double) of the numbers
/// the ASCII surface files share: the vertex coordinates, row by row, and the mean curvature per
/// vertex (fields.H). Formatted once for write_obj, write_ply and write_vtp, which copy it instead
/// of formatting each number again; the files are the same bytes either way.
class SharedNumberText {
 public:
  SharedNumberText(const TriangleMesh& mesh, const SurfaceFields& fields);
  std::string_view vertex(Eigen::Index r, int c) const { return at(3 * r + c); }
  std::string_view mean_curvature(Eigen::Index r) const { return at(3 * vertices_ + r); }
  Eigen::Index vertices() const { return vertices_; }

 private:
  std::string_view at(Eigen::Index i) const {
    const auto k = static_cast<std::size_t>(i);
    return {chars_.data() + begin_[k], begin_[k + 1] - begin_[k]};
  }
  Eigen::Index vertices_ = 0;
  std::string chars_;
  std::vector<std::size_t> begin_;  // number i is chars_[begin_[i], begin_[i + 1])
};

/// `v x y z` per vertex (in mesh order) and `f a b c` per triangle (1-based). Throws FileError.
/// `text`, if given, is the SharedNumberText of the same mesh.
void write_obj(const std::string& path, const TriangleMesh& mesh, const SharedNumberText* text = nullptr);
/// How surface.ply (and surface.vtp) store numbers: `ascii` (doubles, shortest round trip) or
/// `binary` (PLY binary_little_endian with float32 x, y, z, mean_curvature; VTP base64 float32).
enum class MeshFormat { Ascii, Binary };
/// "ascii" or "binary" (ParseError naming `where` otherwise).
MeshFormat mesh_format_from_string(const std::string& s, const std::string& where);

/// PLY with x, y, z, mean_curvature (fields.H: at irregular vertices the mean of the regular
/// neighbours, never the blown-up value) and `uchar regular` (fields.regular) per vertex, and the
/// triangles as `list uchar int vertex_indices`. Throws FileError.
void write_ply(const std::string& path, const TriangleMesh& mesh, const SurfaceFields& fields,
               MeshFormat format = MeshFormat::Ascii, const SharedNumberText* text = nullptr);
/// The segments of the control net (pairs of point indices, net order) joining neighbours along
/// each parameter direction (three directions for triangular nets).
std::vector<std::array<int, 2>> net_segments(const Net& net);
/// The control net as OBJ lines: its points as vertices (net order) and `l a b` segments joining
/// neighbours along each parameter direction (three directions for triangular nets).
void write_net_obj(const std::string& path, const Net& net);

/// Sample any net (the sample_mesh of its type), reporting the stage kSamplingStage to `progress`
/// (core/sample_progress.h; the caller ends the stage).
TriangleMesh sample_net(const Net& net, int samples, const ProgressFn& progress = {});
/// surface.obj, surface.ply, surface.vtp and net.obj into `dir` (which must exist).
void write_surface_files(const std::string& dir, const Net& net, const TriangleMesh& mesh,
                         MeshFormat format = MeshFormat::Ascii);

}  // namespace bpde
