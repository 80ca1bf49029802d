#pragma once
// How the command ends on an exception (FORMATS.md "Exit status and errors"):
//   InvalidInput                      -> 2, one line `error: <what>`
//   std::bad_alloc, InternalError and
//   any other exception               -> 3, one line `internal error: <what>`
// Exit 1 is never an exception: it is a valid input without a solution (result.json written with
// "converged": false; jobs/run_job.h exit_code).
#include <exception>
#include <string>

namespace bpde {

struct ErrorExit {
  int code = 3;
  std::string line;  ///< one line for stderr, ending in '\n' (newlines of the message replaced)
};

/// `s` with its newlines replaced by spaces: a message fit for the one stderr line of the contract.
std::string one_line(std::string s);

/// The exit code and stderr line for an exception (usually std::current_exception()).
ErrorExit error_exit(const std::exception_ptr& e);

}  // namespace bpde
