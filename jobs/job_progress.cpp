#include "bezierpde/jobs/job_progress.h"

#include <utility>

namespace bpde {
namespace {
thread_local ProgressFn current;
}  // namespace

const ProgressFn& job_progress() { return current; }

JobProgressScope::JobProgressScope(ProgressFn progress) : previous_(std::exchange(current, std::move(progress))) {}

JobProgressScope::~JobProgressScope() { current = std::move(previous_); }

}  // namespace bpde
