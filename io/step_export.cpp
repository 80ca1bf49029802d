// STEP export through the plugin bpde_step_plugin.so (io/step_plugin.h), opened on first use.
#include "bezierpde/io/step_export.h"

#include <dlfcn.h>

#include <array>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <mutex>
#include <vector>

#include "bezierpde/core/errors.h"
#include "bezierpde/io/atomic_file.h"
#include "bezierpde/io/step_plugin.h"
#include "bezierpde/triangular/tensor_form.h"

#ifndef BPDE_STEP_PLUGIN_NAME
#define BPDE_STEP_PLUGIN_NAME "bpde_step_plugin.so"
#endif

namespace bpde {
namespace {

namespace fs = std::filesystem;

struct Plugin {
  std::string path;
  bpde_step_write_fn write = nullptr;
  bpde_step_read_fn read = nullptr;
  bpde_step_write_shell_fn write_shell = nullptr;
  bpde_step_topology_fn topology = nullptr;
  std::string error;  // why it could not be loaded (then write/read are null)
};

// The folder of the binary that holds this code: libbpde_step.so in a shared build, else the
// executable or shared object that linked the static library.
fs::path own_folder() {
  Dl_info info{};
  if (dladdr(reinterpret_cast<void*>(&step_plugin_candidates), &info) == 0 || info.dli_fname == nullptr) return {};
  std::error_code ec;
  const fs::path self = fs::canonical(fs::path(info.dli_fname), ec);
  return ec ? fs::path(info.dli_fname).parent_path() : self.parent_path();
}

Plugin load() {
  Plugin p;
  std::string tried;
  for (const std::string& candidate : step_plugin_candidates()) {
    std::error_code ec;
    if (!fs::is_regular_file(candidate, ec)) {
      tried += (tried.empty() ? "" : ", ") + candidate;
      continue;
    }
    void* handle = dlopen(candidate.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (!handle) {
      const char* why = dlerror();
      p.error = "STEP export: cannot load " + candidate + ": " + (why ? why : "dlopen failed");
      return p;
    }
    const auto abi = reinterpret_cast<bpde_step_abi_fn>(dlsym(handle, "bpde_step_plugin_abi"));
    p.write = reinterpret_cast<bpde_step_write_fn>(dlsym(handle, "bpde_step_plugin_write"));
    p.read = reinterpret_cast<bpde_step_read_fn>(dlsym(handle, "bpde_step_plugin_read"));
    p.write_shell = reinterpret_cast<bpde_step_write_shell_fn>(dlsym(handle, "bpde_step_plugin_write_shell"));
    p.topology = reinterpret_cast<bpde_step_topology_fn>(dlsym(handle, "bpde_step_plugin_topology"));
    if (!abi || !p.write || !p.read || !p.write_shell || !p.topology || abi() != BPDE_STEP_PLUGIN_ABI) {
      p.write = nullptr, p.read = nullptr, p.write_shell = nullptr, p.topology = nullptr;
      p.error = "STEP export: " + candidate + " is not a STEP plugin of this build";
      return p;
    }
    p.path = candidate;
    return p;
  }
  p.error = "STEP export: the plugin " BPDE_STEP_PLUGIN_NAME " is not installed (looked for " + tried + ")";
  return p;
}

const Plugin& plugin() {
  static std::once_flag once;
  static Plugin p;
  std::call_once(once, [] { p = load(); });
  if (!p.write) throw StepPluginError(p.error);
  return p;
}

// The shortest decimal that reads back as x.
std::string shortest(double x) {
  char buf[32];
  for (int digits = 1; digits <= 17; ++digits) {
    std::snprintf(buf, sizeof buf, "%.*g", digits, x);
    if (std::strtod(buf, nullptr) == x) break;
  }
  return buf;
}

using Pole = std::array<double, 3>;

// OpenCASCADE takes interior knots of multiplicity <= degree; a bspline net may hold an interior
// knot of multiplicity degree + 1 (FORMATS.md "bspline"), where the surface may jump. With
// K[k] = ... = K[k+deg] = t interior, the row of poles k-1 is the surface at t- and row k the
// surface at t+. Where the two rows are equal (bit for bit) the surface is continuous there and
// dropping one copy of t and row k is exact (the same surface); otherwise UnsupportedProblem
// (exit 2): one face cannot hold the jump. rows[i][j]: the poles with index i in this direction.
void lower_full_multiplicity(std::vector<double>& K, std::vector<std::vector<Pole>>& rows, int deg,
                             const char* direction) {
  for (size_t k = 1; k + static_cast<size_t>(deg) + 1 < K.size(); ++k) {
    if (K[k] == K[k - 1] || K[k + static_cast<size_t>(deg)] != K[k]) continue;  // not the start of a run of deg + 1
    if (rows[k - 1] != rows[k])
      throw UnsupportedProblem(std::string("STEP export: the bspline surface is discontinuous at the ") + direction +
                               " knot " + shortest(K[k]) +
                               " (multiplicity degree + 1 and different control points on either side); a STEP "
                               "face holds a continuous surface");
    K.erase(K.begin() + static_cast<std::ptrdiff_t>(k));
    rows.erase(rows.begin() + static_cast<std::ptrdiff_t>(k));
  }
}

std::vector<std::vector<Pole>> transposed(const std::vector<std::vector<Pole>>& rows) {
  std::vector<std::vector<Pole>> cols(rows.empty() ? 0 : rows[0].size(), std::vector<Pole>(rows.size()));
  for (size_t i = 0; i < rows.size(); ++i)
    for (size_t j = 0; j < rows[i].size(); ++j) cols[j][i] = rows[i][j];
  return cols;
}

// The poles and knots of `net` as the plugin takes them; the vectors own the arrays.
struct Surface {
  bpde_step_surface s{};
  std::vector<double> poles, ku, kv;
};

Surface surface_of(const Net& net) {
  Surface out;
  auto fill = [&](int nu, int nv, auto&& point) {
    out.s.nu = nu, out.s.nv = nv;
    out.poles.resize(static_cast<size_t>(nu) * nv * 3);
    for (int i = 0; i < nu; ++i)
      for (int j = 0; j < nv; ++j)
        for (int c = 0; c < 3; ++c) out.poles[3 * (static_cast<size_t>(i) * nv + j) + c] = point(i, j, c);
  };
  if (const auto* b = std::get_if<BSplineNet>(&net)) {
    out.s.kind = BPDE_STEP_BSPLINE;
    std::vector<std::vector<Pole>> rows(b->nu(), std::vector<Pole>(b->nv()));  // [i][j]
    for (int i = 0; i < b->nu(); ++i)
      for (int j = 0; j < b->nv(); ++j)
        for (int c = 0; c < 3; ++c) rows[i][j][c] = b->points()(b->index(i, j), c);
    out.ku = b->knots_u(), out.kv = b->knots_v();
    lower_full_multiplicity(out.ku, rows, b->p(), "u");
    std::vector<std::vector<Pole>> cols = transposed(rows);
    lower_full_multiplicity(out.kv, cols, b->q(), "v");
    rows = transposed(cols);
    fill(static_cast<int>(rows.size()), rows.empty() ? 0 : static_cast<int>(rows[0].size()),
         [&](int i, int j, int c) { return rows[i][j][c]; });
    out.s.p = b->p(), out.s.q = b->q();
    out.s.knots_u = out.ku.data(), out.s.knots_v = out.kv.data();
  } else {
    const TensorNet t = std::holds_alternative<TensorNet>(net) ? std::get<TensorNet>(net)
                                                               : tensor_form(std::get<TriangularNet>(net));
    out.s.kind = BPDE_STEP_BEZIER;
    fill(t.n() + 1, t.m() + 1, [&](int i, int j, int c) { return t.points()(t.index(i, j), c); });
  }
  out.s.poles = out.poles.data();
  return out;
}

}  // namespace

std::vector<std::string> step_plugin_candidates() {
  if (const char* env = std::getenv("BPDE_STEP_PLUGIN"); env && *env) return {env};
  std::vector<std::string> out;
  auto add = [&](const fs::path& folder) {
    if (folder.empty()) return;
    const std::string p = (folder / BPDE_STEP_PLUGIN_NAME).lexically_normal().string();
    for (const std::string& q : out)
      if (q == p) return;
    out.push_back(p);
  };
  const fs::path own = own_folder();
  add(own);
#ifdef BPDE_STEP_PLUGIN_INSTALL_LIBDIR
  if (!own.empty()) add(own.parent_path() / BPDE_STEP_PLUGIN_INSTALL_LIBDIR);
#endif
#ifdef BPDE_STEP_PLUGIN_INSTALL_DIR
  add(BPDE_STEP_PLUGIN_INSTALL_DIR);
#endif
#ifdef BPDE_STEP_PLUGIN_BUILD_DIR
  add(BPDE_STEP_PLUGIN_BUILD_DIR);
#endif
  return out;
}

std::string step_plugin_path() { return plugin().path; }

void write_step(const std::string& path, const Net& net) {
  check_step_degree(net, "write_step");
  const Plugin& p = plugin();
  const Surface s = surface_of(net);
  // Into a temporary beside the target, renamed onto it only when complete: a failed write (a
  // full disk, a file-size limit) leaves an existing target as it was.
  replace_file_atomically(path, [&](const std::string& tmp) {
    char message[512] = {0};
    switch (p.write(&s.s, tmp.c_str(), message, sizeof message)) {
      case BPDE_STEP_OK:
        return;
      case BPDE_STEP_FILE:
        throw FileError("cannot write file '" + path + "'");
      default:
        throw InternalError("STEP export: " + std::string(message) + " (" + net_kind(net) + " net)");
    }
  });
}

void write_step(const std::string& path, const PatchComplex& c) {
  validate(c);
  const int n = c.patches.front().degree;
  if (n > kMaxStepDegree)
    throw DegreeError("write_step: STEP export: degree " + std::to_string(n) + " is above OpenCASCADE's largest degree " +
                      std::to_string(kMaxStepDegree));
  const Plugin& p = plugin();
  std::vector<Surface> surfaces;
  surfaces.reserve(c.patches.size());
  for (int k = 0; k < static_cast<int>(c.patches.size()); ++k)
    surfaces.push_back(c.patches[k].kind == PatchKind::triangular ? surface_of(triangular_net(c, k))
                                                                  : surface_of(tensor_net(c, k)));
  std::vector<bpde_step_surface> s;
  for (const Surface& surface : surfaces) s.push_back(surface.s);
  const double diag = (c.points.colwise().maxCoeff() - c.points.colwise().minCoeff()).norm();
  const double tolerance = kStepSewingTolerance * std::max(1.0, diag);
  replace_file_atomically(path, [&](const std::string& tmp) {
    char message[512] = {0};
    switch (p.write_shell(s.data(), static_cast<int>(s.size()), tolerance, tmp.c_str(), message, sizeof message)) {
      case BPDE_STEP_OK:
        return;
      case BPDE_STEP_FILE:
        throw FileError("cannot write file '" + path + "'");
      default:
        throw InternalError("STEP export: " + std::string(message) + " (patch complex)");
    }
  });
}

StepTopology read_step_topology(const std::string& path) {
  const Plugin& p = plugin();
  bpde_step_topology t{};
  char message[512] = {0};
  const int status = p.topology(path.c_str(), &t, message, sizeof message);
  if (status == BPDE_STEP_FILE) throw FileError("cannot read STEP file '" + path + "'");
  if (status != BPDE_STEP_OK) throw InternalError("STEP read: " + std::string(message));
  StepTopology out;
  out.valid = t.valid != 0;
  out.solids = t.solids, out.shells = t.shells, out.faces = t.faces, out.edges = t.edges;
  out.free_edges = t.free_edges, out.degenerate_edges = t.degenerate_edges;
  return out;
}

StepReadBack read_step(const std::string& path, const Eigen::MatrixX2d& uv) {
  const Plugin& p = plugin();
  const Eigen::Matrix<double, Eigen::Dynamic, 2, Eigen::RowMajor> pairs = uv;
  Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor> points(uv.rows(), 3);
  points.setZero();
  bpde_step_readback r{};
  char message[512] = {0};
  const int status = p.read(path.c_str(), pairs.data(), static_cast<long>(uv.rows()), &r, points.data(), message,
                            sizeof message);
  if (status == BPDE_STEP_FILE) throw FileError("cannot read STEP file '" + path + "'");
  if (status != BPDE_STEP_OK) throw InternalError("STEP read: " + std::string(message));
  StepReadBack out;
  out.faces = r.faces;
  out.points = points;
  if (r.faces == 0) return out;
  out.surface = r.surface == 0 ? "bezier" : r.surface == 1 ? "bspline" : "other";
  out.u_degree = r.u_degree, out.v_degree = r.v_degree;
  out.u0 = r.u0, out.u1 = r.u1, out.v0 = r.v0, out.v1 = r.v1;
  return out;
}

}  // namespace bpde
