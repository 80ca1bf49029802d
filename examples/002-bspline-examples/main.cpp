// 002-bspline-examples: Sun–Zhu ( "B-spline solutions of general Euler–Lagrange
// equations") Examples 1 and 2 reproduced from their set-up, and the §5 special cases (Coons,
// biharmonic, modified biharmonic), with the solver's ranks and residuals. Prints Markdown (the
// README of this folder holds its output).
//
//   ./build/example_002_bspline_examples
#include "bezierpde/core/eigen.h"
#include <Eigen/Dense>
#include <chrono>
#include <cmath>
#include <complex>
#include <cstdio>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include "bezierpde/energies/energy_spec.h"
#include "examples/common/generated.h"
#include "bezierpde/solvers/bspline/bspline_extremal.h"
#include "bezierpde/solvers/bspline/bspline_pde.h"
#include "bezierpde/tensor/bspline_net.h"
#include "bezierpde/tensor/bspline_ops.h"
#include "bezierpde/tensor/tensor_net.h"

using namespace bpde;

namespace {

std::vector<double> uniform(int count) {
  std::vector<double> K;
  for (int i = 0; i < count; ++i) K.push_back(i);
  return K;
}

std::vector<double> clamped(int k, const std::vector<double>& interior) {
  std::vector<double> K(static_cast<size_t>(k + 1), 0.0);
  K.insert(K.end(), interior.begin(), interior.end());
  K.insert(K.end(), static_cast<size_t>(k + 1), 1.0);
  return K;
}

int rank_of(const Eigen::MatrixXd& A) {
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd(A);
  int r = 0;
  for (int k = 0; k < svd.singularValues().size(); ++k) r += svd.singularValues()(k) > 1e-10 * svd.singularValues()(0);
  return r;
}

std::string frac(double x) {
  // Print small rationals with denominators 1, 2, 3, 6, 9 exactly, else a decimal.
  for (int d : {1, 2, 3, 6, 9, 18, 27}) {
    const double n = x * d;
    if (std::abs(n - std::round(n)) < 1e-9 * (1 + std::abs(n))) {
      char b[64];
      if (d == 1)
        std::snprintf(b, sizeof b, "%.0f", std::round(n));
      else
        std::snprintf(b, sizeof b, "%.0f/%d", std::round(n), d);
      return b;
    }
  }
  char b[64];
  std::snprintf(b, sizeof b, "%.6g", x);
  return b;
}

void print_z_grid(const BSplineNet& net) {
  std::printf("| i \\ j |");
  for (int j = 0; j < net.nv(); ++j) std::printf(" %d |", j);
  std::printf("\n|---|");
  for (int j = 0; j < net.nv(); ++j) std::printf("---|");
  std::printf("\n");
  for (int i = 0; i < net.nu(); ++i) {
    std::printf("| %d |", i);
    for (int j = 0; j < net.nv(); ++j) std::printf(" %s |", frac(net.points()(net.index(i, j), 2)).c_str());
    std::printf("\n");
  }
  std::printf("\n");
}

// Residuals at rounding level (their digits vary with the build): "< 1e-12" below 1e-12.
std::string rounding(double x) { return bpde::examples::stable_small(x, 1e-12); }

// An energy: 8 significant digits, "< 1e-8" where it is 0 up to rounding (a semi-definite energy's
// minimum).
std::string energy_text(double e) {
  if (std::abs(e) < 1e-8) return "< 1e-8";
  char b[32];
  std::snprintf(b, sizeof b, "%.8g", e);
  return b;
}

void report(const char* what, const BSplinePdeResult& r, const EnergySpec& op) {
  std::printf(
      "- %s: %d equations, rank %d over all points, %d over the free points; free parameters %d; "
      "compatibility conditions %d; converged %s; relative residual %s%s\n",
      what, r.equations, r.rank, r.rank_free, r.free_parameters, r.compatibility_conditions,
      r.summary.converged ? "**yes**" : "**no**", rounding(r.summary.residual).c_str(),
      r.minimum_energy_member ? "; **minimum-energy member** returned" : "");
  if (r.summary.converged)
    std::printf("  - energy %s; relative equation residual %s; pde_residual (FORMATS.md, 50 x 50 grid) %s\n",
                energy_text(r.energy).c_str(), rounding(bspline_pde_equation_residual(r.net, op)).c_str(),
                bpde::examples::stable_small(bspline_pde_residual(r.net, op), 1e-6).c_str());
  if (!r.summary.message.empty()) std::printf("  - message: \"%s\"\n", r.summary.message.c_str());
}

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

}  // namespace

int main() {
  // Examples 1 and 2: the generated section bspline-paper-examples of README.md.
  std::optional<bpde::examples::GeneratedSection> paper_section;
  paper_section.emplace("bspline-paper-examples");
  // ------------------------------------------------------------------ Example 1
  std::printf("## Example 1: a x_uu + b x_uv + c x_vv = 0 with (a,b,c) = (1,-2,1), bicubic, 4 x 4 points\n\n");
  std::printf("Set-up: uniform knots 0..7 (h = 1), standard indexing, patch on the span [u3,u4] x [v3,v4].\n\n");
  {
    const std::vector<double> K = uniform(8);
    const EnergySpec op = EnergySpec::second_order(1, -2, 1);
    const Eigen::MatrixXd A = bspline_pde_equations(3, 3, K, K, op);
    std::printf(
        "- Equations (Bernstein coefficients of Lx on the span): %ld; **rank %d** (paper: 13 equations, "
        "\"12\" independent). Solution space: dimension 16 - %d = %d, i.e. f(u+v) + (u-v) g(u+v).\n",
        static_cast<long>(A.rows()), rank_of(A), rank_of(A), 16 - rank_of(A));
    Eigen::MatrixX3d P(16, 3);
    P << 1, 1, 1, 1, 2, -8, 1, 3, 8, 1, 4, 1,  //
        2, 1, 8, 2, 2, -5. / 9, 2, 3, 119. / 9, 2, 4, 4. / 3, 3, 1, -8, 3, 2, -121. / 9, 3, 3, 7. / 9, 3, 4, -40. / 3,
        4, 1, 1, 4, 2, 4. / 3, 4, 3, 56. / 3, 4, 4, 5;
    const BSplineNet paper(3, 3, K, K, P);
    std::printf(
        "- The paper's listed net: relative equation residual %.3g, pde_residual %.3g (a solution gives ~1e-16): "
        "**it does not satisfy the PDE** (docs/errata.md).\n",
        bspline_pde_equation_residual(paper, op), bspline_pde_residual(paper, op));
    const BSplinePdeResult r = solve_bspline_pde(paper, op, std::vector<int>{0, 1, 2, 3});
    report("Solver with the paper's prescribed P_00..P_03", r, op);
    std::printf("\nz-coordinates of the solver's net (P_0j prescribed):\n\n");
    print_z_grid(r.net);
  }

  // ------------------------------------------------------------------ Example 2
  std::printf("## Example 2: fourth order, quintic, 6 x 6 points\n\n");
  std::printf(
      "Set-up: uniform knots 0..11 (h = 1), the span [u5,u6] x [v5,v6]; prescribed P_0j and P_i0 (11 points) "
      "from the paper. \"a = 1, b = 2, c = 1 in Equation (4)\" is read two ways: the operator [1,2,1,0,0] "
      "and the biharmonic [1,0,2,0,1].\n\n");
  {
    const std::vector<double> K = uniform(12);
    const double z[6][6] = {{0, 10, 10, -10, -10, 0},
                            {-10, 0 /*P11 missing*/, -1, -27, -106. / 3, -80. / 3},
                            {-10, 1, 0, -33, -164. / 3, -175. / 3},
                            {10, 27, 33, 0, -30, -45},
                            {10, 106. / 3, 164. / 3, 30, 0, -20},
                            {0, 80. / 3, 175. / 3, 45, 20, 0}};
    Eigen::MatrixX3d P(36, 3);
    for (int i = 0; i < 6; ++i)
      for (int j = 0; j < 6; ++j) P.row(i * 6 + j) << i + 1, j + 1, z[i][j];
    std::vector<int> fixed;
    for (int i = 0; i < 6; ++i)
      for (int j = 0; j < 6; ++j)
        if (i == 0 || j == 0) fixed.push_back(i * 6 + j);
    for (const EnergySpec& op : {EnergySpec::pde_operator({1, 2, 1, 0, 0}), EnergySpec::biharmonic()}) {
      const auto& c = op.operator_coeffs();
      std::printf("### Operator [%g,%g,%g,%g,%g]\n\n", c[0], c[1], c[2], c[3], c[4]);
      const Eigen::MatrixXd A = bspline_pde_equations(5, 5, K, K, op);
      std::printf("- Equations: %ld, **rank %d** (paper: 26 equations, \"10 free points\" i.e. rank 26).\n",
                  static_cast<long>(A.rows()), rank_of(A));
      // The listed net with P11 = (2, 2, z) and z chosen to minimise the equation residual.
      BSplineNet paper(5, 5, K, K, P);
      const Eigen::VectorXd r0 = A * paper.points().col(2);
      const Eigen::VectorXd a = A.col(7);
      const double z11 = -a.dot(r0) / a.squaredNorm();
      paper.points()(7, 2) = z11;
      std::printf(
          "- The paper's listed net, with the missing P_11 = (2, 2, %s) chosen to minimise the residual: "
          "relative equation residual %.3g, pde_residual %.3g: **not a solution**.\n",
          std::abs(z11) < 1e-12 ? "0 up to rounding" : frac(z11).c_str(), bspline_pde_equation_residual(paper, op),
          bspline_pde_residual(paper, op));
      const BSplinePdeResult r = solve_bspline_pde(paper, op, fixed);
      report("Solver with the paper's 11 prescribed points", r, op);
      std::printf("\nz-coordinates of the solver's net (row i = 0 and column j = 0 prescribed):\n\n");
      print_z_grid(r.net);
      BSplinePdeOptions o;
      o.fixed = FixedSet::Boundary;
      const BSplinePdeResult rb = solve_bspline_pde(paper, op, o);
      report("Solver with the whole boundary ring of the listed net prescribed (20 points)", rb, op);
      std::printf("\n");
    }
  }

  paper_section.reset();
  std::printf("\n");
  // ------------------------------------------------------------------ §5 special cases
  // The PDE solutions of §5: the generated section bspline-section5-pde of README.md.
  std::optional<bpde::examples::GeneratedSection> section5;
  section5.emplace("bspline-section5-pde");
  std::printf("## Section 5 special cases on a multi-span net\n\n");
  std::printf(
      "Biquintic, clamped knots [0^6, 0.5, 1^6] in both directions (2 x 2 spans, 7 x 7 points), "
      "boundary ring prescribed.\n\n");
  {
    const std::vector<double> K = clamped(5, {0.5});
    std::mt19937 rng(2019);
    std::uniform_real_distribution<double> R(-1, 1);
    Eigen::MatrixX3d G(49, 3);
    for (int i = 0; i < 7; ++i)
      for (int j = 0; j < 7; ++j) G.row(i * 7 + j) << i / 6.0, j / 6.0, 0.3 * R(rng);
    const BSplineNet generic(5, 5, K, K, G);
    // Exact B-spline nets of polynomials z = f(u, v) (x = u, y = v): Bernstein interpolation on a
    // Chebyshev grid (exact for bidegree <= (5,5)), then blossoming onto the knots.
    auto spline_of = [&](double (*f)(double, double)) {
      Eigen::VectorXd s(6);
      for (int k = 0; k < 6; ++k) s(k) = 0.5 - 0.5 * std::cos(M_PI * (k + 0.5) / 6);
      Eigen::MatrixXd B(6, 6), F(6, 6);
      for (int a = 0; a < 6; ++a)
        for (int k = 0; k < 6; ++k)
          B(a, k) = std::tgamma(6) / (std::tgamma(k + 1) * std::tgamma(6 - k)) * std::pow(s(a), k) *
                    std::pow(1 - s(a), 5 - k);
      for (int a = 0; a < 6; ++a)
        for (int b = 0; b < 6; ++b) F(a, b) = f(s(a), s(b));
      const Eigen::FullPivLU<Eigen::MatrixXd> lu(B);
      const Eigen::MatrixXd C = lu.solve(lu.solve(F).transpose()).transpose();
      TensorNet bez(5, 5);
      for (int i = 0; i < 6; ++i)
        for (int j = 0; j < 6; ++j) bez.points().row(bez.index(i, j)) << i / 5.0, j / 5.0, C(i, j);
      return bspline_from_bezier(bez, 0, 1, 0, 1, 5, 5, K, K);
    };
    auto boundary_only = [](BSplineNet net) {
      for (int idx : net.free_indices(FixedSet::Boundary)) net.points().row(idx).setZero();
      return net;
    };
    // A compatible boundary for the elliptic operators: the biharmonic polynomial
    // z = Re((u + i v)^5) + (u^2 + v^2) u v; and for x_uuuu = 0: z = (u^3 - 2u)(v^5 + v) + u v.
    const BSplineNet poly = spline_of(
        [](double u, double v) { return std::pow(std::complex<double>(u, v), 5).real() + (u * u + v * v) * u * v; });
    const BSplineNet cubic_u =
        spline_of([](double u, double v) { return (u * u * u - 2 * u) * (v * v * v * v * v + v) + u * v; });
    const BSplineNet compatible = boundary_only(poly);

    std::printf("### PDE solutions (Algorithm 2)\n\n");
    const double alpha = 0.8;
    const std::vector<std::pair<const char*, EnergySpec>> ops = {
        {"Coons x_uuvv = 0 (L_{0,0,1,0,0})", EnergySpec::coons()},
        {"biharmonic (L_{1,0,2,0,1})", EnergySpec::biharmonic()},
        {"modified biharmonic, alpha = 0.8 (L_{1,0,2a^2,0,a^4})", EnergySpec::modified_biharmonic(alpha)},
        {"degenerate x_uuuu = 0 (L_{1,0,0,0,0})", EnergySpec::pde_operator({1, 0, 0, 0, 0})}};
    for (const auto& [name, op] : ops) {
      std::printf("**%s**\n\n", name);
      report("generic boundary", solve_bspline_pde(generic, op), op);
      const BSplinePdeResult rc = solve_bspline_pde(compatible, op);
      report("boundary of z = Re((u+iv)^5) + (u^2+v^2)uv, x = u, y = v", rc, op);
      if (op.kind() == EnergyKind::Operator)
        report("boundary of z = (u^3 - 2u)(v^5 + v) + uv (cubic in u), x = u, y = v",
               solve_bspline_pde(boundary_only(cubic_u), op), op);
      if (op.kind() == EnergyKind::Biharmonic && rc.summary.converged)
        std::printf("  - max |P - P_exact| = %s (the biharmonic polynomial is recovered)\n",
                    rounding((rc.net.points() - poly.points()).cwiseAbs().maxCoeff()).c_str());
      std::printf("\n");
    }
    // Coons patch check for the generic boundary.
    {
      const BSplinePdeResult r = solve_bspline_pde(generic, EnergySpec::coons());
      double err = 0;
      for (int a = 0; a <= 20; ++a)
        for (int b = 0; b <= 20; ++b) {
          const double u = a / 20.0, v = b / 20.0;
          const Eigen::Vector3d c = (1 - u) * generic.evaluate(0, v) + u * generic.evaluate(1, v) +
                                    (1 - v) * generic.evaluate(u, 0) + v * generic.evaluate(u, 1) -
                                    ((1 - u) * (1 - v) * generic.evaluate(0, 0) + (1 - u) * v * generic.evaluate(0, 1) +
                                     u * (1 - v) * generic.evaluate(1, 0) + u * v * generic.evaluate(1, 1));
          err = std::max(err, (r.net.evaluate(u, v) - c).norm());
        }
      std::printf(
          "The Coons solution equals the bilinearly blended Coons patch of the four boundary curves: "
          "max deviation on a 21 x 21 grid %s.\n",
          rounding(err).c_str());
    }

    section5.reset();
    std::printf("\n### Extremals (exist for any boundary)\n\n");
    std::optional<bpde::examples::GeneratedSection> section;
    section.emplace("bspline-extremals", "seconds");
    std::printf("| energy | fixed | energy value | relative residual | seconds |\n|---|---|---|---|---|\n");
    for (const auto& [name, e] : std::vector<std::pair<const char*, EnergySpec>>{
             {"coons", EnergySpec::coons()},
             {"biharmonic", EnergySpec::biharmonic()},
             {"laplacian-squared", EnergySpec::laplacian_squared()},
             {"modified-biharmonic 0.8", EnergySpec::modified_biharmonic(alpha)},
             {"dirichlet", EnergySpec::dirichlet()}})
      for (FixedSet fx : {FixedSet::Boundary, FixedSet::BoundaryAdjacent}) {
        const BSplineExtremalResult r = solve_bspline_extremal(generic, e, BSplineExtremalOptions{fx});
        std::printf("| %s | %s | %.10g | %s | %.1e |\n", name, to_string(fx).c_str(), r.energy,
                    bpde::examples::stable_small(r.summary.residual).c_str(), r.summary.seconds);
      }
    section.reset();
    std::printf("\n");
  }

  // ------------------------------------------------------------------ sizes
  std::printf("## Larger nets (timings on this machine)\n\n");
  const bpde::examples::GeneratedSection sizes("bspline-sizes", "seconds");
  std::printf("| net | problem | result | seconds |\n|---|---|---|---|\n");
  for (int spans : {4, 8, 16}) {
    std::vector<double> interior;
    for (int s = 1; s < spans; ++s) interior.push_back(static_cast<double>(s) / spans);
    const std::vector<double> K = clamped(5, interior);
    const int n = spans + 5;
    Eigen::MatrixX3d P(n * n, 3);
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> R(-1, 1);
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) P.row(i * n + j) << i, j, R(rng);
    const BSplineNet net(5, 5, K, K, P);
    auto t0 = std::chrono::steady_clock::now();
    const BSplineExtremalResult e = solve_bspline_extremal(net, EnergySpec::biharmonic());
    std::printf("| biquintic %d x %d spans (%d points) | biharmonic extremal | residual %s | %.3f |\n", spans, spans,
                n * n, bpde::examples::stable_small(e.summary.residual).c_str(), seconds_since(t0));
    t0 = std::chrono::steady_clock::now();
    const BSplinePdeResult r = solve_bspline_pde(net, EnergySpec::coons());
    std::printf("| biquintic %d x %d spans (%d points) | Coons PDE, %d equations | rank %d, converged %s | %.3f |\n",
                spans, spans, n * n, r.equations, r.rank, r.summary.converged ? "yes" : "no", seconds_since(t0));
  }
  return 0;
}
