// The progress of writing a result (core/progress.h through jobs/job_progress.h): sampling
// (core/sample_progress.h), the mean curvature, the CGAL checks and writing the files each report
// fractions done / total in [0, 1] that never fall within the stage, from 0 and ending at 1;
// sampling, the checks and the files with steps in between. The same for sampling a triangular net.
#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "bezierpde/io/json_io.h"
#include "bezierpde/io/mesh_io.h"
#include "bezierpde/jobs/job_progress.h"
#include "bezierpde/jobs/run_demo.h"
#include "bezierpde/jobs/run_job.h"

namespace bpde {
namespace {

namespace fs = std::filesystem;

// The fractions reported per stage, in order of the stages' first reports.
struct Reports {
  std::vector<std::string> order;
  std::map<std::string, std::vector<double>> fractions;
  ProgressFn callback() {
    return [this](std::string_view stage, double done, double total) {
      const std::string s(stage);
      EXPECT_GT(total, 0) << s;  // these stages all know their length
      if (!fractions.count(s)) order.push_back(s);
      fractions[s].push_back(total > 0 ? done / total : -1);
    };
  }
};

void expect_rising_to_one(const std::string& stage, const std::vector<double>& f) {
  SCOPED_TRACE(stage);
  ASSERT_GE(f.size(), 2u);
  EXPECT_EQ(f.front(), 0.0);
  EXPECT_EQ(f.back(), 1.0);
  for (size_t i = 0; i < f.size(); ++i) {
    EXPECT_TRUE(f[i] >= 0 && f[i] <= 1) << f[i];
    if (i) {
      EXPECT_GE(f[i], f[i - 1]);
    }
  }
}

size_t distinct(const std::vector<double>& f) { return std::set<double>(f.begin(), f.end()).size(); }

TEST(OutputProgress, WritingAResultReportsRisingFractionsPerStage) {
  Job job = demo_job();
  job.samples = 60;
  const SolveOutcome out = run_job(job);
  const fs::path dir = fs::temp_directory_path() / ("bpde_output_progress_" + std::to_string(::getpid()));
  Reports r;
  {
    const JobProgressScope scope(r.callback());
    write_job_result(dir.string(), job, out);
  }
  fs::remove_all(dir);
  const std::vector<std::string> stages = {std::string(kSamplingStage), "mean curvature", std::string(kMeshCheckStage),
                                           std::string(kWritingFilesStage)};
  EXPECT_EQ(r.order, stages);
  for (const auto& [stage, f] : r.fractions) expect_rising_to_one(stage, f);
  EXPECT_GE(distinct(r.fractions[std::string(kSamplingStage)]), 7u);    // 0, six evaluations, the curvature, 1
  EXPECT_GE(distinct(r.fractions[std::string(kMeshCheckStage)]), 20u);  // the merge's and the pairs' steps
  // 0, the five files (result.json, surface.obj, .ply, .vtp, net.obj) and the fields, 1
  EXPECT_EQ(distinct(r.fractions[std::string(kWritingFilesStage)]), 1u + 5u + 1u + 1u);
}

TEST(OutputProgress, SamplingATriangularNetReportsTheEvaluations) {
  const Json j = read_json_file(std::string(BPDE_SOURCE_DIR) + "/examples/004-cmc-fig2/bottom-a-arcs-H-2.json");
  const Net net = net_from_json(j["net"]);
  std::vector<double> f;
  const TriangleMesh mesh = sample_net(net, 30, [&](std::string_view stage, double done, double total) {
    EXPECT_EQ(stage, kSamplingStage);
    EXPECT_EQ(total, 1.0);
    f.push_back(done);
  });
  EXPECT_EQ(mesh.V.rows(), 31 * 32 / 2);
  ASSERT_EQ(f.size(), 1u + 6u + 1u);  // the start, six evaluations, the curvature (the caller ends the stage)
  EXPECT_EQ(f.front(), 0.0);
  for (size_t i = 1; i < f.size(); ++i) EXPECT_GT(f[i], f[i - 1]);
  EXPECT_LT(f.back(), 1.0);
  // the same mesh without a callback
  EXPECT_EQ(sample_net(net, 30).V, mesh.V);
}

}  // namespace
}  // namespace bpde
