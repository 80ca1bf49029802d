#pragma once
// What every solver returns beside its result, in the spirit of ceres::Solver::Summary: a typed
// outcome (Status), a human-readable message, iteration count, final residual and wall time.
//
// Contract shared by every solver of bezierpde:
//   - status == Status::Converged  <=>  converged == true  (set both through Summary::finish);
//   - a non-Converged status always carries a non-empty message saying why;
//   - seconds >= 0, measured by ScopedTimer around the whole solve.
// Callers (the job layer, tests) test `status`, never a substring of `message`.
#include <chrono>
#include <string>
#include <utility>

namespace bpde {

/// The optimality tolerance of FORMATS.md "converged": a solve counts as converged when its
/// optimality condition holds to this relative to the size of its terms.
inline constexpr double kConvergenceTolerance = 1e-11;

/// Why a solve ended (compare ceres::TerminationType).
enum class Status {
  Converged,       ///< the optimality condition holds to the tolerance; the solution is usable
  NotUnique,       ///< the linear system is singular on the free unknowns: no unique solution
  Incompatible,    ///< the boundary data violate the compatibility conditions of the problem
  Fold,            ///< a continuation in H met a fold: no critical point on the branch beyond it
  NoConvergence,   ///< an iteration stopped (iteration limit, stalled) above the tolerance
  NumericalLimit,  ///< the solve finished but rounding leaves the residual above the tolerance
};

/// "converged", "not-unique", "incompatible", "fold", "no-convergence", "numerical-limit".
inline const char* to_string(Status s) {
  switch (s) {
    case Status::Converged:
      return "converged";
    case Status::NotUnique:
      return "not-unique";
    case Status::Incompatible:
      return "incompatible";
    case Status::Fold:
      return "fold";
    case Status::NoConvergence:
      return "no-convergence";
    case Status::NumericalLimit:
      return "numerical-limit";
  }
  return "unknown";
}

struct Summary {
  /// Why the solve ended. Converged iff `converged`.
  Status status = Status::NoConvergence;
  /// The solution is usable: the optimality condition holds to kConvergenceTolerance relative to
  /// the size of its terms (FORMATS.md "converged"). A direct solve that succeeded sets it true.
  bool converged = false;
  /// Iterations (Newton steps, continuation steps, ...) or 0 for direct solves.
  int iterations = 0;
  /// Final relative optimality residual (solver-specific; documented by each solver).
  double residual = 0.0;
  /// Human-readable outcome. Required when converged is false, e.g.
  /// "no critical point on the branch from H = 0 beyond H ≈ -2.31".
  std::string message;
  /// Wall time of the solve in seconds.
  double seconds = 0.0;

  /// Mark the solve converged (status Converged, converged = true; the message is kept).
  void set_converged() {
    status = Status::Converged;
    converged = true;
  }
  /// Mark the solve failed with a reason (a non-Converged status) and a non-empty message.
  void set_failed(Status why, std::string what) {
    status = why == Status::Converged ? Status::NoConvergence : why;
    converged = false;
    message = std::move(what);
  }
  /// `ok` ? set_converged() : set_failed(why, what()). `what` is only called on failure.
  template <class Message>
  void finish(bool ok, Status why, const Message& what) {
    if (ok)
      set_converged();
    else
      set_failed(why, what());
  }
};

/// Measures the wall time of a scope into a `double` (usually Summary::seconds):
///   Summary s; { ScopedTimer t(s.seconds); ... solve ... }
/// The target is written when the timer goes out of scope, also when the scope throws.
class ScopedTimer {
 public:
  explicit ScopedTimer(double& seconds) : seconds_(seconds), start_(std::chrono::steady_clock::now()) {}
  ScopedTimer(const ScopedTimer&) = delete;
  ScopedTimer& operator=(const ScopedTimer&) = delete;
  ~ScopedTimer() { seconds_ = elapsed(); }
  /// Seconds since construction.
  double elapsed() const { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count(); }

 private:
  double& seconds_;
  std::chrono::steady_clock::time_point start_;
};

/// f() (a result with a Summary member `summary`) with the wall time of the call in
/// summary.seconds, also when the result is returned by value:
///   return timed_solve([&] { return solve_untimed(data, options); });
template <class F>
auto timed_solve(const F& f) {
  double seconds = 0.0;
  auto r = [&] {
    ScopedTimer timer(seconds);
    return f();
  }();
  r.summary.seconds = seconds;
  return r;
}

}  // namespace bpde
