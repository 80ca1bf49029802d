#include "bezierpde/solvers/cmc/area_route.h"

#include <cstdio>

namespace bpde {
namespace {

std::string g3(double x) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.3g", x == 0.0 ? 0.0 : x);
  return buf;
}

}  // namespace

const char* to_string(AreaRoute r) {
  switch (r) {
    case AreaRoute::MeanCurvatureStart:
      return "mean-curvature-start";
    case AreaRoute::DirichletStart:
      return "dirichlet-start";
    case AreaRoute::HContinuation:
      return "h-continuation";
    case AreaRoute::DirichletVolumeStart:
      return "dirichlet-volume-start";
    case AreaRoute::SmallerVolumeStart:
      return "smaller-volume-start";
    case AreaRoute::VContinuation:
      return "v-continuation";
    case AreaRoute::MinimalSurface:
      return "minimal-surface";
  }
  return "unknown";
}

const char* to_string(AreaPhase p) {
  switch (p) {
    case AreaPhase::RuleRefresh:
      return "rule-refresh";
    case AreaPhase::TruncatedNewton:
      return "truncated-newton";
    case AreaPhase::SoftModeLm:
      return "soft-mode-lm";
    case AreaPhase::SoftModeCeres:
      return "soft-mode-ceres";
    case AreaPhase::TrustRegion:
      return "trust-region";
  }
  return "unknown";
}

const char* to_string(SoftModeEnd e) {
  switch (e) {
    case SoftModeEnd::None:
      return "none";
    case SoftModeEnd::Stationary:
      return "stationary";
    case SoftModeEnd::DegenerateBound:
      return "degenerate-bound";
  }
  return "unknown";
}

int AreaRouteRecord::phase_count(AreaPhase phase) const {
  for (const AreaPhaseRecord& p : phases)
    if (p.phase == phase) return p.count;
  return 0;
}

void AreaRouteRecord::add_phase(AreaPhase phase, int count) {
  if (count <= 0) return;
  for (AreaPhaseRecord& p : phases)
    if (p.phase == phase) {
      p.count += count;
      return;
    }
  phases.push_back({phase, count});
}

const AreaRouteRecord* AreaRouteLog::find(AreaRoute route) const {
  for (const AreaRouteRecord& r : records)
    if (r.route == route) return &r;
  return nullptr;
}
AreaRouteRecord* AreaRouteLog::find(AreaRoute route) {
  return const_cast<AreaRouteRecord*>(static_cast<const AreaRouteLog*>(this)->find(route));
}

const AreaRouteRecord* AreaRouteLog::kept() const {
  for (const AreaRouteRecord& r : records)
    if (r.kept) return &r;
  return nullptr;
}
AreaRouteRecord* AreaRouteLog::kept() { return const_cast<AreaRouteRecord*>(static_cast<const AreaRouteLog*>(this)->kept()); }

int AreaRouteLog::phase_count(AreaPhase phase) const {
  int n = 0;
  for (const AreaRouteRecord& r : records) n += r.phase_count(phase);
  return n;
}

std::string full_report(const AreaRouteLog& log) {
  std::string s;
  for (const AreaRouteRecord& r : log.records) {
    s += to_string(r.route);
    if (!r.tried) {
      s += ": not tried (" + r.why + ")\n";
      continue;
    }
    s += std::string(": ") + to_string(r.status);
    s += ", first variation " + (r.first_variation ? g3(*r.first_variation) : std::string("-"));
    s += ", " + std::to_string(r.iterations) + " iteration(s)";
    if (r.continuation_steps > 0) s += ", " + std::to_string(r.continuation_steps) + " step(s)";
    s += ", " + g3(r.seconds) + " s";
    for (const AreaPhaseRecord& p : r.phases) s += std::string(", ") + to_string(p.phase) + " " + std::to_string(p.count);
    if (r.soft_mode_end != SoftModeEnd::None) s += std::string(", soft-mode end ") + to_string(r.soft_mode_end);
    s += r.kept ? ", kept" : ", not kept";
    if (!r.why.empty()) s += " (" + r.why + ")";
    s += "\n";
  }
  return s;
}

std::string brief_report(const AreaRouteLog& log) {
  const AreaRouteRecord* k = log.kept();
  if (!k) return "no route kept (" + std::to_string(log.records.size()) + " considered)";
  return std::string(to_string(k->route)) + ": " + to_string(k->status) +
         (k->first_variation ? ", first variation " + g3(*k->first_variation) : std::string());
}

std::string route_notes(const AreaRouteLog& log) {
  std::string s;
  for (const AreaRouteRecord& r : log.records) {
    if (!r.tried) {
      s += std::string(" (") + to_string(r.route) + " not tried: " + r.why + ")";
    } else if (log.reported && r.route == *log.reported) {
      if (r.kept && !r.why.empty()) s += " (kept: " + r.why + ")";
    } else {
      s += std::string(" (") + to_string(r.route) + ": " + r.message + (r.why.empty() ? "" : "; " + r.why) + ")";
    }
  }
  return s;
}

}  // namespace bpde
