// An outside project's program over the installed bezierpde package (tests/package): it runs the
// README's "Library use" snippets, compiled verbatim (snippets.inc is extracted from README.md by
// tests/package/run_consumer.cmake), from a folder holding net.json and job.json.
//
// The project has its own core/errors.h on its include path: bezierpde's headers are included as
// "bezierpde/<folder>/<name>.h", so they never pick up the consumer's core/ (and this one never
// picks up bezierpde's).
#include <cstdio>
#include <exception>

#include "core/errors.h"  // the consumer's own
#include "snippets.inc"   // the README snippets, each wrapped in a function snippet_<name>()

int main() {
  static_assert(consumer::kOwnCoreErrors, "the consumer's core/errors.h was shadowed");
  try {
    run_readme_snippets();
  } catch (const std::exception& e) {
    std::fprintf(stderr, "consumer: %s\n", e.what());
    return 1;
  }
  std::puts("consumer: README snippets ran");
  return 0;
}
