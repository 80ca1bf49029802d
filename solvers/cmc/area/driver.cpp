// The area solve as a short loop over named routes (docs/cmc_algorithm.md): routes_for() gives the
// routes for the options in the order they are tried and how each enters; Driver::solve() runs
// them, keeps the better end where two are compared, writes one AreaRouteRecord per route
// considered, then the final rule check and the verdict on the final net.
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <type_traits>
#include <vector>

#include "bezierpde/core/kron.h"
#include "bezierpde/core/progress.h"
#include "bezierpde/solvers/cmc/area/area_solve.h"

namespace bpde::cmc_detail::area_impl {
namespace {

/// How a route enters the sequence.
enum class Entry {
  First,          ///< runs while no route has produced a point
  SecondOpinion,  ///< runs also after a point above the tolerance; then `keep` decides between the two ends
  LastResort,     ///< runs only when every route before it failed, from fresh damping and ε = 0
};
/// When a second opinion's end replaces the point before it.
enum class Keep {
  OnlyIfConverged,      ///< only where it meets the tolerance (H form: a lower numerical limit can lie
                        ///< further from H; the tensor catenoid at n = 8, docs/cmc_measurements.md)
  LowerFirstVariation,  ///< where its checked first variation is lower (V form past the hemisphere)
};
struct RoutePlan {
  AreaRoute route;
  Entry entry = Entry::First;
  Keep keep = Keep::OnlyIfConverged;
  /// SecondOpinion: the route whose end it is a second opinion on (an end from any other route
  /// stands as it is).
  AreaRoute on = AreaRoute::DirichletStart;
};

/// The routes for the options, in order. mean-curvature-start first unless "start" says
/// otherwise; "start": "minimal-surface" runs the continuation from the minimal surface alone.
std::vector<RoutePlan> routes_for(const CmcOptions& o) {
  const bool minimal = o.area_start == AreaStart::MinimalSurface;
  if (minimal) {
    if (o.V) return {{AreaRoute::VContinuation}};
    return {{o.H == 0.0 ? AreaRoute::MinimalSurface : AreaRoute::HContinuation}};
  }
  std::vector<RoutePlan> plan;
  if (o.area_start == AreaStart::MeanCurvature) plan.push_back({AreaRoute::MeanCurvatureStart});
  if (o.V) {
    plan.push_back({AreaRoute::DirichletVolumeStart});
    plan.push_back({AreaRoute::SmallerVolumeStart, Entry::SecondOpinion, Keep::LowerFirstVariation,
                    AreaRoute::DirichletVolumeStart});
    plan.push_back({AreaRoute::VContinuation, Entry::LastResort});
  } else if (o.H == 0.0) {
    plan.push_back({AreaRoute::MinimalSurface});
  } else {
    plan.push_back({AreaRoute::DirichletStart});
    plan.push_back({AreaRoute::HContinuation, Entry::SecondOpinion, Keep::OnlyIfConverged, AreaRoute::DirichletStart});
  }
  return plan;
}

template <class Net>
struct Driver {
  Driver(AreaSolve<Net>& s_, const CmcOptions& o_, CmcResult<Net>& res_, const Eigen::MatrixX3d& extremal_,
         const std::vector<int>& fixed_idx_, const double* V0_)
      : s(s_), o(o_), res(res_), extremal(extremal_), fixed_idx(fixed_idx_), V0(V0_) {}

  AreaSolve<Net>& s;
  const CmcOptions& o;
  CmcResult<Net>& res;
  const Eigen::MatrixX3d& extremal;  ///< the Dirichlet extremal (H = 0), the continuations' start
  const std::vector<int>& fixed_idx;
  const double* V0;

  AreaOutcome out;                   ///< the end reported so far
  AreaRouteRecord* reported = nullptr;  ///< its record
  int steps = 0;                     ///< its continuation steps
  bool mean_curvature_failed = false;

  AreaRouteLog& log() { return res.routes; }

  /// The route's own run, from the state the driver leaves.
  AreaOutcome dispatch(AreaRoute route, int& route_steps) {
    switch (route) {
      case AreaRoute::MeanCurvatureStart: {
        double h = o.H;
        std::string note;
        if (s.from_mean_curvature(V0, h, note, route_steps))
          return {h, true, Status::Converged,
                  (V0 ? "the volume-constrained critical point of A from " : "the critical point of A_H from ") + note};
        return {h, false, Status::NoConvergence, note};
      }
      case AreaRoute::DirichletStart: {
        std::string note;
        if (s.from_dirichlet(o.H, note))
          return {o.H, true, Status::Converged,
                  "the D_H critical point at H = " + num(o.H) + " corrected on A_H" + (note.empty() ? "" : " (" + note + ")")};
        return {o.H, false, Status::NoConvergence, note};
      }
      case AreaRoute::HContinuation:
        return s.continuation(extremal, fixed_idx, route_steps);
      case AreaRoute::DirichletVolumeStart:
        return s.from_dirichlet_volume(*V0);
      case AreaRoute::SmallerVolumeStart:
        return s.volume_continuation_from_smaller(*V0, s.p.base.f->volume_form().value(extremal), route_steps);
      case AreaRoute::VContinuation:
        return s.volume_continuation(extremal, route_steps);
      case AreaRoute::MinimalSurface:
        s.p.base.P = extremal;
        return s.minimal_surface_route();
    }
    return {};
  }

  /// Runs `route` into a new record: iterations, steps, seconds, phases, its status and first variation.
  AreaOutcome run(AreaRoute route, AreaRouteRecord*& rec, int& route_steps) {
    log().records.push_back({});
    rec = &log().records.back();
    rec->route = route;
    rec->tried = true;
    const int iterations0 = res.summary.iterations;
    s.record = rec;
    AreaOutcome r;
    {
      ScopedTimer timer(rec->seconds);
      r = dispatch(route, route_steps);
    }
    s.record = nullptr;
    rec->iterations = res.summary.iterations - iterations0;
    rec->continuation_steps = route_steps;
    rec->message = r.message;
    if (r.ok) {
      const double fv = V0 ? s.vresidual(*V0, r.H) : s.p.residual_at(o.H == 0.0 ? 0.0 : r.H, 0.0);
      rec->first_variation = fv;
      rec->status = fv <= o.tolerance ? Status::Converged : Status::NumericalLimit;
      rec->soft_mode_end = s.soft_end();
    } else {
      rec->status = r.why;
    }
    return r;
  }

  /// The gate of mean-curvature-start: not tried where the D_H point already nearly is a critical
  /// point of A_H (conformal data).
  bool gate_mean_curvature_start() {
    if (!has_mean_curvature_start(s.data)) {
      AreaRouteRecord rec;
      rec.route = AreaRoute::MeanCurvatureStart;
      rec.why = "the least squares of the mean curvature are dense: a complex of at most " +
                std::to_string(kMeanCurvatureStartCoordinates) + " free coordinates";
      log().records.push_back(rec);
      return false;
    }
    const double r = s.dirichlet_first_variation(V0);
    if (r > kConformalFirstVariation) return true;
    AreaRouteRecord rec;
    rec.route = AreaRoute::MeanCurvatureStart;
    rec.why = "the first variation of A_H at the " + std::string(V0 ? "minimiser of D at V0" : "D_H critical point") +
              " is " + num(r, 3) + ", at most " + num(kConformalFirstVariation, 1) + ", as on conformal data";
    log().records.push_back(rec);
    return false;
  }

  void take(const AreaOutcome& r, AreaRouteRecord* rec, int route_steps) {
    out = r;
    reported = rec;
    steps = route_steps;
  }

  /// A second opinion after a point above the tolerance: the better end by `keep`, the other's
  /// state put back where it is not kept.
  void second_opinion(const RoutePlan& plan) {
    const double r1 = s.checked_residual(out.H);
    if (!(r1 > o.tolerance)) return;
    reported->first_variation = r1;
    const auto before = s.save();
    AreaRouteRecord* rec = nullptr;
    int route_steps = 0;
    const AreaOutcome r = run(plan.route, rec, route_steps);
    const double r2 = r.ok ? s.checked_residual(r.H) : std::numeric_limits<double>::infinity();
    if (r.ok) rec->first_variation = r2;
    const bool keep = plan.keep == Keep::OnlyIfConverged ? r2 <= o.tolerance : r2 < r1;
    if (keep) {
      rec->why = std::string(to_string(reported->route)) + " ended at " + num(r1, 3) + ", above the tolerance";
      take(r, rec, route_steps);
      return;
    }
    s.restore(before);
    rec->why = "not kept: " + std::string(r.ok ? "ended above the tolerance too, at " + num(r2, 3) : "failed");
    reported->why = std::string(to_string(plan.route)) +
                    (r.ok ? " ended above the tolerance too, at " + num(r2, 3) : " failed");
  }

  /// Where mean-curvature-start stalled within kAreaStallResidual and the other routes end
  /// higher (or fail), its end instead (the tensor catenoid at n = 10: 2.6e-11 against 5.2e-11).
  void reconsider_mean_curvature_end() {
    if (V0 || !mean_curvature_failed || !s.stalled_mean_curvature_end) return;
    const double r_dh = out.ok ? s.checked_residual(o.H) : std::numeric_limits<double>::infinity();
    if (!(r_dh > o.tolerance)) return;
    const auto theirs = s.save();
    s.restore(s.stalled_mean_curvature_end->state);
    const double r0 = s.checked_residual(o.H);
    if (!(r0 < r_dh && r0 <= kAreaStallResidual)) {
      s.restore(theirs);
      return;
    }
    s.p.eps = 0.0;  // A_H itself, as mean-curvature-start ended
    s.theta = kFreshDamping;
    AreaRouteRecord* mc = log().find(AreaRoute::MeanCurvatureStart);
    mc->first_variation = r0;
    mc->status = Status::NumericalLimit;
    mc->why = out.ok ? "the other routes ended higher, at " + num(r_dh, 3) : "the other routes failed";
    if (reported) reported->why = "not kept: mean-curvature-start's end is lower";
    take({o.H, true, Status::Converged, "the end of mean-curvature-start, " + s.stalled_mean_curvature_end->note}, mc, 0);
  }

  void run_routes() {
    log().records.reserve(8);  // records are held by pointer while routes run: no reallocation
    for (const RoutePlan& plan : routes_for(o)) {
      if (plan.entry == Entry::SecondOpinion && out.ok) {
        if (reported && reported->route == plan.on) second_opinion(plan);
        continue;
      }
      if (out.ok) continue;  // a point is there: First and LastResort routes are not needed
      if (plan.route == AreaRoute::MeanCurvatureStart && !gate_mean_curvature_start()) continue;
      if (plan.entry == Entry::LastResort) {
        s.theta = 1.0;  // as a first route, not with the other routes' damping or regulariser
        s.p.eps = 0.0;
      }
      AreaRouteRecord* rec = nullptr;
      int route_steps = 0;
      const AreaOutcome r = run(plan.route, rec, route_steps);
      if (plan.route == AreaRoute::MeanCurvatureStart && !r.ok) {
        mean_curvature_failed = true;  // the state went back: the next route starts afresh
        continue;
      }
      take(r, rec, route_steps);
    }
    reconsider_mean_curvature_end();
    if (reported) {
      reported->kept = out.ok;
      log().reported = reported->route;
    }
    out.message += route_notes(log());
  }
};

/// Triangular complexes of at most kComplexPolishCoordinates free coordinates, H form: a converged end taken on towards kComplexPolishFactor × the tolerance by the
/// final phases, on a rule chosen for that tolerance. On the fans of triangles the surface's
/// distance from the exact one is 1e3 … 1e4 × the first variation (the soft modes are nearly
/// reparametrisations: the residual they hold leaves the parametrisation, and with it the surface,
/// short of the discrete critical point), so the tolerance the solve is judged by leaves the
/// surface far from where the degree would put it. The polished net is kept only where its first
/// variation is lower and still meets the tolerance; `note` says what it reached.
template <class Net>
void polish(AreaSolve<Net>& s, const AreaOutcome& out, const CmcOptions& o, Summary& summary, AreaRouteRecord* record,
            std::string& note) {
  if constexpr (std::is_same_v<Net, ComplexNet>) {
    // Triangular fans, dense: the tensor ring's soft modes do not hold its surface back (the
    // catenoid at degree 8: 6.6e-10 from the exact surface at the tolerance), and on the larger
    // complexes the dense phases cost minutes (kComplexPolishCoordinates).
    if (!out.ok || o.V || !s.tri || s.p.sparse || 3 * s.p.k() > kComplexPolishCoordinates) return;
    CmcOptions deep = o;
    deep.tolerance = std::max(kComplexPolishFloor, kComplexPolishFactor * o.tolerance);
    if (!(deep.tolerance < o.tolerance)) return;
    AreaSolve<Net> d(s.data, deep, s.p, summary);
    d.theta = s.theta;
    d.record = record;
    d.choose_rule();
    const double r0 = d.p.residual(out.H);
    if (!(r0 > deep.tolerance)) return;
    const CorrectorStats st = d.finish(out.H, o.max_corrector_iterations);
    summary.iterations += st.iterations;
    const double r1 = d.p.residual(out.H);
    if (!(r1 < r0 && r1 <= o.tolerance)) return;
    s.p = d.p;
    s.rule_change = d.rule_change;
    note = "; polished by the final phases to a first variation of " + num(r1, 3);
  } else {
    (void)s, (void)out, (void)o, (void)summary, (void)record, (void)note;
  }
}

/// The result's numbers at the final net, the verdict on it (tolerance, regularity) and the summary.
template <class Net>
void fill(CmcResult<Net>& res, AreaSolve<Net>& s, AreaOutcome out, const Net& data, const CmcOptions& o) {
  const Net net = make_net(data, s.p.P());
  const CmcFunctional& f = *s.p.base.f;
  res.net = net;
  res.H = out.H;
  res.D = f.dirichlet(s.p.P());
  res.V = f.volume(s.p.P());
  res.DH = res.D + 2.0 * out.H * res.V;
  res.A = s.p.area();
  res.energy = res.A + 2.0 * out.H * res.V;
  res.quadrature_points = s.p.a->points_per_direction();
  res.quadrature_grading = s.p.a->grading();
  res.quadrature_levels = s.p.a->levels();
  res.quadrature_nodes = s.p.a->nodes();
  res.summary.residual = s.p.residual(out.H);
  if (o.V) {
    const double vs = f.volume_form().value_scale(s.p.P());
    res.summary.residual = std::max(res.summary.residual, std::abs(res.V - *o.V) / (vs > 0 ? vs : 1.0));
  }
  const Regularity reg = final_regularity(net, res.A);
  res.parametrisation = parametrisation_check(reg);
  if (out.ok && !(res.summary.residual <= o.tolerance)) {
    out = {out.H, false, Status::NumericalLimit,
           "the final net misses the first variation of A_H by " + num(res.summary.residual) + " (relative)" +
               s.soft_verdict(true) + "; reached after: " + out.message};
  }
  if (!reg.ok) {
    out.ok = false;
    out.why = Status::NoConvergence;
    out.message = "degenerate parametrisation: " + reg.describe() + " (not a CMC surface); " + out.message;
  }
  if (out.ok) {
    res.summary.message = out.message;
    res.summary.set_converged();
  } else {
    res.summary.set_failed(out.why, out.message);
  }
}

template <class Net>
CmcResult<Net> solve(const Net& data, const CmcOptions& o) {
  // The Hessian's per-thread scratch lives as long as the solve (AreaForm::hessian).
  struct ReleaseScratch {
    ~ReleaseScratch() { AreaForm::release_scratch(); }
  } release_scratch;
  CmcResult<Net> res;
  res.functional = CmcFunctionalKind::Area;
  {
    ScopedTimer timer(res.summary.seconds);
    DirichletStart start = dirichlet_start(data, o);
    CmcProblem& base = start.p;
    const Eigen::MatrixX3d extremal = base.P;
    AreaProblem problem;
    problem.base = base;
    bool sparse = false;
    if constexpr (std::is_same_v<Net, ComplexNet>) sparse = 3 * base.k() > kSparseFromCoordinates;
    if (sparse) {
      // Several patches, many points: sparse Gram and Hessians, sparse factors (sparse_terms.h).
      if constexpr (std::is_same_v<Net, ComplexNet>)
        problem.sparse = std::make_shared<const SparseAreaTerms>(*base.f, base.free, data.triangular(), data.n());
    } else {
      const Eigen::MatrixXd Cff = base.f->gram()(base.free, base.free);
      problem.C = kron(Cff, Eigen::Matrix3d::Identity());
    }
    AreaSolve<Net> s(data, o, std::move(problem), res.summary);
    if (o.progress) s.p.progress = &o.progress;
    Driver<Net> d(s, o, res, extremal, start.fixed_idx, o.V ? &*o.V : nullptr);
    d.run_routes();
    res.continuation_steps = d.steps;
    if (!o.V) d.out.H = d.out.ok ? o.H : d.out.H;
    s.rule_check(d.out);
    std::string polished;
    polish(s, d.out, o, res.summary, d.reported, polished);
    d.out.message += polished;
    fill(res, s, d.out, data, o);
  }
  report(o.progress, kAreaStage, 1, 1);
  return res;
}

}  // namespace
}  // namespace bpde::cmc_detail::area_impl

namespace bpde::cmc_detail {

CmcResult<TriangularNet> solve_area(const TriangularNet& data, const CmcOptions& options) {
  return area_impl::solve(data, options);
}
CmcResult<TensorNet> solve_area(const TensorNet& data, const CmcOptions& options) {
  return area_impl::solve(data, options);
}
CmcResult<ComplexNet> solve_area(const ComplexNet& data, const CmcOptions& options) {
  return area_impl::solve(data, options);
}

}  // namespace bpde::cmc_detail
