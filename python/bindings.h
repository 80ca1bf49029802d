// Shared declarations of the pybind11 module bezierpde._core (python/module.cpp): one bind_<topic>
// per file python/bind_<topic>.cpp, and the conversions every topic uses (python/bindings.cpp).
// Every binding file includes this header first, so all of them see the same pybind11 type
// casters (Eigen, STL, std::function, numpy).
#pragma once

#include <pybind11/eigen.h>
#include <pybind11/functional.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include "bezierpde/core/eigen.h"

#include <optional>
#include <string>
#include <type_traits>
#include <utility>

#include "bezierpde/core/errors.h"
#include "bezierpde/core/fixed_set.h"
#include "bezierpde/core/mesh.h"
#include "bezierpde/core/progress.h"
#include "bezierpde/energies/energy_spec.h"
#include "bezierpde/io/json_io.h"
#include "bezierpde/core/interruption.h"
#include "bezierpde/jobs/job_progress.h"
#include "bezierpde/solvers/requirements.h"

namespace bpde::python {

namespace py = pybind11;

// The module's contents by topic, registered in this order by PYBIND11_MODULE: a class is
// registered before the functions whose signatures or default arguments name it.
void bind_errors(py::module_& m);    // the exception hierarchy of core/errors.h
void bind_summary(py::module_& m);   // Status and Summary (solvers/summary.h)
void bind_nets(py::module_& m);      // TensorNet, TriangularNet, BSplineNet, net_from_dict
void bind_jobs(py::module_& m);      // the command contract: solve_result, sample, energy, check, ...
void bind_pde(py::module_& m);       // polynomial PDE solutions (solvers/pde/) and C1 surfaces (solvers/c1/)
void bind_cmc(py::module_& m);       // CmcOptions, CmcResult*, solve_cmc (solvers/cmc/cmc.h)
void bind_extremal(py::module_& m);  // extremals of quadratic energies (solvers/extremal.h)
void bind_bspline(py::module_& m);   // B-spline extremals and PDE solutions (solvers/bspline/)
void bind_blend(py::module_& m);     // smoothing PDE splines (solvers/blend/smoothing_spline.h)
void bind_sweep(py::module_& m);     // sweeps (jobs/sweep.h)
void bind_complex(py::module_& m);   // patch complexes (complex/, solvers/complex/, solvers/cmc/complex_cmc.h)

// ------------------------------------------------------------------ dict <-> JSON
// One-to-one: bool, int, float, str, None, list/tuple, dict with str keys. Floats keep every bit
// (nlohmann stores the double); non-finite floats are refused as the JSON files refuse them.
// `what` names the argument in the messages (ParseError, NonFiniteError, SizeError beyond
// kMaxJsonDepth levels).
Json to_json(py::handle h, const std::string& what, int depth = 0);
py::object from_json(const Json& j);

// ------------------------------------------------------------------ Ctrl-C and the limits
// A progress callback (core/progress.h) that lets Ctrl-C stop long C++ work called from Python
// with the GIL released: at most every 50 ms it takes the GIL and runs Python's signal handlers
// (PyErr_CheckSignals, which acts on the main thread only); when one raises (KeyboardInterrupt),
// the exception leaves the solver as py::error_already_set and reaches the caller as that Python
// exception. `inner` (the progress a caller installed) is called as before.
bpde::ProgressFn interruptible(bpde::ProgressFn inner = {});

// Installs an interruption check (core/interruption.h) that runs Python's signal handlers as
// interruptible() does, for the C++ work of this thread while it lives: the dense and sparse
// factorisations (extremals, tetraharmonic and biharmonic-load operators, the blend) stop on
// Ctrl-C at their interruption points. A call guard of the solver entry points.
class InterruptibleSolve {
 public:
  InterruptibleSolve();

 private:
  bpde::InterruptionScope scope_;
};

// Installs interruptible(the current job progress) for the jobs run on this thread while it lives
// (jobs/job_progress.h): the cmc continuation and the other long stages check for signals, and
// the factorisations at their interruption points (InterruptibleSolve).
class InterruptibleJobs {
 public:
  InterruptibleJobs() : scope_(interruptible(bpde::job_progress())) {}

 private:
  bpde::JobProgressScope scope_;
  InterruptibleSolve solve_;
};

// The limits of FORMATS.md "Input limits" that a job checks before it runs (the degrees of the
// solver's requirements), checked for a solver entry point called directly: the same typed
// errors (DegreeError, UnsupportedProblem) as the command's exit 2, the message starting with
// `where` (the Python function's name).
void check_limits(const bpde::SolverRequirements& r, const bpde::NetShape& shape, bpde::FixedSet fixed,
                  const std::string& method, const std::string& where);

// ------------------------------------------------------------------ numpy arrays owning Eigen storage
template <class M>
py::array adopt(M&& m) {
  using Mat = std::decay_t<M>;
  using S = typename Mat::Scalar;
  auto* p = new Mat(std::move(m));
  py::capsule owner(p, [](void* q) { delete static_cast<Mat*>(q); });
  if constexpr (Mat::ColsAtCompileTime == 1) {
    return py::array_t<S>({static_cast<py::ssize_t>(p->size())}, {static_cast<py::ssize_t>(sizeof(S))}, p->data(),
                          owner);
  } else {
    const auto r = static_cast<py::ssize_t>(p->rows()), c = static_cast<py::ssize_t>(p->cols());
    return py::array_t<S>({r, c}, {static_cast<py::ssize_t>(sizeof(S)), static_cast<py::ssize_t>(sizeof(S)) * r},
                          p->data(), owner);
  }
}

// (V, F, H) arrays owning the mesh's buffers.
py::tuple mesh_tuple(TriangleMesh&& mesh);

// ------------------------------------------------------------------ arguments
// A str argument, taken as any object by the binding (Text below) and converted in the function
// body by text(), so that a wrong type or a str that is not valid Unicode (a lone surrogate, which
// UTF-8 cannot hold) raises ParseError naming the argument instead of pybind11's TypeError.
struct Text {
  py::object value;
};
// The UTF-8 of a str; ParseError naming `what` for a non-str or a lone surrogate.
std::string text(py::handle h, const std::string& what);
inline std::string text(const Text& t, const std::string& what) { return text(t.value, what); }
// A file or folder path: a str or an os.PathLike whose path is a str (as text()).
std::string path_text(const Text& t, const std::string& what);
inline std::optional<std::string> path_text(const std::optional<Text>& t, const std::string& what) {
  if (!t) return std::nullopt;
  return path_text(*t, what);
}

// A net from a TensorNet, TriangularNet or BSplineNet object, or from a NET dict.
Net net_arg(py::handle h);
// The Python object of a net (its class).
py::object net_object(Net&& net);
// "boundary", "boundary+adjacent" or "u-boundaries"; ParameterError otherwise.
FixedSet parse_fixed(const std::string& s);
// An energy or operator from its name or an ENERGY dict.
EnergySpec energy_arg(py::handle h);

// A rows x C matrix of S (float64 by default; int for triangle indices) from an array (or nested
// list) argument: SizeError naming `what` on a wrong shape (pybind11's Eigen caster would raise a
// TypeError), ParseError on non-numbers. Fortran-ordered input of type S is read in place; other
// input is converted once by numpy.
template <int C, class S = double>
Eigen::Matrix<S, Eigen::Dynamic, C> points_arg(py::handle h, const std::string& what, Eigen::Index rows = -1) {
  using Array = py::array_t<S, py::array::f_style | py::array::forcecast>;
  const Array a = Array::ensure(h);
  if (!a) throw bpde::ParseError(what + ": expected an array of numbers");
  const auto expected = [&] {
    return what + ": expected an array of shape (" + (rows >= 0 ? std::to_string(rows) : std::string("N")) + ", " +
           std::to_string(C) + "), got shape " + py::repr(a.attr("shape")).template cast<std::string>();
  };
  if (a.ndim() != 2 || a.shape(1) != C || (rows >= 0 && a.shape(0) != rows)) throw bpde::SizeError(expected());
  return Eigen::Map<const Eigen::Matrix<S, Eigen::Dynamic, C>>(a.data(), a.shape(0), C);
}

// NonFiniteError naming `what`, the row and the column of the first NaN or infinite entry.
void require_finite(const Eigen::Ref<const Eigen::MatrixXd>& P, const std::string& what);

}  // namespace bpde::python

namespace pybind11::detail {
// Any object loads as a Text (shown as `str` in signatures); text() checks it.
template <>
struct type_caster<bpde::python::Text> {
  PYBIND11_TYPE_CASTER(bpde::python::Text, const_name("str"));
  bool load(handle src, bool) {
    if (!src) return false;
    value.value = reinterpret_borrow<object>(src);
    return true;
  }
  static handle cast(const bpde::python::Text& t, return_value_policy, handle) { return t.value.inc_ref(); }
};
}  // namespace pybind11::detail
