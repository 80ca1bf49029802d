#pragma once
// What a solver accepts: the net kinds, the prescribed (fixed) sets with their minimum degrees,
// square degrees, the methods it offers, the optional problem fields it refuses. Each solver
// declares its requirements next to its Options (e.g. extremal_requirements() in
// solvers/extremal.h); the job layer (jobs/run_job.h) checks a job against them before anything
// runs, and answers bad combinations with the typed errors of core/errors.h (UnsupportedProblem,
// DegreeError). The solvers still check their own preconditions when called directly.
#include <string>
#include <vector>

#include "bezierpde/core/fixed_set.h"

namespace bpde {

/// The net types of FORMATS.md.
enum class NetKind { Tensor, Triangular, BSpline };

/// "tensor", "triangular" or "bspline".
const char* to_string(NetKind k);

/// The kind and degrees of a net: (n, m) of a tensor net, (p, q) of a B-spline net, (n, n) of a
/// triangular net.
struct NetShape {
  NetKind kind = NetKind::Tensor;
  int n = 0, m = 0;
};

/// The smallest degree a solver takes on one net kind with one fixed set: both degrees of a
/// tensor or B-spline net, the degree of a triangular net.
struct MinDegree {
  NetKind net;
  FixedSet fixed;
  int degree;
};

/// The largest degree a solver takes on one net kind (both degrees of a tensor or B-spline net),
/// and why: the size or the conditioning past which it cannot deliver in reasonable time, memory
/// or precision. Checked up front (DegreeError, exit 2), like the minimum degrees.
struct MaxDegree {
  NetKind net;
  int degree;
  std::string reason;  ///< e.g. "the Bernstein Gram system is numerically singular above"
};

/// An optional field of a problem (a job's key, FORMATS.md) that a combination does not take, and
/// the message when a job gives it.
struct RefusedField {
  std::string field;   ///< e.g. "start"
  std::string reason;  ///< e.g. "only with \"functional\": \"area\""
};

struct SolverRequirements {
  /// How messages name the problem, e.g. `problem "extremal"` (FORMATS.md problem kinds).
  std::string problem;
  /// The net kinds taken, in the order messages list them.
  std::vector<NetKind> nets;
  /// The fixed sets taken; `fixed_reason` is the message when the job's is not among them (empty:
  /// a message listing them).
  std::vector<FixedSet> fixed;
  std::string fixed_reason;
  /// Minimum degrees per (net kind, fixed set); no entry means no minimum.
  std::vector<MinDegree> min_degrees;
  /// Largest degrees per net kind (a documented limit of the method: docs/FORMATS.md "Input
  /// limits"); no entry means none below kMaxDegree.
  std::vector<MaxDegree> max_degrees;
  /// Tensor nets must have n = m.
  bool square = false;
  /// The method names offered for this problem ("explicit", "lu"; "newton", "ceres", "nlopt");
  /// `method_reason` is the message when the job's method is not among them (empty: a message
  /// listing them).
  std::vector<std::string> methods;
  std::string method_reason;
  /// Optional problem fields this combination does not take (the job reader, io/job.cpp, asks
  /// refusal() for each one a job gives and refuses it with ParseError).
  std::vector<RefusedField> refused_fields;

  bool takes(NetKind k) const;
  bool takes(FixedSet f) const;
  /// The minimum degree for (k, f), 0 when there is none.
  int min_degree(NetKind k, FixedSet f) const;
  /// The maximum degree entry for k, nullptr when there is none.
  const MaxDegree* max_degree(NetKind k) const;
  /// Why `field` is refused, nullptr when it is taken.
  const std::string* refusal(const std::string& field) const;
};

/// Check a net and fixed set (and, unless `method` is empty, a method name) against `r`, in this
/// order: the fixed set is defined for the net kind ("u-boundaries" is not, on triangular nets),
/// the net kind, the fixed set, the method (UnsupportedProblem for each); n = m, the maximum
/// degree, the minimum degree (DegreeError). Every message starts with `where: `. The degree message names the net
/// kind and the fixed set when the minimum depends on the fixed set, e.g.
///   job: problem "extremal" on a tensor net with boundary data needs degrees >= 2, got [1, 1]
///   job: problem "pde" needs degrees >= 2, got [1, 3]
///   job: problem "tetraharmonic" needs n = m >= 4, got 3
///   job: problem "cmc" on a triangular net takes degrees up to 24 (<reason>), got 64
void check_requirements(const SolverRequirements& r, const NetShape& net, FixedSet fixed, const std::string& method,
                        const std::string& where);

/// The part of check_requirements that needs no net: the fixed set and, unless `method` is empty,
/// the method (UnsupportedProblem, the same messages). An Options::validate without a net checks
/// its fixed set and method with it.
void check_fixed_set_and_method(const SolverRequirements& r, FixedSet fixed, const std::string& method,
                                const std::string& where);

}  // namespace bpde
