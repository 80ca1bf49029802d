#pragma once
// KeyedCache<Key, Value>: a bounded, thread-safe cache of values that are expensive to build and
// depend on a key only (basis-change tables, solution operators, factored solvers).
//
//   static KeyedCache<int, Tables> cache(16);                    // one per call site
//   std::shared_ptr<const Tables> t = cache.get(n, [](int n) { return build_tables(n); });
//
// Contract:
//   - get(key, build) returns the value for key, calling build(key) (which returns a Value, or
//     anything convertible to std::shared_ptr<const Value>) only when the cache has no entry;
//   - a key is built at most once while it stays cached: concurrent callers of the same key wait
//     for the one build; different keys build in parallel (no lock is held while building, so a
//     build may itself use the cache for another key);
//   - if build throws, every caller waiting on that build gets the exception and nothing is kept
//     (the next get tries again);
//   - at most `capacity` entries are kept; inserting beyond evicts the least recently used. The
//     returned shared_ptr keeps an evicted value alive for as long as the caller holds it.
// Keys need operator< (std::map).
//
// DegreeCache<Value> is the cache of a value per degree 0..kMaxDegree: it holds every degree
// (capacity kMaxDegree + 1, so nothing is ever evicted and a reference into a value stays valid
// for the life of the process) and throws DegreeError naming `what` for a degree out of range.
#include <cstddef>
#include <cstdint>
#include <future>
#include <list>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <type_traits>
#include <utility>

#include "bezierpde/core/bernstein.h"  // kMaxDegree
#include "bezierpde/core/errors.h"

namespace bpde {

template <class Key, class Value>
class KeyedCache {
 public:
  using Pointer = std::shared_ptr<const Value>;

  /// capacity >= 1 (ParameterError otherwise).
  explicit KeyedCache(std::size_t capacity) : capacity_(capacity) {
    if (capacity < 1) throw ParameterError("KeyedCache: capacity must be >= 1");
  }
  KeyedCache(const KeyedCache&) = delete;
  KeyedCache& operator=(const KeyedCache&) = delete;

  template <class Build>
  Pointer get(const Key& key, Build&& build) {
    std::shared_future<Pointer> future;
    std::promise<Pointer> promise;
    std::uint64_t ticket = 0;
    {
      std::lock_guard<std::mutex> lock(mutex_);
      auto it = index_.find(key);
      if (it != index_.end()) {
        order_.splice(order_.begin(), order_, it->second);  // most recent first
        future = it->second->future;
      } else {
        ticket = ++tickets_;
        future = promise.get_future().share();
        order_.push_front(Entry{key, future, ticket});
        index_[key] = order_.begin();
        while (order_.size() > capacity_) {
          index_.erase(order_.back().key);
          order_.pop_back();
        }
      }
    }
    if (ticket == 0) return future.get();  // cached, or being built by another caller
    try {
      promise.set_value(make_pointer(build(key)));
    } catch (...) {
      promise.set_exception(std::current_exception());
      std::lock_guard<std::mutex> lock(mutex_);
      auto it = index_.find(key);
      if (it != index_.end() && it->second->ticket == ticket) {  // still our failed entry
        order_.erase(it->second);
        index_.erase(it);
      }
    }
    return future.get();
  }

  /// Number of entries held (including ones being built).
  std::size_t size() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return order_.size();
  }
  std::size_t capacity() const { return capacity_; }
  /// Whether key has an entry (built or being built); does not change the recency order.
  bool contains(const Key& key) const {
    std::lock_guard<std::mutex> lock(mutex_);
    return index_.count(key) != 0;
  }
  /// Drops every entry (values held by callers stay alive).
  void clear() {
    std::lock_guard<std::mutex> lock(mutex_);
    index_.clear();
    order_.clear();
  }

 private:
  struct Entry {
    Key key;
    std::shared_future<Pointer> future;
    std::uint64_t ticket;
  };

  template <class V>
  static Pointer make_pointer(V&& v) {
    if constexpr (std::is_convertible_v<V, Pointer>)
      return Pointer(std::forward<V>(v));
    else
      return std::make_shared<const Value>(std::forward<V>(v));
  }

  const std::size_t capacity_;
  mutable std::mutex mutex_;
  std::list<Entry> order_;
  std::map<Key, typename std::list<Entry>::iterator> index_;
  std::uint64_t tickets_ = 0;
};

template <class Value>
class DegreeCache {
 public:
  DegreeCache() : cache_(kMaxDegree + 1) {}

  template <class Build>
  std::shared_ptr<const Value> get(int n, Build&& build, const char* what = "per-degree cache") {
    if (n < 0 || n > kMaxDegree)
      throw DegreeError(std::string(what) + ": degree " + std::to_string(n) + " out of range 0.." +
                        std::to_string(kMaxDegree));
    return cache_.get(n, std::forward<Build>(build));
  }

 private:
  KeyedCache<int, Value> cache_;
};

}  // namespace bpde
