#include "bezierpde/core/binomial.h"

#include <array>
#include <atomic>
#include <limits>
#include <memory>
#include <mutex>
#include <string>

#include "bezierpde/core/errors.h"

namespace bpde {
namespace {

// Rows 0..built-1 are complete and never move; readers check `built` (acquire) and read without
// a lock, writers extend under the mutex and publish with a release store.
template <class T>
class PascalTriangle {
 public:
  T get(int n, int k) {
    if (n >= built_.load(std::memory_order_acquire)) grow(n);
    return rows_[static_cast<size_t>(n)][static_cast<size_t>(k)];
  }

 private:
  void grow(int n) {
    std::lock_guard<std::mutex> lock(mutex_);
    int b = built_.load(std::memory_order_relaxed);
    for (; b <= n; ++b) {
      auto row = std::make_unique<T[]>(static_cast<size_t>(b) + 1);
      row[0] = T(1);
      for (int k = 1; k <= b; ++k) {
        const T* prev = rows_[static_cast<size_t>(b - 1)].get();
        row[static_cast<size_t>(k)] = prev[k - 1] + ((k <= b - 1) ? prev[k] : T(0));
      }
      rows_[static_cast<size_t>(b)] = std::move(row);
    }
    built_.store(b, std::memory_order_release);
  }

  std::mutex mutex_;
  std::atomic<int> built_{0};
  std::array<std::unique_ptr<T[]>, kMaxBinomialRow + 1> rows_;
};

}  // namespace

template <class T>
T binomial(int n, int k) {
  if (k < 0 || n < 0 || k > n) return T(0);
  if (n > kMaxBinomialRow) throw DegreeError("binomial: n = " + std::to_string(n) + " exceeds the table");
  static PascalTriangle<T> triangle;
  return triangle.get(n, k);
}

template double binomial<double>(int, int);
double binomial(int n, int k) { return binomial<double>(n, k); }
template long double binomial<long double>(int, int);
template quad binomial<quad>(int, int);

double factorial(int n) {
  // The same left-to-right products as the plain loop, tabulated (171! overflows to inf).
  static const std::array<double, 171> table = [] {
    std::array<double, 171> t{};
    t[0] = 1.0;
    for (int i = 1; i <= 170; ++i) t[static_cast<size_t>(i)] = i == 1 ? 1.0 : t[static_cast<size_t>(i - 1)] * i;
    return t;
  }();
  if (n < 0) return 1.0;
  if (n > 170) return std::numeric_limits<double>::infinity();
  return table[static_cast<size_t>(n)];
}

}  // namespace bpde
