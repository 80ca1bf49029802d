#include "bezierpde/solvers/requirements.h"

#include <algorithm>

#include "bezierpde/core/errors.h"

namespace bpde {

const char* to_string(NetKind k) {
  switch (k) {
    case NetKind::Tensor:
      return "tensor";
    case NetKind::Triangular:
      return "triangular";
    case NetKind::BSpline:
      return "bspline";
  }
  return "?";
}

bool SolverRequirements::takes(NetKind k) const { return std::find(nets.begin(), nets.end(), k) != nets.end(); }

bool SolverRequirements::takes(FixedSet f) const { return std::find(fixed.begin(), fixed.end(), f) != fixed.end(); }

const MaxDegree* SolverRequirements::max_degree(NetKind k) const {
  for (const MaxDegree& d : max_degrees)
    if (d.net == k) return &d;
  return nullptr;
}

const std::string* SolverRequirements::refusal(const std::string& field) const {
  for (const RefusedField& f : refused_fields)
    if (f.field == field) return &f.reason;
  return nullptr;
}

int SolverRequirements::min_degree(NetKind k, FixedSet f) const {
  for (const MinDegree& d : min_degrees)
    if (d.net == k && d.fixed == f) return d.degree;
  return 0;
}

namespace {

// "a", "a or b", "a, b or c".
template <class T, class Name>
std::string alternatives(const std::vector<T>& xs, const Name& name) {
  std::string s;
  for (size_t i = 0; i < xs.size(); ++i) {
    if (i > 0) s += i + 1 == xs.size() ? " or " : ", ";
    s += name(xs[i]);
  }
  return s;
}

// Does the minimum degree on this net kind depend on the fixed set? Then messages name both.
bool degree_depends_on_fixed_set(const SolverRequirements& r, NetKind k) {
  int seen = 0;
  for (const MinDegree& d : r.min_degrees) {
    if (d.net != k) continue;
    if (seen != 0 && d.degree != seen) return true;
    seen = d.degree;
  }
  return false;
}

// "[n, m]" (appended piecewise: GCC 12 warns falsely (-Wrestrict) on "[" + std::string).
std::string pair(int n, int m) {
  std::string s = "[";
  s += std::to_string(n);
  s += ", ";
  s += std::to_string(m);
  s += ']';
  return s;
}

// "\"boundary\"".
std::string quoted(FixedSet f) {
  std::string s = "\"";
  s += to_string(f);
  s += '"';
  return s;
}

}  // namespace

void check_fixed_set_and_method(const SolverRequirements& r, FixedSet fixed, const std::string& method,
                                const std::string& where) {
  auto unsupported = [&](const std::string& msg) { throw UnsupportedProblem(where + ": " + msg); };
  if (!r.takes(fixed))
    unsupported(!r.fixed_reason.empty() ? r.fixed_reason
                                        : r.problem + " takes \"fixed\": " + alternatives(r.fixed, quoted));
  if (!method.empty() && std::find(r.methods.begin(), r.methods.end(), method) == r.methods.end())
    unsupported(!r.method_reason.empty() ? r.method_reason
                                         : r.problem + " has no method \"" + method + "\" (expected " +
                                               alternatives(r.methods, [](const std::string& s) { return s; }) + ")");
}

void check_requirements(const SolverRequirements& r, const NetShape& net, FixedSet fixed, const std::string& method,
                        const std::string& where) {
  auto unsupported = [&](const std::string& msg) { throw UnsupportedProblem(where + ": " + msg); };
  auto degree = [&](const std::string& msg) { throw DegreeError(where + ": " + msg); };
  const std::string kind = to_string(net.kind);

  if (net.kind == NetKind::Triangular && fixed == FixedSet::UBoundaries)
    unsupported("fixed \"u-boundaries\" is only defined for tensor nets");
  if (!r.takes(net.kind))
    unsupported(r.problem + " needs a " + alternatives(r.nets, [](NetKind k) { return std::string(to_string(k)); }) +
                " net, not a " + kind + " net");
  check_fixed_set_and_method(r, fixed, method, where);

  const bool triangular = net.kind == NetKind::Triangular;
  if (r.square && !triangular && net.n != net.m) degree(r.problem + " needs n = m, got " + pair(net.n, net.m));
  if (const MaxDegree* top = r.max_degree(net.kind); top && (net.n > top->degree || net.m > top->degree))
    degree(r.problem + " on a " + kind + " net takes degrees up to " + std::to_string(top->degree) + " (" +
           top->reason + "), got " + (triangular ? std::to_string(net.n) : pair(net.n, net.m)));
  const int need = r.min_degree(net.kind, fixed);
  if (need <= 0) return;
  const std::string at_least = std::to_string(need);
  if (r.square || triangular) {
    if (net.n >= need) return;
    if (r.square) degree(r.problem + " needs n = m >= " + at_least + ", got " + std::to_string(net.n));
    if (degree_depends_on_fixed_set(r, net.kind))
      degree(r.problem + " on a triangular net with " + to_string(fixed) + " data needs degree >= " + at_least +
             ", got " + std::to_string(net.n));
    degree(r.problem + " needs degree >= " + at_least + ", got " + std::to_string(net.n));
  }
  if (net.n >= need && net.m >= need) return;
  if (degree_depends_on_fixed_set(r, net.kind))
    degree(r.problem + " on a " + kind + " net with " + to_string(fixed) + " data needs degrees >= " + at_least +
           ", got " + pair(net.n, net.m));
  degree(r.problem + " needs degrees >= " + at_least + ", got " + pair(net.n, net.m));
}

}  // namespace bpde
