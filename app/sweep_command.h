#pragma once
// `bpde sweep SWEEP.json --out DIR [--jobs N] [--progress]` (FORMATS.md "Sweeps"; jobs/sweep.h).
#include <string>

namespace bpde::app {

/// Run a sweep on `jobs` threads (0: every core) with a progress bar and an ETA on a terminal
/// (stderr), plain lines otherwise or when `lines` (--progress) is set. Returns 0 when every job converged, 1 when some did not or
/// failed (their rows say why; the tables are written either way). A bad sweep file throws
/// InvalidInput (exit 2) before anything runs.
int cmd_sweep(const std::string& sweep_path, const std::string& out_dir, int jobs, bool lines = false);

}  // namespace bpde::app
