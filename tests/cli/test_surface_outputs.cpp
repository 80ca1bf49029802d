// The command's surface outputs beyond OBJ/PLY: --mesh-format and "mesh_format" (binary PLY and
// VTP), by running the binary.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "tests/cli/cli_run.h"

namespace fs = std::filesystem;
using bpde::testing::CmdResult;
using bpde::testing::run;
using bpde::testing::slurp;
using bpde::testing::tmpdir;
using bpde::testing::write;

namespace {
const char* kTensor = R"({"type": "tensor", "degree": [1, 1], "points": [[0,0,0],[0,1,0],[1,0,0],[1,1,1]]})";
}  // namespace

TEST(CliSurfaceOutputs, SampleWritesBinaryPlyAndVtpOnRequest) {
  const fs::path net = write("st.json", kTensor);
  for (const std::string format : {"ascii", "binary"}) {
    const fs::path out = tmpdir() / ("so_" + format);
    const CmdResult r =
        run("sample " + net.string() + " --out " + out.string() + " --samples 3 --mesh-format " + format);
    ASSERT_EQ(r.status, 0) << r.err;
    const std::string ply = slurp(out / "surface.ply"), vtp = slurp(out / "surface.vtp");
    EXPECT_NE(ply.find(format == "binary" ? "format binary_little_endian 1.0\n" : "format ascii 1.0\n"),
              std::string::npos);
    EXPECT_NE(ply.find("property uchar regular\n"), std::string::npos);
    EXPECT_NE(vtp.find("NumberOfPoints=\"16\""), std::string::npos);
    EXPECT_NE(vtp.find(format == "binary" ? "format=\"binary\"" : "format=\"ascii\""), std::string::npos);
  }
  const fs::path bad = tmpdir() / "so_bad";
  const CmdResult r = run("sample " + net.string() + " --out " + bad.string() + " --mesh-format float");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("--mesh-format"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(bad));
}

// A Dirichlet extremal job on a biquadratic net, without its closing brace (tests add fields).
const char* const kDirichletJob =
    R"({"net": {"type": "tensor", "degree": [2, 2], "points": [[0,0,0],[0,0.5,0],[0,1,0],[0.5,0,0],[0,0,0],)"
    R"([0.5,1,0],[1,0,0],[1,0.5,0.5],[1,1,1]]}, "problem": {"kind": "extremal", "energy": {"name": "dirichlet"}}, )"
    R"("samples": 4)";

TEST(CliSurfaceOutputs, JobMeshFormatIsReadAndCheckedBeforeAnythingRuns) {
  const std::string job = std::string(kDirichletJob) + ", ";
  const fs::path good = write("mf.json", job + R"("mesh_format": "binary"})");
  const fs::path out = tmpdir() / "mf_out";
  CmdResult r = run("solve " + good.string() + " --out " + out.string());
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(slurp(out / "surface.ply").find("binary_little_endian"), std::string::npos);
  EXPECT_TRUE(fs::exists(out / "surface.vtp"));
  const fs::path bad = write("mf_bad.json", job + R"("mesh_format": 3})");
  const fs::path bad_out = tmpdir() / "mf_bad_out";
  r = run("solve " + bad.string() + " --out " + bad_out.string());
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("mesh_format"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(bad_out));
}

TEST(CliSurfaceOutputs, HtmlExportAndViewWriteThePage) {
  const std::string job = kDirichletJob;
  const fs::path with_export = write("ex.json", job + R"(, "export": ["html"]})");
  const fs::path out = tmpdir() / "ex_out";
  CmdResult r = run("solve " + with_export.string() + " --out " + out.string());
  ASSERT_EQ(r.status, 0) << r.err;
  const std::string page = slurp(out / "view.html");
  EXPECT_NE(page.find("\"vertices\":25"), std::string::npos);
  // bpde view rewrites the same page from result.json at the same resolution
  fs::remove(out / "view.html");
  r = run("view " + out.string() + " --samples 4");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(slurp(out / "view.html"), page);
  // bad input: an unknown export, a folder without result.json
  const fs::path bad = write("ex_bad.json", job + R"(, "export": ["pdf"]})");
  r = run("solve " + bad.string() + " --out " + (tmpdir() / "ex_bad_out").string());
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("export[0]"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(tmpdir() / "ex_bad_out"));
  fs::create_directories(tmpdir() / "empty_dir");
  r = run("view " + (tmpdir() / "empty_dir").string());
  EXPECT_EQ(r.status, 2);
  EXPECT_FALSE(fs::exists(tmpdir() / "empty_dir" / "view.html"));
}

TEST(CliSurfaceOutputs, StepExportFromTheCommandAndFromAJob) {
  const fs::path net = write("step_net.json", kTensor);
  const fs::path step = tmpdir() / "net.step";
  CmdResult r = run("export " + net.string() + " --step " + step.string());
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(bpde::testing::printed_files(r.out), std::vector<fs::path>{step});
  EXPECT_EQ(std::count(r.out.begin(), r.out.end(), '\n'), 1) << r.out;  // OpenCASCADE's messages stay off stdout
  const std::string text = slurp(step);
  EXPECT_EQ(text.rfind("ISO-10303-21;", 0), 0u);
  EXPECT_NE(text.find("B_SPLINE_SURFACE"), std::string::npos);
  const char* net2 = R"({"type": "tensor", "degree": [2, 2], "points": [[0,0,0],[0,0.5,0],[0,1,0],[0.5,0,0],[0,0,0],)"
                     R"([0.5,1,0],[1,0,0],[1,0.5,0.5],[1,1,1]]})";
  const std::string job = std::string(R"({"net": )") + net2 +
                          R"(, "problem": {"kind": "extremal", "energy": {"name": "dirichlet"}}, "export": ["step"]})";
  const fs::path out = tmpdir() / "step_job";
  r = run("solve " + write("step_job.json", job).string() + " --out " + out.string());
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(slurp(out / "surface.step").rfind("ISO-10303-21;", 0), 0u);
  // a degree OpenCASCADE cannot hold is refused before anything runs
  std::string big = R"({"net": {"type": "triangular", "degree": 26, "points": [)";
  for (int k = 0; k < 27 * 28 / 2; ++k) big += std::string(k ? "," : "") + "[" + std::to_string(k) + ",0,1]";
  big += R"(]}, "problem": {"kind": "extremal", "energy": {"name": "dirichlet"}}, "export": ["step"]})";
  const fs::path big_out = tmpdir() / "step_big";
  r = run("solve " + write("step_big.json", big).string() + " --out " + big_out.string());
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_NE(r.err.find("STEP"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(big_out));
  r = run("export " + net.string() + " --step /nonexistent-dir/x.step");
  EXPECT_EQ(r.status, 2) << r.err;
}

TEST(CliSurfaceOutputs, StepExportOfAKnotOfFullMultiplicity) {
  // u knot 0.5 of multiplicity degree + 1 = 2, which the reader takes and OpenCASCADE does not:
  // exported where the surface is continuous (rows 1 and 2 equal), exit 2 where it jumps, the
  // existing file kept. Never exit 3.
  const std::string head = R"({"type": "bspline", "degree": [1, 1], "knots": [[0, 0, 0.5, 0.5, 1, 1], [0, 0, 1, 1]],)";
  const fs::path continuous = write("full_mult_c0.json", head + R"( "points": [[0,0,0],[0,1,0],[0.5,0,0],[0.5,1,0],)"
                                                                R"([0.5,0,0],[0.5,1,0],[1,0,1],[1,1,1]]})");
  const fs::path jump = write("full_mult_jump.json", head + R"( "points": [[0,0,0],[0,1,0],[0.5,0,0],[0.5,1,0],)"
                                                            R"([0.5,0,1],[0.5,1,1],[1,0,1],[1,1,1]]})");
  const fs::path step = tmpdir() / "full_mult.step";
  fs::remove(step);
  CmdResult r = run("export " + continuous.string() + " --step " + step.string());
  ASSERT_EQ(r.status, 0) << r.err;
  const std::string text = slurp(step);
  EXPECT_NE(text.find("B_SPLINE_SURFACE"), std::string::npos);
  r = run("export " + jump.string() + " --step " + step.string());
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_EQ(slurp(step), text);
  // sample and check take both nets
  EXPECT_EQ(run("check " + jump.string()).status, 0);
}

TEST(CliSurfaceOutputs, StepExportWithoutThePluginExitsThreeAndLeavesNoFile) {
  // OpenCASCADE lives in the STEP plugin (io/step_export.h), opened on the first STEP file only:
  // BPDE_STEP_PLUGIN points the search at a missing file, then at a file that is no plugin.
  const fs::path net = write("noplugin_net.json", kTensor);
  const char* net2 = R"({"type": "tensor", "degree": [2, 2], "points": [[0,0,0],[0,0.5,0],[0,1,0],[0.5,0,0],[0,0,0],)"
                     R"([0.5,1,0],[1,0,0],[1,0.5,0.5],[1,1,1]]})";
  const std::string job = std::string(R"({"net": )") + net2 +
                          R"(, "problem": {"kind": "extremal", "energy": {"name": "dirichlet"}}, "export": ["step"]})";
  const fs::path job_file = write("noplugin_job.json", job);
  for (const fs::path& plugin : {tmpdir() / "no_such_plugin.so", net}) {
    ASSERT_EQ(setenv("BPDE_STEP_PLUGIN", plugin.c_str(), 1), 0);
    const fs::path step = tmpdir() / "noplugin.step", out = tmpdir() / "noplugin_out";
    fs::remove(step);
    fs::remove_all(out);
    CmdResult r = run("export " + net.string() + " --step " + step.string());
    EXPECT_EQ(r.status, 3) << r.err;
    EXPECT_FALSE(fs::exists(step));
    r = run("solve " + job_file.string() + " --out " + out.string());
    EXPECT_EQ(r.status, 3) << r.err;
    EXPECT_FALSE(fs::exists(out));
    // a job without STEP export does not need the plugin
    r = run("solve " + write("noplugin_job2.json", std::string(R"({"net": )") + net2 +
                                                       R"(, "problem": {"kind": "extremal", "energy": {"name": "dirichlet"}}})")
                               .string() +
            " --out " + out.string());
    EXPECT_EQ(r.status, 0) << r.err;
    fs::remove_all(out);
  }
  ASSERT_EQ(unsetenv("BPDE_STEP_PLUGIN"), 0);
}

TEST(CliSurfaceOutputs, OnlyAStepExportLoadsOpenCascade) {
  // the dynamic loader's list of the objects it opens (LD_DEBUG=files), for --version and export
  const fs::path net = write("occ_net.json", kTensor);
  ASSERT_EQ(setenv("LD_DEBUG", "files", 1), 0);
  const CmdResult version = run("--version");
  const CmdResult exported = run("export " + net.string() + " --step " + (tmpdir() / "occ.step").string());
  ASSERT_EQ(unsetenv("LD_DEBUG"), 0);
  ASSERT_EQ(version.status, 0);
  ASSERT_EQ(exported.status, 0) << exported.err;
  EXPECT_EQ(version.err.find("libTKernel"), std::string::npos);
  EXPECT_NE(exported.err.find("libTKernel"), std::string::npos);  // the check above can fail
}

TEST(CliSurfaceOutputs, StepExportReadsTheResultJsonBpdeWrites) {
  const fs::path out = tmpdir() / "step_from_result";
  CmdResult r = run("solve " + write("step_result_job.json", std::string(kDirichletJob) + "}").string() + " --out " +
                    out.string());
  ASSERT_EQ(r.status, 0) << r.err;
  const fs::path step = tmpdir() / "from_result.step";
  fs::remove(step);
  r = run("export " + (out / "result.json").string() + " --step " + step.string());
  ASSERT_EQ(r.status, 0) << r.err;
  ASSERT_TRUE(fs::exists(step));
  EXPECT_GT(fs::file_size(step), 0u);
  EXPECT_EQ(slurp(step).rfind("ISO-10303-21;", 0), 0u);
}
