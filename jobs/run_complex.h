#pragma once
// Jobs whose boundary is a patch complex (FORMATS.md "Patch complexes"): the solve and the files.
//
// The solve is the extremal of the job's energy on the complex (solvers/complex/complex_extremal.h).
// The report adds `patches`, `degree`, `refine`, `seam_angle_max` (degrees, complex/complex_mesh.h
// at 16 points per seam), `area` (the sum of the patches' areas by energies/area_functional.h)
// and `volume` (the sum of the patches' volumes, energies/volume.h). The files are those of a
// single net, written from one welded mesh (complex/complex_mesh.h): surface.obj, surface.ply,
// surface.vtp (with the patch id of every triangle as the CellData "patch"), and net.obj (every
// complex row once, and each patch's control net lines).
// Per-vertex fields: the normal and K from the patch that sampled the vertex first (at its
// parameters; where that patch is singular, at the point nudged towards its domain's centre),
// H and `regular` from the mesh; uv are those parameters in that patch.
#include <string>

#include "bezierpde/jobs/run_job.h"

namespace bpde {

/// The extremal of job.problem.energy on *job.complex. Throws the solver's InvalidInput errors.
SolveOutcome run_complex_job(const Job& job);

/// result.json and the surface files of a complex job's outcome (out.complex), all or nothing.
WrittenResult write_complex_result(const std::string& dir, const Job& job, const SolveOutcome& out);

}  // namespace bpde
