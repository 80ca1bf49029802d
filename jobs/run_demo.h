#pragma once
// The built-in default job of `bpde demo` (the README's main command): the jobs, and the summary
// the command prints from their results.
#include <string>
#include <vector>

#include "bezierpde/io/job.h"
#include "bezierpde/triangular/triangular_net.h"

namespace bpde {

/// The triangular CMC paper's Fig. 1 set-up: a unit circle split into three arcs (parametrised by
/// angle, so not conformally) bounds a degree-8 triangular net; the critical point of the paper's
/// D + 2HV at H = -1/2 on the branch from the Dirichlet extremal (Newton), 50 samples. The answer
/// to "a surface of mean curvature -1/2 spanning this circle" is the spherical cap of radius 2.
Job demo_job();
/// The same boundary and H with "functional": "area": the critical point of A + 2HV.
Job demo_area_job();
/// The same boundary and H with "functional": "mean-curvature": the least squares of the mean
/// curvature, ∫ρ(H_x − H)² dA, minimised (solvers/cmc/cmc.h).
Job demo_mean_curvature_job();

/// max over a 40-sample grid (corners included) of | |x - c| - 1/|H| |, c the centre of the small
/// spherical cap of mean curvature H (|H| < 1, H ≠ 0) through the unit circle in z = 0, on the
/// side H < 0 bulges to; +inf when |H| >= 1 or H = 0.
double unit_circle_cap_distance(const TriangularNet& net, double H);

/// One column of the demo: the report of a result the demo wrote (result.json's "report", with
/// `mean_curvature` and `check`), its distance to the exact cap, and its output directory.
struct DemoColumn {
  std::string title;  ///< e.g. "D + 2HV (the paper)"
  Json report;
  double distance = 0.0;
  std::string dir;
};

/// The lines `bpde demo` prints, the functionals side by side (the first column is the paper's).
std::string demo_summary(const std::vector<DemoColumn>& columns);

}  // namespace bpde
