#pragma once
// Run a job (FORMATS.md "Jobs") and write its results: the library entry point behind
// `bpde solve`, usable from C++ directly.
//
//   bpde::Job job = bpde::read_job_file("job.json");    // throws InvalidInput on bad input
//   bpde::SolveOutcome out = bpde::run_job(job);         // no files written
//   int status = bpde::write_outcome("out/dir", job, out); // 0 solved, 1 no solution
//
// One table (jobs/run_job.cpp) maps each problem kind and net kind to the solver that runs it and
// to that solver's requirements (solvers/requirements.h, declared next to each solver's Options).
// The same table validates a job when it is read and dispatches it when it runs.
#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "bezierpde/checks/mesh_checks.h"
#include "bezierpde/core/mesh.h"
#include "bezierpde/energies/cmc.h"
#include "bezierpde/io/job.h"
#include "bezierpde/jobs/exports.h"
#include "bezierpde/solvers/cmc/cmc.h"
#include "bezierpde/solvers/requirements.h"
#include "bezierpde/solvers/summary.h"

namespace bpde {

/// Parse (io/job.h) and validate (validate_job) a job. Throws InvalidInput subclasses naming the
/// JSON path or the file; nothing has run when it throws.
Job job_from_json(const Json& j, const std::string& source = "job");
Job read_job_file(const std::string& path);

/// Check the combination of net, fixed set and problem against the requirements of the solver
/// that would run it (UnsupportedProblem, DegreeError; messages start with `where: `).
void validate_job(const Job& job, const std::string& where = "job");

/// The kind and degrees of a net.
NetShape net_shape(const Net& net);

/// The figures of a solve, typed, taken from the solver's result struct: the report (FORMATS.md
/// "Results") is written from them, and so is the summary `bpde solve` prints
/// (jobs/solve_summary.h). A figure the problem does not report is empty; a reported value that is
/// not finite (a failed solve) is written as null.
struct SolveFigures {
  ProblemKind problem = ProblemKind::Extremal;
  Summary summary;                        ///< converged and status, message, seconds
  std::string energy_name;                ///< the energy or operator (extremal, pde); else empty
  std::string method;                     ///< "explicit" | "lu" (pde, tetraharmonic); else empty
  std::string solver;                     ///< "newton" | "ceres" | "nlopt" (cmc); else empty
  std::optional<int> iterations;          ///< summary.iterations where > 0; cmc: always
  std::optional<int> continuation_steps;  ///< cmc
  std::optional<double> energy;           ///< the value of the energy or functional solved
  std::optional<double> D, volume, H;     ///< cmc: Dirichlet energy, volume, H of the net
  std::optional<double> residual;         ///< cmc: summary.residual
  std::optional<double> pde_residual;     ///< pde_residual of the net (solvers/pde/pde_residual.h)
};

/// What a solve produced: the net, its figures, the report object (FORMATS.md "Results": the
/// figures and the solver's own fields), extra top-level result fields (e.g. {"load": NET} for
/// biharmonic-load) and how it ended.
struct SolveOutcome {
  Net net;
  SolveFigures figures;
  Json report = Json::object();
  Json extra = Json::object();
  /// status == Status::Converged (the exit code follows it).
  bool converged = true;
  Status status = Status::Converged;
  /// A complex job (Job::complex): the solved complex; `net` is then its first patch.
  std::shared_ptr<const PatchComplex> complex = nullptr;
  /// A complex job: the complex data it was solved on (the job's, or the last refinement
  /// round's: its degree, refine and boundary fits); null: the job's.
  std::shared_ptr<const ComplexJobData> complex_data = nullptr;
};

/// The CmcOptions of a cmc job (H or V form, functional, solver, fixed set, start, progress).
CmcOptions job_cmc_options(const Job& job);
/// The figures and report fields of a cmc result (D, V, H, energy, steps, residual, functional,
/// area, quadrature, routes, parametrisation) into `out`; NetT: TriangularNet, TensorNet or
/// PatchComplex (a complex job, jobs/run_complex.h).
template <class NetT>
void add_cmc_figures(SolveOutcome& out, const CmcOptions& o, const CmcResult<NetT>& r);

/// The status of a solver's Summary, checked against its contract (solvers/summary.h): a
/// Converged status with converged = false, or the reverse, is a broken invariant (InternalError).
Status checked_status(const Summary& s);

/// The exit code of the command for a status: 0 for Converged, else 1 (FORMATS.md).
inline int exit_code(Status s) { return s == Status::Converged ? 0 : 1; }

/// Validate (validate_job) and run a job. Throws InvalidInput for problems the solvers reject; a
/// valid problem without a solution returns a non-Converged status with report["message"].
SolveOutcome run_job(const Job& job);

/// What a result is written from: one net, or a solved patch complex with its job's complex data
/// (result.json's "net", FORMATS.md "Patch complexes"). Everything after the solve (the
/// report's sampled figures, the certificate, the summary, the files) takes this one form.
struct ResultSurface {
  Net net;                                             ///< the net (a complex: its first patch, unused)
  std::shared_ptr<const PatchComplex> complex;         ///< a complex result, else null
  std::shared_ptr<const ComplexJobData> complex_data;  ///< its layout and loops (with `complex`)
  bool is_complex() const { return complex != nullptr; }
};
/// The surface of a job's outcome (out.complex with job.complex, else out.net).
ResultSurface result_surface(const Job& job, const SolveOutcome& out);

/// A result surface sampled: the mesh the files are written from and where each vertex lies.
/// A single net: sample_net's mesh (its layout, core/mesh.h), patch 0, (u, v) the sample's domain
/// point (a bspline net: relative to its knot domain, as the statistics have always counted it).
/// A complex: the welded mesh of complex/complex_mesh.h, each vertex in the first patch that
/// sampled it.
struct SampledSurface {
  TriangleMesh mesh;
  Eigen::VectorXi vertex_patch;    ///< per vertex: its patch (a single net: 0)
  Eigen::MatrixX2d uv;             ///< per vertex: its domain point (u, v) in that patch
  Eigen::VectorXi triangle_patch;  ///< per triangle: its patch (a complex; empty for a single net)
  /// per vertex: 1 when the mean-curvature statistics count it (below, kStatsCornerMargin)
  Eigen::Matrix<std::uint8_t, Eigen::Dynamic, 1> counted;
  bool complex = false;
  int samples = 0;  ///< N: samples per (patch) edge it was sampled at
};

/// The corner margin of the mean-curvature statistics, in each patch's domain: a sample within
/// it of a patch corner that lies on the surface's boundary is left out (the corners of a single
/// net are all on its boundary; a circle split into arcs makes them nearly singular). A complex
/// leaves out only its boundary corners where the boundary turns (kStatsCornerAngle); its inner
/// corners (where patches meet inside) and the layout vertices on smooth stretches of a loop are
/// counted: the statistics and the certificate cover its seams.
inline constexpr double kStatsCornerMargin = 0.1;
/// A complex's boundary corner is left out only where the boundary turns by more than this angle
/// (radians, 2°: the default `smooth_corner_angle` of single nets): at a layout vertex on a smooth
/// stretch of a loop the samples count.
inline constexpr double kStatsCornerAngle = 0.03490658503988659;

/// A net's sampled surface from its mesh at `samples` (sample_net(net, samples)).
SampledSurface sampled_net(const Net& net, TriangleMesh mesh, int samples);
/// A complex's welded mesh at `samples` per patch edge.
SampledSurface sampled_complex(const PatchComplex& c, int samples);
/// sampled_net or sampled_complex, reporting the sampling stage to job_progress().
SampledSurface sample_surface(const ResultSurface& s, int samples);

/// Mean-curvature statistics over the counted samples, with the vertices where min and max are
/// taken (the first in vertex order; -1 when count is 0). at_min / at_max are their (u, v).
struct SurfaceStats : MeanCurvatureStats {
  Eigen::Index vertex_min = -1, vertex_max = -1;
};
SurfaceStats surface_stats(const SampledSurface& s);
/// surface_stats(sampled_net(...)): the statistics of a sampled net, away from the corners.
MeanCurvatureStats surface_mean_curvature_stats(const Net& net, const TriangleMesh& mesh, int samples);
/// The same as the report writes it: {min, max, mean, count, at_min, at_max} (a complex adds
/// patch_at_min, patch_at_max), null when no sample qualifies.
Json mean_curvature_stats(const Net& net, const TriangleMesh& mesh, int samples);
Json surface_stats_json(const SurfaceStats& st, const SampledSurface& s);
/// The object `bpde check` prints for a mesh (CGAL figures).
Json check_report(const TriangleMesh& mesh);

/// The files of a result folder: result.json and the surface files (result_file_names), or the
/// surface files alone (`bpde sample`: surface.obj, surface.ply, surface.vtp, net.obj);
/// output_file_names adds the requested exports (surface.step, view.html).
const std::vector<std::string>& result_file_names();
const std::vector<std::string>& surface_file_names();
std::vector<std::string> output_file_names(bool with_result, const Exports& exports);

/// Throw FileError now when DIR cannot receive `names` (io/output_folder.h OutputFolder::check),
/// so that a command fails before it runs a solver whose result it could not write.
void check_output_dir(const std::string& dir, const std::vector<std::string>& names = result_file_names());

/// Write DIR all or nothing (io/output_folder.h): result.json (unless `result` is null) and the
/// surface files of `net` and its sampled `mesh` (PLY and VTP in `format`), and the requested
/// exports (DIR/surface.step, DIR/view.html showing result's report). DIR is created with its
/// parents if missing; an existing DIR keeps its other files. On FileError DIR and its parents are
/// as they were.
void write_output_files(const std::string& dir, const Json* result, const Net& net, const TriangleMesh& mesh,
                        MeshFormat format = MeshFormat::Ascii, const Exports& exports = {});
/// The same for any result surface: a complex writes its welded mesh (surface.vtp with the cell
/// data `patch`) and net.obj with every control point once (jobs/run_complex.h).
void write_output_files(const std::string& dir, const Json* result, const ResultSurface& surface,
                        const SampledSurface& sampled, MeshFormat format = MeshFormat::Ascii,
                        const Exports& exports = {});

/// How far a CMC result is from what was asked (report.certificate, FORMATS.md): the largest
/// |H(x) − H| over the report's samples away from the corners (the samples of
/// mean_curvature_stats), where it is, and that deviation relative to the reference curvature
/// max(|H|, 1/R), R the radius of the sampled surface's bounding sphere (half its bounding-box
/// diagonal), so that a minimal surface (H = 0) is measured against its own size. A result whose
/// relative deviation exceeds kCmcDeviationLimit is not presented as a CMC surface: the summary
/// says so.
struct CmcCertificate {
  double H = 0;                       ///< the H of the result (asked in the H form, found in the V form)
  double deviation = 0;               ///< max |H(x) − H| over the samples
  std::array<double, 2> at{-1, -1};   ///< the domain point (u, v) of that sample
  int patch = -1;                     ///< its patch (a complex; -1 for a single net)
  std::optional<std::array<double, 3>> point;  ///< the sample's point x(u, v)
  double reference_curvature = 0;     ///< max(|H|, 1/R)
  double relative = 0;                ///< deviation / reference_curvature
  bool near_constant() const;         ///< relative <= kCmcDeviationLimit
};
/// 5 %: far beyond the discretisation error of a converged area solve (1e-4 and below at degree
/// 10 on the reference boundaries, docs/cmc.md), and beyond what the D_H approximations of the
/// paper's figures reach at the degrees they use.
inline constexpr double kCmcDeviationLimit = 0.05;
/// The certificate of a CMC result from its mesh statistics (count > 0) and its H.
CmcCertificate cmc_certificate(const MeanCurvatureStats& stats, double H, const TriangleMesh& mesh);
/// The same located on its sampled surface: the patch and point of the worst sample.
CmcCertificate cmc_certificate(const SurfaceStats& stats, double H, const SampledSurface& s);
/// report.certificate as FORMATS.md writes it (`at` null where the statistics have no location;
/// `patch` for a complex; `point` where located). `boundary` (report.boundary_error) is added by
/// complete_report.
Json certificate_json(const CmcCertificate& c);

/// How far the surface's boundary is from the boundary curves the job gave (a job in the boundary
/// form; report.boundary_error, and certificate.boundary of a cmc result). A complex: the largest
/// distance from the loops' curves, sampled densely, to the boundary edges (jobs/run_complex.h),
/// with where it is. A single net: the largest max_error of report.boundary_fit and its edge
/// (the fit keeps no location: `at` null).
struct BoundaryError {
  double max_error = 0;
  int edge = -1;                              ///< boundary_fit's entry (edge) where it is
  std::optional<int> loop, curve;             ///< a complex: the loop and curve there
  std::optional<double> t;                    ///< the curve's parameter there
  std::optional<std::array<double, 3>> point; ///< the curve's point there
};
Json boundary_error_json(const BoundaryError& e);
/// The boundary error of a single net from its boundary_fit list (null list: none).
std::optional<BoundaryError> fit_boundary_error(const Json& boundary_fit);

/// What was written: the whole result.json object, the exit code, and the figures write_result
/// added to the report (empty where the report had them already).
struct WrittenResult {
  Json result;
  int exit_code = 0;
  std::optional<SurfaceStats> mean_curvature;  ///< count 0: no sample away from the corners
  std::optional<MeshCheckReport> check;
  std::optional<CmcCertificate> certificate;  ///< CMC results with samples away from the corners
};

/// The report as result.json holds it: `report` with `mean_curvature`, `check` (unless already
/// present) and, for a cmc result, its `certificate`, from the sampled `mesh` of `net` (`samples`
/// per side). The figures it computed go into `added` when given.
Json complete_report(const Net& net, const TriangleMesh& mesh, int samples, Json report, WrittenResult* added = nullptr);
/// The same for any sampled result surface.
Json complete_report(const SampledSurface& sampled, Json report, WrittenResult* added = nullptr);

/// Write DIR/result.json and surface.obj, surface.ply, surface.vtp, net.obj (write_output_files:
/// all or nothing; PLY and VTP in `format`). The report is completed by complete_report. The exit
/// code is exit_code(status).
WrittenResult write_result(const std::string& dir, const Net& net, const TriangleMesh& mesh, int samples, Json report,
                           const Json& extra, Status status, MeshFormat format = MeshFormat::Ascii,
                           const Exports& exports = {});
/// The same for any result surface: result.json's "net" is the net, or the complex
/// (io/complex_job.h complex_to_json).
WrittenResult write_result(const std::string& dir, const ResultSurface& surface, const SampledSurface& sampled,
                           Json report, const Json& extra, Status status, MeshFormat format = MeshFormat::Ascii,
                           const Exports& exports = {});
/// result.json's object for a job's outcome without writing files: the report completed as
/// write_job_result completes it (the Python module's solve without an output folder).
Json job_result_json(const Job& job, const SolveOutcome& out);
/// write_result for a job's outcome, sampled at job.samples, in job.mesh_format, and the job's
/// exports (job.export_step: DIR/surface.step; job.export_html: DIR/view.html; jobs/exports.h).
WrittenResult write_job_result(const std::string& dir, const Job& job, const SolveOutcome& out);
/// write_job_result's exit code: 0 if converged, else 1.
int write_outcome(const std::string& dir, const Job& job, const SolveOutcome& out);

}  // namespace bpde
