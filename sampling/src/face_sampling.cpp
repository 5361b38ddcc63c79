// Face interiors: Poisson-disk samples by dart throwing on the surface (area
// uniform), never a grid, kept clear of edge, corner and triplet samples. The
// Poisson radius follows the face's spacing field cell by cell, and point by
// point near its finer convex edges (one value for the whole face unless the
// spacing is graded); the darts go tile by tile, evaluated in parallel
// batches that keep the samples of one dart at a time.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <memory>
#include <random>
#include <vector>

#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include <BRepAdaptor_Surface.hxx>
#include <BRepGProp.hxx>
#include <BRepTools.hxx>
#include <GProp_GProps.hxx>

#include "face_uv_classifier.hpp"
#include "sampling_context.hpp"

namespace cadmedial {

namespace {
constexpr double kMinDistanceFraction = 0.75;  // Poisson radius = this × face spacing
constexpr double kDartsPerDisk = 12.0;         // candidates per expected sample
constexpr double kMaxDarts = 4e6;              // per face, to bound time on huge faces
constexpr double kTileRadii = 32.0;            // tile side, in Poisson radii (~800 samples a tile)
constexpr double kLeafRadii = 4.0;             // a tile near a finer edge is split down to this width, in its radii
constexpr int kMaxSplits = 8;                  // in four, at most this often
// Darts are evaluated in batches (see throwDarts), sized so that about
// kClearPerBatch of them are clear of the samples before the batch: while
// a tile fills, batches grow from kMinBatch as fewer darts land clear.
constexpr std::int64_t kMinBatch = 64, kMaxBatch = 4096;
constexpr double kClearPerBatch = 16;
constexpr std::size_t kDartGrain = 16;  // darts per parallel task

std::int64_t nextBatchSize(std::int64_t last, std::size_t clearInLast) {
  const double size = kClearPerBatch * static_cast<double>(last) / std::max<double>(1.0, static_cast<double>(clearInLast));
  return static_cast<std::int64_t>(std::clamp(size, static_cast<double>(kMinBatch), static_cast<double>(kMaxBatch)));
}

// Tiles along a UV side of 3D length `length`: about kTileRadii radii each.
int tileCount(double length, double radius) {
  const double tiles = length / (kTileRadii * radius);
  return std::isfinite(tiles) ? static_cast<int>(std::clamp(std::ceil(tiles), 1.0, 4096.0)) : 1;
}

struct Tile {
  double u, v, du, dv;  // UV corner and sides
  double share;         // of a whole tile: 1, 1/4, 1/16 ... (exact, so a uniform face's darts are as before)
};

// What a dart's evaluation found, before the darts kept earlier in its batch
// are looked at: rejected, or clear of every sample kept before the batch
// and (when the UV classifier was asked) inside or outside the face; or
// Failed: OCCT threw, and the dart is evaluated again in order (see throwDarts).
enum class DartState : std::uint8_t { Rejected, Clear, Inside, Outside, Failed };

// One dart: its random numbers, then what evaluating it found.
struct Dart {
  double u, v, area;  // UV point; uniform in [0, 1) for the area-element rejection
  gp_Pnt p;           // the surface point
  double local = 0;   // Poisson radius at p: the sample's exclusion radius
  double reach = 0;   // clearance it needs from earlier samples: max(local, the cell's lowest)
  DartState state = DartState::Rejected;
};

// A thread's own evaluators for one face.
struct DartEvaluators {
  explicit DartEvaluators(const TopoDS_Face& face) : surface(face, true), classifier(face, 1e-9) {}
  BRepAdaptor_Surface surface;
  FaceUVClassifier classifier;
};

struct TileRadius {
  double radius;     // the smallest Poisson radius anywhere in the tile
  double width;      // 3D: the diameter of the ball that holds it (FaceSpacingField::ballHolding), ~1.25 x its diagonal
  bool nearSources;  // the radius comes from a convex edge's points (FaceSpacingField::gradeFrom)
};

// Calls visit(leaf, radius) for the leaves of `tile`. A tile gets 12 darts
// per disk of its smallest radius, so one whose radius comes from a finer
// convex edge is split in four (Z order: the darts stay local) while it is
// wider than kLeafRadii of its own radius (about 3 across its diagonal):
// next to a hole's rim the spacing grows by 0.5 per unit of distance, and a
// tile 32 of the rim's radii wide threw darts for 0.45 over ground that needs
// 2.2 (twice the darts of the whole face on the bundled flange, measured).
template <typename Measure, typename Visit>
void forEachLeaf(const Tile& tile, int splits, const Measure& measure, const Visit& visit) {
  const TileRadius r = measure(tile);
  if (r.nearSources && splits < kMaxSplits && r.width > kLeafRadii * r.radius) {
    for (int k = 0; k < 4; ++k)
      forEachLeaf(Tile{tile.u + (k & 1) * tile.du / 2, tile.v + (k >> 1) * tile.dv / 2, tile.du / 2, tile.dv / 2,
                       tile.share / 4},
                  splits + 1, measure, visit);
    return;
  }
  visit(tile, r.radius);
}
}  // namespace

void sampleFaceInteriors(SamplingContext& ctx, SampleBuilder& builder, unsigned seed) {
  const SolidTopology& topo = ctx.topo;
  for (int f = 0; f < topo.faceCount(); ++f) {
    const TopoDS_Face& face = topo.face(f);
    const FaceSpacingField& field = ctx.faceSpacing[f];
    const double smallestRadius = kMinDistanceFraction * field.minimum();
    GProp_GProps props;
    BRepGProp::SurfaceProperties(face, props);
    const double area = props.Mass();
    if (!(area > 0)) continue;

    BRepAdaptor_Surface surf(face, true);
    double u0, u1, v0, v1;
    BRepTools::UVBounds(face, u0, u1, v0, v1);
    // Largest area element over the UV box, for rejection sampling, and the
    // mean lengths of the UV box's sides in 3D, for the tiles below.
    double maxJ = 0, sumSu = 0, sumSv = 0;
    constexpr int n = 12;
    for (int i = 0; i <= n; ++i)
      for (int j = 0; j <= n; ++j) {
        gp_Pnt p;
        gp_Vec su, sv;
        surf.D1(u0 + (u1 - u0) * i / n, v0 + (v1 - v0) * j / n, p, su, sv);
        maxJ = std::max(maxJ, su.Crossed(sv).Magnitude());
        sumSu += su.Magnitude();
        sumSv += sv.Magnitude();
      }
    if (!(maxJ > 0)) continue;
    maxJ *= 1.5;

    // The darts go tile by tile over the UV box (equal UV areas, serpentine
    // order), not scattered over the whole face:
    // each clearance check then reads the hash cells the previous darts just
    // read. Scattered darts missed the cache on almost every lookup (90 % of
    // the sampling time on a 540 k-sample box). Positions stay uniform in UV;
    // only the order differs, and each dart still has to clear every sample
    // accepted before it.
    const double count = static_cast<double>((n + 1) * (n + 1));
    const int tilesU = tileCount(sumSu / count * (u1 - u0), smallestRadius);
    const int tilesV = tileCount(sumSv / count * (v1 - v0), smallestRadius);
    const double du = (u1 - u0) / tilesU, dv = (v1 - v0) / tilesV;
    const std::int64_t tiles = static_cast<std::int64_t>(tilesU) * tilesV;
    auto tileAt = [&](std::int64_t t) {
      const std::int64_t row = t / tilesU, column = row % 2 == 0 ? t % tilesU : tilesU - 1 - t % tilesU;
      return Tile{u0 + du * static_cast<double>(column), v0 + dv * static_cast<double>(row), du, dv, 1.0};
    };

    // Each tile's radius is the smallest its cells of the field ask for (and
    // near a finer convex edge, its points; then the tile is split, see
    // forEachLeaf); its darts are its share of 12 per disk of that radius.
    // weight = share × (smallest radius / tile radius)^2 is exactly 1 per
    // tile on a uniform field, where every tile then gets the same share as
    // with one radius for the face. Two passes (sum, then throw) instead of
    // per-tile arrays: a tiny --spacing can make millions of tiles.
    auto measure = [&](const Tile& t) {
      TileRadius r{kMinDistanceFraction * field.minOver(t.u, t.u + t.du, t.v, t.v + t.dv), 0, false};
      if (!field.nearSources(t.u, t.u + t.du, t.v, t.v + t.dv)) return r;
      // Ask the edge's points about a ball that holds the tile.
      const FaceSpacingField::Ball ball = FaceSpacingField::ballHolding(surf, t.u, t.u + t.du, t.v, t.v + t.dv);
      const double cellSpacing = r.radius / kMinDistanceFraction;
      const double spacing = field.sourcesAllow(ball.centre, ball.radius, cellSpacing);
      return TileRadius{kMinDistanceFraction * spacing, 2 * ball.radius, spacing < cellSpacing};
    };
    auto weight = [&](const Tile& t, double radius) {
      return t.share * (smallestRadius / radius) * (smallestRadius / radius);
    };
    double weightSum = 0;
    for (std::int64_t t = 0; t < tiles; ++t)
      forEachLeaf(tileAt(t), 0, measure, [&](const Tile& leaf, double radius) { weightSum += weight(leaf, radius); });
    const double totalDarts = std::floor(std::min(
        kMaxDarts, kDartsPerDisk * area / (smallestRadius * smallestRadius) * (weightSum / static_cast<double>(tiles))));

    // Each thread evaluates darts with its own surface adaptor (B-spline
    // adaptors cache a span) and its own UV classifier, as ExactOracle does.
    tbb::enumerable_thread_specific<DartEvaluators> evaluators(face);
    std::mt19937_64 rng(seed * 1000003ull + static_cast<unsigned>(f));
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    std::vector<Dart> batch;
    double weightBefore = 0, dartsBefore = 0;
    std::size_t clearSeen = 0, clearKept = 0;  // in the last batch: darts clear of the samples before it, and kept clear by it
    // A dart is kept iff, in the order thrown, it passes the area-element
    // rejection, lies inside the face and keeps clear of every sample kept
    // before it: by the larger of the radius at its point and the smallest
    // its field cell can ask for, and by each earlier sample's own radius.
    // (On a uniform field every point has the tile's radius; with the tile's
    // smallest instead of the point's, a fine strip along one edge, a hole's
    // rim, made the whole tile as fine.)
    // The darts of a leaf go in batches: their random numbers are drawn in
    // throw order, the costly part (surface point, field, clearance from
    // the samples kept before the batch, UV classifier) runs in parallel,
    // and then, in order, each survivor is checked against the darts kept
    // earlier in its batch. Same samples as one dart at a time, on any
    // number of threads.
    auto classify = [&](DartEvaluators& mine, Dart& d) {
      d.state = mine.classifier.Perform(gp_Pnt2d(d.u, d.v)) == TopAbs_IN ? DartState::Inside : DartState::Outside;
    };
    // classifyToo: ask the UV classifier as well (see speculate below).
    auto evaluate = [&](DartEvaluators& mine, Dart& d, bool classifyToo) {
      d.state = DartState::Rejected;
      gp_Vec su, sv;
      mine.surface.D1(d.u, d.v, d.p, su, sv);
      if (d.area * maxJ > su.Crossed(sv).Magnitude()) return;
      // Most darts land too near a sample even for the smallest radius their
      // field cell can ask for: those go before the search for the radius at
      // the point near a convex edge's points (at()).
      const double lowest = kMinDistanceFraction * field.lowestNear(d.u, d.v);
      if (!builder.isClear(d.p, lowest)) return;
      d.local = kMinDistanceFraction * field.at(d.u, d.v, d.p);
      if (d.local > lowest && !builder.isClear(d.p, d.local)) return;
      d.reach = std::max(lowest, d.local);
      d.state = DartState::Clear;
      if (classifyToo) classify(mine, d);
    };
    // Clear of the darts kept earlier in the batch: the builder holds them
    // too (with their own radii), and every sample it held before the batch
    // is already cleared, so asking it again gives one-at-a-time's answer.
    auto clearOfBatch = [&](const Dart& d) { return builder.isClear(d.p, d.reach); };
    auto throwDarts = [&](const Tile& leaf, double radius) {
      weightBefore += weight(leaf, radius);
      const double dartsAfter = std::floor(totalDarts * weightBefore / weightSum);
      const std::int64_t dartsHere = static_cast<std::int64_t>(dartsAfter - dartsBefore);
      dartsBefore = dartsAfter;
      // A leaf starts empty: most darts are clear, and many of them are
      // then rejected by a dart kept earlier in the same batch.
      std::int64_t batchSize = ctx.oneDartAtATime ? 1 : kMinBatch;
      for (std::int64_t first = 0; first < dartsHere; first += batchSize) {
        if (first > 0 && !ctx.oneDartAtATime) batchSize = nextBatchSize(batchSize, clearSeen);
        const std::size_t n = static_cast<std::size_t>(std::min<std::int64_t>(batchSize, dartsHere - first));
        batch.resize(n);
        for (Dart& d : batch) {
          d.u = leaf.u + leaf.du * unit(rng);
          d.v = leaf.v + leaf.dv * unit(rng);
          d.area = unit(rng);
        }
        // The classifier is the costliest step. Asked in parallel for every
        // dart clear of the earlier samples, it also answers for darts that
        // a dart kept earlier in the batch then rejects: most of them while
        // a tile is still empty (the face sampling took 1.9x the time of
        // one dart at a time on NIST CTC-01). So it is asked in parallel
        // only while most such darts were kept in the last batch of this
        // leaf, and otherwise in order, for the darts still clear.
        const bool speculate = first > 0 && !ctx.oneDartAtATime && clearKept >= 0.5 * clearSeen;
        tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, kDartGrain),
                          [&](const tbb::blocked_range<std::size_t>& range) {
                            DartEvaluators& mine = evaluators.local();
                            for (std::size_t i = range.begin(); i != range.end(); ++i) {
                              try {
                                evaluate(mine, batch[i], speculate);
                              } catch (...) {
                                batch[i].state = DartState::Failed;
                              }
                            }
                          });
        clearSeen = clearKept = 0;
        for (std::size_t i = 0; i < n; ++i) {
          Dart& d = batch[i];
          // A dart OCCT failed on (it may have got further than one at a
          // time would take it) goes again against every sample kept before
          // it, which is how one at a time evaluates it: it throws exactly
          // where that would.
          if (d.state == DartState::Failed) evaluate(evaluators.local(), d, false);
          if (d.state == DartState::Rejected) continue;
          ++clearSeen;
          if (!clearOfBatch(d)) continue;
          ++clearKept;
          if (d.state == DartState::Clear) classify(evaluators.local(), d);
          if (d.state != DartState::Inside) continue;
          ctx.recordFaceUv(builder.add(d.p, SampleKind::Face, f, d.local), gp_Pnt2d(d.u, d.v));
        }
      }
    };
    for (std::int64_t t = 0; t < tiles; ++t) forEachLeaf(tileAt(t), 0, measure, throwDarts);
  }
}

}  // namespace cadmedial
