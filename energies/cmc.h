#pragma once
// The CMC functional of Arnal, Lluch, Monterde (triangular CMC), Prop. 4 and eq. (11):
//   D_H(x) = D(x) + 2H V(x),  D = 1/2 ∫ |x_u|^2 + |x_v|^2,  V = 1/3 ∫ <x_u ∧ x_v, x>,
// on triangular nets (domain T = {u, v >= 0, u + v <= 1}) and on tensor nets ([0,1]^2).
//
// Gradient (eq. (11), exact; docs/errata.md, triangular CMC eq. (11)): for every control point P_I
//   F_I = dD_H/dP_I = sum_J C_IJ P_J + 2H dV/dP_I,
// where for interior points dV/dP_I = ∫ B_I x_u ∧ x_v = 1/2 sum_JK C_IJK P_J ∧ P_K, so F_I is
// eq. (11) "sum_J C_IJ P_J + H sum_JK C_IJK P_J ∧ P_K". Its Euler–Lagrange equation is
// Δx = 2H x_u ∧ x_v (eq. (1)).
// Hessian (exact, symmetric): the 3x3 block of (I, L) is C_IL Id + 2H d^2V/dP_I dP_L (volume.h).
//
// Sign convention (FORMATS.md "Orientation and curvature"): with the triangular corners
// P_{00n} -> P_{n00} -> P_{0n0} (tensor: P_00 -> P_n0 -> P_nn -> P_0n) counter-clockwise seen from
// +z, x_u ∧ x_v points to +z, and a critical point with H < 0 bulges towards +z. The mean
// curvature reported by TriangularNet::geometry is then close to H.
//
// Points P are N x 3 matrices in the net's order. Restricted gradients/Hessians over a list of
// point indices idx use the entry 3a + c for (idx[a], coordinate c).
#include "bezierpde/core/eigen.h"
#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <array>
#include <memory>
#include <vector>

#include "bezierpde/core/mesh.h"
#include "bezierpde/energies/volume.h"

namespace bpde {

class TriangularNet;
class TensorNet;
struct PatchAssembly;

class CmcFunctional {
 public:
  /// Degree-n triangular nets (DegreeError unless 1 <= n <= kMaxDegree).
  static CmcFunctional triangular(int n);
  /// Degree-(n,m) tensor nets.
  static CmcFunctional tensor(int n, int m);
  /// Shared, cached instances (thread-safe; the 16 most recently used degrees are kept).
  static std::shared_ptr<const CmcFunctional> cached_triangular(int n);
  static std::shared_ptr<const CmcFunctional> cached_tensor(int n, int m);
  /// D_H of a surface of several patches (energies/patch_assembly.h) on its #global x 3 points:
  /// the Gram is the patch's summed through the local -> global maps (held sparse, #global x
  /// #global: sparse_gram(); up to 500 points also dense, with the dense products of one patch),
  /// the volume form VolumeForm::assembled; every method below then holds for the complex, with
  /// point indices and rows global. The residual's term sizes use the summed |C| of the patches.
  static CmcFunctional assembled(std::shared_ptr<const CmcFunctional> patch, std::shared_ptr<const PatchAssembly> assembly);
  /// The assembly of an assembled functional (null for a single patch).
  const std::shared_ptr<const PatchAssembly>& assembly() const { return volume_.assembly(); }

  int size() const { return static_cast<int>(assembly() ? sgram_.rows() : gram_.rows()); }
  /// Dirichlet Gram C (N x N): D = 1/2 sum_c P_c^T C P_c. Triangular: eq. (2)–(4); tensor:
  /// kron(K_u, M_v) + kron(M_u, K_v) of the 1-D integrals ∫B_i' B_k' and ∫B_j B_l.
  /// An assembled functional forms this dense copy of its sparse Gram on the first call only.
  const Eigen::MatrixXd& gram() const;
  /// The assembled Gram, sparse (both triangles stored; empty for a single patch).
  const Eigen::SparseMatrix<double>& sparse_gram() const { return sgram_; }
  const VolumeForm& volume_form() const { return volume_; }
  /// Bytes held (Gram + volume tables).
  std::size_t memory_bytes() const;

  double dirichlet(const Eigen::MatrixX3d& P) const;
  double volume(const Eigen::MatrixX3d& P) const { return volume_.value(P); }
  /// D_H = D + 2HV.
  double value(const Eigen::MatrixX3d& P, double H) const;
  /// N x 3 gradient of D_H (rows F_I).
  Eigen::MatrixX3d gradient(const Eigen::MatrixX3d& P, double H) const;
  /// k x 3 rows idx of the gradient (fast for interior points, VolumeForm::gradient_rows).
  Eigen::MatrixX3d gradient_rows(const Eigen::MatrixX3d& P, double H, const std::vector<int>& idx) const;
  /// 3k x 3k Hessian of D_H over the points idx.
  Eigen::MatrixXd hessian(const Eigen::MatrixX3d& P, double H, const std::vector<int>& idx) const;
  /// Relative residual of eq. (11) over the points idx:
  ///   max_{I in idx, c} |F_Ic| / max_{I in idx, c} (sum_J |C_IJ| |P_Jc| + 2|H| S_Ic),
  /// the denominator being the size of the terms of F: S_I = ∫ B_I |x_u ∧ x_v| (componentwise) for
  /// interior points (VolumeForm::gradient_scale_rows).
  /// When F is given it receives gradient_rows(P, H, idx); when scale is given, the denominator.
  double residual(const Eigen::MatrixX3d& P, double H, const std::vector<int>& idx, Eigen::MatrixX3d* F = nullptr,
                  double* scale = nullptr) const;

 private:
  struct DenseGram;  // the dense copy of an assembled Gram, formed once on demand
  Eigen::MatrixXd gram_, abs_gram_;                  // one patch
  Eigen::SparseMatrix<double> sgram_, sabs_gram_;    // assembled
  std::shared_ptr<DenseGram> dense_;
  VolumeForm volume_;
};

/// D, V and D_H = D + 2HV of a net (FORMATS.md `bpde energy NET --energy cmc --H h`), exact.
struct CmcEnergies {
  double D = 0, V = 0, DH = 0;
};
CmcEnergies cmc_energies(const TriangularNet& net, double H);
CmcEnergies cmc_energies(const TensorNet& net, double H);

/// {min, max, mean} of the mean curvature (FORMATS.md sign) over a sample grid, away from the
/// corners. Triangular: the points u = a/N, v = b/N (a + b <= N) whose three barycentric
/// coordinates are all <= 1 - corner_margin. Tensor: the (N+1)^2 grid without the points within
/// corner_margin (in both u and v) of a corner. Singular points are skipped. `count` is the number
/// of samples used (0: min = max = mean = 0). Requires N >= 1 and 0 <= corner_margin < 1/2
/// (ParameterError).
struct MeanCurvatureStats {
  double min = 0, max = 0, mean = 0;
  int count = 0;
  /// The domain point (u, v) of the sample where min (max) is taken (the first such sample in the
  /// layout's order); {-1, -1} when count is 0.
  std::array<double, 2> at_min{-1, -1}, at_max{-1, -1};
};
/// Both evaluate the net once on the grid (sample_mesh: tabulated Bernstein values and derivatives,
/// not per-point de Casteljau) and take the statistics of that mesh (below).
MeanCurvatureStats mean_curvature_stats(const TriangularNet& net, int N = 50, double corner_margin = 0.1);
MeanCurvatureStats mean_curvature_stats(const TensorNet& net, int N = 50, double corner_margin = 0.1);

/// The order of the samples of a mesh: TensorGrid, the (N+1)^2 points a(N+1)+b at u = a/N,
/// v = b/N (tensor and B-spline sample_mesh, parameters relative to the domain); TriangularGrid,
/// the (N+1)(N+2)/2 points u = a/N, v = b/N, a + b <= N, a-major (triangular sample_mesh).
enum class SampleLayout { TensorGrid, TriangularGrid };

/// The same statistics from an already sampled mesh (mesh.H, and mesh.regular to skip singular
/// samples when skip_singular is true; an empty mesh.regular counts every sample), so that the
/// report and the surface files share one evaluation. Throws ParameterError as above and
/// SizeError when the mesh does not have the layout's number of vertices for N.
MeanCurvatureStats mean_curvature_stats(const TriangleMesh& mesh, SampleLayout layout, int N,
                                        double corner_margin = 0.1, bool skip_singular = true);

}  // namespace bpde
