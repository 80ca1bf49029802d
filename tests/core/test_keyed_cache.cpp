// core/keyed_cache: built once per key, across threads; bounded with least-recently-used
// eviction; a failed build retries; DegreeCache range-checked and never evicting.
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "bezierpde/core/errors.h"
#include "bezierpde/core/keyed_cache.h"

using namespace bpde;

namespace {

TEST(DegreeCache, BuildsEachDegreeOnceAcrossThreads) {
  DegreeCache<int> cache;  // local: the count holds under --gtest_repeat too
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
        if (*cache.get(n, build) != n * n) ++wrong;
    });
  for (auto& th : threads) th.join();
  EXPECT_EQ(wrong.load(), 0);
  EXPECT_EQ(builds.load(), 21);
}

TEST(DegreeCache, RangeAndRetry) {
  DegreeCache<int> cache;
  EXPECT_THROW(cache.get(-1, [](int n) { return n; }), DegreeError);
  EXPECT_THROW(cache.get(kMaxDegree + 1, [](int n) { return n; }), DegreeError);
  EXPECT_THROW(cache.get(3, [](int) -> int { throw std::runtime_error("no"); }), std::runtime_error);
  EXPECT_EQ(*cache.get(3, [](int n) { return 10 * n; }), 30);  // the failed build left no value
  EXPECT_EQ(*cache.get(3, [](int) { return -1; }), 30);        // built once: the first success stays
}

TEST(DegreeCache, KeepsEveryDegree) {
  DegreeCache<int> cache;
  std::vector<const int*> first;
  for (int n = 0; n <= kMaxDegree; ++n) first.push_back(cache.get(n, [](int d) { return d; }).get());
  for (int n = 0; n <= kMaxDegree; ++n)
    EXPECT_EQ(cache.get(n, [](int) { return -1; }).get(), first[static_cast<size_t>(n)]) << n;
}

TEST(KeyedCache, EvictsTheLeastRecentlyUsed) {
  KeyedCache<std::string, int> cache(2);
  int builds = 0;
  auto build = [&](const std::string& k) {
    ++builds;
    return static_cast<int>(k.size());
  };
  EXPECT_EQ(*cache.get("a", build), 1);
  EXPECT_EQ(*cache.get("bb", build), 2);
  EXPECT_EQ(*cache.get("a", build), 1);  // hit: "a" becomes the most recent
  EXPECT_EQ(builds, 2);
  const auto held = cache.get("ccc", build);  // evicts "bb", the least recent
  EXPECT_EQ(builds, 3);
  EXPECT_EQ(cache.size(), 2u);
  EXPECT_TRUE(cache.contains("a"));
  EXPECT_FALSE(cache.contains("bb"));
  EXPECT_TRUE(cache.contains("ccc"));
  EXPECT_EQ(*cache.get("bb", build), 2);  // rebuilt; evicts "a"
  EXPECT_EQ(builds, 4);
  EXPECT_FALSE(cache.contains("a"));
  cache.clear();
  EXPECT_EQ(cache.size(), 0u);
  EXPECT_EQ(*held, 3);  // a value held by a caller outlives its eviction
  EXPECT_THROW((KeyedCache<int, int>(0)), ParameterError);
}

TEST(KeyedCache, ConcurrentCallersOfOneKeyShareOneBuild) {
  KeyedCache<int, std::vector<int>> cache(4);
  std::atomic<int> builds{0};
  auto slow = [&](int k) {
    ++builds;
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
    return std::vector<int>(1000, k);
  };
  std::vector<std::thread> threads;
  std::vector<std::shared_ptr<const std::vector<int>>> got(8);
  for (int t = 0; t < 8; ++t) threads.emplace_back([&, t] { got[static_cast<size_t>(t)] = cache.get(t % 2, slow); });
  for (auto& th : threads) th.join();
  EXPECT_EQ(builds.load(), 2);
  for (int t = 0; t < 8; ++t) {
    EXPECT_EQ(got[static_cast<size_t>(t)], got[static_cast<size_t>(t % 2)]);
    EXPECT_EQ((*got[static_cast<size_t>(t)])[999], t % 2);
  }
}

TEST(KeyedCache, ManyThreadsManyKeysWithEviction) {
  // More keys than capacity, hammered from several threads: every value is right, the size
  // never exceeds the capacity.
  KeyedCache<int, int> cache(3);
  std::atomic<int> wrong{0};
  std::vector<std::thread> threads;
  for (int t = 0; t < 6; ++t)
    threads.emplace_back([&, t] {
      for (int i = 0; i < 2000; ++i) {
        const int k = (i * 7 + t) % 10;
        if (*cache.get(k, [](int x) { return 3 * x + 1; }) != 3 * k + 1) ++wrong;
        if (cache.size() > 3) ++wrong;
      }
    });
  for (auto& th : threads) th.join();
  EXPECT_EQ(wrong.load(), 0);
}

TEST(KeyedCache, AFailedBuildReachesEveryWaiterAndIsNotKept) {
  KeyedCache<int, int> cache(4);
  std::atomic<int> failures{0};
  std::vector<std::thread> threads;
  for (int t = 0; t < 4; ++t)
    threads.emplace_back([&] {
      try {
        cache.get(7, [](int) -> int {
          std::this_thread::sleep_for(std::chrono::milliseconds(20));
          throw std::runtime_error("build failed");
        });
      } catch (const std::runtime_error&) {
        ++failures;
      }
    });
  for (auto& th : threads) th.join();
  EXPECT_EQ(failures.load(), 4);  // every build throws, so does every get
  EXPECT_FALSE(cache.contains(7));
  EXPECT_EQ(*cache.get(7, [](int k) { return k; }), 7);
}

}  // namespace
