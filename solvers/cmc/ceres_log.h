#pragma once
// Ceres's own log. Ceres (Debian's build) logs through glog, and some stops of its minimiser go to
// stderr at level ERROR whatever Solver::Options::logging_type says, e.g.
//   E… trust_region_minimizer.cc:118] Terminating: projected_gradient_step = Plus(x, -gradient) failed.
// when a manifold's Plus fails on the whole gradient step (the mean-curvature V form from a folded
// start, docs/cmc_algorithm.md, "The routes"). The solvers report what they concluded in their Summary, so an
// application that keeps stderr for its own messages turns that log off once at start: the bpde CLI
// and the Python module do. A C++ program linking the library decides for itself: glog's level is a
// process-wide setting, and the library never changes it on its own.

namespace bpde {

/// Sets glog's minimum level to FATAL, so that Ceres writes nothing to stderr (a fatal message
/// aborts the process anyway). Call it before any solve; calling it again changes nothing.
void quiet_ceres_log();

}  // namespace bpde
