#pragma once
// Sampling a net with progress: the sample_mesh of each net (tensor/tensor_net.h,
// triangular/triangular_net.h, tensor/bspline_net.h; the same mesh) reporting the stage
// kSamplingStage (core/progress.h) with total 1: the fraction of the tabulated evaluations done
// (the points and their five derivatives, then the mean curvature), from 0 up to before 1 (the
// caller ends the stage). A header of its own, so that the nets' headers do not change.
#include <string_view>

#include "bezierpde/core/mesh.h"
#include "bezierpde/core/progress.h"

namespace bpde {

class TensorNet;
class TriangularNet;
class BSplineNet;

inline constexpr std::string_view kSamplingStage = "sampling";

TriangleMesh sample_mesh(const TensorNet& net, int N, const ProgressFn& progress);
TriangleMesh sample_mesh(const TriangularNet& net, int N, const ProgressFn& progress);
TriangleMesh sample_mesh(const BSplineNet& net, int N, const ProgressFn& progress);

/// The fraction reported after `evaluations` of the 6 tabulated evaluations (the mean curvature,
/// about as long as all of them together (measured), then takes the fractions up to 0.95).
inline double sampling_fraction(int evaluations) { return 0.45 * evaluations / 6.0; }

}  // namespace bpde
