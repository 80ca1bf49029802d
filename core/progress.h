#pragma once
// Progress of long work (sampling and checking at thousands of samples, the CMC continuation): a
// callback that solvers and jobs call with the stage and how far it is. Null by default, and a
// null callback costs one test per step (report() below): progress is off unless a caller, such
// as the `bpde` command on a terminal, installs one.
//
//   stage  a short name of what runs now ("sampling", "checking", "cmc continuation", ...)
//   done   how far the stage is, in units of `total`, 0 <= done <= total
//   total  the stage's size; 0 when unknown (the reporter shows the elapsed time only)
// A stage is finished when it is reported with done == total > 0.
#include <exception>
#include <functional>
#include <string_view>

namespace bpde {

using ProgressFn = std::function<void(std::string_view stage, double done, double total)>;

/// Call `progress` if it is set.
inline void report(const ProgressFn& progress, std::string_view stage, double done, double total) {
  if (progress) progress(stage, done, total);
}

/// Reports `stage` as started on construction and as finished on destruction unless an exception
/// leaves the scope (work without
/// intermediate steps: one library call such as the CGAL checks).
class ProgressStage {
 public:
  ProgressStage(const ProgressFn& progress, std::string_view stage) : progress_(progress), stage_(stage) {
    report(progress_, stage_, 0, 1);
  }
  ~ProgressStage() {
    if (std::uncaught_exceptions() == 0) report(progress_, stage_, 1, 1);  // not "done" when it threw
  }
  ProgressStage(const ProgressStage&) = delete;
  ProgressStage& operator=(const ProgressStage&) = delete;

 private:
  const ProgressFn& progress_;
  std::string_view stage_;
};

}  // namespace bpde
