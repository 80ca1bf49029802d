#pragma once
// The "complex" boundary form of a job (FORMATS.md "Patch complexes"): a surface of several
// patches spanning boundary loops, on an automatic layout or one given by the user, refined in
// h `refine` times. Parsing builds the complex (the loops checked, the layout made and its
// boundary fitted at `degree`, then refined), so every input error surfaces before anything runs.
#include <memory>
#include <string>
#include <vector>

#include "bezierpde/complex/layout_loops.h"
#include "bezierpde/complex/planar_domain.h"
#include "bezierpde/io/json_io.h"

namespace bpde {

/// The complex of a job: the loop complex at the job's degree (its layout, boundary pieces and
/// fits) and the complex refined `refine` times in h (patch p of it refines layout face
/// p / 4^refine). With `refit`, the refined complex's boundary is fitted again on the refined
/// layout (refit_boundary, complex/layout_loops.h) and coarse.fits are those fits (one entry per
/// coarse boundary edge, the largest error of its pieces).
struct ComplexJobData {
  LoopComplex coarse;
  PatchComplex complex;
  int refine = 0;
  /// What the complex was built from, so that it can be built again at another degree or
  /// refinement (complex_job_at: the tolerance rounds, jobs/run_complex.h): the loops, the fit
  /// options and, for a user layout, the layout and its boundary pieces as given.
  std::vector<Loop> loops;
  LoopOptions options;
  bool user_layout = false;
  Layout layout;
  std::vector<LayoutBoundaryEdge> layout_boundary;
  bool refit = false;
  Continuity continuity = Continuity::C0;  ///< "continuity": "C0" (default) or "C1" (triangular only)
  /// C1: the planar domain of `complex` (layout_domain_positions of the coarse layout, refined)
  std::vector<DomainTriangle> domain;
};

/// True when j is a job whose "boundary" has "type": "complex".
bool is_complex_boundary(const Json& job);

/// The "boundary" object of a complex job (path e.g. "job.boundary"). Throws ParseError (unknown
/// fields, wrong types), DegreeError (degree outside 1..kMaxComplexExtremalDegree), SizeError
/// (refine outside 0..kMaxComplexRefine, more than kMaxComplexPatches patches after refinement or
/// more than kMaxComplexGramEntries Gram entries (solvers/complex/complex_extremal.h), loops), LoopNotClosedError, CurvesOutOfOrderError, LayoutMismatchError, ParameterError and the
/// fits' errors, each message starting with its JSON path.
ComplexJobData complex_from_json(const Json& j, const std::string& path, FitMethod default_fit);

/// The same job's complex at degree n, refined `refine` times: the boundary fitted again at n
/// (a higher degree fits the loops more closely), the layout unchanged. Throws the DegreeError /
/// SizeError of complex_from_json (the degree, refine, patch and Gram-entry limits), with `path`.
ComplexJobData complex_job_at(const ComplexJobData& data, int n, int refine, const std::string& path);

/// The result.json "net" of a complex: {"type": "complex", "patch", "degree", "refine", "refit",
/// "patches": [NET, ...], "layout": {"vertices", "faces", "boundary": [{"from", "to", "loop",
/// "curve", "range"}]}}.
Json complex_to_json(const ComplexJobData& data, const PatchComplex& solved);

}  // namespace bpde
