#pragma once
// The ceres::Solve options of the cmc family's Ceres routes (cmc_ceres.cpp, the bordered corrector
// of the area's V form; area/soft_mode_phase.cpp; mean_curvature_ceres.cpp, the least squares of
// the mean curvature; the corrector of eq. (11) runs ceres::TinySolver instead, cmc_ceres.cpp):
// Levenberg–Marquardt with a dense normal-Cholesky step (Eigen), single-threaded, silent, and
// Ceres's own function, gradient and parameter tolerances set out of the way, because each route
// stops by its own IterationCallback at the library's convergence test.
#include "bezierpde/core/eigen.h"
#include <ceres/ceres.h>

namespace bpde::cmc_detail {

inline ceres::Solver::Options ceres_lm_options(int max_iterations) {
  ceres::Solver::Options so;
  so.minimizer_type = ceres::TRUST_REGION;
  so.trust_region_strategy_type = ceres::LEVENBERG_MARQUARDT;
  so.linear_solver_type = ceres::DENSE_NORMAL_CHOLESKY;
  so.dense_linear_algebra_library_type = ceres::EIGEN;
  so.max_num_iterations = max_iterations;
  so.function_tolerance = 1e-30;
  so.gradient_tolerance = 1e-30;
  so.parameter_tolerance = 1e-30;
  so.num_threads = 1;
  so.logging_type = ceres::SILENT;
  so.minimizer_progress_to_stdout = false;
  return so;
}

}  // namespace bpde::cmc_detail
