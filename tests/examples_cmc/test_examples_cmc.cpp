// The triangular CMC example jobs (examples/004-cmc-*) run through read_job_file / run_job, the path of
// `bpde solve`: they converge (or stop at the documented fold), and their key numbers hold against
// independent truths (Enneper's surface, the sphere, symmetries) and the values in the READMEs.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>

#include "bezierpde/io/json_io.h"
#include "bezierpde/io/mesh_io.h"
#include "bezierpde/jobs/run_job.h"
#include "bezierpde/tensor/tensor_net.h"
#include "bezierpde/triangular/triangular_net.h"

namespace fs = std::filesystem;
using namespace bpde;

namespace {

fs::path example(const std::string& dir, const std::string& job) {
  return fs::path(BPDE_SOURCE_DIR) / "examples" / dir / job;
}

struct JobRun {
  Job job;
  SolveOutcome out;
};
JobRun run(const std::string& dir, const std::string& job) {
  JobRun r{read_job_file(example(dir, job).string()), {}};
  r.out = run_job(r.job);
  return r;
}

double num(const SolveOutcome& o, const char* key) { return o.report.at(key).get<double>(); }

int self_intersections(const JobRun& r) {
  return check_report(sample_net(r.out.net, r.job.samples))["self_intersections"].get<int>();
}

double mean_H(const JobRun& r) {
  const TriangleMesh mesh = sample_net(r.out.net, r.job.samples);
  return mean_curvature_stats(r.out.net, mesh, r.job.samples)["mean"].get<double>();
}

}  // namespace

// Fig. 1 at the paper's degree n = 4: all three H are on the branch (fold at |H| ≈ 1.5558).
TEST(ExamplesCmc, CircleFigure1AtDegree4) {
  const char* jobs[] = {"n4-a-H-1.5.json", "n4-b-H-1.json", "n4-c-H-0.5.json"};
  const double DH[] = {2.529971, 3.870131, 4.412570};
  const double V[] = {2.416420, 0.802165, 0.328453};
  for (int k = 0; k < 3; ++k) {
    SCOPED_TRACE(jobs[k]);
    const JobRun r = run("004-cmc-circle", jobs[k]);
    ASSERT_TRUE(r.out.converged) << r.out.report.dump();
    EXPECT_NEAR(num(r.out, "energy"), DH[k], 1e-5);
    EXPECT_NEAR(num(r.out, "volume"), V[k], 1e-5);
    // D_H = D + 2 H V.
    EXPECT_NEAR(num(r.out, "energy"), num(r.out, "D") + 2 * r.job.problem.H * num(r.out, "volume"), 1e-10);
    // H < 0 bulges towards +z (the corners run counter-clockwise seen from +z).
    EXPECT_GT(std::get<TriangularNet>(r.out.net).evaluate(1.0 / 3, 1.0 / 3).z(), 0.1);
    EXPECT_LT(mean_H(r), 0.0);
    EXPECT_EQ(self_intersections(r), 0);
  }
}

// n = 6, H = −1.5 lies past the fold: a valid problem without a solution, exit status 1.
TEST(ExamplesCmc, CirclePastTheFoldIsReportedNotThrown) {
  const JobRun r = run("004-cmc-circle", "n6-H-1.5-past-fold.json");
  EXPECT_FALSE(r.out.converged);
  EXPECT_EQ(
      r.out.report.value("message", std::string()).rfind("no critical point on the branch from H = 0 beyond H ≈", 0),
      0u)
      << r.out.report.dump();
  EXPECT_NEAR(num(r.out, "H"), -1.1422, 1e-3);
  const fs::path dir = fs::path(::testing::TempDir()) / "bpde_examples_cmc_fold";
  EXPECT_EQ(write_outcome(dir.string(), r.job, r.out), 1);
  EXPECT_TRUE(fs::exists(dir / "result.json"));
  fs::remove_all(dir);
}

// Fig. 2 top: Enneper's boundary. At H = 0 the extremal is Enneper's surface itself (a harmonic,
// conformal cubic); H = ±1 are mirror images (D equal, V opposite).
TEST(ExamplesCmc, Figure2TopEnneper) {
  const JobRun h0 = run("004-cmc-fig2", "top-b-enneper-H0.json");
  ASSERT_TRUE(h0.out.converged);
  const auto& net = std::get<TriangularNet>(h0.out.net);
  double err = 0;
  for (int a = 0; a <= 10; ++a)
    for (int b = 0; a + b <= 10; ++b) {
      const double u = a / 10.0, v = b / 10.0, s = 1.5 * (u - 1.0 / 3), t = 1.5 * (v - 1.0 / 3);
      const Eigen::Vector3d E(s - s * s * s / 3 + s * t * t, t - t * t * t / 3 + t * s * s, s * s - t * t);
      err = std::max(err, (net.evaluate(u, v) - E).norm());
    }
  EXPECT_LT(err, 1e-12);
  EXPECT_NEAR(mean_H(h0), 0.0, 1e-9);

  const JobRun m = run("004-cmc-fig2", "top-a-enneper-H-1.json");
  const JobRun p = run("004-cmc-fig2", "top-c-enneper-H1.json");
  ASSERT_TRUE(m.out.converged);
  ASSERT_TRUE(p.out.converged);
  EXPECT_NEAR(num(m.out, "D"), num(p.out, "D"), 1e-9);
  EXPECT_NEAR(num(m.out, "volume"), -num(p.out, "volume"), 1e-9);
  EXPECT_NEAR(num(m.out, "energy"), 1.710066, 1e-5);
  EXPECT_LT(mean_H(m), -0.5);
  EXPECT_GT(mean_H(p), 0.5);
}

// Fig. 2 bottom: three arcs of the sphere of radius 2/3 (conformal data, orientation with the
// sphere at H = −1.5). H = −1.5 is close to the sphere; more negative H bulges further out.
TEST(ExamplesCmc, Figure2BottomSphericalArcs) {
  const JobRun s = run("004-cmc-fig2", "bottom-b-arcs-H-1.5.json");
  ASSERT_TRUE(s.out.converged);
  const auto& net = std::get<TriangularNet>(s.out.net);
  double dist = 0;
  for (int a = 0; a <= 20; ++a)
    for (int b = 0; a + b <= 20; ++b)
      dist = std::max(dist, std::abs(net.evaluate(a / 20.0, b / 20.0).norm() - 2.0 / 3));
  EXPECT_LT(dist, 2e-3);  // 1.3e-3 at n = 6 (README)
  EXPECT_NEAR(mean_H(s), -1.5, 0.03);
  const JobRun a = run("004-cmc-fig2", "bottom-a-arcs-H-2.json");
  const JobRun c = run("004-cmc-fig2", "bottom-c-arcs-H-1.json");
  ASSERT_TRUE(a.out.converged);
  ASSERT_TRUE(c.out.converged);
  EXPECT_GT(num(a.out, "volume"), num(s.out, "volume"));
  EXPECT_GT(num(s.out, "volume"), num(c.out, "volume"));
}

// Figs. 3–4: C¹ data on the equilateral triangle; the boundary and the lifted adjacent ring are kept,
// and the centre rises with |H| (H < 0 bulges towards +z).
TEST(ExamplesCmc, C1TriangleFigure4) {
  const char* jobs[] = {"n6-c-H-1.json", "n6-b-H-1.5.json", "n6-a-H-2.json"};
  double previous_z = 0;
  for (const char* j : jobs) {
    SCOPED_TRACE(j);
    const JobRun r = run("004-cmc-c1-triangle", j);
    ASSERT_TRUE(r.out.converged);
    EXPECT_EQ(r.job.fixed, FixedSet::BoundaryAdjacent);
    const auto& data = std::get<TriangularNet>(r.job.net);
    const auto& x = std::get<TriangularNet>(r.out.net);
    for (int i : data.fixed_indices(FixedSet::BoundaryAdjacent))
      EXPECT_EQ((x.points().row(i) - data.points().row(i)).norm(), 0.0);
    const double z = x.evaluate(1.0 / 3, 1.0 / 3).z();
    EXPECT_GT(z, previous_z + 0.05);
    previous_z = z;
    EXPECT_EQ(self_intersections(r), 0);
  }
}

// Sphere data (inverse stereographic, H = +1 in the FORMATS.md orientation) at n = 8.
TEST(ExamplesCmc, SphereJobsAtDegree8) {
  const JobRun t = run("004-cmc-sphere-convergence", "triangle-n8.json");
  const JobRun q = run("004-cmc-sphere-convergence", "square-n8.json");
  ASSERT_TRUE(t.out.converged);
  ASSERT_TRUE(q.out.converged);
  double dt = 0, dq = 0;
  const auto& tn = std::get<TriangularNet>(t.out.net);
  const auto& qn = std::get<TensorNet>(q.out.net);
  for (int a = 0; a <= 40; ++a)
    for (int b = 0; b <= 40; ++b) {
      if (a + b <= 40) dt = std::max(dt, std::abs(tn.evaluate(a / 40.0, b / 40.0).norm() - 1));
      dq = std::max(dq, std::abs(qn.evaluate(a / 40.0, b / 40.0).norm() - 1));
    }
  EXPECT_LT(dt, 1e-4);  // 5.6e-5 (README)
  EXPECT_LT(dq, 2e-5);  // 9.5e-6
  EXPECT_NEAR(mean_H(t), 1.0, 2e-3);
  EXPECT_NEAR(mean_H(q), 1.0, 1e-3);
  // A conformal unit-sphere patch with inward normal has D = area = −3V, so D_H = D + 2V = −V.
  EXPECT_LT(num(t.out, "volume"), 0.0);
  EXPECT_NEAR(num(t.out, "energy"), -num(t.out, "volume"), 1e-5);
  EXPECT_NEAR(num(q.out, "energy"), -num(q.out, "volume"), 1e-5);
}
