// Default options of the sanitizer runtimes, compiled into every executable of a BPDE_SANITIZE
// build (CMakeLists.txt) and nowhere else. A report exits with status 86, which no bpde command
// and no test uses: the CLI tests accept exit 1 for "valid input, no solution", which is also the
// runtimes' default exit status, so without this a leak reported at exit, or a report after
// result.json was written, would pass as a legitimate exit 1. Leaks are checked at exit.
// ASAN_OPTIONS / UBSAN_OPTIONS / LSAN_OPTIONS in the environment are read after these and
// override them.
//
// fast_unwind_on_malloc=0: the allocation stacks are taken by the slow (DWARF) unwinder. Debian's
// OpenCASCADE libraries have no frame pointers, so the fast unwinder stops at their first frame
// and a leak there could be matched only by library name, never by the function that made it.
// It costs about 10 % on the CLI tests (docs/robustness.md, "Recorded runs").
//
// The suppressions are OpenCASCADE's own process-lifetime state, allocated once and never freed,
// reached through io/step_plugin.cpp (the STEP plugin): the STEP controller that the first STEPControl_Writer
// registers (STEPControl_Controller::Init: the editors, static parameters and work session, 136
// blocks), and the default placement that the first transfer caches
// (STEPConstruct_ContextTool::GetDefaultAxis, 2 blocks). Measured with OpenCASCADE 7.6 (Debian 12):
// 2964 bytes in 138 blocks after one STEP export, and the same after every test of test_step
// (dozens of exports and read-backs), so nothing grows per call. Any other leak, also one inside
// OpenCASCADE reached from another caller, is still reported.

extern "C" const char* __asan_default_options() { return "exitcode=86:detect_leaks=1:fast_unwind_on_malloc=0"; }
extern "C" const char* __ubsan_default_options() { return "exitcode=86:print_stacktrace=1"; }
extern "C" const char* __lsan_default_suppressions() {
  return "leak:STEPControl_Controller::Init\n"
         "leak:STEPConstruct_ContextTool::GetDefaultAxis\n";
}
