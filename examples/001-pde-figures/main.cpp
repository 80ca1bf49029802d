// 001-pde-figures: Arnal–Monterde–Ugail (explicit PDE solutions) Figs. 1–4, solved from their job files.
//
// Usage: example_001_pde_figures [EXAMPLE_DIR [OUT_DIR]]
//   EXAMPLE_DIR defaults to examples/001-pde-figures, OUT_DIR to out/001-pde-figures.
// For each job: the explicit solution (written to OUT_DIR/<job>/), the lu solution, their
// largest control-point difference relative to the net's size, the PDE residual, and the
// energy extremal with the same boundary (docs/errata.md, explicit PDE solutions §2: it is a different surface with
// lower energy). Prints a Markdown table as the generated section "pde-figures" of README.md
// (scripts/docs.sh); residual and difference at rounding level print as "< 1e-13".
#include <cstdio>
#include <filesystem>

#include "bezierpde/energies/quadratic_energy.h"
#include "examples/common/generated.h"
#include "bezierpde/io/mesh_io.h"
#include "bezierpde/jobs/run_job.h"
#include "bezierpde/solvers/extremal.h"
#include "bezierpde/solvers/pde/pde_lu.h"
#include "bezierpde/solvers/pde/pde_residual.h"

int main(int argc, char** argv) {
  namespace fs = std::filesystem;
  const fs::path dir = argc > 1 ? argv[1] : "examples/001-pde-figures";
  const fs::path out = argc > 2 ? argv[2] : "out/001-pde-figures";
  std::vector<fs::path> jobs;
  for (const auto& e : fs::directory_iterator(dir))
    if (e.path().extension() == ".json") jobs.push_back(e.path());
  std::sort(jobs.begin(), jobs.end());
  const bpde::examples::GeneratedSection section("pde-figures");
  std::printf(
      "| job | operator | E(PDE solution) | pde_residual | explicit vs lu | E(extremal) | self-intersections |\n");
  std::printf("|---|---|---|---|---|---|---|\n");
  for (const auto& path : jobs) {
    const bpde::Job job = bpde::read_job_file(path.string());
    const bpde::SolveOutcome ex = bpde::run_job(job);
    bpde::write_outcome((out / path.stem()).string(), job, ex);
    const auto& data = std::get<bpde::TensorNet>(job.net);
    const auto& op = *job.problem.energy;
    const bpde::PdeSolution lu = bpde::solve_pde_lu(data, op);
    const auto& P = std::get<bpde::TensorNet>(ex.net).points();
    const double diff = (P - lu.net.points()).cwiseAbs().maxCoeff() / P.cwiseAbs().maxCoeff();
    const bpde::ExtremalResult xt = bpde::solve_extremal(data, op, bpde::FixedSet::Boundary);
    std::printf("| %s | %s | %.6g | %s | %s | %.6g | %d |\n", path.stem().c_str(), op.name().c_str(),
                ex.report["energy"].get<double>(),
                bpde::examples::stable_small(ex.report["pde_residual"].get<double>()).c_str(),
                bpde::examples::stable_small(diff).c_str(), xt.energy,
                bpde::check_report(bpde::sample_net(ex.net, job.samples))["self_intersections"].get<int>());
  }
  return 0;
}
