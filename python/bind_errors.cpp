// Python exceptions for the typed exceptions of core/errors.h: one hierarchy.
#include "bindings.h"

namespace bpde::python {

namespace {

PyObject* new_exception(py::module_& m, const char* name, py::handle bases, const char* doc) {
  const std::string qualified = std::string("bezierpde.") + name;
  PyObject* e = PyErr_NewExceptionWithDoc(qualified.c_str(), doc, bases.ptr(), nullptr);
  if (!e) throw py::error_already_set();
  m.add_object(name, py::handle(e));
  return e;
}

}  // namespace

void bind_errors(py::module_& m) {
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
}

}  // namespace bpde::python
