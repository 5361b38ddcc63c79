// Open-addressing hash table from an unordered index pair {a, b} to a value.
// Built once, then only looked up: no allocation per query, no std::map in hot
// loops.
#pragma once

#include <cstdint>
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
    keys_.assign(cap, kEmpty);
    values_.assign(cap, kNoIndex);
    mask_ = cap - 1;
    size_ = 0;
  }

  // Inserts {a,b} -> value if absent; returns the stored value (the old one if present).
  Index insert(Index a, Index b, Index value) {
    if (2 * (size_ + 1) > keys_.size()) grow();
    const std::uint64_t k = key(a, b);
    std::size_t slot = hash(k) & mask_;
    while (keys_[slot] != kEmpty) {
      if (keys_[slot] == k) return values_[slot];
      slot = (slot + 1) & mask_;
    }
    keys_[slot] = k;
    values_[slot] = value;
    ++size_;
    return value;
  }

  Index find(Index a, Index b) const {
    if (keys_.empty()) return kNoIndex;
    const std::uint64_t k = key(a, b);
    std::size_t slot = hash(k) & mask_;
    while (keys_[slot] != kEmpty) {
      if (keys_[slot] == k) return values_[slot];
      slot = (slot + 1) & mask_;
    }
    return kNoIndex;
  }

  std::size_t size() const { return size_; }

 private:
  static constexpr std::uint64_t kEmpty = ~std::uint64_t(0);
  static std::uint64_t hash(std::uint64_t x) {
    x ^= x >> 33;
    x *= 0xff51afd7ed558ccdULL;
    x ^= x >> 33;
    x *= 0xc4ceb9fe1a85ec53ULL;
    x ^= x >> 33;
    return x;
  }
  void grow() {
    std::vector<std::uint64_t> oldKeys;
    std::vector<Index> oldValues;
    oldKeys.swap(keys_);
    oldValues.swap(values_);
    reserve(oldKeys.empty() ? 8 : oldKeys.size());
    for (std::size_t i = 0; i < oldKeys.size(); ++i)
      if (oldKeys[i] != kEmpty) insert(static_cast<Index>(oldKeys[i] >> 32), static_cast<Index>(oldKeys[i]), oldValues[i]);
  }

  std::vector<std::uint64_t> keys_;
  std::vector<Index> values_;
  std::size_t mask_ = 0;
  std::size_t size_ = 0;
};

}  // namespace cadmedial
