// The interruption check of this thread (core/interruption.h).
#include "bezierpde/core/interruption.h"

#include <utility>

namespace bpde {

namespace {
thread_local InterruptionCheck current;
}  // namespace

void check_interruption() {
  if (current) current();
}

InterruptionScope::InterruptionScope(InterruptionCheck check) : previous_(std::exchange(current, std::move(check))) {}

InterruptionScope::~InterruptionScope() { current = std::move(previous_); }

}  // namespace bpde
