#pragma once
// Typed exceptions of bezierpde.
//
// Every error the library raises derives from bpde::Error. Errors caused by bad input (the
// caller's data is malformed, of the wrong size, non-finite, a degree too low for the method, a
// singular parameter matrix, ...) derive from bpde::InvalidInput; the command maps them to one
// line `error: ...` and exit status 2. A valid request that has no solution (a fold in a
// continuation, no convergence, incompatible data) is NOT an exception: solvers report it in their
// Summary (converged = false, message), and the command exits 1. A broken invariant is an
// InternalError (exit status 3).
#include <stdexcept>
#include <string>

namespace bpde {

/// Base class of every exception bezierpde throws.
class Error : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// The input is not acceptable (command exit status 2). The message names the problem and,
/// where known, where it is (a JSON path such as `net.points[3][1]`).
class InvalidInput : public Error {
 public:
  using Error::Error;
};

/// Malformed JSON, a value of the wrong JSON type, an unknown field, a missing field.
/// (InvalidInput is a virtual base here and in NonFiniteError, so that NumberOverflowError can be
/// both with one InvalidInput.)
class ParseError : public virtual InvalidInput {
 public:
  using InvalidInput::InvalidInput;
};

/// A missing or unreadable file, or one that cannot be written.
class FileError : public InvalidInput {
 public:
  using InvalidInput::InvalidInput;
};

/// A degree out of range or too low for the method.
class DegreeError : public InvalidInput {
 public:
  using InvalidInput::InvalidInput;
};

/// Arrays of the wrong size (point counts, matrix shapes, knot counts).
class SizeError : public InvalidInput {
 public:
  using InvalidInput::InvalidInput;
};

/// NaN or infinite numbers, or numbers that overflow.
class NonFiniteError : public virtual InvalidInput {
 public:
  using InvalidInput::InvalidInput;
};

/// A JSON number that does not fit in a double (1e999, -1e400): the text cannot be read as the
/// JSON it claims to be (a ParseError) and its value would be infinite (a NonFiniteError). Every
/// JSON reader of io/ throws this one type, so a caller may catch it as either.
class NumberOverflowError : public ParseError, public NonFiniteError {
 public:
  explicit NumberOverflowError(const std::string& what) : InvalidInput(what), ParseError(what), NonFiniteError(what) {}
};

/// A parameter outside its valid set: a singular G, epsilon <= 0, a non-elliptic operator for a
/// method that needs ellipticity, an option out of range, ...
class ParameterError : public InvalidInput {
 public:
  using InvalidInput::InvalidInput;
};

/// A combination of net kind, fixed set and problem that the method cannot use (for example
/// `u-boundaries` with a fourth-order PDE), or a solver that this build does not provide.
class UnsupportedProblem : public InvalidInput {
 public:
  using InvalidInput::InvalidInput;
};

/// A broken invariant of the library: a failure that is not the input's fault (for example a
/// Summary whose status and `converged` disagree). NOT an InvalidInput: the command maps it, like
/// out-of-memory, to one line `internal error: ...` and exit status 3.
class InternalError : public Error {
 public:
  using Error::Error;
};

}  // namespace bpde
