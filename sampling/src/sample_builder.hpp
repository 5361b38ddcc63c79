// Grows a SampleSet while keeping samples apart: every sample carries an
// exclusion radius, and a spatial hash answers "is this spot clear?".
#pragma once

#include <cmath>
#include <cstdint>
#include <unordered_map>
#include <vector>

#include <gp_Pnt.hxx>

#include "cadmedial/sample_set.hpp"

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
    grid_[key(cellOf(p.X()), cellOf(p.Y()), cellOf(p.Z()))].push_back(id);
    return id;
  }

  // True iff no sample q (other than `ignore`) has |p - q| < max(radius, exclusion(q)),
  // or |p - q| < radius when the others' exclusion radii are not to be honoured.
  bool isClear(const gp_Pnt& p, double radius, Index ignore = kNoIndex, bool honourExclusion = true) const {
    const double reach = honourExclusion ? std::max(radius, maxExclusion_) : radius;
    const long r = static_cast<long>(std::ceil(reach / cell_));
    const long cx = cellOf(p.X()), cy = cellOf(p.Y()), cz = cellOf(p.Z());
    for (long i = cx - r; i <= cx + r; ++i)
      for (long j = cy - r; j <= cy + r; ++j)
        for (long k = cz - r; k <= cz + r; ++k) {
          auto it = grid_.find(key(i, j, k));
          if (it == grid_.end()) continue;
          for (Index q : it->second) {
            if (q == ignore) continue;
            const auto& c = set_.points[q];
            const double dx = c[0] - p.X(), dy = c[1] - p.Y(), dz = c[2] - p.Z();
            const double limit = honourExclusion ? std::max(radius, exclusion_[q]) : radius;
            if (dx * dx + dy * dy + dz * dz < limit * limit) return false;
          }
        }
    return true;
  }

  double exclusion(Index i) const { return exclusion_[i]; }
  void setExclusion(Index i, double r) {
    exclusion_[i] = r;
    maxExclusion_ = std::max(maxExclusion_, r);
  }
  SampleSet& set() { return set_; }

 private:
  long cellOf(double x) const { return static_cast<long>(std::floor(x / cell_)); }
  static std::uint64_t key(long i, long j, long k) {
    return (static_cast<std::uint64_t>(i & 0x1FFFFF) << 42) | (static_cast<std::uint64_t>(j & 0x1FFFFF) << 21) |
           static_cast<std::uint64_t>(k & 0x1FFFFF);
  }

  SampleSet& set_;
  double cell_;
  std::vector<double> exclusion_;
  double maxExclusion_ = 0;
  std::unordered_map<std::uint64_t, std::vector<Index>> grid_;
};

}  // namespace cadmedial
