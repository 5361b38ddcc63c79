// Grows a SampleSet while keeping samples apart: every sample carries an
// exclusion radius, and a spatial hash of small trees (clearance_tree.hpp)
// answers "is this spot clear?".
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include <gp_Pnt.hxx>

#include "cadmedial/sample_set.hpp"
#include "clearance_tree.hpp"

namespace cadmedial {

class SampleBuilder {
 public:
  SampleBuilder(SampleSet& set, double cellSize) : set_(set), cell_(cellSize) {}

  Index add(const gp_Pnt& p, SampleKind kind, int owner, double exclusionRadius) {
    const Index id = static_cast<Index>(set_.points.size());
    set_.points.push_back({p.X(), p.Y(), p.Z()});
    set_.kind.push_back(kind);
    set_.owner.push_back(owner);
    set_.onConvexEdge.push_back(0);
    set_.isNonConcaveCorner.push_back(0);
    exclusion_.push_back(exclusionRadius);
    maxExclusion_ = std::max(maxExclusion_, exclusionRadius);
    trees_.insert(cellTree(p.X(), p.Y(), p.Z()), {p.X(), p.Y(), p.Z(), exclusionRadius, id});
    if (set_.points.size() >= nextCellCheck_ || 2.67 * maxExclusion_ > 2 * cell_) fitCells();
    return id;
  }

  // True iff no sample q (other than `ignore`) has |p - q| < max(radius, exclusion(q)),
  // or |p - q| < radius when the others' exclusion radii are not to be honoured.
  bool isClear(const gp_Pnt& p, double radius, Index ignore = kNoIndex, bool honourExclusion = true) const {
    const double reach = honourExclusion ? std::max(radius, maxExclusion_) : radius;
    const long cx = cellOf(p.X()), cy = cellOf(p.Y()), cz = cellOf(p.Z());
    auto cellIsClear = [&](long i, long j, long k) {
      const Index tree = grid_.find(key(i, j, k));
      return tree == kNoIndex || !trees_.anyBlocks(tree, p.X(), p.Y(), p.Z(), radius, ignore, honourExclusion);
    };
    // Own cell first: most rejected darts land next to a sample there.
    if (!cellIsClear(cx, cy, cz)) return false;
    // Only the cells the ball of radius `reach` overlaps (2 x 2 x 2 at most
    // when reach <= cell / 2): fewer scattered buckets per dart.
    for (long i = cellOf(p.X() - reach); i <= cellOf(p.X() + reach); ++i)
      for (long j = cellOf(p.Y() - reach); j <= cellOf(p.Y() + reach); ++j)
        for (long k = cellOf(p.Z() - reach); k <= cellOf(p.Z() + reach); ++k)
          if ((i != cx || j != cy || k != cz) && !cellIsClear(i, j, k)) return false;
    return true;
  }

  double exclusion(Index i) const { return exclusion_[i]; }
  double cellSize() const { return cell_; }
  void setExclusion(Index i, double r) {
    exclusion_[i] = r;
    maxExclusion_ = std::max(maxExclusion_, r);
    if (2.67 * maxExclusion_ > 2 * cell_) {
      fitCells();  // the cell trees are rebuilt, with the entry's new radius
      return;
    }
    const auto& c = set_.points[i];
    trees_.setExclusion(cellTree(c[0], c[1], c[2]), i, c[0], c[1], c[2], r);
  }
  SampleSet& set() { return set_; }

 private:
  long cellOf(double x) const { return static_cast<long>(std::floor(x / cell_)); }
  static std::uint64_t key(long i, long j, long k) {
    return (static_cast<std::uint64_t>(i & 0x1FFFFF) << 42) | (static_cast<std::uint64_t>(j & 0x1FFFFF) << 21) |
           static_cast<std::uint64_t>(k & 0x1FFFFF);
  }

  // isClear is exact for any cell size; the size only sets its cost. The
  // caller's guess (twice the largest spacing asked for) can be far above
  // the exclusion radii the samples get: on the bottle, cells of 4.7 for
  // radii of at most 0.19 held ~340 samples per query. So each time the
  // sample count doubles, cells more than 4x too large for the largest
  // radius so far (a ball of it then overlaps at most 2 cells per axis at
  // the size aimed for, 2.67x that radius) are rebuilt at that size; cells
  // below half that size, for a radius that grew, are rebuilt at once (a query
  // would otherwise visit (2 reach / cell + 1)^3 of them). Samples and
  // answers are the same either way.
  void fitCells() {
    nextCellCheck_ = 2 * set_.points.size();
    const double aim = 2.67 * maxExclusion_;
    if (!(aim > 0) || (cell_ <= 4 * aim && cell_ >= 0.5 * aim)) return;
    cell_ = aim;
    grid_ = CellTable();
    trees_.clear();
    // Sample ids index exclusion_ (the builder starts from an empty set).
    for (Index id = 0; id < exclusion_.size(); ++id) {
      const auto& c = set_.points[id];
      trees_.insert(cellTree(c[0], c[1], c[2]), {c[0], c[1], c[2], exclusion_[id], id});
    }
  }

  // The tree of the cell holding (x, y, z), made on first use.
  Index cellTree(double x, double y, double z) {
    Index& tree = grid_.slot(key(cellOf(x), cellOf(y), cellOf(z)));
    if (tree == kNoIndex) tree = trees_.newTree();
    return tree;
  }

  SampleSet& set_;
  double cell_;
  std::vector<double> exclusion_;
  double maxExclusion_ = 0;
  std::size_t nextCellCheck_ = 4096;
  // Cell key -> root of the cell's tree. Open addressing with linear
  // probing: the dart loop does ~27 lookups per dart, and std::unordered_map's
  // prime modulo and node chasing made those lookups most of the sampling time.
  class CellTable {
   public:
    Index find(std::uint64_t k) const {
      if (keys_.empty()) return kNoIndex;
      for (std::size_t s = hash(k);; s = (s + 1) & mask_) {
        if (keys_[s] == k) return index_[s];
        if (keys_[s] == kEmpty) return kNoIndex;
      }
    }
    // The value slot of key k, kNoIndex when k is new.
    Index& slot(std::uint64_t k) {
      if (2 * (used_ + 1) > keys_.size()) grow();
      std::size_t s = hash(k);
      for (; keys_[s] != kEmpty; s = (s + 1) & mask_)
        if (keys_[s] == k) return index_[s];
      keys_[s] = k;
      index_[s] = kNoIndex;
      ++used_;
      return index_[s];
    }

   private:
    static constexpr std::uint64_t kEmpty = ~std::uint64_t{0};  // keys use 63 bits
    std::size_t hash(std::uint64_t k) const { return static_cast<std::size_t>((k * 0x9E3779B97F4A7C15ull) >> shift_); }
    void grow() {
      const std::size_t size = keys_.empty() ? 1024 : 2 * keys_.size();
      int bits = 0;
      while ((std::size_t{1} << bits) < size) ++bits;
      shift_ = 64 - bits;
      mask_ = size - 1;
      std::vector<std::uint64_t> oldKeys(size, kEmpty);
      oldKeys.swap(keys_);
      std::vector<Index> oldIndex(size, 0);
      oldIndex.swap(index_);
      for (std::size_t i = 0; i < oldKeys.size(); ++i) {
        if (oldKeys[i] == kEmpty) continue;
        std::size_t s = hash(oldKeys[i]);
        while (keys_[s] != kEmpty) s = (s + 1) & mask_;
        keys_[s] = oldKeys[i];
        index_[s] = oldIndex[i];
      }
    }
    std::vector<std::uint64_t> keys_;
    std::vector<Index> index_;
    std::size_t used_ = 0;
    std::size_t mask_ = 0;
    int shift_ = 64;
  };
  CellTable grid_;
  ClearanceTrees trees_;
};

}  // namespace cadmedial
