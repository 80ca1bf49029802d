// core/per_degree: built once per degree, across threads; range checked; a failed build retries.
#include <gtest/gtest.h>

#include <atomic>
#include <stdexcept>
#include <thread>
#include <vector>

#include "core/errors.h"
#include "core/per_degree.h"

using namespace bpde;

namespace {

TEST(PerDegree, BuildsEachDegreeOnceAcrossThreads) {
  static PerDegree<int> cache;
  std::atomic<int> builds{0};
  auto build = [&](int n) {
    ++builds;
    return n * n;
  };
  std::vector<std::thread> threads;
  std::atomic<int> wrong{0};
  for (int t = 0; t < 8; ++t)
    threads.emplace_back([&] {
      for (int n = 0; n <= 20; ++n)
        if (cache.get(n, build) != n * n) ++wrong;
    });
  for (auto& th : threads) th.join();
  EXPECT_EQ(wrong.load(), 0);
  EXPECT_EQ(builds.load(), 21);
}

TEST(PerDegree, RangeAndRetry) {
  PerDegree<int> cache;
  EXPECT_THROW(cache.get(-1, [](int n) { return n; }), DegreeError);
  EXPECT_THROW(cache.get(kMaxDegree + 1, [](int n) { return n; }), DegreeError);
  EXPECT_THROW(cache.get(3, [](int) -> int { throw std::runtime_error("no"); }), std::runtime_error);
  EXPECT_EQ(cache.get(3, [](int n) { return 10 * n; }), 30);  // the failed build left no value
  EXPECT_EQ(cache.get(3, [](int) { return -1; }), 30);        // built once: the first success stays
}

}  // namespace
