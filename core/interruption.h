#pragma once
// Interrupting long solves (docs/robustness.md, "Interrupting a solve"): a check that the long
// dense and sparse solves call where they can stop, before and after each factorisation and
// between the blocks of their loops. The check installed on the calling thread throws to stop the
// solve (Python's KeyboardInterrupt, through python/bindings.h `interruptible`); with none
// installed, check_interruption() costs one test. The command `bpde` installs none: SIGINT keeps
// its default action there and ends the process at once (io/output_folder.h removes a staging
// folder first).
//
// A solver that calls check_interruption() must leave no state behind when it throws (caches
// keep nothing of a build that threw, core/keyed_cache.h).
#include <functional>

namespace bpde {

/// Called at the interruption points; throws to interrupt the solve.
using InterruptionCheck = std::function<void()>;

/// Run the check installed on this thread, if any.
void check_interruption();

/// Installs `check` for this thread while it lives (scopes nest; an empty check removes it).
class InterruptionScope {
 public:
  explicit InterruptionScope(InterruptionCheck check);
  ~InterruptionScope();
  InterruptionScope(const InterruptionScope&) = delete;
  InterruptionScope& operator=(const InterruptionScope&) = delete;

 private:
  InterruptionCheck previous_;
};

}  // namespace bpde
