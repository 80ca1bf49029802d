#pragma once
// A sampled surface: vertices, triangles and the mean curvature at each vertex.
#include <Eigen/Core>

namespace bpde {

/// Triangle mesh of a sampled patch.
///  - V: #V by 3 vertex positions, in the sampling order of FORMATS.md ("bpde sample").
///  - F: #F by 3 vertex indices; each triangle is counter-clockwise in the parameter plane, so
///    its geometric normal agrees with x_u ^ x_v.
///  - H: #V mean curvatures (FORMATS.md sign convention). At a singular parameter point (a
///    degenerate corner) the value is taken at a point nudged towards the domain's centre; it is
///    never NaN.
struct TriangleMesh {
  Eigen::MatrixX3d V;
  Eigen::MatrixX3i F;
  Eigen::VectorXd H;
};

}  // namespace bpde
