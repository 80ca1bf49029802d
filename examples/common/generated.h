#pragma once
// The generated sections of the docs (scripts/docs.sh): an example program prints each of its
// tables between
//   <!-- generated: NAME -->   (or <!-- generated: NAME; machine-dependent: COL, COL -->)
//   ...
//   <!-- end -->
// and scripts/docs.py copies it between the same markers of the example's README.md (or of a
// docs/*.md); the CTest test Docs.GeneratedSectionsMatchTheExamples fails when they differ.
// Columns named machine-dependent (timings) are not compared. Numbers at rounding level are
// printed with stable_small(), so that the sections do not depend on the last bits. Sections whose
// name ends in "-full" are heavy: the program prints them only with the arguments of FULL_ARGS in
// scripts/docs.py (scripts/docs.sh --full), and the CTest check does not compare them.
#include <cmath>
#include <cstdio>
#include <string>

namespace bpde::examples {

/// Prints the begin marker on construction and the end marker on destruction (to stdout).
class GeneratedSection {
 public:
  explicit GeneratedSection(const char* name, const char* machine_dependent_columns = nullptr) {
    if (machine_dependent_columns)
      std::printf("<!-- generated: %s; machine-dependent: %s -->\n", name, machine_dependent_columns);
    else
      std::printf("<!-- generated: %s -->\n", name);
  }
  ~GeneratedSection() { std::printf("<!-- end -->\n"); }
  GeneratedSection(const GeneratedSection&) = delete;
  GeneratedSection& operator=(const GeneratedSection&) = delete;
};

/// A non-negative error or residual for a table: "< floor" below `floor` (rounding level, whose
/// digits vary with the machine and compiler), "0" when exactly 0, else 2 significant digits ("%.1e").
inline std::string stable_small(double x, double floor = 1e-13) {
  char buf[32];
  if (x == 0)
    return "0";  // exactly: the same computation on both sides
  else if (x < floor)
    std::snprintf(buf, sizeof buf, "< %.0e", floor);
  else
    std::snprintf(buf, sizeof buf, "%.1e", x);
  return buf;
}

/// A residual dominated by rounding (its digits, even its first, vary with the machine): the
/// power of ten above it, "< 1e-11" for 8.6e-12; "0" for 0.
inline std::string order_bound(double x) {
  if (!(x > 0)) return "0";
  char buf[32];
  std::snprintf(buf, sizeof buf, "< 1e%d", static_cast<int>(std::floor(std::log10(x))) + 1);
  return buf;
}

}  // namespace bpde::examples
