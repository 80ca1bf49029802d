// io/json_io and io/job (with the job layer's validation, jobs/run_job.h): round trips and every
// kind of bad input as typed exceptions.
#include <gtest/gtest.h>

#include "bezierpde/core/errors.h"
#include "bezierpde/io/job.h"
#include "bezierpde/io/json_io.h"
#include "bezierpde/jobs/run_job.h"

using namespace bpde;

namespace {
Json tensor22() {
  Json pts = Json::array();
  for (int i = 0; i < 9; ++i) pts.push_back({i * 0.1, i * 0.25 - 1, 1.0 / (i + 1)});
  return {{"type", "tensor"}, {"degree", {2, 2}}, {"points", pts}};
}
Json tri(int n) {
  Json pts = Json::array();
  for (int i = 0; i < (n + 1) * (n + 2) / 2; ++i) pts.push_back({i * 0.1, 0.3, -0.7 * i});
  return {{"type", "triangular"}, {"degree", n}, {"points", pts}};
}
Json job(Json net, Json problem, std::string fixed = "boundary") {
  return {{"net", net}, {"fixed", fixed}, {"problem", problem}};
}
}  // namespace

TEST(JsonIo, NetRoundTripsAreExact) {
  for (const Json& j : {tensor22(), tri(4)}) {
    const Net net = net_from_json(j);
    const Json back = net_to_json(net);
    EXPECT_EQ(back, j);
    // through text, doubles must survive exactly
    EXPECT_EQ(parse_json(back.dump(), "x"), j);
  }
  Json b = {{"type", "bspline"},
            {"degree", {2, 1}},
            {"knots", {{0, 0, 0, 0.5, 1, 1, 1}, {0, 0, 1, 1}}},
            {"points", Json::array()}};
  for (int i = 0; i < 8; ++i) b["points"].push_back({i, 0.5 * i, 1.0 / 3.0});
  EXPECT_EQ(net_to_json(net_from_json(b)), b);
}

TEST(JsonIo, MalformedJsonAndDuplicates) {
  EXPECT_THROW(parse_json("{\"type\": ", "f"), ParseError);
  EXPECT_THROW(parse_json("[1e999]", "f"), ParseError);
  EXPECT_THROW(parse_json("{\"a\": 1, \"a\": 2}", "f"), ParseError);
  EXPECT_THROW(read_json_file("/nonexistent/net.json"), FileError);
}

TEST(JsonIo, BadNetsAreTypedAndNamed) {
  Json j = tensor22();
  j["points"][3][1] = "x";
  try {
    net_from_json(j);
    FAIL();
  } catch (const ParseError& e) {
    EXPECT_NE(std::string(e.what()).find("net.points[3][1]"), std::string::npos) << e.what();
  }
  j = tensor22();
  j["points"].erase(0);
  EXPECT_THROW(net_from_json(j), SizeError);
  j = tensor22();
  j["color"] = "red";
  EXPECT_THROW(net_from_json(j), ParseError);
  for (Json d : {Json{0, 2}, Json{-1, 2}, Json{65, 2}, Json{2.5, 2}}) {
    j = tensor22();
    j["degree"] = d;
    EXPECT_THROW(net_from_json(j), InvalidInput) << d;
  }
  j = tensor22();
  j["degree"] = {0, 2};
  j["points"] = Json::array();  // the degree is checked before the point count
  EXPECT_THROW(net_from_json(j), DegreeError);
  j = tri(3);
  j["degree"] = 4;
  EXPECT_THROW(net_from_json(j), SizeError);
  j = tri(3);
  j["type"] = "hexagonal";
  EXPECT_THROW(net_from_json(j), ParseError);
  Json b = {{"type", "bspline"},
            {"degree", {2, 1}},
            {"knots", {{0, 0.5, 0, 0.5, 1, 1, 1}, {0, 0, 1, 1}}},
            {"points", Json::array()}};
  for (int i = 0; i < 8; ++i) b["points"].push_back({i, 0, 0});
  EXPECT_THROW(net_from_json(b), ParameterError);  // decreasing knots
  b["knots"] = {{0, 0, 0, 1, 1, 1}, {0, 0, 1, 1}};
  EXPECT_THROW(net_from_json(b), SizeError);  // 3 x 2 control points, 8 given
}

TEST(JsonIo, JobsValidateTheProblemTable) {
  const Json bih = {{"kind", "extremal"}, {"energy", {{"name", "biharmonic"}}}};
  EXPECT_NO_THROW(job_from_json(job(tensor22(), bih)));
  EXPECT_THROW(job_from_json(job(tensor22(), bih, "boundary+adjacent")), DegreeError);  // C1 needs >= 4
  EXPECT_THROW(job_from_json(job(tri(2), bih)), DegreeError);                           // triangular C0 needs >= 3
  EXPECT_THROW(job_from_json(job(tri(5), bih, "boundary+adjacent")), DegreeError);      // C1 needs >= 6
  EXPECT_THROW(job_from_json(job(tri(4), bih, "u-boundaries")), UnsupportedProblem);
  EXPECT_THROW(job_from_json(job(tensor22(), bih, "everything")), ParseError);
  Json extra = job(tensor22(), bih);
  extra["colour"] = 1;
  EXPECT_THROW(job_from_json(extra), ParseError);
  extra = job(tensor22(), bih);
  extra["samples"] = 0;
  EXPECT_THROW(job_from_json(extra), ParameterError);

  const Json pde_explicit_fo = {
      {"kind", "pde"}, {"operator", {{"name", "fourth-order"}, {"coeffs", {1, 0, 3, 0, 1}}}}, {"method", "explicit"}};
  try {
    job_from_json(job(tensor22(), pde_explicit_fo));
    FAIL();
  } catch (const UnsupportedProblem& e) {
    EXPECT_NE(std::string(e.what()).find("lu"), std::string::npos);
  }
  // proportional to a G-norm operator: explicit is fine
  const Json pde_gn = {
      {"kind", "pde"}, {"operator", {{"name", "operator"}, {"coeffs", {8, 0, 10, 0, 2}}}}, {"method", "explicit"}};
  EXPECT_NO_THROW(job_from_json(job(tensor22(), pde_gn)));
  EXPECT_THROW(job_from_json(job(tensor22(), {{"kind", "extremal"},
                                              {"energy", {{"name", "operator"}, {"coeffs", {1, 0, 2, 0, 1}}}}})),
               ParseError);
  const Json harm = {{"kind", "pde"}, {"operator", {{"name", "dirichlet"}}}};
  EXPECT_THROW(job_from_json(job(tensor22(), harm)), UnsupportedProblem);
  EXPECT_NO_THROW(job_from_json(job(tensor22(), harm, "u-boundaries")));
  EXPECT_THROW(
      job_from_json(job(tensor22(), {{"kind", "pde"}, {"operator", {{"name", "biharmonic"}}}}, "u-boundaries")),
      UnsupportedProblem);

  const Json tetra = {{"kind", "tetraharmonic"}, {"method", "explicit"}};
  EXPECT_THROW(job_from_json(job(tensor22(), tetra, "boundary+adjacent")), DegreeError);
  EXPECT_THROW(job_from_json(job(tensor22(), tetra)), UnsupportedProblem);

  EXPECT_NO_THROW(job_from_json(job(tri(4), {{"kind", "cmc"}, {"H", -1.5}})));
  EXPECT_THROW(job_from_json(job(tri(4), {{"kind", "cmc"}, {"H", -1.5}, {"V", 1}})), ParseError);
  EXPECT_THROW(job_from_json(job(tri(4), {{"kind", "cmc"}, {"V", 1}, {"solver", "newton"}})), UnsupportedProblem);
  EXPECT_THROW(job_from_json(job(tri(4), {{"kind", "cmc"}, {"H", "big"}})), ParseError);
  const Job v = job_from_json(job(tri(4), {{"kind", "cmc"}, {"V", 0.25}}));
  EXPECT_EQ(v.problem.solver, CmcSolver::NLopt);
}

// The job layer's validation (jobs/run_job.h, solvers/requirements.h): whole messages, as they
// were before the solvers' requirements became one registry.
TEST(JsonIo, JobsAreRefusedWithTheirMessages) {
  auto message = [](const Json& j) {
    try {
      job_from_json(j);
    } catch (const InvalidInput& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  const Json bih = {{"kind", "extremal"}, {"energy", {{"name", "biharmonic"}}}};
  EXPECT_EQ(message(job(tensor22(), bih, "boundary+adjacent")),
            "job: problem \"extremal\" on a tensor net with boundary+adjacent data needs degrees >= 4, got [2, 2]");
  EXPECT_EQ(message(job(tri(2), bih)),
            "job: problem \"extremal\" on a triangular net with boundary data needs degree >= 3, got 2");
  EXPECT_EQ(message(job(tri(4), bih, "u-boundaries")), "job: fixed \"u-boundaries\" is only defined for tensor nets");
  EXPECT_EQ(message(job(tri(4), {{"kind", "pde"}, {"operator", {{"name", "biharmonic"}}}})),
            "job: problem \"pde\" needs a tensor or bspline net, not a triangular net");
  EXPECT_EQ(message(job(tri(4), {{"kind", "tetraharmonic"}}, "boundary+adjacent")),
            "job: problem \"tetraharmonic\" needs a tensor net, not a triangular net");
  EXPECT_EQ(message(job(tensor22(), {{"kind", "tetraharmonic"}}, "boundary+adjacent")),
            "job: problem \"tetraharmonic\" needs n = m >= 4, got 2");
  EXPECT_EQ(message(job(tensor22(), {{"kind", "biharmonic-load"}})),
            "job: problem \"biharmonic-load\" takes C1 data: \"fixed\": \"boundary+adjacent\"");
  EXPECT_EQ(message(job(tensor22(), {{"kind", "pde"}, {"operator", {{"name", "dirichlet"}}}})),
            "job: a second-order pde (dirichlet) takes \"fixed\": \"u-boundaries\"");
  EXPECT_EQ(message(job(tensor22(), {{"kind", "pde"}, {"operator", {{"name", "dirichlet"}}}, {"method", "explicit"}},
                        "u-boundaries")),
            "job: the second-order pde has no explicit method (Arnal-Monterde-Ugail); use \"method\": \"lu\"");
  EXPECT_EQ(message(job(tensor22(), {{"kind", "pde"}, {"operator", {{"name", "biharmonic"}}}}, "u-boundaries")),
            "job: a fourth-order pde (biharmonic) takes \"fixed\": \"boundary\"");
  // explicit needs n = m: refused when the job is read, before anything runs
  Json t23 = {{"type", "tensor"}, {"degree", {2, 3}}, {"points", Json::array()}};
  for (int i = 0; i < 12; ++i) t23["points"].push_back({i * 0.1, 0.2, 0.3});
  EXPECT_EQ(message(job(t23, {{"kind", "pde"}, {"operator", {{"name", "biharmonic"}}}, {"method", "explicit"}})),
            "job: problem \"pde\" needs n = m, got [2, 3]");
  EXPECT_EQ(message(job(t23, {{"kind", "pde"}, {"operator", {{"name", "biharmonic"}}}})), "accepted");
}

// check_requirements' own messages, for requirements that give no reason of their own.
TEST(JsonIo, RequirementsWithoutReasonsListWhatTheyTake) {
  SolverRequirements r;
  r.problem = "problem \"x\"";
  r.nets = {NetKind::Tensor, NetKind::BSpline};
  r.fixed = {FixedSet::Boundary, FixedSet::BoundaryAdjacent};
  r.methods = {"a", "b", "c"};
  r.min_degrees = {{NetKind::Tensor, FixedSet::Boundary, 3}};
  auto message = [&](NetShape s, FixedSet f, const std::string& method) {
    try {
      check_requirements(r, s, f, method, "w");
    } catch (const InvalidInput& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  EXPECT_EQ(message({NetKind::Triangular, 4, 4}, FixedSet::Boundary, ""),
            "w: problem \"x\" needs a tensor or bspline net, not a triangular net");
  EXPECT_EQ(message({NetKind::Tensor, 4, 4}, FixedSet::UBoundaries, ""),
            "w: problem \"x\" takes \"fixed\": \"boundary\" or \"boundary+adjacent\"");
  EXPECT_EQ(message({NetKind::Tensor, 4, 4}, FixedSet::Boundary, "d"),
            "w: problem \"x\" has no method \"d\" (expected a, b or c)");
  EXPECT_EQ(message({NetKind::Tensor, 4, 2}, FixedSet::Boundary, "a"),
            "w: problem \"x\" needs degrees >= 3, got [4, 2]");
  EXPECT_EQ(message({NetKind::Tensor, 4, 3}, FixedSet::Boundary, "a"), "accepted");
  EXPECT_EQ(message({NetKind::Tensor, 1, 1}, FixedSet::BoundaryAdjacent, ""), "accepted");  // no minimum given
  EXPECT_THROW(check_requirements(r, {NetKind::Tensor, 2, 2}, FixedSet::Boundary, "", "w"), DegreeError);
  EXPECT_THROW(check_requirements(r, {NetKind::Tensor, 4, 4}, FixedSet::UBoundaries, "", "w"), UnsupportedProblem);
}

TEST(JsonIo, EnergiesAndSingularG) {
  const EnergySpec g = energy_from_json({{"name", "gnorm"}, {"G", {{1, 2}, {0, 1}}}}, "e", false);
  // columns e1 = (1, 0), e2 = (2, 1): [|e1|^2, 2<e1,e2>, |e1|^2+|e2|^2, 2<e1,e2>, |e2|^2] = [1, 4, 6, 4, 5]
  const auto c = g.operator_coeffs();
  EXPECT_EQ(c[0], 1);
  EXPECT_EQ(c[1], 4);
  EXPECT_EQ(c[2], 6);
  EXPECT_EQ(c[3], 4);
  EXPECT_EQ(c[4], 5);
  EXPECT_THROW(energy_from_json({{"name", "gnorm"}, {"G", {{1, 2}, {2, 4}}}}, "e", false), ParameterError);
  EXPECT_THROW(energy_from_json({{"name", "gnorm"}, {"rho", 0}, {"t", 1}}, "e", false), ParameterError);
  EXPECT_THROW(energy_from_json({{"name", "second-order"}, {"coeffs", {1, 2}}}, "e", false), SizeError);
  EXPECT_THROW(energy_from_json({{"name", "biharmonic"}, {"alpha", 1}}, "e", false), ParseError);
  EXPECT_THROW(energy_from_argument("{\"name\": "), ParseError);
  EXPECT_THROW(energy_from_argument("thin-plate"), ParseError);
  EXPECT_EQ(energy_from_argument("coons").name(), "coons");
}
