#pragma once
// The progress line of `bpde` on stderr (core/progress.h callbacks): on a terminal one line
// rewritten in place, cleared at the end; when forced (--progress) onto a file or pipe, one line
// per stage start and end and at most one a second in between (FORMATS.md, "Command"):
//
//   bpde: STAGE, 3 s elapsed                     unknown length (total 0), or nothing done yet
//   bpde: STAGE 4%, 3 s elapsed                  a fraction below kEtaFromFraction
//   bpde: STAGE 45%, 3 s elapsed, ~4 s left      the estimate: elapsed × (1 − f) / f
//   bpde: STAGE done in 7.2 s
//
// The elapsed time of a stage runs from its first report, also when other stages report in
// between (the least squares inside the area solve): returning to a stage keeps its clock.
#include <chrono>
#include <cstdio>
#include <map>
#include <string>

#include "bezierpde/core/progress.h"

namespace bpde::app {

/// Whether `bpde` shows progress: --progress given, or stderr is a terminal.
bool progress_wanted(bool forced);

/// The fraction from which a stage of known length shows an estimate of the time left (below it
/// the estimate would rest on too little of the stage).
inline constexpr double kEtaFromFraction = 0.05;

/// The text of one progress line (without the '\r' or '\n'), `elapsed` seconds into the stage.
std::string progress_text(std::string_view stage, double done, double total, double elapsed);

class ProgressLine {
 public:
  using Clock = std::chrono::steady_clock;

  /// `terminal`: rewrite one line with '\r' (else write whole lines).
  ProgressLine(std::FILE* out, bool terminal);
  ~ProgressLine();  ///< clears the line on a terminal
  ProgressLine(const ProgressLine&) = delete;
  ProgressLine& operator=(const ProgressLine&) = delete;

  void update(std::string_view stage, double done, double total) { update(stage, done, total, Clock::now()); }
  /// update() at the time `now` (the tests drive the clock).
  void update(std::string_view stage, double done, double total, Clock::time_point now);
  /// A callback calling update() (valid while this object lives).
  ProgressFn callback();

 private:
  std::FILE* out_;
  bool terminal_;
  bool drawn_ = false;
  std::string stage_;                               ///< the stage drawn last
  std::map<std::string, Clock::time_point> start_;  ///< each stage's first report
  Clock::time_point last_draw_;
};

}  // namespace bpde::app
