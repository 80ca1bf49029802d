#pragma once
// PerDegree<T>: values that depend on a degree only (basis-change tables, solution operators),
// built on first use and kept for the life of the process.
//
//   static PerDegree<Tables> cache;                  // one per call site
//   const Tables& t = cache.get(n, [](int n) { return build_tables(n); });
//
// Thread-safe: each degree has its own std::call_once, so different degrees build in parallel and
// a degree is built exactly once (if its build throws, the next call tries again). Degrees outside
// 0..kMaxDegree throw DegreeError naming `what`.
#include <array>
#include <mutex>
#include <string>

#include "core/bernstein.h"  // kMaxDegree
#include "core/errors.h"

namespace bpde {

template <class T>
class PerDegree {
 public:
  template <class Build>
  const T& get(int n, Build&& build, const char* what = "per-degree cache") {
    if (n < 0 || n > kMaxDegree)
      throw DegreeError(std::string(what) + ": degree " + std::to_string(n) + " out of range 0..64");
    const auto k = static_cast<size_t>(n);
    std::call_once(once_[k], [&] { values_[k] = build(n); });
    return values_[k];
  }

 private:
  std::array<std::once_flag, kMaxDegree + 1> once_;
  std::array<T, kMaxDegree + 1> values_{};
};

}  // namespace bpde
