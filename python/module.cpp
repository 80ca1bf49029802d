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
#include "bezierpde/core/eigen.h"
#include <pybind11/eigen.h>
#include <pybind11/functional.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <cmath>
#include <limits>
#include <optional>
#include <string>

#include "bezierpde/core/errors.h"
#include "bezierpde/core/fixed_set.h"
#include "bezierpde/core/mesh.h"
#include "bezierpde/io/blend_config.h"
#include "bezierpde/io/job.h"
#include "bezierpde/io/json_io.h"
#include "bezierpde/io/mesh_io.h"
#include "bezierpde/jobs/run_blend.h"
#include "bezierpde/jobs/run_energy.h"
#include "bezierpde/jobs/run_job.h"
#include "bezierpde/jobs/run_plate.h"
#include "bezierpde/jobs/sweep.h"
#include "bezierpde/solvers/blend/smoothing_spline.h"
#include "bezierpde/solvers/bspline/bspline_extremal.h"
#include "bezierpde/solvers/bspline/bspline_pde.h"
#include "bezierpde/solvers/c1/clamped_plate.h"
#include "bezierpde/solvers/c1/tetraharmonic.h"
#include "bezierpde/solvers/cmc/cmc.h"
#include "bezierpde/solvers/extremal.h"
#include "bezierpde/solvers/cmc/ceres_log.h"
#include "bezierpde/solvers/pde/pde_explicit.h"
#include "bezierpde/solvers/pde/pde_lu.h"
#include "bezierpde/solvers/summary.h"

namespace py = pybind11;
using bpde::Json;

namespace {

// ------------------------------------------------------------------ dict <-> JSON
// One-to-one: bool, int, float, str, None, list/tuple, dict with str keys. Floats keep every bit
// (nlohmann stores the double); non-finite floats are refused as the JSON files refuse them.
Json to_json(py::handle h, int depth = 0) {
  if (depth > bpde::kMaxJsonDepth)
    throw bpde::SizeError("JSON input nested deeper than " + std::to_string(bpde::kMaxJsonDepth) + " levels");
  if (h.is_none()) return nullptr;
  if (py::isinstance<py::bool_>(h)) return h.cast<bool>();
  if (py::isinstance<py::int_>(h)) {
    try {
      return h.cast<long long>();
    } catch (const py::cast_error&) {
      throw bpde::ParseError("integer out of range: " + py::str(h).cast<std::string>());
    }
  }
  if (py::isinstance<py::float_>(h)) {
    const double x = h.cast<double>();
    if (!std::isfinite(x)) throw bpde::NonFiniteError("a number is not finite (JSON has no NaN or infinity)");
    return x;
  }
  if (py::isinstance<py::str>(h)) return h.cast<std::string>();
  if (py::isinstance<py::dict>(h)) {
    Json j = Json::object();
    for (auto item : h.cast<py::dict>()) {
      if (!py::isinstance<py::str>(item.first)) throw bpde::ParseError("a JSON object key must be a str");
      j[item.first.cast<std::string>()] = to_json(item.second, depth + 1);
    }
    return j;
  }
  if (py::isinstance<py::list>(h) || py::isinstance<py::tuple>(h)) {
    Json j = Json::array();
    for (auto v : h) j.push_back(to_json(v, depth + 1));
    return j;
  }
  // numpy scalars and arrays: through their Python values.
  if (py::hasattr(h, "tolist")) return to_json(h.attr("tolist")(), depth + 1);
  throw bpde::ParseError("cannot convert a Python " + py::str(h.get_type().attr("__name__")).cast<std::string>() +
                         " to JSON");
}

py::object from_json(const Json& j) {
  switch (j.type()) {
    case Json::value_t::null:
      return py::none();
    case Json::value_t::boolean:
      return py::bool_(j.get<bool>());
    case Json::value_t::number_integer:
      return py::int_(j.get<long long>());
    case Json::value_t::number_unsigned:
      return py::int_(j.get<unsigned long long>());
    case Json::value_t::number_float:
      return py::float_(j.get<double>());
    case Json::value_t::string:
      return py::str(j.get<std::string>());
    case Json::value_t::array: {
      py::list l;
      for (const Json& v : j) l.append(from_json(v));
      return l;
    }
    case Json::value_t::object: {
      py::dict d;
      for (auto it = j.begin(); it != j.end(); ++it) d[py::str(it.key())] = from_json(it.value());
      return d;
    }
    default:
      throw bpde::InternalError("JSON value of an unexpected type");
  }
}

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

py::tuple mesh_tuple(bpde::TriangleMesh&& mesh) {
  return py::make_tuple(adopt(std::move(mesh.V)), adopt(std::move(mesh.F)), adopt(std::move(mesh.H)));
}

// ------------------------------------------------------------------ nets
bpde::Net net_arg(py::handle h) {
  if (py::isinstance<bpde::TensorNet>(h)) return h.cast<bpde::TensorNet>();
  if (py::isinstance<bpde::TriangularNet>(h)) return h.cast<bpde::TriangularNet>();
  if (py::isinstance<bpde::BSplineNet>(h)) return h.cast<bpde::BSplineNet>();
  const Json j = to_json(h);
  return bpde::net_from_json(j, "net");
}

py::object net_object(bpde::Net&& net) {
  return std::visit([](auto&& n) -> py::object { return py::cast(std::move(n)); }, std::move(net));
}

bpde::FixedSet parse_fixed(const std::string& s) {
  if (s == "boundary") return bpde::FixedSet::Boundary;
  if (s == "boundary+adjacent") return bpde::FixedSet::BoundaryAdjacent;
  if (s == "u-boundaries") return bpde::FixedSet::UBoundaries;
  throw bpde::ParameterError("fixed: expected \"boundary\", \"boundary+adjacent\" or \"u-boundaries\", got \"" + s +
                             "\"");
}

bpde::EnergySpec energy_arg(py::handle h) {
  if (py::isinstance<py::str>(h)) return bpde::energy_from_argument(h.cast<std::string>());
  return bpde::energy_from_json(to_json(h), "operator", true);
}

template <class NetT>
void set_points(NetT& net, const Eigen::Ref<const Eigen::MatrixX3d>& P) {
  if (P.rows() != net.points().rows())
    throw bpde::SizeError("points: expected " + std::to_string(net.points().rows()) + " x 3, got " +
                          std::to_string(P.rows()) + " x 3");
  net.points() = P;
}

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

// A matrix field of a C++ struct as a property: a read-only numpy view of it, set from any array
// of shape (N, C) (SizeError otherwise).
template <int C, auto Field, class T>
void matrix_field(py::class_<T>& c, const char* name, const char* doc) {
  c.def_property(
      name, [](const T& t) -> const Eigen::Matrix<double, Eigen::Dynamic, C>& { return t.*Field; },
      [name](T& t, py::handle a) { t.*Field = points_arg<C>(a, name); }, py::return_value_policy::reference_internal,
      doc);
}

// ------------------------------------------------------------------ the command contract
// result.json's object for a job (the report completed with mean_curvature and check, as
// write_result completes it), written to `out` when given.
Json solve_result(const Json& job_json, const std::optional<std::string>& out) {
  const bpde::Job job = bpde::job_from_json(job_json, "job");
  const bpde::SolveOutcome outcome = bpde::run_job(job);
  if (out) return bpde::write_job_result(*out, job, outcome).result;
  const bpde::TriangleMesh mesh = bpde::sample_net(outcome.net, job.samples);
  Json report = outcome.report;
  if (!report.contains("mean_curvature"))
    report["mean_curvature"] = bpde::mean_curvature_stats(outcome.net, mesh, job.samples);
  if (!report.contains("check")) report["check"] = bpde::check_report(mesh);
  Json result = {{"net", bpde::net_to_json(outcome.net)}, {"report", report}};
  for (auto it = outcome.extra.begin(); it != outcome.extra.end(); ++it) result[it.key()] = it.value();
  return result;
}

void check_samples(int samples) {
  if (samples < 1 || samples > bpde::kMaxSamples)
    throw bpde::ParameterError("samples must be in 1.." + std::to_string(bpde::kMaxSamples) + ", got " +
                               std::to_string(samples));
}

// ------------------------------------------------------------------ exceptions
PyObject* new_exception(py::module_& m, const char* name, py::handle bases, const char* doc) {
  const std::string qualified = std::string("bezierpde.") + name;
  PyObject* e = PyErr_NewExceptionWithDoc(qualified.c_str(), doc, bases.ptr(), nullptr);
  if (!e) throw py::error_already_set();
  m.add_object(name, py::handle(e));
  return e;
}

}  // namespace

PYBIND11_MODULE(_core, m) {
  m.doc() = "bezierpde: Bézier surfaces from boundary data by energies and PDEs (C++ core).";
  m.attr("__version__") = BPDE_VERSION;
  bpde::quiet_ceres_log();  // no glog lines from Ceres on the interpreter's stderr (ceres_log.h)

  // Exceptions (one hierarchy, mirroring core/errors.h).
  static PyObject* Error = new_exception(m, "Error", PyExc_Exception, "Every error of bezierpde.");
  static PyObject* InvalidInput =
      new_exception(m, "InvalidInput", py::make_tuple(py::handle(Error), py::handle(PyExc_ValueError)),
                    "Bad input (the command's exit 2).");
  static PyObject* ParseError =
      new_exception(m, "ParseError", InvalidInput, "Malformed JSON or a field of the wrong type.");
  static PyObject* FileError = new_exception(m, "FileError", InvalidInput, "A file that cannot be read or written.");
  static PyObject* DegreeError = new_exception(m, "DegreeError", InvalidInput, "A degree the problem does not take.");
  static PyObject* SizeError =
      new_exception(m, "SizeError", InvalidInput, "A wrong number of points or an input too large.");
  static PyObject* NonFiniteError = new_exception(m, "NonFiniteError", InvalidInput, "A NaN or infinite number.");
  static PyObject* ParameterError = new_exception(m, "ParameterError", InvalidInput, "A parameter out of its range.");
  static PyObject* UnsupportedProblem =
      new_exception(m, "UnsupportedProblem", InvalidInput, "A combination of net, data and problem no solver takes.");
  static PyObject* InternalError =
      new_exception(m, "InternalError", py::make_tuple(py::handle(Error), py::handle(PyExc_RuntimeError)),
                    "A broken invariant (the command's exit 3), never bad input.");
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const bpde::ParseError& e) {
      PyErr_SetString(ParseError, e.what());
    } catch (const bpde::FileError& e) {
      PyErr_SetString(FileError, e.what());
    } catch (const bpde::DegreeError& e) {
      PyErr_SetString(DegreeError, e.what());
    } catch (const bpde::SizeError& e) {
      PyErr_SetString(SizeError, e.what());
    } catch (const bpde::NonFiniteError& e) {
      PyErr_SetString(NonFiniteError, e.what());
    } catch (const bpde::ParameterError& e) {
      PyErr_SetString(ParameterError, e.what());
    } catch (const bpde::UnsupportedProblem& e) {
      PyErr_SetString(UnsupportedProblem, e.what());
    } catch (const bpde::InvalidInput& e) {
      PyErr_SetString(InvalidInput, e.what());
    } catch (const bpde::InternalError& e) {
      PyErr_SetString(InternalError, e.what());
    } catch (const bpde::Error& e) {
      PyErr_SetString(Error, e.what());
    } catch (const nlohmann::json::exception& e) {
      PyErr_SetString(InternalError, e.what());
    }
  });

  // Status and Summary (solvers/summary.h).
  py::enum_<bpde::Status>(m, "Status", "Why a solve ended (solvers/summary.h).")
      .value("Converged", bpde::Status::Converged)
      .value("NotUnique", bpde::Status::NotUnique)
      .value("Incompatible", bpde::Status::Incompatible)
      .value("Fold", bpde::Status::Fold)
      .value("NoConvergence", bpde::Status::NoConvergence)
      .value("NumericalLimit", bpde::Status::NumericalLimit)
      .def_property_readonly(
          "text", [](bpde::Status s) { return std::string(bpde::to_string(s)); },
          "The FORMATS.md name: \"converged\", \"fold\", ...");
  py::class_<bpde::Summary>(m, "Summary",
                            "How a solve ended: status, converged, iterations, residual, message, seconds.")
      .def(py::init<>())
      .def_readonly("status", &bpde::Summary::status)
      .def_readonly("converged", &bpde::Summary::converged)
      .def_readonly("iterations", &bpde::Summary::iterations)
      .def_readonly("residual", &bpde::Summary::residual)
      .def_readonly("message", &bpde::Summary::message)
      .def_readonly("seconds", &bpde::Summary::seconds)
      .def("__repr__", [](const bpde::Summary& s) {
        return "Summary(status=" + std::string(bpde::to_string(s.status)) +
               ", iterations=" + std::to_string(s.iterations) +
               ", residual=" + py::repr(py::float_(s.residual)).cast<std::string>() +
               (s.message.empty() ? "" : ", message=" + py::repr(py::str(s.message)).cast<std::string>()) + ")";
      });

  // Nets. `points` is a writable N x 3 view of the net's storage (no copy).
  py::class_<bpde::TensorNet>(m, "TensorNet", "Tensor Bézier net of degree (n, m); points row i*(m+1)+j, N x 3.")
      .def(py::init<int, int>(), py::arg("n"), py::arg("m"))
      .def(py::init<int, int, Eigen::MatrixX3d>(), py::arg("n"), py::arg("m"), py::arg("points"))
      .def_property_readonly("n", &bpde::TensorNet::n)
      .def_property_readonly("m", &bpde::TensorNet::m)
      .def_property(
          "points", [](bpde::TensorNet& n) -> Eigen::MatrixX3d& { return n.points(); },
          [](bpde::TensorNet& n, const Eigen::Ref<const Eigen::MatrixX3d>& P) { set_points(n, P); },
          py::return_value_policy::reference_internal)
      .def("evaluate", &bpde::TensorNet::evaluate, py::arg("u"), py::arg("v"))
      .def("to_dict", [](const bpde::TensorNet& n) { return from_json(bpde::net_to_json(n)); })
      .def("__repr__", [](const bpde::TensorNet& n) {
        return "TensorNet(n=" + std::to_string(n.n()) + ", m=" + std::to_string(n.m()) + ")";
      });
  py::class_<bpde::TriangularNet>(m, "TriangularNet",
                                  "Triangular Bézier net of degree n; points P_{n00} first, P_{00n} last, N x 3.")
      .def(py::init<int>(), py::arg("n"))
      .def(py::init<int, Eigen::MatrixX3d>(), py::arg("n"), py::arg("points"))
      .def_property_readonly("n", &bpde::TriangularNet::n)
      .def_property(
          "points", [](bpde::TriangularNet& n) -> Eigen::MatrixX3d& { return n.points(); },
          [](bpde::TriangularNet& n, const Eigen::Ref<const Eigen::MatrixX3d>& P) { set_points(n, P); },
          py::return_value_policy::reference_internal)
      .def("evaluate", &bpde::TriangularNet::evaluate, py::arg("u"), py::arg("v"))
      .def("to_dict", [](const bpde::TriangularNet& n) { return from_json(bpde::net_to_json(n)); })
      .def("__repr__", [](const bpde::TriangularNet& n) { return "TriangularNet(n=" + std::to_string(n.n()) + ")"; });
  py::class_<bpde::BSplineNet>(m, "BSplineNet",
                               "Tensor B-spline net of degree (p, q) over the knots (U, V) (FORMATS.md \"bspline\"); "
                               "points row i*nv + j, (nu*nv) x 3.")
      .def(py::init([](int p, int q, std::vector<double> U, std::vector<double> V, py::handle points) {
             // The point count is checked by the constructor, after the knots.
             return bpde::BSplineNet(p, q, std::move(U), std::move(V), points_arg<3>(points, "points"));
           }),
           py::arg("p"), py::arg("q"), py::arg("U"), py::arg("V"), py::arg("points"))
      .def_property_readonly("p", &bpde::BSplineNet::p)
      .def_property_readonly("q", &bpde::BSplineNet::q)
      .def_property_readonly("nu", &bpde::BSplineNet::nu)
      .def_property_readonly("nv", &bpde::BSplineNet::nv)
      .def_property_readonly("knots_u", &bpde::BSplineNet::knots_u)
      .def_property_readonly("knots_v", &bpde::BSplineNet::knots_v)
      .def_property(
          "points", [](bpde::BSplineNet& n) -> Eigen::MatrixX3d& { return n.points(); },
          [](bpde::BSplineNet& n, const Eigen::Ref<const Eigen::MatrixX3d>& P) { set_points(n, P); },
          py::return_value_policy::reference_internal)
      .def("evaluate", &bpde::BSplineNet::evaluate, py::arg("u"), py::arg("v"), "A point; (u, v) in the knot domain.")
      .def("derivative", &bpde::BSplineNet::derivative, py::arg("u"), py::arg("v"), py::arg("du"), py::arg("dv"))
      .def("to_dict", [](const bpde::BSplineNet& n) { return from_json(bpde::net_to_json(n)); })
      .def("__repr__", [](const bpde::BSplineNet& n) {
        return "BSplineNet(p=" + std::to_string(n.p()) + ", q=" + std::to_string(n.q()) +
               ", nu=" + std::to_string(n.nu()) + ", nv=" + std::to_string(n.nv()) + ")";
      });
  m.def(
      "net_from_dict", [](py::handle d) { return net_object(net_arg(d)); }, py::arg("net"),
      "A TensorNet, TriangularNet or BSplineNet from a NET dict (FORMATS.md \"Nets\").");

  // The command contract (same JSON as `bpde`).
  m.def(
      "solve_result",
      [](py::handle job, std::optional<std::string> out) {
        const Json j = to_json(job);
        Json result;
        {
          py::gil_scoped_release release;
          result = solve_result(j, out);
        }
        return from_json(result);
      },
      py::arg("job"), py::arg("out") = py::none(),
      "result.json of `bpde solve` for a JOB dict (written to `out` with the surface files when given).");
  m.def(
      "sample",
      [](py::handle net, int samples, std::optional<std::string> out) {
        const bpde::Net n = net_arg(net);
        check_samples(samples);
        bpde::TriangleMesh mesh;
        {
          py::gil_scoped_release release;
          mesh = bpde::sample_net(n, samples);
          if (out) {
            bpde::write_output_files(*out, nullptr, n, mesh);  // as `bpde sample`: all or nothing
          }
        }
        return mesh_tuple(std::move(mesh));
      },
      py::arg("net"), py::arg("samples") = 50, py::arg("out") = py::none(),
      "(V, F, H) of `bpde sample`: vertices (V x 3 float64), triangles (F x 3 int32), mean curvature per vertex.");
  m.def(
      "energy",
      [](py::handle net, const std::string& energy, std::optional<double> H) {
        const bpde::Net n = net_arg(net);
        Json r;
        {
          py::gil_scoped_release release;
          r = bpde::energy_report(n, energy, H);
        }
        return from_json(r);
      },
      py::arg("net"), py::arg("energy"), py::arg("H") = py::none(), "What `bpde energy` prints, as a dict.");
  m.def(
      "check",
      [](py::handle net, int samples) {
        const bpde::Net n = net_arg(net);
        check_samples(samples);
        Json r;
        {
          py::gil_scoped_release release;
          r = bpde::check_report(bpde::sample_net(n, samples));
        }
        return from_json(r);
      },
      py::arg("net"), py::arg("samples") = 50, "What `bpde check` prints, as a dict (CGAL figures).");
  m.def(
      "check_mesh",
      [](const Eigen::MatrixX3d& V, const Eigen::MatrixX3i& F) {
        Json r;
        {
          py::gil_scoped_release release;
          r = bpde::check_report(bpde::TriangleMesh{V, F, Eigen::VectorXd()});
        }
        return from_json(r);
      },
      py::arg("V"), py::arg("F"), "The CGAL figures of a mesh given as arrays.");
  m.def(
      "plate",
      [](double aspect, int degree, const std::string& method) {
        bpde::PlateOutcome out;
        {
          py::gil_scoped_release release;
          out = bpde::run_plate(aspect, degree, method);
        }
        return from_json(out.report);
      },
      py::arg("aspect"), py::arg("degree"), py::arg("method"), "What `bpde plate` prints, as a dict.");
  m.def(
      "blend_result",
      [](py::handle config, std::optional<std::string> out) {
        const bpde::BlendConfig c = bpde::blend_config_from_json(to_json(config));
        Json result;
        {
          py::gil_scoped_release release;
          const bpde::BlendOutcome o = bpde::run_blend(c);
          if (out) {
            bpde::write_blend_outcome(*out, c, o);
            result = bpde::read_json_file(*out + "/result.json");
          } else {
            Json report = o.report;
            const bpde::Net net(o.net);
            if (!report.contains("mean_curvature"))
              report["mean_curvature"] = bpde::mean_curvature_stats(net, o.mesh, c.samples);
            if (!report.contains("check")) report["check"] = bpde::check_report(o.mesh);
            result = {{"net", bpde::net_to_json(net)}, {"report", report}};
          }
        }
        return from_json(result);
      },
      py::arg("config"), py::arg("out") = py::none(), "result.json of `bpde blend` for a CONFIG dict.");

  // Solver entry points with their Options and Summary.
  py::class_<bpde::PdeExplicitOptions>(m, "PdeExplicitOptions")
      .def(py::init<>())
      .def_readwrite("singular_tolerance", &bpde::PdeExplicitOptions::singular_tolerance)
      .def_readwrite("rank_tolerance", &bpde::PdeExplicitOptions::rank_tolerance);
  py::class_<bpde::PdeLuOptions>(m, "PdeLuOptions")
      .def(py::init<>())
      .def_property(
          "formulation",
          [](const bpde::PdeLuOptions& o) {
            return o.formulation == bpde::PdeLuOptions::Formulation::Bernstein ? "bernstein" : "anti-diagonal";
          },
          [](bpde::PdeLuOptions& o, const std::string& s) {
            if (s == "bernstein")
              o.formulation = bpde::PdeLuOptions::Formulation::Bernstein;
            else if (s == "anti-diagonal")
              o.formulation = bpde::PdeLuOptions::Formulation::AntiDiagonal;
            else
              throw bpde::ParameterError("formulation: expected \"anti-diagonal\" or \"bernstein\", got \"" + s + "\"");
          })
      .def_readwrite("compatibility_tolerance", &bpde::PdeLuOptions::compatibility_tolerance)
      .def_readwrite("rank_tolerance", &bpde::PdeLuOptions::rank_tolerance);
  m.def(
      "solve_pde_explicit",
      [](const bpde::TensorNet& data, py::handle op, const bpde::PdeExplicitOptions& options) {
        const bpde::EnergySpec spec = energy_arg(op);
        py::gil_scoped_release release;
        bpde::PdeSolution s = bpde::solve_pde_explicit(data, spec, options);
        return std::make_pair(std::move(s.net), s.summary);
      },
      py::arg("data"), py::arg("operator"), py::arg("options") = bpde::PdeExplicitOptions(),
      "Explicit polynomial PDE solution (solvers/pde/pde_explicit.h) -> (TensorNet, Summary).");
  m.def(
      "solve_pde_lu",
      [](const bpde::TensorNet& data, py::handle op, const bpde::PdeLuOptions& options) {
        const bpde::EnergySpec spec = energy_arg(op);
        py::gil_scoped_release release;
        bpde::PdeSolution s = bpde::solve_pde_lu(data, spec, options);
        return std::make_pair(std::move(s.net), s.summary);
      },
      py::arg("data"), py::arg("operator"), py::arg("options") = bpde::PdeLuOptions(),
      "PDE solution by the block LU (solvers/pde/pde_lu.h) -> (TensorNet, Summary).");

  py::class_<bpde::CmcOptions>(m, "CmcOptions")
      .def(py::init<>())
      .def_readwrite("H", &bpde::CmcOptions::H)
      .def_readwrite("V", &bpde::CmcOptions::V)
      .def_property(
          "solver", [](const bpde::CmcOptions& o) { return bpde::to_string(o.solver); },
          [](bpde::CmcOptions& o, const std::string& s) { o.solver = bpde::parse_cmc_solver(s); })
      .def_property(
          "fixed", [](const bpde::CmcOptions& o) { return bpde::to_string(o.fixed); },
          [](bpde::CmcOptions& o, const std::string& s) { o.fixed = parse_fixed(s); })
      .def_property(
          "functional", [](const bpde::CmcOptions& o) { return bpde::to_string(o.functional); },
          [](bpde::CmcOptions& o, const std::string& s) { o.functional = bpde::parse_cmc_functional(s); },
          "\"dirichlet\" (default), \"area\" or \"mean-curvature\" (solvers/cmc/cmc.h).")
      .def_readwrite("tolerance", &bpde::CmcOptions::tolerance)
      .def_readwrite("mean_curvature_tolerance", &bpde::CmcOptions::mean_curvature_tolerance)
      .def_readwrite("max_least_squares_iterations", &bpde::CmcOptions::max_least_squares_iterations)
      .def_readwrite("geodesic_acceleration", &bpde::CmcOptions::geodesic_acceleration)
      .def_property(
          "area_start", [](const bpde::CmcOptions& o) { return bpde::to_string(o.area_start); },
          [](bpde::CmcOptions& o, const std::string& s) { o.area_start = bpde::parse_area_start(s); },
          "area functional: \"mean-curvature\" (default: the least-squares mean-curvature surface first, "
          "route 0, not tried where the D_H solution is already within 1e-6 of a critical point of A_H, as "
          "on conformal data), \"dirichlet\" (from the D_H solution) or \"minimal-surface\" (the branch "
          "from the minimal surface, H = 0, alone); docs/cmc.md, \"The area functional\".")
      .def_readwrite("area_trust_region", &bpde::CmcOptions::area_trust_region,
                     "area functional: the trust-region part of the soft-mode phase (default True; False "
                     "stops where its Levenberg-Marquardt loop stops, as before 2026-12-06); docs/cmc.md.")
      .def_readwrite("max_corrector_iterations", &bpde::CmcOptions::max_corrector_iterations)
      .def_readwrite("max_continuation_steps", &bpde::CmcOptions::max_continuation_steps)
      .def_readwrite("min_step", &bpde::CmcOptions::min_step);
  auto cmc_result = [&m](const char* name, auto tag) {
    using R = decltype(tag);
    py::class_<R>(m, name)
        .def_readonly("net", &R::net)
        .def_readonly("H", &R::H)
        .def_readonly("D", &R::D)
        .def_readonly("V", &R::V)
        .def_readonly("DH", &R::DH)
        .def_readonly("A", &R::A)
        .def_readonly("energy", &R::energy)
        .def_property_readonly("functional", [](const R& r) { return bpde::to_string(r.functional); })
        .def_readonly("quadrature_points", &R::quadrature_points)
        .def_readonly("quadrature_grading", &R::quadrature_grading)
        .def_readonly("quadrature_levels", &R::quadrature_levels)
        .def_readonly("quadrature_nodes", &R::quadrature_nodes)
        .def_readonly("continuation_steps", &R::continuation_steps)
        .def_readonly("summary", &R::summary);
  };
  cmc_result("CmcResultTriangular", bpde::CmcResult<bpde::TriangularNet>{});
  cmc_result("CmcResultTensor", bpde::CmcResult<bpde::TensorNet>{});
  m.def(
      "solve_cmc",
      [](const bpde::TriangularNet& data, const bpde::CmcOptions& options) { return bpde::solve_cmc(data, options); },
      py::arg("data"), py::arg("options"), py::call_guard<py::gil_scoped_release>(),
      "The cmc problem of solvers/cmc/cmc.h (options.functional: the critical point of D + 2HV, of A + 2HV, "
      "or the least squares of the mean curvature) -> CmcResult (net, H, D, V, DH, A, energy, functional, summary).");
  m.def(
      "solve_cmc",
      [](const bpde::TensorNet& data, const bpde::CmcOptions& options) { return bpde::solve_cmc(data, options); },
      py::arg("data"), py::arg("options"), py::call_guard<py::gil_scoped_release>());

  py::class_<bpde::TetraharmonicOptions>(m, "TetraharmonicOptions")
      .def(py::init<>())
      .def_property(
          "method",
          [](const bpde::TetraharmonicOptions& o) {
            return o.method == bpde::TetraharmonicOptions::Method::Explicit ? "explicit" : "lu";
          },
          [](bpde::TetraharmonicOptions& o, const std::string& s) { o.method = bpde::parse_tetraharmonic_method(s); });
  m.def(
      "solve_tetraharmonic",
      [](const bpde::TensorNet& data, const bpde::TetraharmonicOptions& options) {
        bpde::TetraharmonicResult r = bpde::solve_tetraharmonic(data, options);
        return std::make_pair(std::move(r.net), r.summary);
      },
      py::arg("data"), py::arg("options") = bpde::TetraharmonicOptions(), py::call_guard<py::gil_scoped_release>(),
      "Tetraharmonic C1 surface (C1 methods, Theorem 1) -> (TensorNet, Summary).");

  py::class_<bpde::ClampedPlateOptions>(m, "ClampedPlateOptions")
      .def(py::init<>())
      .def_readwrite("aspect", &bpde::ClampedPlateOptions::aspect)
      .def_readwrite("degree", &bpde::ClampedPlateOptions::degree)
      .def_property(
          "method",
          [](const bpde::ClampedPlateOptions& o) {
            return o.method == bpde::ClampedPlateOptions::Method::AdmissibleLoad ? "admissible-load" : "ritz";
          },
          [](bpde::ClampedPlateOptions& o, const std::string& s) { o.method = bpde::parse_plate_method(s); });
  py::class_<bpde::ClampedPlateResult>(m, "ClampedPlateResult")
      .def_readonly("center_deflection", &bpde::ClampedPlateResult::center_deflection)
      .def_readonly("energy", &bpde::ClampedPlateResult::energy)
      .def_readonly("net", &bpde::ClampedPlateResult::net)
      .def_readonly("load", &bpde::ClampedPlateResult::load)
      .def_readonly("summary", &bpde::ClampedPlateResult::summary);
  m.def("solve_clamped_plate", &bpde::solve_clamped_plate, py::arg("options"), py::call_guard<py::gil_scoped_release>(),
        "Clamped plate under uniform load (C1 methods §6).");

  // Extremals of quadratic energies (solvers/extremal.h): tensor and triangular nets.
  py::class_<bpde::ExtremalOptions>(m, "ExtremalOptions",
                                    "Options of solve_extremal and ExtremalSolver (solvers/extremal.h).")
      .def(py::init<>())
      .def_readwrite("singular_tolerance", &bpde::ExtremalOptions::singular_tolerance,
                     "Smallest accepted reciprocal condition number of the reduced system, in [0, 1) (1e-13).")
      .def_readwrite("conditioned_basis", &bpde::ExtremalOptions::conditioned_basis,
                     "Tensor nets: assemble in the conditioned (Gegenbauer) basis (True).")
      .def_readwrite("use_cache", &bpde::ExtremalOptions::use_cache,
                     "Tensor nets: reuse a process-wide cache of factored solvers (False).")
      .def("validate", &bpde::ExtremalOptions::validate, "Raises ParameterError naming a bad field.");
  py::class_<bpde::ExtremalResult>(m, "ExtremalResult", "A tensor extremal: net, energy, summary.")
      .def_readonly("net", &bpde::ExtremalResult::net)
      .def_readonly("energy", &bpde::ExtremalResult::energy)
      .def_readonly("summary", &bpde::ExtremalResult::summary);
  py::class_<bpde::TriangularExtremalResult>(m, "TriangularExtremalResult",
                                             "A triangular extremal: net, energy, summary.")
      .def_readonly("net", &bpde::TriangularExtremalResult::net)
      .def_readonly("energy", &bpde::TriangularExtremalResult::energy)
      .def_readonly("summary", &bpde::TriangularExtremalResult::summary);
  m.def(
      "solve_extremal",
      [](const bpde::TensorNet& data, py::handle energy, const std::string& fixed,
         const bpde::ExtremalOptions& options) {
        const bpde::EnergySpec spec = energy_arg(energy);
        const bpde::FixedSet f = parse_fixed(fixed);
        py::gil_scoped_release release;
        return bpde::solve_extremal(data, spec, f, options);
      },
      py::arg("data"), py::arg("energy"), py::arg("fixed") = "boundary", py::arg("options") = bpde::ExtremalOptions(),
      "The minimiser of a quadratic energy over the free control points, the `fixed` points of `data` "
      "prescribed (FORMATS.md problem \"extremal\") -> ExtremalResult, or TriangularExtremalResult for a "
      "TriangularNet. `energy` is a name or an ENERGY dict.");
  m.def(
      "solve_extremal",
      [](const bpde::TriangularNet& data, py::handle energy, const std::string& fixed,
         const bpde::ExtremalOptions& options) {
        const bpde::EnergySpec spec = energy_arg(energy);
        const bpde::FixedSet f = parse_fixed(fixed);
        py::gil_scoped_release release;
        return bpde::solve_extremal(data, spec, f, options);
      },
      py::arg("data"), py::arg("energy"), py::arg("fixed") = "boundary", py::arg("options") = bpde::ExtremalOptions());
  py::class_<bpde::ExtremalSolver>(
      m, "ExtremalSolver",
      "A factored extremal problem (solvers/extremal.h): X_free = mould @ X_fixed, one product per boundary.")
      .def(py::init([](py::handle energy, int n, int m, const std::string& fixed, const bpde::ExtremalOptions& o) {
             const bpde::EnergySpec spec = energy_arg(energy);
             const bpde::FixedSet f = parse_fixed(fixed);
             py::gil_scoped_release release;
             return bpde::ExtremalSolver(spec, n, m, f, o);
           }),
           py::arg("energy"), py::arg("n"), py::arg("m"), py::arg("fixed") = "boundary",
           py::arg("options") = bpde::ExtremalOptions(), "Tensor nets of degree (n, m).")
      .def(py::init([](const Eigen::MatrixXd& Q, std::vector<int> fixed, const bpde::ExtremalOptions& o) {
             py::gil_scoped_release release;
             return bpde::ExtremalSolver(Q, std::move(fixed), o);
           }),
           py::arg("gram"), py::arg("fixed_indices"), py::arg("options") = bpde::ExtremalOptions(),
           "Generic: an N x N Gram matrix and the prescribed point indices.")
      .def_property_readonly("size", &bpde::ExtremalSolver::size)
      .def_property_readonly("fixed_indices", &bpde::ExtremalSolver::fixed_indices)
      .def_property_readonly("free_indices", &bpde::ExtremalSolver::free_indices)
      .def_property_readonly("mould", &bpde::ExtremalSolver::mould, py::return_value_policy::reference_internal,
                             "#free x #fixed (read-only view).")
      .def_property_readonly("gram", &bpde::ExtremalSolver::gram, py::return_value_policy::reference_internal)
      .def(
          "solve",
          [](const bpde::ExtremalSolver& s, py::handle points) {
            const Eigen::MatrixX3d P = points_arg<3>(points, "points", s.size());
            Eigen::MatrixX3d X;
            {
              py::gil_scoped_release release;
              X = s.solve(P);
            }
            return adopt(std::move(X));
          },
          py::arg("points"), "The extremal's points (N x 3) for the fixed rows of `points` (N x 3).")
      .def(
          "reduced_residual",
          [](const bpde::ExtremalSolver& s, py::handle points) {
            return s.reduced_residual(points_arg<3>(points, "points", s.size()));
          },
          py::arg("points"))
      .def(
          "extremal_energy",
          [](const bpde::ExtremalSolver& s, py::handle points) {
            return s.extremal_energy(points_arg<3>(points, "points", s.size()));
          },
          py::arg("points"))
      .def(
          "energy",
          [](const bpde::ExtremalSolver& s, py::handle points) {
            return s.energy(points_arg<3>(points, "points", s.size()));
          },
          py::arg("points"));

  // B-spline nets (solvers/bspline/): extremals and PDE solutions.
  py::class_<bpde::BSplineExtremalOptions>(m, "BSplineExtremalOptions",
                                           "Options of solve_bspline_extremal (solvers/bspline/bspline_extremal.h).")
      .def(py::init<>())
      .def_property(
          "fixed", [](const bpde::BSplineExtremalOptions& o) { return bpde::to_string(o.fixed); },
          [](bpde::BSplineExtremalOptions& o, const std::string& s) { o.fixed = parse_fixed(s); },
          "\"boundary\" (default), \"boundary+adjacent\" or \"u-boundaries\".")
      .def_readwrite("tolerance", &bpde::BSplineExtremalOptions::tolerance,
                     "Relative residual above which the solve fails, in (0, 1) (1e-11).")
      .def("validate", &bpde::BSplineExtremalOptions::validate, "Raises ParameterError naming a bad field.");
  py::class_<bpde::BSplineExtremalResult>(m, "BSplineExtremalResult", "A B-spline extremal: net, energy, summary.")
      .def_readonly("net", &bpde::BSplineExtremalResult::net)
      .def_readonly("energy", &bpde::BSplineExtremalResult::energy)
      .def_readonly("summary", &bpde::BSplineExtremalResult::summary);
  m.def(
      "solve_bspline_extremal",
      [](const bpde::BSplineNet& data, py::handle energy, const bpde::BSplineExtremalOptions& options,
         std::optional<std::vector<int>> fixed_indices) {
        const bpde::EnergySpec spec = energy_arg(energy);
        py::gil_scoped_release release;
        return fixed_indices ? bpde::solve_bspline_extremal(data, spec, *fixed_indices, options)
                             : bpde::solve_bspline_extremal(data, spec, options);
      },
      py::arg("data"), py::arg("energy"), py::arg("options") = bpde::BSplineExtremalOptions(),
      py::arg("fixed_indices") = py::none(),
      "Extremal of a quadratic energy on a B-spline net -> BSplineExtremalResult. The prescribed points are "
      "options.fixed, or the strictly increasing indices i*nv + j of `fixed_indices` when given.");
  py::class_<bpde::BSplinePdeOptions>(m, "BSplinePdeOptions",
                                      "Options of solve_bspline_pde (solvers/bspline/bspline_pde.h).")
      .def(py::init<>())
      .def_property(
          "fixed", [](const bpde::BSplinePdeOptions& o) { return bpde::to_string(o.fixed); },
          [](bpde::BSplinePdeOptions& o, const std::string& s) { o.fixed = parse_fixed(s); },
          "\"boundary\" (default), \"boundary+adjacent\" or \"u-boundaries\" (second order only).")
      .def_readwrite("rank_tolerance", &bpde::BSplinePdeOptions::rank_tolerance, "In (0, 1) (1e-10).")
      .def_readwrite("consistency_tolerance", &bpde::BSplinePdeOptions::consistency_tolerance, "In (0, 1) (1e-10).")
      .def("validate", &bpde::BSplinePdeOptions::validate, "Raises ParameterError naming a bad field.");
  py::class_<bpde::BSplinePdeResult>(m, "BSplinePdeResult",
                                     "A B-spline PDE solution: net, summary, equations, ranks, free parameters, ...")
      .def_readonly("net", &bpde::BSplinePdeResult::net)
      .def_readonly("summary", &bpde::BSplinePdeResult::summary)
      .def_readonly("equations", &bpde::BSplinePdeResult::equations)
      .def_readonly("rank", &bpde::BSplinePdeResult::rank)
      .def_readonly("rank_free", &bpde::BSplinePdeResult::rank_free)
      .def_readonly("free_parameters", &bpde::BSplinePdeResult::free_parameters)
      .def_readonly("compatibility_conditions", &bpde::BSplinePdeResult::compatibility_conditions)
      .def_readonly("minimum_energy_member", &bpde::BSplinePdeResult::minimum_energy_member)
      .def_readonly("energy", &bpde::BSplinePdeResult::energy);
  m.def(
      "solve_bspline_pde",
      [](const bpde::BSplineNet& data, py::handle op, const bpde::BSplinePdeOptions& options,
         std::optional<std::vector<int>> fixed_indices) {
        const bpde::EnergySpec spec = energy_arg(op);
        py::gil_scoped_release release;
        return fixed_indices ? bpde::solve_bspline_pde(data, spec, *fixed_indices, options)
                             : bpde::solve_bspline_pde(data, spec, options);
      },
      py::arg("data"), py::arg("operator"), py::arg("options") = bpde::BSplinePdeOptions(),
      py::arg("fixed_indices") = py::none(),
      "B-spline solution of the Euler-Lagrange PDE of `operator` (B-spline Euler-Lagrange, Algorithms 1-2) -> "
      "BSplinePdeResult; converged False with a message (status Incompatible) when the data admit no solution.");

  // Smoothing PDE splines (solvers/blend/smoothing_spline.h): the blend of `bpde blend`.
  py::class_<bpde::SmoothingSplineProblem> spline_problem(
      m, "SmoothingSplineProblem",
      "The data of a discrete smoothing PDE spline (smoothing PDE splines, eq. (6)): partition k x l, a, "
      "epsilon, the edges y = 0 and y = 1 ((k+1) x 3 values and d/dy), approximation points (m x 2) and "
      "their data (m x 3), an optional load f(x, y) -> 3 numbers.");
  spline_problem.def(py::init<>())
      .def_static(
          "from_config", [](py::handle config) { return bpde::blend_config_from_json(to_json(config)).problem; },
          py::arg("config"), "The problem of a blend CONFIG dict (FORMATS.md; \"edges\" or \"surfaces\").")
      .def_readwrite("k", &bpde::SmoothingSplineProblem::k, "Intervals in x (8).")
      .def_readwrite("l", &bpde::SmoothingSplineProblem::l, "Intervals in y (4).")
      .def_readwrite("a", &bpde::SmoothingSplineProblem::a, "The operator's a, in [1e-6, 1e6] (1).")
      .def_readwrite("epsilon", &bpde::SmoothingSplineProblem::epsilon, "epsilon > 0 (1).")
      .def_readwrite("load", &bpde::SmoothingSplineProblem::load,
                     "f(x, y) -> (3,) or None (f = 0); called with the GIL held.")
      .def("validate", &bpde::SmoothingSplineProblem::validate, "Raises the InvalidInput subclass naming a bad field.");
  matrix_field<3, &bpde::SmoothingSplineProblem::y0_value>(spline_problem, "y0_value",
                                                           "Values at the k+1 nodes of y = 0, (k+1) x 3.");
  matrix_field<3, &bpde::SmoothingSplineProblem::y0_dy>(spline_problem, "y0_dy",
                                                        "d/dy at the k+1 nodes of y = 0, (k+1) x 3.");
  matrix_field<3, &bpde::SmoothingSplineProblem::y1_value>(spline_problem, "y1_value",
                                                           "Values at the k+1 nodes of y = 1, (k+1) x 3.");
  matrix_field<3, &bpde::SmoothingSplineProblem::y1_dy>(spline_problem, "y1_dy",
                                                        "d/dy at the k+1 nodes of y = 1, (k+1) x 3.");
  matrix_field<2, &bpde::SmoothingSplineProblem::points>(spline_problem, "points",
                                                         "Approximation points (x, y) in [0,1]^2, m x 2.");
  matrix_field<3, &bpde::SmoothingSplineProblem::data>(spline_problem, "data", "Their data, m x 3.");
  py::class_<bpde::SmoothingSplineOptions>(m, "SmoothingSplineOptions", "Options of solve_smoothing_spline.")
      .def(py::init<>())
      .def_property(
          "method",
          [](const bpde::SmoothingSplineOptions& o) {
            return o.method == bpde::SmoothingSplineOptions::Method::kElimination ? "elimination" : "kkt-lu";
          },
          [](bpde::SmoothingSplineOptions& o, const std::string& s) {
            if (s == "elimination")
              o.method = bpde::SmoothingSplineOptions::Method::kElimination;
            else if (s == "kkt-lu")
              o.method = bpde::SmoothingSplineOptions::Method::kKktLu;
            else
              throw bpde::ParameterError("method: expected \"elimination\" or \"kkt-lu\", got \"" + s + "\"");
          },
          "\"elimination\" (default: reduced SPD system, sparse Cholesky) or \"kkt-lu\" (eq. (8), sparse LU).")
      .def_readwrite("load_quadrature", &bpde::SmoothingSplineOptions::load_quadrature,
                     "Gauss points per direction and element for the load, 1..50 (6).")
      .def_readwrite("threaded_factorization", &bpde::SmoothingSplineOptions::threaded_factorization,
                     "Let CHOLMOD's factorisation run its OpenMP threads (False: they cost more CPU than they "
                     "save on blend systems, docs/performance.md section 3b).")
      .def("validate", &bpde::SmoothingSplineOptions::validate, "Raises ParameterError naming a bad field.");
  py::class_<bpde::SmoothingSpline>(m, "SmoothingSpline", "The C1 bicubic (BFS) spline on [0,1]^2.")
      .def_property_readonly(
          "coefficients", [](const bpde::SmoothingSpline& s) -> const Eigen::MatrixX3d& { return s.coefficients(); },
          py::return_value_policy::reference_internal, "num_dofs x 3 in the dof order of the BFS space (read-only).")
      .def("evaluate", &bpde::SmoothingSpline::evaluate, py::arg("x"), py::arg("y"), py::arg("dx") = 0,
           py::arg("dy") = 0)
      .def(
          "sample",
          [](const bpde::SmoothingSpline& s, int samples) {
            bpde::TriangleMesh mesh;
            {
              py::gil_scoped_release release;
              mesh = s.sample(samples);
            }
            return mesh_tuple(std::move(mesh));
          },
          py::arg("samples") = 50, "(V, F, H) as `bpde blend` samples the surface.")
      .def("to_bspline_net", &bpde::SmoothingSpline::to_bspline_net, "The same surface as a bicubic BSplineNet.");
  py::class_<bpde::SmoothingSplineResult>(m, "SmoothingSplineResult")
      .def_readonly("spline", &bpde::SmoothingSplineResult::spline)
      .def_readonly("functional", &bpde::SmoothingSplineResult::functional, "J of eq. (6).")
      .def_readonly("data_misfit", &bpde::SmoothingSplineResult::data_misfit)
      .def_readonly("energy", &bpde::SmoothingSplineResult::energy, "|sigma|_L^2.")
      .def_readonly("max_data_error", &bpde::SmoothingSplineResult::max_data_error)
      .def_readonly("multipliers", &bpde::SmoothingSplineResult::multipliers, "4(k+1) x 3.")
      .def_readonly("summary", &bpde::SmoothingSplineResult::summary);
  m.def("solve_smoothing_spline", &bpde::solve_smoothing_spline, py::arg("problem"),
        py::arg("options") = bpde::SmoothingSplineOptions(), py::call_guard<py::gil_scoped_release>(),
        "The discrete smoothing PDE spline (Theorem 6, eq. (8)) -> SmoothingSplineResult.");
  py::class_<bpde::SmoothingSplineSolver>(m, "SmoothingSplineSolver",
                                          "Assembled and factored once for a partition, a, epsilon and points.")
      .def(py::init<const bpde::SmoothingSplineProblem&, const bpde::SmoothingSplineOptions&>(), py::arg("problem"),
           py::arg("options") = bpde::SmoothingSplineOptions(), py::call_guard<py::gil_scoped_release>())
      .def("solve", &bpde::SmoothingSplineSolver::solve, py::arg("problem"), py::call_guard<py::gil_scoped_release>(),
           "Solve for the edges, data and load of `problem` (same k, l, a, epsilon, points).");

  // Sweeps: the one expansion (jobs/sweep.h), and one job run as the command runs it.
  m.def(
      "expand_sweep",
      [](py::handle spec, const std::string& base_dir) {
        const bpde::SweepSpec s = bpde::sweep_from_json(to_json(spec), "sweep", base_dir);
        const std::vector<bpde::SweepJob> jobs = bpde::expand_sweep(s);
        py::list out;
        for (const bpde::SweepJob& j : jobs) {
          py::dict d;
          d["index"] = j.index;
          d["id"] = j.id;
          d["values"] = from_json(j.values);
          d["job"] = from_json(j.job);
          d["error"] = j.error;
          out.append(d);
        }
        py::list columns;
        for (const std::string& c : bpde::sweep_columns(s)) columns.append(c);
        return py::make_tuple(out, columns);
      },
      py::arg("spec"), py::arg("base_dir") = ".",
      "(jobs, columns): the sweep's jobs as dicts {index, id, values, job, error} and the table's columns.");
  m.def(
      "run_sweep_job",
      [](py::handle job, const std::string& dir, bool resume) {
        bpde::SweepJob j;
        j.index = job["index"].cast<int>();
        j.id = job["id"].cast<std::string>();
        j.values = to_json(job["values"]);
        j.job = to_json(job["job"]);
        j.error = job["error"].cast<std::string>();
        Json row;
        {
          py::gil_scoped_release release;
          if (resume) row = bpde::finished_sweep_row(j, dir);
          if (row.is_null()) row = bpde::run_sweep_job(j, dir);
        }
        return from_json(row);
      },
      py::arg("job"), py::arg("dir"), py::arg("resume") = true,
      "Run one expanded job into `dir` as `bpde sweep` does; its row (a dict).");
  m.def(
      "write_sweep_tables",
      [](py::handle spec, const std::string& base_dir, const std::string& out_dir, py::handle rows) {
        const bpde::SweepSpec s = bpde::sweep_from_json(to_json(spec), "sweep", base_dir);
        std::vector<Json> r;
        for (auto row : rows) r.push_back(to_json(row));
        py::gil_scoped_release release;
        bpde::write_sweep_tables(out_dir, s, r);
      },
      py::arg("spec"), py::arg("base_dir"), py::arg("out_dir"), py::arg("rows"),
      "Write out_dir/results.csv and results.jsonl as `bpde sweep` does.");
  m.def("sweep_boundary_names", &bpde::sweep_boundary_names);
}
