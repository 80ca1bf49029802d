#include "bezierpde/io/complex_job.h"

#include "bezierpde/complex/refine.h"
#include "bezierpde/core/errors.h"
#include "bezierpde/io/error_path.h"
#include "bezierpde/io/boundary_json.h"
#include "bezierpde/io/complex_json.h"
#include "bezierpde/solvers/complex/complex_extremal.h"
#include "bezierpde/tensor/tensor_net.h"
#include "bezierpde/triangular/triangular_net.h"

namespace bpde {
namespace {

std::vector<Loop> loops_from_json(const Json& j, const std::string& path) {
  if (!j.is_array() || j.empty()) throw ParseError(path + ": expected an array of loops (arrays of curves)");
  std::vector<Loop> loops;
  for (std::size_t l = 0; l < j.size(); ++l) {
    const std::string lp = path + "[" + std::to_string(l) + "]";
    if (!j[l].is_array() || j[l].empty()) throw ParseError(lp + ": expected a non-empty array of curves");
    Loop loop;
    for (std::size_t k = 0; k < j[l].size(); ++k) loop.push_back(curve_from_json(j[l][k], lp + "[" + std::to_string(k) + "]"));
    loops.push_back(std::move(loop));
  }
  return loops;
}


/// The user's layout: {"vertices": [[x,y,z], ...], "faces": [[a,b,c(,d)], ...],
/// "boundary": [{"from": a, "to": b, "loop": l, "curve": k, "range": [t0, t1]}, ...]}.
LoopComplex user_layout(const Json& j, const std::string& path, PatchKind kind, int n, const std::vector<Loop>& loops,
                        const LoopOptions& options) {
  using namespace json_read;
  require_object(j, path);
  check_keys(j, path, {"vertices", "faces", "boundary"});
  const Layout L = layout_vertices_and_faces_from_json(j, path, kind);
  const Json& boundary = field(j, path, "boundary");
  if (!boundary.is_array()) throw ParseError(path + ".boundary: expected an array of boundary edges");
  std::vector<LayoutBoundaryEdge> edges;
  for (std::size_t k = 0; k < boundary.size(); ++k) {
    const std::string bp = path + ".boundary[" + std::to_string(k) + "]";
    edges.push_back(layout_boundary_edge_from_json(boundary[k], bp));
  }
  return at_path(path, [&] { return layout_complex(L, n, loops, edges, options); });
}

/// data.complex: data.coarse refined data.refine times, after the patch and Gram-entry limits.
void build_refined(ComplexJobData& data, int n, const std::string& path) {
  const long long patches = static_cast<long long>(data.coarse.complex.patches.size()) << (2 * data.refine);
  if (patches > kMaxComplexPatches)
    throw SizeError(path + ": " + std::to_string(data.coarse.complex.patches.size()) + " patches refined " +
                    std::to_string(data.refine) + " times are " + std::to_string(patches) + ", more than " +
                    std::to_string(kMaxComplexPatches));
  const long long per_patch = static_cast<long long>(data.coarse.complex.patches.front().points.size());
  if (patches * per_patch * per_patch > kMaxComplexGramEntries)
    throw SizeError(path + ": " + std::to_string(patches) + " patches of degree " + std::to_string(n) + " need " +
                    std::to_string(patches * per_patch * per_patch) + " Gram entries, more than " +
                    std::to_string(kMaxComplexGramEntries) + " (a lower degree or less refinement)");
  data.complex = data.coarse.complex;
  for (int r = 0; r < data.refine; ++r) data.complex = refine_h(data.complex);
  if (data.refit)
    data.coarse.fits = at_path(path + ".loops", [&] {
      return refit_boundary(data.complex, data.coarse, data.refine, data.loops, data.options);
    });
  if (data.continuity == Continuity::C1) {
    data.domain = at_path(path + ".continuity", [&] {
      return layout_domain(data.coarse.layout, layout_domain_positions(data.coarse.layout));
    });
    for (int r = 0; r < data.refine; ++r) data.domain = refine_domain_h(data.domain);
  }
}


}  // namespace

bool is_complex_boundary(const Json& job) {
  return job.is_object() && job.contains("boundary") && job["boundary"].is_object() &&
         job["boundary"].contains("type") && job["boundary"]["type"] == "complex";
}

ComplexJobData complex_from_json(const Json& j, const std::string& path, FitMethod default_fit) {
  using namespace json_read;
  require_object(j, path);
  check_keys(j, path, {"type", "patch", "degree", "refine", "refit", "loops", "layout", "fit", "corner_tolerance",
                       "continuity"});
  const std::pair<PatchKind, int> patch_and_degree = complex_patch_and_degree(j, path);
  const PatchKind kind = patch_and_degree.first;  // (not a structured binding: lambdas capture these)
  const int n = patch_and_degree.second;
  ComplexJobData data;
  if (j.contains("refine")) data.refine = integer(j["refine"], path + ".refine");
  if (data.refine < 0 || data.refine > kMaxComplexRefine)
    throw SizeError(path + ".refine: must be in 0.." + std::to_string(kMaxComplexRefine) + ", got " +
                    std::to_string(data.refine));
  if (j.contains("refit")) {
    if (!j["refit"].is_boolean()) throw ParseError(path + ".refit: expected true or false");
    data.refit = j["refit"].get<bool>();
  }
  if (j.contains("continuity")) {
    const std::string c = string(j["continuity"], path + ".continuity");
    if (c != "C0" && c != "C1") throw ParseError(path + ".continuity: expected \"C0\" or \"C1\", got \"" + c + "\"");
    data.continuity = c == "C1" ? Continuity::C1 : Continuity::C0;
    if (data.continuity == Continuity::C1 && kind != PatchKind::triangular)
      throw ParameterError(path + ".continuity: C1 takes triangular complexes (FORMATS.md \"Patch complexes\")");
  }
  LoopOptions options;
  options.method = default_fit;
  if (j.contains("fit")) {
    const std::string f = string(j["fit"], path + ".fit");
    if (f == "interpolation") options.method = FitMethod::Interpolation;
    else if (f == "least-squares") options.method = FitMethod::LeastSquares;
    else if (f == "geometric") options.method = FitMethod::Geometric;
    else throw ParseError(path + ".fit: unknown fit \"" + f + "\" (expected interpolation, least-squares or geometric)");
  }
  if (j.contains("corner_tolerance")) {
    options.corner_tolerance = number(j["corner_tolerance"], path + ".corner_tolerance");
    if (!(options.corner_tolerance > 0)) throw ParameterError(path + ".corner_tolerance: must be > 0");
  }
  data.loops = loops_from_json(field(j, path, "loops"), path + ".loops");
  data.options = options;
  if (j.contains("layout")) {
    data.user_layout = true;
    data.coarse = user_layout(j["layout"], path + ".layout", kind, n, data.loops, options);
    data.layout = data.coarse.layout;
    data.layout_boundary = data.coarse.boundary;
  } else {
    data.coarse = at_path(path + ".loops", [&] { return loop_complex(kind, n, data.loops, options); });
  }
  build_refined(data, n, path);
  return data;
}

ComplexJobData complex_job_at(const ComplexJobData& data, int n, int refine, const std::string& path) {
  if (n < 1 || n > kMaxComplexExtremalDegree)
    throw DegreeError(path + ".degree: a complex takes degrees 1.." + std::to_string(kMaxComplexExtremalDegree) +
                      " (the Bernstein Gram systems lose a digit per degree), got " + std::to_string(n));
  if (refine < 0 || refine > kMaxComplexRefine)
    throw SizeError(path + ".refine: must be in 0.." + std::to_string(kMaxComplexRefine) + ", got " +
                    std::to_string(refine));
  ComplexJobData out = data;
  out.refine = refine;
  const PatchKind kind = data.coarse.complex.patches.front().kind;
  if (data.user_layout)
    out.coarse = at_path(path + ".layout", [&] {
      return layout_complex(data.layout, n, data.loops, data.layout_boundary, data.options);
    });
  else
    out.coarse = at_path(path + ".loops", [&] { return loop_complex(kind, n, data.loops, data.options); });
  build_refined(out, n, path);
  return out;
}

Json complex_to_json(const ComplexJobData& data, const PatchComplex& solved) {
  ComplexNetFile file;
  file.complex = solved;
  file.layout = data.coarse.layout;
  file.refine = data.refine;
  file.refit = data.refit;
  file.boundary = data.coarse.boundary;
  return complex_net_to_json(file);
}

}  // namespace bpde
