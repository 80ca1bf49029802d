#pragma once
// The progress line of `bpde` on stderr (core/progress.h callbacks): on a terminal one line
// rewritten in place ("bpde: cmc continuation 45%, 3 s elapsed, ~4 s left"), cleared at the end;
// when forced (--progress) onto a file or pipe, one line per stage start and end and at most one
// per second in between.
#include <chrono>
#include <cstdio>
#include <string>

#include "bezierpde/core/progress.h"

namespace bpde::app {

/// Whether `bpde` shows progress: --progress given, or stderr is a terminal.
bool progress_wanted(bool forced);

class ProgressLine {
 public:
  /// `terminal`: rewrite one line with '\r' (else write whole lines).
  ProgressLine(std::FILE* out, bool terminal);
  ~ProgressLine();  ///< clears the line on a terminal
  ProgressLine(const ProgressLine&) = delete;
  ProgressLine& operator=(const ProgressLine&) = delete;

  void update(std::string_view stage, double done, double total);
  /// A callback calling update() (valid while this object lives).
  ProgressFn callback();

 private:
  using Clock = std::chrono::steady_clock;
  std::FILE* out_;
  bool terminal_;
  bool drawn_ = false;
  std::string stage_;
  Clock::time_point stage_start_, last_draw_;
};

}  // namespace bpde::app
