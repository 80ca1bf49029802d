#pragma once
// The C interface of the STEP plugin, bpde_step_plugin.so: the one module that links OpenCASCADE
// (io/step_plugin.cpp). The library (io/step_export.cpp) opens it with dlopen on the first STEP
// write or read, so that a process that writes no STEP file never loads OpenCASCADE (its
// libraries carry most of the symbol relocations of a process that links them; docs/performance.md,
// "Start-up"). Plain C types only: the plugin links no bezierpde library and throws nothing across
// this boundary; the library turns its status codes into the typed exceptions of io/step_export.h.
//
// Poles: pole (i, j) (i along u, j along v) at poles[3 * (i * nv + j) + c], c = x, y, z.
#include <stddef.h>

extern "C" {

/// Raised whenever a struct or a function below changes: the library refuses a plugin whose
/// bpde_step_plugin_abi() differs (a plugin of another build).
#define BPDE_STEP_PLUGIN_ABI 2

enum bpde_step_kind { BPDE_STEP_BEZIER = 0, BPDE_STEP_BSPLINE = 1 };

/// A surface to write: a Bézier patch on [0,1]^2 (degrees nu - 1, nv - 1) or a B-spline surface
/// of degrees (p, q) with full knot vectors knots_u (nu + p + 1 values) and knots_v (nv + q + 1).
struct bpde_step_surface {
  int kind;
  int nu, nv;
  const double* poles;
  int p, q;
  const double* knots_u;
  const double* knots_v;
};

/// Status codes of the functions below; `message` (of `size` bytes) then holds the reason.
enum bpde_step_status {
  BPDE_STEP_OK = 0,
  BPDE_STEP_REFUSED = 1,  ///< OpenCASCADE refused the surface or the transfer (an internal failure)
  BPDE_STEP_FILE = 2      ///< the file cannot be written or read
};

/// What a STEP file holds (io/step_export.h StepReadBack); surface: 0 Bézier, 1 B-spline, 2 other.
struct bpde_step_readback {
  int faces;
  int surface;
  int u_degree, v_degree;
  double u0, u1, v0, v1;
};

/// The topology of a STEP file's shape, as OpenCASCADE reads it back (io/step_export.h
/// StepTopology): `valid` is BRepCheck_Analyzer's verdict (1 valid); shapes counted once each;
/// `free_edges` are the edges of exactly one face that are not degenerate (a face's boundary not
/// shared with another face), `degenerate_edges` the edges collapsed to a point.
struct bpde_step_topology {
  int valid;
  int solids, shells, faces, edges, free_edges, degenerate_edges;
};

typedef int (*bpde_step_abi_fn)(void);
typedef int (*bpde_step_write_fn)(const bpde_step_surface* s, const char* path, char* message, size_t size);
/// Reads `path`; for the first face, the surface's points at the `rows` parameter pairs uv[2k],
/// uv[2k+1] go to points[3k..3k+2] (untouched when the file has no face).
typedef int (*bpde_step_read_fn)(const char* path, const double* uv, long rows, bpde_step_readback* out,
                                 double* points, char* message, size_t size);

/// Writes the `count` surfaces as one shape: one face per surface, sewn with BRepBuilderAPI_Sewing
/// at `tolerance` into a shell (a connected surface; a compound of shells otherwise).
typedef int (*bpde_step_write_shell_fn)(const bpde_step_surface* s, int count, double tolerance, const char* path,
                                        char* message, size_t size);
typedef int (*bpde_step_topology_fn)(const char* path, bpde_step_topology* out, char* message, size_t size);

int bpde_step_plugin_abi(void);
int bpde_step_plugin_write_shell(const bpde_step_surface* s, int count, double tolerance, const char* path,
                                 char* message, size_t size);
int bpde_step_plugin_topology(const char* path, bpde_step_topology* out, char* message, size_t size);
int bpde_step_plugin_write(const bpde_step_surface* s, const char* path, char* message, size_t size);
int bpde_step_plugin_read(const char* path, const double* uv, long rows, bpde_step_readback* out, double* points,
                          char* message, size_t size);
}
