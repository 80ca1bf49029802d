// max_seam_angle (complex_cmc.h): the angle between the patches' normals across shared edges.
#include "bezierpde/core/eigen.h"
#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <functional>
#include <numbers>
#include <vector>

#include "bezierpde/energies/complex_functionals.h"
#include "bezierpde/solvers/cmc/complex_cmc.h"

namespace bpde {
namespace {

// An edge of a patch: its control rows (local) in order and its parameter t -> (u, v), the edge
// being the Bernstein curve of those rows in t.
struct Edge {
  std::vector<int> rows;
  std::function<Eigen::Vector2d(double)> uv;
};

std::vector<Edge> patch_edges(PatchKind kind, int n) {
  std::vector<Edge> e(kind == PatchKind::triangular ? 3 : 4);
  for (int k = 0; k <= n; ++k) {
    if (kind == PatchKind::triangular) {
      e[0].rows.push_back(TriangularNet::index(n, n - k, k));  // w = 0, from (1, 0) to (0, 1)
      e[1].rows.push_back(TriangularNet::index(n, 0, n - k));  // u = 0, from (0, 1) to (0, 0)
      e[2].rows.push_back(TriangularNet::index(n, k, 0));      // v = 0, from (0, 0) to (1, 0)
    } else {
      e[0].rows.push_back(k * (n + 1));            // v = 0
      e[1].rows.push_back(n * (n + 1) + k);        // u = 1
      e[2].rows.push_back((n - k) * (n + 1) + n);  // v = 1
      e[3].rows.push_back(n - k);                  // u = 0
    }
  }
  if (kind == PatchKind::triangular) {
    e[0].uv = [](double t) { return Eigen::Vector2d(1 - t, t); };
    e[1].uv = [](double t) { return Eigen::Vector2d(0, 1 - t); };
    e[2].uv = [](double t) { return Eigen::Vector2d(t, 0); };
  } else {
    e[0].uv = [](double t) { return Eigen::Vector2d(t, 0); };
    e[1].uv = [](double t) { return Eigen::Vector2d(1, t); };
    e[2].uv = [](double t) { return Eigen::Vector2d(1 - t, 1); };
    e[3].uv = [](double t) { return Eigen::Vector2d(0, 1 - t); };
  }
  return e;
}

std::vector<int> global(const ComplexPatch& p, const std::vector<int>& local) {
  std::vector<int> g;
  for (int r : local) g.push_back(p.points[static_cast<std::size_t>(r)]);
  return g;
}

template <class Net>
Eigen::Vector3d unit_normal(const Net& net, const Eigen::Vector2d& uv) {
  const Eigen::Vector3d N = net.derivative(uv(0), uv(1), 1, 0).cross(net.derivative(uv(0), uv(1), 0, 1));
  const double l = N.norm();
  return l > 0 ? Eigen::Vector3d(N / l) : Eigen::Vector3d::Zero();
}

template <class Net>
double seam_angle(const PatchComplex& c, const std::function<Net(int)>& net, int samples) {
  const int n = c.patches.front().degree;
  const std::vector<Edge> edges = patch_edges(c.patches.front().kind, n);
  double worst = 0.0;
  const int P = static_cast<int>(c.patches.size());
  for (int p = 0; p < P; ++p)
    for (int q = p + 1; q < P; ++q)
      for (const Edge& e : edges)
        for (const Edge& f : edges) {
          const std::vector<int> ge = global(c.patches[static_cast<std::size_t>(p)], e.rows);
          std::vector<int> gf = global(c.patches[static_cast<std::size_t>(q)], f.rows);
          bool reversed = false;
          if (ge != gf) {
            std::reverse(gf.begin(), gf.end());
            if (ge != gf) continue;
            reversed = true;
          }
          const Net a = net(p), b = net(q);
          for (int s = 0; s < samples; ++s) {
            const double t = (s + 0.5) / samples;
            const Eigen::Vector3d na = unit_normal(a, e.uv(t)), nb = unit_normal(b, f.uv(reversed ? 1 - t : t));
            const double ang = na.isZero() || nb.isZero() ? std::numbers::pi
                                                          : std::acos(std::clamp(na.dot(nb), -1.0, 1.0));
            worst = std::max(worst, ang);
          }
        }
  return worst;
}

}  // namespace

double max_seam_angle(const PatchComplex& c, int samples) {
  patch_assembly(c);  // checks the complex
  if (c.patches.front().kind == PatchKind::triangular)
    return seam_angle<TriangularNet>(c, [&](int p) { return triangular_patch(c, p); }, samples);
  return seam_angle<TensorNet>(c, [&](int p) { return tensor_patch(c, p); }, samples);
}

}  // namespace bpde
