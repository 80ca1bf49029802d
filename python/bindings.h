// Shared declarations of the pybind11 module bezierpde._core (python/module.cpp): one bind_<topic>
// per file python/bind_<topic>.cpp, and the conversions every topic uses (python/bindings.cpp).
// Every binding file includes this header first, so all of them see the same pybind11 type
// casters (Eigen, STL, std::function, numpy).
#pragma once

#include "bezierpde/core/eigen.h"
#include <pybind11/eigen.h>
#include <pybind11/functional.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <string>
#include <type_traits>
#include <utility>

#include "bezierpde/core/errors.h"
#include "bezierpde/core/fixed_set.h"
#include "bezierpde/core/mesh.h"
#include "bezierpde/energies/energy_spec.h"
#include "bezierpde/io/json_io.h"

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

// ------------------------------------------------------------------ dict <-> JSON
// One-to-one: bool, int, float, str, None, list/tuple, dict with str keys. Floats keep every bit
// (nlohmann stores the double); non-finite floats are refused as the JSON files refuse them.
Json to_json(py::handle h, int depth = 0);
py::object from_json(const Json& j);

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
// A net from a TensorNet, TriangularNet or BSplineNet object, or from a NET dict.
Net net_arg(py::handle h);
// The Python object of a net (its class).
py::object net_object(Net&& net);
// "boundary", "boundary+adjacent" or "u-boundaries"; ParameterError otherwise.
FixedSet parse_fixed(const std::string& s);
// An energy or operator from its name or an ENERGY dict.
EnergySpec energy_arg(py::handle h);

// A rows x C float64 matrix from an array (or nested list) argument: SizeError naming `what` on a
// wrong shape (pybind11's Eigen caster would raise a TypeError), ParseError on non-numbers. Float64
// Fortran-ordered input is read in place; other input is converted once by numpy.
template <int C>
Eigen::Matrix<double, Eigen::Dynamic, C> points_arg(py::handle h, const std::string& what, Eigen::Index rows = -1) {
  using Array = py::array_t<double, py::array::f_style | py::array::forcecast>;
  const Array a = Array::ensure(h);
  if (!a) throw bpde::ParseError(what + ": expected an array of numbers");
  const auto expected = [&] {
    return what + ": expected an array of shape (" + (rows >= 0 ? std::to_string(rows) : std::string("N")) + ", " +
           std::to_string(C) + "), got shape " + py::repr(a.attr("shape")).cast<std::string>();
  };
  if (a.ndim() != 2 || a.shape(1) != C || (rows >= 0 && a.shape(0) != rows)) throw bpde::SizeError(expected());
  return Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, C>>(a.data(), a.shape(0), C);
}

}  // namespace bpde::python
