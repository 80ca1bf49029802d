#pragma once
// The built-in default job of `bpde demo` (the README's main command): the jobs, and the summary
// the command prints from their results.
#include <string>

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

/// max over a 40-sample grid (corners included) of | |x - c| - 1/|H| |, c the centre of the small
/// spherical cap of mean curvature H (|H| < 1, H ≠ 0) through the unit circle in z = 0, on the
/// side H < 0 bulges to; +inf when |H| >= 1 or H = 0.
double unit_circle_cap_distance(const TriangularNet& net, double H);

/// The lines `bpde demo` prints, side by side for the two functionals, from the reports of the
/// results it wrote (result.json's "report", with `mean_curvature` and `check`), the distances to
/// the exact cap, and the output directories.
std::string demo_summary(const Json& dirichlet, const Json& area, double dist_dirichlet, double dist_area,
                         const std::string& out_dir, const std::string& area_dir);

}  // namespace bpde
