// bezierpde._core: the pybind11 module behind the Python package `bezierpde` (python/bezierpde/).
//
// The command contract from Python: solve, sample, energy, check, plate, blend take and return the
// same JSON as `bpde` (Python dicts, converted one-to-one to nlohmann::json: numbers keep every
// bit), and go through jobs/ as the command does. The nets are classes over the C++ nets (points
// as N x 3 numpy views of the net's own storage), meshes are (V, F, H) numpy arrays that own the
// C++ buffers (no copy), and the main solver entry points come with their Options and Summary.
// Errors: the typed exceptions of core/errors.h become one Python hierarchy
//   bezierpde.Error(Exception)
//     bezierpde.InvalidInput(Error, ValueError)  ParseError, FileError, DegreeError, SizeError,
//                                                NonFiniteError, ParameterError, UnsupportedProblem
//     bezierpde.InternalError(Error, RuntimeError)
// std::bad_alloc is MemoryError. The GIL is released while C++ runs.
//
// One file per topic registers its part (bindings.h); the order below matters: a class is
// registered before the functions whose signatures or default arguments name it.
#include "bindings.h"

#include "bezierpde/solvers/cmc/ceres_log.h"

PYBIND11_MODULE(_core, m) {
  m.doc() = "bezierpde: Bézier surfaces from boundary data by energies and PDEs (C++ core).";
  m.attr("__version__") = BPDE_VERSION;
  bpde::quiet_ceres_log();  // no glog lines from Ceres on the interpreter's stderr (ceres_log.h)

  using namespace bpde::python;
  bind_errors(m);
  bind_summary(m);
  bind_nets(m);
  bind_jobs(m);
  bind_pde(m);
  bind_cmc(m);
  bind_extremal(m);
  bind_bspline(m);
  bind_blend(m);
  bind_sweep(m);
  bind_complex(m);
}
