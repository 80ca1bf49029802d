// Default options of the sanitizer runtimes, compiled into every executable of a BPDE_SANITIZE
// build (CMakeLists.txt) and nowhere else. A report exits with status 86, which no bpde command
// and no test uses: the CLI tests accept exit 1 for "valid input, no solution", which is also the
// runtimes' default exit status, so without this a leak reported at exit, or a report after
// result.json was written, would pass as a legitimate exit 1. Leaks are checked at exit.
// ASAN_OPTIONS / UBSAN_OPTIONS in the environment are read after these and override them.

extern "C" const char* __asan_default_options() { return "exitcode=86:detect_leaks=1"; }
extern "C" const char* __ubsan_default_options() { return "exitcode=86:print_stacktrace=1"; }
