// Open-addressing hash table from an unordered index pair {a, b} to a value.
// Built once, then only looked up: no allocation per query, no std::map in hot
// loops.
#pragma once

#include <cstdint>
#include <utility>
#include <vector>

#include "cadmedial/sample_set.hpp"

namespace cadmedial {

class PairTable {
 public:
  static std::uint64_t key(Index a, Index b) {
    if (a > b) std::swap(a, b);
    return (static_cast<std::uint64_t>(a) << 32) | b;
  }

  void reserve(std::size_t count) {
    std::size_t cap = 16;
    while (cap < 2 * count + 1) cap <<= 1;
    slots_.assign(cap, Slot{});
    mask_ = cap - 1;
    size_ = 0;
  }

  // Inserts {a,b} -> value if absent; returns the stored value (the old one if present).
  Index insert(Index a, Index b, Index value) {
    if (2 * (size_ + 1) > slots_.size()) grow();
    if (a > b) std::swap(a, b);
    std::size_t i = hash(key(a, b)) & mask_;
    while (!slots_[i].empty()) {
      if (slots_[i].low == a && slots_[i].high == b) return slots_[i].value;
      i = (i + 1) & mask_;
    }
    slots_[i] = {a, b, value};
    ++size_;
    return value;
  }

  Index find(Index a, Index b) const {
    if (slots_.empty()) return kNoIndex;
    if (a > b) std::swap(a, b);
    std::size_t i = hash(key(a, b)) & mask_;
    while (!slots_[i].empty()) {
      if (slots_[i].low == a && slots_[i].high == b) return slots_[i].value;
      i = (i + 1) & mask_;
    }
    return kNoIndex;
  }

  // Starts loading {a,b}'s first slot, so that several finds issued after
  // a few prefetches wait for their cache misses together, not in turn.
  void prefetch(Index a, Index b) const {
    if (!slots_.empty()) __builtin_prefetch(&slots_[hash(key(a, b)) & mask_]);
  }

  std::size_t size() const { return size_; }

 private:
  // Pair and value side by side: a lookup in a table larger than the cache
  // costs one miss, where separate key and value arrays cost two.
  struct Slot {
    Index low = kNoIndex, high = kNoIndex, value = kNoIndex;
    bool empty() const { return low == kNoIndex && high == kNoIndex; }
  };
  static std::uint64_t hash(std::uint64_t x) {
    x ^= x >> 33;
    x *= 0xff51afd7ed558ccdULL;
    x ^= x >> 33;
    x *= 0xc4ceb9fe1a85ec53ULL;
    x ^= x >> 33;
    return x;
  }
  void grow() {
    std::vector<Slot> old;
    old.swap(slots_);
    reserve(old.empty() ? 8 : old.size());
    for (const Slot& slot : old)
      if (!slot.empty()) insert(slot.low, slot.high, slot.value);
  }

  std::vector<Slot> slots_;
  std::size_t mask_ = 0;
  std::size_t size_ = 0;
};

}  // namespace cadmedial
