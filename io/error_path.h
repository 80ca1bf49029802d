#pragma once
// Input errors located by a JSON path: the library's InvalidInput messages carry no location, so
// the readers (io/boundary_json.cpp, io/complex_job.cpp) run each library call through at_path(),
// which puts `path: ` in front of the message and keeps the exception's type (the command maps
// every InvalidInput to exit 2; tests and Python catch the subclasses).
#include <exception>
#include <string>

#include "bezierpde/complex/layout_loops.h"
#include "bezierpde/core/errors.h"

namespace bpde {

/// f(), with an InvalidInput's message prefixed by `path: ` and its type kept (most derived
/// first). A leading `drop` ("boundary: " of the boundary fit's messages) is removed, since the
/// path names it.
template <class F>
auto at_path(const std::string& path, F&& f, const std::string& drop = "") -> decltype(f()) {
  auto msg = [&](const std::exception& e) {
    std::string m = e.what();
    if (!drop.empty() && m.rfind(drop, 0) == 0) m = m.substr(drop.size());
    return path + ": " + m;
  };
  try {
    return f();
  } catch (const LoopNotClosedError& e) {
    throw LoopNotClosedError(msg(e));
  } catch (const CurvesOutOfOrderError& e) {
    throw CurvesOutOfOrderError(msg(e));
  } catch (const LayoutMismatchError& e) {
    throw LayoutMismatchError(msg(e));
  } catch (const DegreeError& e) {
    throw DegreeError(msg(e));
  } catch (const SizeError& e) {
    throw SizeError(msg(e));
  } catch (const NonFiniteError& e) {
    throw NonFiniteError(msg(e));
  } catch (const ParameterError& e) {
    throw ParameterError(msg(e));
  }
}

}  // namespace bpde
