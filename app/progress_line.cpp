#include "app/progress_line.h"

#include <unistd.h>

namespace bpde::app {

bool progress_wanted(bool forced) { return forced || ::isatty(STDERR_FILENO) == 1; }

ProgressLine::ProgressLine(std::FILE* out, bool terminal) : out_(out), terminal_(terminal) {}

ProgressLine::~ProgressLine() {
  if (terminal_ && drawn_) std::fputs("\r\033[K", out_);
  std::fflush(out_);
}

void ProgressLine::update(std::string_view stage, double done, double total) {
  const Clock::time_point now = Clock::now();
  const bool new_stage = stage != stage_;
  if (new_stage) {
    stage_ = std::string(stage);
    stage_start_ = now;
  }
  const bool finished = total > 0 && done >= total;
  // Redraw at most 10 times a second on a terminal, once a second into a file, and always at a
  // stage's start and end.
  const double since_draw = std::chrono::duration<double>(now - last_draw_).count();
  if (!new_stage && !finished && since_draw < (terminal_ ? 0.1 : 1.0)) return;
  last_draw_ = now;
  const double elapsed = std::chrono::duration<double>(now - stage_start_).count();
  char line[256];
  if (finished)
    std::snprintf(line, sizeof line, "bpde: %s done in %.1f s", stage_.c_str(), elapsed);
  else if (total > 0 && done > 0)
    std::snprintf(line, sizeof line, "bpde: %s %.0f%%, %.0f s elapsed, ~%.0f s left", stage_.c_str(),
                  100.0 * done / total, elapsed, elapsed * (total - done) / done);
  else
    std::snprintf(line, sizeof line, "bpde: %s, %.0f s elapsed", stage_.c_str(), elapsed);
  if (terminal_)
    std::fprintf(out_, "\r%s\033[K", line);
  else
    std::fprintf(out_, "%s\n", line);
  std::fflush(out_);
  drawn_ = true;
}

ProgressFn ProgressLine::callback() {
  return [this](std::string_view stage, double done, double total) { update(stage, done, total); };
}

}  // namespace bpde::app
