#include "app/progress_line.h"

#include <unistd.h>

#include <algorithm>
#include <cmath>

namespace bpde::app {

bool progress_wanted(bool forced) { return forced || ::isatty(STDERR_FILENO) == 1; }

std::string progress_text(std::string_view stage, double done, double total, double elapsed) {
  const std::string name(stage);
  char line[320];
  const double f = total > 0 ? std::clamp(done / total, 0.0, 1.0) : 0.0;
  const double percent = std::floor(100 * f + 1e-9);  // 100% only when done
  if (total > 0 && done >= total)
    std::snprintf(line, sizeof line, "bpde: %s done in %.1f s", name.c_str(), elapsed);
  else if (f >= kEtaFromFraction)
    std::snprintf(line, sizeof line, "bpde: %s %.0f%%, %.0f s elapsed, ~%.0f s left", name.c_str(), percent, elapsed,
                  elapsed * (1 - f) / f);
  else if (f > 0)
    std::snprintf(line, sizeof line, "bpde: %s %.0f%%, %.0f s elapsed", name.c_str(), percent, elapsed);
  else
    std::snprintf(line, sizeof line, "bpde: %s, %.0f s elapsed", name.c_str(), elapsed);
  return line;
}

ProgressLine::ProgressLine(std::FILE* out, bool terminal) : out_(out), terminal_(terminal) {}

ProgressLine::~ProgressLine() {
  if (terminal_ && drawn_) std::fputs("\r\033[K", out_);
  std::fflush(out_);
}

void ProgressLine::update(std::string_view stage, double done, double total, Clock::time_point now) {
  const bool new_stage = stage != stage_;
  if (new_stage) stage_ = std::string(stage);
  const Clock::time_point started = start_.try_emplace(stage_, now).first->second;
  const bool finished = total > 0 && done >= total;
  // Redraw at most 10 times a second on a terminal, once a second into a file, and always at a
  // change of stage and a stage's end.
  const double since_draw = std::chrono::duration<double>(now - last_draw_).count();
  if (!new_stage && !finished && since_draw < (terminal_ ? 0.1 : 1.0)) return;
  last_draw_ = now;
  const std::string line = progress_text(stage_, done, total, std::chrono::duration<double>(now - started).count());
  if (finished) start_.erase(stage_);  // a stage reported again after its end starts a new clock
  if (terminal_)
    std::fprintf(out_, "\r%s\033[K", line.c_str());
  else
    std::fprintf(out_, "%s\n", line.c_str());
  std::fflush(out_);
  drawn_ = true;
}

ProgressFn ProgressLine::callback() {
  return [this](std::string_view stage, double done, double total) { update(stage, done, total); };
}

}  // namespace bpde::app
