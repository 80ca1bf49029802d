#include "bezierpde/jobs/exit_status.h"

#include <new>

#include "bezierpde/core/errors.h"

namespace bpde {

std::string one_line(std::string s) {
  for (char& c : s)
    if (c == '\n' || c == '\r') c = ' ';
  return s;
}

ErrorExit error_exit(const std::exception_ptr& e) {
  try {
    std::rethrow_exception(e);
  } catch (const InvalidInput& x) {
    return {2, "error: " + one_line(x.what()) + "\n"};
  } catch (const std::bad_alloc&) {
    return {3, "internal error: out of memory\n"};
  } catch (const std::exception& x) {
    return {3, "internal error: " + one_line(x.what()) + "\n"};
  } catch (...) {
    return {3, "internal error: unknown exception\n"};
  }
}

}  // namespace bpde
