#pragma once
// Jobs of `bpde solve` (FORMATS.md "Jobs"): the file format. The job layer (jobs/run_job.h) adds
// the validation against the solvers' requirements, so that bad input (exit 2) is rejected before
// anything runs and never leaves files behind.
#include <memory>
#include <optional>
#include <string>

#include "bezierpde/core/fixed_set.h"
#include "bezierpde/core/mesh.h"
#include "bezierpde/energies/energy_spec.h"
#include "bezierpde/io/complex_job.h"
#include "bezierpde/io/json_io.h"
#include "bezierpde/io/mesh_io.h"
#include "bezierpde/solvers/cmc/cmc.h"

namespace bpde {

enum class ProblemKind { Extremal, Pde, Tetraharmonic, BiharmonicLoad, CmcH, CmcV };
enum class PdeMethod { Explicit, Lu };

std::string to_string(ProblemKind k);
std::string to_string(PdeMethod m);

struct Problem {
  ProblemKind kind = ProblemKind::Extremal;
  /// extremal: the energy; pde: the operator (its Euler–Lagrange operator).
  std::optional<EnergySpec> energy;
  PdeMethod method = PdeMethod::Lu;      ///< pde, tetraharmonic (default lu)
  CmcSolver solver = CmcSolver::Newton;  ///< cmc (default: default_cmc_solver of the functional and form)
  double H = 0.0;                        ///< cmc with "H"
  double V = 0.0;                        ///< cmc with "V"
  /// cmc: "dirichlet" (D_H, default), "area" (A_H) or "mean-curvature" (least squares of H_x − H)
  CmcFunctionalKind functional = CmcFunctionalKind::Dirichlet;
  double mean_curvature_tolerance = 1e-6;  ///< cmc, functional mean-curvature: converged when √Φ ≤ this
  /// cmc, functional area: "start": "mean-curvature" (the default: the mean-curvature-start route
  /// first), "dirichlet" (the routes from the D_H critical point) or "minimal-surface" (the branch
  /// from H = 0 alone); CmcOptions::area_start
  AreaStart area_start = AreaStart::MeanCurvature;
};

/// A job's `tolerance` (FORMATS.md "Patch complexes", "Tolerances and refinement"): what the
/// result must meet, and the limits of the refinement rounds that try to meet it. Complex jobs
/// only. Absent tolerances are not checked.
struct Tolerance {
  std::optional<double> mean_curvature;  ///< cmc: max |H(x) − H| over the certificate's samples
  std::optional<double> seam_angle;      ///< degrees: seam_angle_max
  std::optional<double> boundary;        ///< the certificate's boundary error (a distance)
  int max_degree = 0;                    ///< the highest degree a round may use (default kMaxToleranceDegree)
  int max_refine = 0;                    ///< the most h refinements (default kMaxComplexRefine)
  int max_rounds = 0;                    ///< the most rounds (default kMaxToleranceRounds)
};
/// The defaults of Tolerance's limits: degree 10 (each round is a full solve: the cmc area solve
/// of the spherical cap on a fan of 6 patches took 2 s at degree 4 and 22 s at degree 8 on the
/// build machine, and the Gram systems lose a digit per degree), and 8 rounds.
inline constexpr int kMaxToleranceDegree = 10;
inline constexpr int kMaxToleranceRounds = 8;

struct Job {
  Net net;
  FixedSet fixed = FixedSet::Boundary;
  Problem problem;
  int samples = 50;  ///< mesh resolution of the surface files, 1..kMaxSamples
  /// A job given in the "boundary" form (io/boundary_json.h): how each edge was fitted, the
  /// report's `boundary_fit` (boundary_fit_to_json); null when the job gives the net.
  Json boundary_fit = nullptr;
  /// bezierpde extensions (FORMATS.md): `"mesh_format": "ascii" | "binary"` for surface.ply and
  /// surface.vtp; `"export": ["step", "html"]` for DIR/surface.step and DIR/view.html.
  MeshFormat mesh_format = MeshFormat::Ascii;
  bool export_step = false;
  bool export_html = false;
  /// A job whose boundary is a patch complex (FORMATS.md "Patch complexes"): the complex, built
  /// and refined when the job is read; `net` is then its first patch (for messages only).
  std::shared_ptr<const ComplexJobData> complex = nullptr;
  /// `"tolerance"` (complex jobs): solve, measure, refine until it holds (jobs/run_complex.h).
  std::optional<Tolerance> tolerance = std::nullopt;
};

// kMaxSamples (core/mesh.h): the largest accepted `samples`, bounded by the memory it needs.

/// An ENERGY object (FORMATS.md). `allow_operator`: the "operator" form is accepted (pde only).
EnergySpec energy_from_json(const Json& j, const std::string& path, bool allow_operator);
/// The `--energy` argument of `bpde energy`: a bare name or an ENERGY JSON object. Errors name the
/// argument as `name` (the Python module passes its own argument's name).
EnergySpec energy_from_argument(const std::string& arg, const std::string& name = "--energy");

/// Parse a whole job: the net (or the "boundary" form, FORMATS.md "Boundary curves"), the fixed set, the problem (each field strictly, as FORMATS.md
/// says). Throws InvalidInput subclasses naming the JSON path. Whether the solvers take the
/// combination of net, fixed set and problem is checked by the job layer against the solvers'
/// requirements: use job_from_json / read_job_file of jobs/run_job.h, which parse and validate.
Job parse_job(const Json& j, const std::string& source = "job");
Job parse_job_file(const std::string& path);

}  // namespace bpde
