#pragma once
// A sampled surface: vertices, triangles and the mean curvature at each vertex.
#include "bezierpde/core/eigen.h"
#include <Eigen/Core>
#include <cstddef>
#include <string>

namespace bpde {

/// Largest mesh resolution N of every sampled output (`samples` of jobs and blend configs,
/// `--samples` of `bpde sample` and `bpde check`): a mesh of N has (N+1)^2 vertices, and the whole
/// run (the mesh, the CGAL checks, the files) needs about kBytesPerSampleVertex bytes per vertex
/// (measured: 123 MB at N = 500, 7.6 GB at N = 4096), so N = 2000 is about 1.8 GB.
inline constexpr int kMaxSamples = 2000;
inline constexpr std::size_t kBytesPerSampleVertex = 450;

/// The message of a resolution out of 1..kMaxSamples, with the memory it would need; `what`
/// names the field (e.g. "samples").
inline std::string samples_limit_message(const std::string& what, long long samples) {
  const double n1 = static_cast<double>(samples) + 1.0;
  const double gb = n1 * n1 * static_cast<double>(kBytesPerSampleVertex) / 1e9;
  std::string s = what + " must be in 1.." + std::to_string(kMaxSamples) + ", got " + std::to_string(samples);
  if (samples > kMaxSamples)
    s += " (a mesh of N samples needs about " + std::to_string(kBytesPerSampleVertex) + " (N+1)^2 bytes: " +
         std::to_string(static_cast<long long>(gb * 10 + 0.5) / 10) + "." +
         std::to_string(static_cast<long long>(gb * 10 + 0.5) % 10) + " GB here)";
  return s;
}

/// Triangle mesh of a sampled patch.
///  - V: #V by 3 vertex positions, in the sampling order of FORMATS.md ("bpde sample").
///  - F: #F by 3 vertex indices; each triangle is counter-clockwise in the parameter plane, so
///    its geometric normal agrees with x_u ^ x_v.
///  - H: #V mean curvatures (FORMATS.md sign convention). At a singular parameter point (a
///    degenerate corner) the value is taken at a point nudged towards the domain's centre; it is
///    never NaN.
///  - regular: #V flags, 1 where the parametrisation is regular at the sample itself (H is the
///    curvature there), 0 where H was taken at a nudged point. The sample_mesh functions of the
///    nets fill it (the one tabulated evaluation that the report statistics share with the files,
///    energies/cmc.h); empty when a producer does not know, read as "all regular".
struct TriangleMesh {
  Eigen::MatrixX3d V;
  Eigen::MatrixX3i F;
  Eigen::VectorXd H;
  Eigen::Matrix<unsigned char, Eigen::Dynamic, 1> regular;
};

}  // namespace bpde

namespace bpde {

/// The 2N^2 triangles of an (N+1) x (N+1) grid indexed a(N+1)+b, counter-clockwise when a runs
/// along the first parameter and b along the second.
inline Eigen::MatrixX3i grid_triangles(int N) {
  Eigen::MatrixX3i F(2 * N * N, 3);
  int f = 0;
  for (int a = 0; a < N; ++a)
    for (int b = 0; b < N; ++b) {
      const int p00 = a * (N + 1) + b, p10 = (a + 1) * (N + 1) + b, p11 = p10 + 1, p01 = p00 + 1;
      F.row(f++) << p00, p10, p11;
      F.row(f++) << p00, p11, p01;
    }
  return F;
}

}  // namespace bpde
