// The conversions shared by the binding files (bindings.h).
#include "bindings.h"

#include <chrono>
#include <cmath>
#include <memory>
#include <variant>

#include "bezierpde/io/job.h"

namespace bpde::python {

std::string text(py::handle h, const std::string& what) {
  if (!PyUnicode_Check(h.ptr()))
    throw bpde::ParseError(what + ": expected a str, got " +
                           py::str(h.get_type().attr("__name__")).cast<std::string>());
  Py_ssize_t size = 0;
  const char* data = PyUnicode_AsUTF8AndSize(h.ptr(), &size);
  if (!data) {
    PyErr_Clear();
    throw bpde::ParseError(what + ": a str that is not valid Unicode text (it holds a lone surrogate)");
  }
  return std::string(data, static_cast<size_t>(size));
}

std::string path_text(const Text& t, const std::string& what) {
  if (PyUnicode_Check(t.value.ptr())) return text(t.value, what);
  PyObject* p = PyOS_FSPath(t.value.ptr());  // os.fspath: str or bytes of an os.PathLike
  if (!p) {
    PyErr_Clear();
    throw bpde::ParseError(what + ": expected a str or os.PathLike path, got " +
                           py::str(t.value.get_type().attr("__name__")).cast<std::string>());
  }
  const py::object path = py::reinterpret_steal<py::object>(p);
  return text(path, what);
}

void require_finite(const Eigen::Ref<const Eigen::MatrixXd>& P, const std::string& what) {
  for (Eigen::Index r = 0; r < P.rows(); ++r)
    for (Eigen::Index c = 0; c < P.cols(); ++c)
      if (!std::isfinite(P(r, c)))
        throw bpde::NonFiniteError(what + ": row " + std::to_string(r) + " column " + std::to_string(c) +
                                   " is not finite");
}

Json to_json(py::handle h, const std::string& what, int depth) {
  if (depth > bpde::kMaxJsonDepth)
    throw bpde::SizeError(what + ": nested deeper than " + std::to_string(bpde::kMaxJsonDepth) + " levels");
  if (h.is_none()) return nullptr;
  if (py::isinstance<py::bool_>(h)) return h.cast<bool>();
  if (py::isinstance<py::int_>(h)) {
    try {
      return h.cast<long long>();
    } catch (const py::cast_error&) {
      throw bpde::ParseError(what + ": integer out of range: " + py::str(h).cast<std::string>());
    }
  }
  if (py::isinstance<py::float_>(h)) {
    const double x = h.cast<double>();
    if (!std::isfinite(x)) throw bpde::NonFiniteError(what + ": a number is not finite (JSON has no NaN or infinity)");
    return x;
  }
  if (py::isinstance<py::str>(h)) return text(h, what);
  if (py::isinstance<py::dict>(h)) {
    Json j = Json::object();
    for (auto item : h.cast<py::dict>()) {
      if (!py::isinstance<py::str>(item.first)) throw bpde::ParseError(what + ": a JSON object key must be a str");
      j[text(item.first, what + " (a key)")] = to_json(item.second, what, depth + 1);
    }
    return j;
  }
  if (py::isinstance<py::list>(h) || py::isinstance<py::tuple>(h)) {
    Json j = Json::array();
    for (auto v : h) j.push_back(to_json(v, what, depth + 1));
    return j;
  }
  // numpy scalars and arrays: through their Python values.
  if (py::hasattr(h, "tolist")) return to_json(h.attr("tolist")(), what, depth + 1);
  throw bpde::ParseError(what + ": cannot convert a Python " +
                         py::str(h.get_type().attr("__name__")).cast<std::string>() + " to JSON");
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

py::tuple mesh_tuple(bpde::TriangleMesh&& mesh) {
  return py::make_tuple(adopt(std::move(mesh.V)), adopt(std::move(mesh.F)), adopt(std::move(mesh.H)));
}

bpde::Net net_arg(py::handle h) {
  // A net object's points may have been written through its `points` view: checked here.
  const auto checked = [](auto net) {
    require_finite(net.points(), "net.points");
    return bpde::Net(std::move(net));
  };
  if (py::isinstance<bpde::TensorNet>(h)) return checked(h.cast<bpde::TensorNet>());
  if (py::isinstance<bpde::TriangularNet>(h)) return checked(h.cast<bpde::TriangularNet>());
  if (py::isinstance<bpde::BSplineNet>(h)) return checked(h.cast<bpde::BSplineNet>());
  const Json j = to_json(h, "net");
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
  if (py::isinstance<py::str>(h)) return bpde::energy_from_argument(text(h, "energy"), "energy");
  return bpde::energy_from_json(to_json(h, "energy"), "operator", true);
}

bpde::ProgressFn interruptible(bpde::ProgressFn inner) {
  using Clock = std::chrono::steady_clock;
  auto last = std::make_shared<Clock::time_point>(Clock::now());
  return [inner = std::move(inner), last](std::string_view stage, double done, double total) {
    const Clock::time_point now = Clock::now();
    if (now - *last >= std::chrono::milliseconds(50)) {
      *last = now;
      py::gil_scoped_acquire gil;
      if (PyErr_CheckSignals() != 0) throw py::error_already_set();
    }
    if (inner) inner(stage, done, total);
  };
}

InterruptibleSolve::InterruptibleSolve()
    : scope_([check = interruptible()] { check("interruption check", 0, 0); }) {}

void check_limits(const bpde::SolverRequirements& r, const bpde::NetShape& shape, bpde::FixedSet fixed,
                  const std::string& method, const std::string& where) {
  bpde::check_requirements(r, shape, fixed, method, where);
}

}  // namespace bpde::python
