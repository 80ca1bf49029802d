// §6 of Pasadas–Rodríguez (smoothing PDE splines): blending the cylinders
//   f(x, y) = (2y - 1, 2 cos 2πx, 2 sin 2πx),   g(x, y) = (2y + 1, cos 2πx, sin 2πx)
// by discrete smoothing PDE splines on the 8×4 BFS partition, for the four parameter sets of
// Figure 2. Boundary data (docs/errata.md, smoothing PDE splines §6): u(x,0) = f(x,1), u_y(x,0) = f_y(x,1), u(x,1) =
// g(x,0), u_y(x,1) = g_y(x,0) at the nodes x_i = i/8; approximation points A = {(i/9, 1/2)}, β = ρh with h(x, y) = (2y
// - 1, 0.5 cos 2πx, 0.5 sin 2πx).
//
// Usage: example_003_blend_cylinders EXAMPLE_DIR [OUT_DIR]
//   Writes EXAMPLE_DIR/fig2{a,b,c,d}.json (FORMATS.md blend configs), reads them back, solves
//   each one by the KKT system (LU) and by elimination, and prints the README table (its
//   generated section "blend-cylinders", scripts/docs.sh; seconds are machine-dependent). With
//   OUT_DIR, also writes OUT_DIR/fig2X.obj (the (50+1)² sampled surface).
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <numbers>
#include <string>

#include "bezierpde/checks/mesh_checks.h"
#include "bezierpde/core/errors.h"
#include "examples/common/generated.h"
#include "bezierpde/io/blend_config.h"
#include "bezierpde/solvers/blend/smoothing_spline.h"

using namespace bpde;

namespace {

constexpr double kTwoPi = 2 * std::numbers::pi;

BlendConfig figure2(double a, double eps, bool with_points) {
  BlendConfig c;
  SmoothingSplineProblem& p = c.problem;
  p.k = 8;
  p.l = 4;
  p.a = a;
  p.epsilon = eps;
  p.y0_value.resize(9, 3);
  p.y0_dy.resize(9, 3);
  p.y1_value.resize(9, 3);
  p.y1_dy.resize(9, 3);
  for (int i = 0; i <= 8; ++i) {
    const double x = i / 8.0;
    p.y0_value.row(i) << 2 * 1.0 - 1, 2 * std::cos(kTwoPi * x), 2 * std::sin(kTwoPi * x);  // f(x,1)
    p.y0_dy.row(i) << 2, 0, 0;                                                             // f_y
    p.y1_value.row(i) << 2 * 0.0 + 1, std::cos(kTwoPi * x), std::sin(kTwoPi * x);          // g(x,0)
    p.y1_dy.row(i) << 2, 0, 0;                                                             // g_y
  }
  const int m = with_points ? 9 : 0;
  p.points.resize(m, 2);
  p.data.resize(m, 3);
  for (int i = 0; i < m; ++i) {
    const double x = i / 9.0;
    p.points.row(i) << x, 0.5;
    p.data.row(i) << 2 * 0.5 - 1, 0.5 * std::cos(kTwoPi * x), 0.5 * std::sin(kTwoPi * x);  // h
  }
  c.samples = 50;
  return c;
}

/// FORMATS.md order, one point per line (blend_config_to_json holds the same data).
std::string pretty(const BlendConfig& c) {
  const nlohmann::json j = blend_config_to_json(c);
  auto rows = [](const nlohmann::json& a, const std::string& indent) {
    std::string s = "[";
    for (std::size_t r = 0; r < a.size(); ++r) {
      s += r ? ",\n" : "\n";
      s += indent;
      s += a[r].dump();
    }
    if (!a.empty()) {
      s += '\n';
      s.append(indent, 1, std::string::npos);
    }
    s += ']';
    return s;
  };
  std::string s = "{\"kind\": \"blend\", \"partition\": " + j["partition"].dump() + ", \"a\": " + j["a"].dump() +
                  ", \"epsilon\": " + j["epsilon"].dump() + ",\n \"edges\": {\n";
  for (const char* e : {"y0", "y1"}) {
    s += std::string("  \"") + e + "\": {\"value\": " + rows(j["edges"][e]["value"], "     ") +
         ",\n         \"dy\": " + rows(j["edges"][e]["dy"], "     ") + "}" + (e[1] == '0' ? ",\n" : "},\n");
  }
  s += " \"points\": " + rows(j["points"], "  ") + ",\n \"data\": " + rows(j["data"], "  ") +
       ",\n \"samples\": " + j["samples"].dump() + "}\n";
  return s;
}

void write_obj(const std::string& path, const TriangleMesh& m) {
  std::ofstream out(path);
  char buf[128];
  for (Eigen::Index v = 0; v < m.V.rows(); ++v) {
    std::snprintf(buf, sizeof buf, "v %.17g %.17g %.17g\n", m.V(v, 0), m.V(v, 1), m.V(v, 2));
    out << buf;
  }
  for (Eigen::Index f = 0; f < m.F.rows(); ++f)
    out << "f " << m.F(f, 0) + 1 << ' ' << m.F(f, 1) + 1 << ' ' << m.F(f, 2) + 1 << '\n';
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: %s EXAMPLE_DIR [OUT_DIR]\n", argv[0]);
    return 2;
  }
  try {
    const std::filesystem::path dir = argv[1];
    const char* names[4] = {"fig2a", "fig2b", "fig2c", "fig2d"};
    const BlendConfig configs[4] = {figure2(1, 1, false), figure2(10, 1, false), figure2(10, 1e-3, true),
                                    figure2(10, 1e-5, true)};
    const bpde::examples::GeneratedSection section("blend-cylinders", "seconds");
    std::printf(
        "| config | A | ε | a | converged | stationarity | J(σ) | \\|σ\\|_L² | max \\|σ(a_i) − β_i\\| "
        "| σ(x,½): X range | σ(x,½): radius range | surface X range | H min / mean / max "
        "| self-intersections | KKT − elimination | seconds |\n");
    std::printf("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
    for (int c = 0; c < 4; ++c) {
      const std::string file = (dir / (std::string(names[c]) + ".json")).string();
      {
        std::ofstream out(file);
        out << pretty(configs[c]);
        if (!out) throw FileError("cannot write " + file);
      }
      const BlendConfig cfg = read_blend_config(file);
      const auto t0 = std::chrono::steady_clock::now();
      const SmoothingSplineResult r = solve_smoothing_spline(cfg.problem);
      const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      SmoothingSplineOptions elim;
      elim.method = SmoothingSplineOptions::Method::kElimination;
      const SmoothingSplineResult r2 = solve_smoothing_spline(cfg.problem, elim);
      const double diff = (r.spline.coefficients() - r2.spline.coefficients()).cwiseAbs().maxCoeff();

      const TriangleMesh mesh = r.spline.sample(cfg.samples);
      double xmin = 1e300, xmax = -1e300, rmin = 1e300, rmax = -1e300;
      for (int a = 0; a <= 200; ++a) {
        const Eigen::Vector3d p = r.spline.evaluate(a / 200.0, 0.5);
        xmin = std::min(xmin, p.x());
        xmax = std::max(xmax, p.x());
        const double rad = std::hypot(p.y(), p.z());
        rmin = std::min(rmin, rad);
        rmax = std::max(rmax, rad);
      }
      const double sxmin = mesh.V.col(0).minCoeff(), sxmax = mesh.V.col(0).maxCoeff();
      std::vector<double> verts;
      std::vector<int> tris;
      for (Eigen::Index v = 0; v < mesh.V.rows(); ++v)
        for (int k = 0; k < 3; ++k) verts.push_back(mesh.V(v, k));
      for (Eigen::Index f = 0; f < mesh.F.rows(); ++f)
        for (int k = 0; k < 3; ++k) tris.push_back(mesh.F(f, k));
      const MeshCheckReport check = check_mesh(verts, tris);
      const auto& P = cfg.problem;
      std::printf(
          "| %s | %s | %g | %g | %s | %s | %.6g | %.6g | %s | [%.4f, %.4f] | [%.4f, %.4f] | "
          "[%.4f, %.4f] | %.3f / %.3f / %.3f | %d | %s | %.4f |\n",
          names[c], P.points.rows() ? "(i/9, ½), i = 0..8" : "∅", P.epsilon, P.a, r.summary.converged ? "yes" : "no",
          bpde::examples::stable_small(r.summary.residual).c_str(), r.functional, r.energy,
          P.points.rows() ? (std::to_string(r.max_data_error)).c_str() : "—", xmin, xmax, rmin, rmax, sxmin, sxmax,
          mesh.H.minCoeff(), mesh.H.mean(), mesh.H.maxCoeff(), check.self_intersections,
          bpde::examples::order_bound(diff).c_str(), secs);
      if (argc >= 3) {
        std::filesystem::create_directories(argv[2]);
        write_obj((std::filesystem::path(argv[2]) / (std::string(names[c]) + ".obj")).string(), mesh);
      }
    }
  } catch (const InvalidInput& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 2;
  }
  return 0;
}
