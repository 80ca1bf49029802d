#include "bezierpde/io/job.h"

#include "bezierpde/complex/complex_mesh.h"
#include "bezierpde/complex/refine.h"
#include "bezierpde/solvers/complex/complex_extremal.h"

#include <cmath>
#include <cstdio>

#include "bezierpde/core/errors.h"
#include "bezierpde/io/boundary_json.h"
#include "bezierpde/io/step_export.h"

namespace bpde {

std::string to_string(ProblemKind k) {
  switch (k) {
    case ProblemKind::Extremal:
      return "extremal";
    case ProblemKind::Pde:
      return "pde";
    case ProblemKind::Tetraharmonic:
      return "tetraharmonic";
    case ProblemKind::BiharmonicLoad:
      return "biharmonic-load";
    case ProblemKind::CmcH:
    case ProblemKind::CmcV:
      return "cmc";
  }
  return "?";
}
std::string to_string(PdeMethod m) { return m == PdeMethod::Explicit ? "explicit" : "lu"; }

EnergySpec energy_from_json(const Json& j, const std::string& path, bool allow_operator) {
  using namespace json_read;
  require_object(j, path);
  const std::string name = string(field(j, path, "name"), path + ".name");
  auto coeffs = [&](int n) { return numbers(field(j, path, "coeffs"), path + ".coeffs", n); };
  if (name == "dirichlet" || name == "biharmonic" || name == "laplacian-squared" || name == "coons") {
    check_keys(j, path, {"name"});
    if (name == "dirichlet") return EnergySpec::dirichlet();
    if (name == "biharmonic") return EnergySpec::biharmonic();
    if (name == "laplacian-squared") return EnergySpec::laplacian_squared();
    return EnergySpec::coons();
  }
  if (name == "second-order") {
    check_keys(j, path, {"name", "coeffs"});
    const auto c = coeffs(3);
    return EnergySpec::second_order(c[0], c[1], c[2]);
  }
  if (name == "modified-biharmonic") {
    check_keys(j, path, {"name", "alpha"});
    return EnergySpec::modified_biharmonic(number(field(j, path, "alpha"), path + ".alpha"));
  }
  if (name == "fourth-order" || name == "operator") {
    if (name == "operator" && !allow_operator)
      throw ParseError(path + ": energy \"operator\" is only for problems of kind \"pde\"");
    check_keys(j, path, {"name", "coeffs"});
    const auto c = coeffs(5);
    const std::array<double, 5> a{c[0], c[1], c[2], c[3], c[4]};
    if (std::abs(a[0]) + std::abs(a[1]) + std::abs(a[2]) + std::abs(a[3]) + std::abs(a[4]) == 0.0)
      throw ParameterError(path + ".coeffs: all five coefficients are zero");
    return name == "operator" ? EnergySpec::pde_operator(a) : EnergySpec::fourth_order(a);
  }
  if (name == "gnorm") {
    if (j.contains("G")) {
      check_keys(j, path, {"name", "G"});
      const Json& G = field(j, path, "G");
      if (!G.is_array() || G.size() != 2) throw SizeError(path + ".G: expected [[g11, g12], [g21, g22]]");
      const auto r0 = numbers(G[0], path + ".G[0]", 2), r1 = numbers(G[1], path + ".G[1]", 2);
      Eigen::Matrix2d M;
      M << r0[0], r0[1], r1[0], r1[1];
      try {
        return EnergySpec::gnorm(M);
      } catch (const ParameterError& e) {
        throw ParameterError(path + ".G: " + e.what());
      }
    }
    check_keys(j, path, {"name", "rho", "t"});
    const double rho = number(field(j, path, "rho"), path + ".rho");
    const double t = number(field(j, path, "t"), path + ".t");
    try {
      return EnergySpec::gnorm(rho, t);
    } catch (const ParameterError& e) {
      throw ParameterError(path + ": " + e.what());
    }
  }
  throw ParseError(path + ".name: unknown energy \"" + name +
                   "\" (expected dirichlet, second-order, biharmonic, laplacian-squared, coons, "
                   "modified-biharmonic, fourth-order, gnorm" +
                   std::string(allow_operator ? ", operator" : "") + ")");
}

EnergySpec energy_from_argument(const std::string& arg, const std::string& name) {
  if (!arg.empty() && arg.front() == '{') return energy_from_json(parse_json(arg, name), name, false);
  if (arg == "dirichlet") return EnergySpec::dirichlet();
  if (arg == "biharmonic") return EnergySpec::biharmonic();
  if (arg == "laplacian-squared") return EnergySpec::laplacian_squared();
  if (arg == "coons") return EnergySpec::coons();
  throw ParseError(name + ": unknown energy \"" + arg +
                   "\" (a bare name is one of dirichlet, biharmonic, laplacian-squared, coons, cmc; "
                   "others are given as a JSON object such as {\"name\": \"gnorm\", \"rho\": 2, \"t\": 1})");
}

namespace {

FixedSet fixed_from_string(const std::string& s, const std::string& path) {
  if (s == "boundary") return FixedSet::Boundary;
  if (s == "boundary+adjacent") return FixedSet::BoundaryAdjacent;
  if (s == "u-boundaries") return FixedSet::UBoundaries;
  throw ParseError(path + ": unknown fixed set \"" + s + "\" (expected boundary, boundary+adjacent or u-boundaries)");
}

Problem problem_from_json(const Json& j, const std::string& path) {
  using namespace json_read;
  require_object(j, path);
  const std::string kind = string(field(j, path, "kind"), path + ".kind");
  Problem p;
  auto method = [&]() {
    if (!j.contains("method")) return PdeMethod::Lu;
    const std::string m = string(j["method"], path + ".method");
    if (m == "explicit") return PdeMethod::Explicit;
    if (m == "lu") return PdeMethod::Lu;
    throw ParseError(path + ".method: unknown method \"" + m + "\" (expected explicit or lu)");
  };
  if (kind == "extremal") {
    check_keys(j, path, {"kind", "energy"});
    p.kind = ProblemKind::Extremal;
    p.energy = energy_from_json(field(j, path, "energy"), path + ".energy", false);
  } else if (kind == "pde") {
    check_keys(j, path, {"kind", "operator", "method"});
    p.kind = ProblemKind::Pde;
    p.energy = energy_from_json(field(j, path, "operator"), path + ".operator", true);
    p.method = method();
  } else if (kind == "tetraharmonic") {
    check_keys(j, path, {"kind", "method"});
    p.kind = ProblemKind::Tetraharmonic;
    p.method = method();
  } else if (kind == "biharmonic-load") {
    check_keys(j, path, {"kind"});
    p.kind = ProblemKind::BiharmonicLoad;
  } else if (kind == "cmc") {
    check_keys(j, path, {"kind", "H", "V", "solver", "functional", "mean_curvature_tolerance", "start"});
    const bool hasH = j.contains("H"), hasV = j.contains("V");
    if (hasH == hasV) throw ParseError(path + ": a cmc problem gives exactly one of \"H\" and \"V\"");
    if (j.contains("functional")) {
      const std::string f = string(j["functional"], path + ".functional");
      if (f != "dirichlet" && f != "area" && f != "mean-curvature")
        throw ParseError(path + ".functional: unknown functional \"" + f +
                         "\" (expected dirichlet, area or mean-curvature)");
      p.functional = parse_cmc_functional(f);
    }
    // Which fields the functional takes, and the solver it runs by default, are the solver's rules
    // (cmc_requirements); whether it takes the solver and the fixed set is checked with the net
    // (jobs/run_job.h validate_job).
    const SolverRequirements rules = cmc_requirements(p.functional, hasV);
    auto refuse = [&](const std::string& key) {
      if (const std::string* why = rules.refusal(key)) throw ParseError(path + "." + key + ": " + *why);
    };
    if (j.contains("mean_curvature_tolerance")) {
      refuse("mean_curvature_tolerance");
      p.mean_curvature_tolerance = number(j["mean_curvature_tolerance"], path + ".mean_curvature_tolerance");
      if (!mean_curvature_tolerance_in_range(p.mean_curvature_tolerance)) {
        char got[32];
        std::snprintf(got, sizeof got, "%g", p.mean_curvature_tolerance);
        throw ParseError(path + ".mean_curvature_tolerance: must be in (0, 1), got " + got);
      }
    }
    if (j.contains("start")) {
      refuse("start");
      try {
        p.area_start = parse_area_start(string(j["start"], path + ".start"));
      } catch (const ParameterError& e) {  // the names live in one place (cmc_solver_name.cpp)
        throw ParseError(path + ".start: " + e.what());
      }
    }
    p.solver = default_cmc_solver(p.functional, hasV);
    if (j.contains("solver")) {
      const std::string s = string(j["solver"], path + ".solver");
      if (s != "newton" && s != "ceres" && s != "nlopt")
        throw ParseError(path + ".solver: unknown solver \"" + s + "\" (expected newton, ceres or nlopt)");
      p.solver = parse_cmc_solver(s);
    }
    if (hasH) {
      p.kind = ProblemKind::CmcH;
      p.H = number(j["H"], path + ".H");
    } else {
      p.kind = ProblemKind::CmcV;
      p.V = number(j["V"], path + ".V");
    }
  } else {
    throw ParseError(path + ".kind: unknown problem kind \"" + kind +
                     "\" (expected extremal, pde, tetraharmonic, biharmonic-load or cmc)");
  }
  return p;
}

// The default `fit` of a "boundary" form (FORMATS.md, "Boundary curves"): "geometric" for the
// functionals whose results do not depend on the boundary's parametrisation (area and
// mean-curvature: only the curve matters, and the orthogonal least squares follows it 60 ... 1e7
// times more closely than the interpolant at n = 4 ... 10), "interpolation" for every other problem
// (the paper's D_H and the extremals depend on the parametrisation the curve is given in). Only a
// peek: the problem is checked in full afterwards, and a malformed one fails there.
FitMethod default_boundary_fit(const Json& j) {
  if (!j.is_object() || !j.contains("problem")) return FitMethod::Interpolation;
  const Json& p = j["problem"];
  if (!p.is_object() || !p.contains("kind") || p["kind"] != "cmc" || !p.contains("functional") ||
      !p["functional"].is_string())
    return FitMethod::Interpolation;
  const std::string f = p["functional"].get<std::string>();
  return f == "area" || f == "mean-curvature" ? FitMethod::Geometric : FitMethod::Interpolation;
}

// What a complex job takes (FORMATS.md "Patch complexes"): the extremal problem or cmc (the
// mean-curvature functional by solver newton only), C⁰ data.
void check_complex_job(const Job& job, const std::string& source) {
  const bool cmc = job.problem.kind == ProblemKind::CmcH || job.problem.kind == ProblemKind::CmcV;
  if (job.problem.kind != ProblemKind::Extremal && !cmc)
    throw UnsupportedProblem(source + ".problem: a complex boundary takes problem \"extremal\" or \"cmc\", not \"" +
                             to_string(job.problem.kind) + "\"");
  if (cmc && job.problem.functional == CmcFunctionalKind::MeanCurvature && job.problem.solver == CmcSolver::Ceres)
    throw UnsupportedProblem(source + ".problem.solver: the \"mean-curvature\" functional on a complex boundary takes "
                             "the solver \"newton\", not \"ceres\"");
  if (job.fixed != FixedSet::Boundary)
    throw UnsupportedProblem(source + ".fixed: a complex boundary takes fixed \"boundary\" (C0 data) only");
  const PatchComplex& c = job.complex->complex;
  const long long vertices = static_cast<long long>(c.patches.size()) * (job.samples + 1) * (job.samples + 1);
  if (vertices > kMaxComplexSampleVertices)
    throw ParameterError(source + ".samples: " + std::to_string(c.patches.size()) + " patches at " +
                         std::to_string(job.samples) + " samples are " + std::to_string(vertices) +
                         " mesh vertices, more than " + std::to_string(kMaxComplexSampleVertices));
}

// `"tolerance"` (FORMATS.md "Patch complexes"): complex jobs only; mean_curvature only for cmc.
Tolerance tolerance_from_json(const Json& j, const std::string& path, const Job& job) {
  using namespace json_read;
  if (!job.complex)
    throw UnsupportedProblem(path + ": tolerances and refinement rounds take a complex boundary "
                             "(\"boundary\": {\"type\": \"complex\", ...}), not a single net");
  require_object(j, path);
  check_keys(j, path, {"mean_curvature", "seam_angle", "boundary", "max_degree", "max_refine", "max_rounds"});
  Tolerance t;
  auto positive = [&](const char* key) -> std::optional<double> {
    if (!j.contains(key)) return std::nullopt;
    const double x = number(j[key], path + "." + key);
    if (!(x > 0) || !std::isfinite(x)) throw ParameterError(path + "." + key + ": must be a number > 0");
    return x;
  };
  t.mean_curvature = positive("mean_curvature");
  t.seam_angle = positive("seam_angle");
  t.boundary = positive("boundary");
  const bool cmc = job.problem.kind == ProblemKind::CmcH || job.problem.kind == ProblemKind::CmcV;
  if (t.mean_curvature && !cmc)
    throw UnsupportedProblem(path + ".mean_curvature: only a cmc problem has a mean-curvature certificate");
  auto limit = [&](const char* key, int lo, int hi, int fallback) {
    if (!j.contains(key)) return fallback;
    const int v = integer(j[key], path + "." + key);
    if (v < lo || v > hi)
      throw ParameterError(path + "." + key + ": must be in " + std::to_string(lo) + ".." + std::to_string(hi) +
                           ", got " + std::to_string(v));
    return v;
  };
  t.max_degree = limit("max_degree", 1, kMaxComplexExtremalDegree, kMaxToleranceDegree);
  t.max_refine = limit("max_refine", 0, kMaxComplexRefine, kMaxComplexRefine);
  t.max_rounds = limit("max_rounds", 1, 100, kMaxToleranceRounds);
  return t;
}

}  // namespace

Job parse_job(const Json& j, const std::string& source) {
  using namespace json_read;
  check_keys(j, source, {"net", "boundary", "fixed", "problem", "samples", "mesh_format", "export", "tolerance"});
  if (j.contains("net") == j.contains("boundary"))
    throw ParseError(source + ": a job gives exactly one of \"net\" and \"boundary\"");
  Job job;
  std::optional<BoundaryNet> b;
  if (j.contains("net")) {
    job.net = net_from_json(j["net"], source + ".net");
  } else if (is_complex_boundary(j)) {
    job.complex = std::make_shared<const ComplexJobData>(
        complex_from_json(j["boundary"], source + ".boundary", default_boundary_fit(j)));
    const PatchComplex& c = job.complex->complex;
    if (c.patches.front().kind == PatchKind::triangular) job.net = triangular_net(c, 0);
    else job.net = tensor_net(c, 0);
    job.boundary_fit = boundary_fit_to_json(job.complex->coarse.fits);
  } else {
    b = boundary_from_json(j["boundary"], source + ".boundary", default_boundary_fit(j));
  }
  if (j.contains("fixed")) job.fixed = fixed_from_string(string(j["fixed"], source + ".fixed"), source + ".fixed");
  if (b) {
    if (job.fixed == FixedSet::BoundaryAdjacent && !b->c1)
      throw ParameterError(source +
                           ".boundary: fixed \"boundary+adjacent\" needs \"tangents\" (the cross-boundary "
                           "derivative along every edge)");
    if (job.fixed != FixedSet::BoundaryAdjacent && b->c1)
      throw ParameterError(source + ".boundary.tangents: C1 data, but fixed is not \"boundary+adjacent\"");
    job.net = std::move(b->net);
    job.boundary_fit = boundary_fit_to_json(b->fits);
  }
  job.problem = problem_from_json(field(j, source, "problem"), source + ".problem");
  if (j.contains("samples")) {
    job.samples = integer(j["samples"], source + ".samples");
    if (job.samples < 1 || job.samples > kMaxSamples)
      throw ParameterError(samples_limit_message(source + ".samples", job.samples));
  }
  if (j.contains("mesh_format"))
    job.mesh_format = mesh_format_from_string(string(j["mesh_format"], source + ".mesh_format"), source + ".mesh_format");
  if (j.contains("export")) {
    const std::string where = source + ".export";
    if (!j["export"].is_array()) throw ParseError(where + ": expected an array of export names (\"step\", \"html\")");
    for (size_t k = 0; k < j["export"].size(); ++k) {
      const std::string e = string(j["export"][k], where + "[" + std::to_string(k) + "]");
      if (e == "step") {
        check_step_degree(job.net, where);
        job.export_step = true;
      }
      else if (e == "html")
        job.export_html = true;
      else
        throw ParseError(where + "[" + std::to_string(k) + "]: unknown export \"" + e + "\" (expected step or html)");
    }
  }
  if (job.complex) check_complex_job(job, source);
  if (j.contains("tolerance")) job.tolerance = tolerance_from_json(j["tolerance"], source + ".tolerance", job);
  return job;
}

Job parse_job_file(const std::string& path) { return parse_job(read_json_file(path), path); }

}  // namespace bpde
