#include <algorithm>
#include <chrono>
#include <cmath>
#include <iomanip>
#include <sstream>
#include <stdexcept>

#include <BRepBndLib.hxx>
#include <BRepGProp.hxx>
#include <Bnd_Box.hxx>
#include <GProp_GProps.hxx>

#include "cadmedial/errors.hpp"
#include "cadmedial/sampling.hpp"
#include "feature_classification.hpp"
#include "sampling_context.hpp"

namespace cadmedial {

namespace {
using Clock = std::chrono::steady_clock;
double secondsSince(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

constexpr double kDefaultSpacingFraction = 1.0 / 40;  // of the bounding-box diagonal

FeatureCounts countFeatures(const SolidTopology& topo, const std::vector<EdgeFeature>& edges,
                            const std::vector<VertexFeature>& vertices) {
  FeatureCounts c;
  c.faces = topo.faceCount();
  c.edges = topo.edgeCount();
  c.vertices = topo.vertexCount();
  for (int e = 0; e < topo.edgeCount(); ++e) {
    const EdgeFeature& f = edges[e];
    if (topo.edgeDegenerate[e]) {
      ++c.degenerateEdges;
    } else if (f.seam) {
      ++c.seamEdges;
    } else if (f.free) {
      ++c.freeEdges;
    } else if (f.kind == EdgeKind::Convex) {
      ++c.convexEdges;
      c.convexLength += f.length;
    } else if (f.kind == EdgeKind::Concave) {
      ++c.concaveEdges;
      c.concaveLength += f.length;
    } else {
      ++c.smoothEdges;
    }
    if (f.mixedSign) ++c.mixedSignEdges;
  }
  for (const VertexFeature& v : vertices) {
    if (!v.isCorner) continue;
    ++c.corners;
    if (v.nonConcave) ++c.nonConcaveCorners;
  }
  return c;
}

Bnd_Box boundingBox(const TopoDS_Shape& shape) {
  Bnd_Box box;
  BRepBndLib::AddOptimal(shape, box, false, false);
  return box;
}

// A spacing that asks for more face samples than any machine holds (area /
// h² above 1e8, about 100 × the 2 GiB of a million samples) is refused
// before any work, with the spacing of about a million samples: `--spacing
// 1e-9` on a 60 mm box ran for 10 minutes without end.
void refuseSpacingBeyondReach(double area, double spacing) {
  constexpr double kMaxSamples = 1e8;
  if (!(area / (spacing * spacing) > kMaxSamples)) return;
  std::ostringstream message;
  message << std::setprecision(3) << "spacing " << spacing << " would need about " << area / (spacing * spacing)
          << " samples on a surface of area " << area << " (at most " << kMaxSamples
          << "); a spacing of " << std::sqrt(area / 1e6) << " gives about a million";
  throw InputError(kExitUsage, message.str());
}

// One warning for a feature finer than the finest spacing can follow:
// "<what><size><unit> at (p) is <finer> than the finest spacing m can
// follow (it needs n): the axis there is approximate; --spacing s or finer
// samples it as finely as it needs", s = n / minSpacingFraction rounded
// down to 3 digits. A promise about the sampling only: on the lever and NIST
// CTC-01 the spacings these warnings named gave the axis more islands and
// loops, not fewer (README, Known gaps).
void warnBeyondFinestSpacing(const SamplingContext& ctx, const SamplingParams& params, const char* what, double size,
                             const char* unit, const gp_Pnt& at, const char* finer, double needs,
                             SamplingReport& report) {
  const double needed = needs / params.minSpacingFraction;
  const double thirdDigit = std::pow(10.0, std::floor(std::log10(needed)) - 2);
  std::ostringstream message;
  message << std::setprecision(3) << what << size << unit << " at (" << std::setprecision(7) << at.X() << ", "
          << at.Y() << ", " << at.Z() << std::setprecision(3) << ") is " << finer << " than the finest spacing " << ctx.minSpacing
          << " can follow (it needs " << needs << "): the axis there is approximate; --spacing "
          << std::floor(needed / thirdDigit) * thirdDigit << " or finer samples it as finely as it needs";
  report.warnings.push_back(message.str());
}

// A wall thinner than the finest spacing can follow (0.4 × its thickness
// below h × minSpacingFraction) is sampled too coarsely for the Voronoi
// facets between its sides to be medial: the axis there is approximate
// (a 100 × 100 × 0.01 foil at the default spacing: 0.03 % coverage). Said
// once per solid, with the thinnest wall and a spacing that samples it finely enough.
void warnAboutUnresolvedWalls(const SamplingContext& ctx, const SamplingParams& params, SamplingReport& report) {
  const FaceSpacingField* thinnest = nullptr;
  for (const FaceSpacingField& field : ctx.faceSpacing)
    if (!thinnest || field.thinnestWall() < thinnest->thinnestWall()) thinnest = &field;
  const double fraction = FaceSpacingField::kThicknessFraction * ctx.boundsScale;
  if (!thinnest || !(fraction * thinnest->thinnestWall() < ctx.minSpacing)) return;
  const double wall = thinnest->thinnestWall();
  warnBeyondFinestSpacing(ctx, params, "a wall ", wall, " thick", thinnest->thinnestWallAt(), "thinner", fraction * wall,
                          report);
}

// An edge curved tighter than the finest spacing can follow (eight chords
// a turn, 0.77 × its radius, below h × minSpacingFraction): a pin or a hole
// of radius 0.05 on a 200 mm part. Its faces are sampled by their boundary
// only and can come out flat (the two halves of a pin's side on one strip),
// and the axis there is approximate, often with an island or a loop too
// many. Said once per solid, with the tightest edge and a spacing that
// samples it finely enough.
void warnAboutUnresolvedCurves(const SamplingContext& ctx, const SamplingParams& params, SamplingReport& report) {
  constexpr double kChordFraction = 0.8;  // ≥ 8 chords a full turn
  const double fraction = kChordFraction * ctx.boundsScale;
  if (!(fraction * ctx.tightestEdgeRadius < ctx.minSpacing)) return;
  const double radius = ctx.tightestEdgeRadius;
  warnBeyondFinestSpacing(ctx, params, "an edge curved to radius ", radius, "", ctx.tightestEdgeAt, "tighter",
                          fraction * radius, report);
}

double defaultSpacingIn(const Bnd_Box& box) {
  if (box.IsVoid()) return 1.0;
  return kDefaultSpacingFraction * std::sqrt(box.SquareExtent());
}

}  // namespace

double defaultSpacing(const TopoDS_Shape& solid) { return defaultSpacingIn(boundingBox(solid)); }

FeatureCounts classifyFeatures(const TopoDS_Shape& solid, double smoothAngleDeg) {
  const SolidTopology topo = buildSolidTopology(solid, false);
  const auto edges = classifyEdges(topo, smoothAngleDeg);
  return countFeatures(topo, edges, classifyVertices(topo, edges));
}

SolidSampling sampleSolid(const TopoDS_Shape& solid, const SamplingParams& params,
                          const PointsReady& pointsReady) {
  SolidSampling out;
  SamplingReport& report = out.report;
  SampleSet& set = out.samples;

  auto t = Clock::now();
  const SolidTopology topo = buildSolidTopology(solid);
  const auto edgeFeatures = classifyEdges(topo, params.smoothAngleDeg);
  const auto vertexFeatures = classifyVertices(topo, edgeFeatures);
  report.features = countFeatures(topo, edgeFeatures, vertexFeatures);
  if (report.features.freeEdges > 0)
    report.warnings.push_back(std::to_string(report.features.freeEdges) + " free edge(s): the shell is not closed");
  report.secondsClassify = secondsSince(t);

  t = Clock::now();
  SamplingContext ctx(topo, edgeFeatures, vertexFeatures);
  // The tight box costs a particle-swarm search per B-spline face (1.5 s
  // on the public gear): once for the spacing and the sample set.
  const Bnd_Box box = boundingBox(solid);
  ctx.spacing = params.spacing > 0 ? params.spacing : defaultSpacingIn(box);
  GProp_GProps area;
  BRepGProp::SurfaceProperties(solid, area);
  report.exactArea = area.Mass();
  refuseSpacingBeyondReach(report.exactArea, ctx.spacing);
  ctx.minSpacing = ctx.spacing * params.minSpacingFraction;
  ctx.gradedSpacing = params.gradedSpacing;
  ctx.boundsScale = params.boundsScale;
  ctx.oneDartAtATime = params.oneDartAtATime;
  set.spacing = ctx.spacing;
  set.faceCount = topo.faceCount();
  double x0, y0, z0, x1, y1, z1;
  box.Get(x0, y0, z0, x1, y1, z1);
  set.bboxMin = {x0, y0, z0};
  set.bboxMax = {x1, y1, z1};

  computeSpacings(ctx);
  warnAboutUnresolvedWalls(ctx, params, report);
  warnAboutUnresolvedCurves(ctx, params, report);
  // The builder's hash cell follows the largest spacing actually used, not
  // the global target: every exclusion radius is at most ~that, and on thin
  // walls (face spacing 0.4 x thickness << h) cells of size h held hundreds
  // of samples each, which made dart throwing quadratic-like. isClear is
  // exact for any cell size, so the samples do not change.
  double largestSpacing = 0;
  for (const FaceSpacingField& field : ctx.faceSpacing) largestSpacing = std::max(largestSpacing, field.maximum());
  for (int e = 0; e < topo.edgeCount(); ++e)
    if (!topo.edgeDegenerate[e]) largestSpacing = std::max(largestSpacing, ctx.edgeSpacing[e]);
  // Cells twice that size: a dart's ball (radius 0.75 x its spacing) then
  // overlaps at most 2 cells per axis.
  SampleBuilder builder(set, 2.0 * (largestSpacing > 0 ? largestSpacing : ctx.spacing));
  sampleVerticesAndEdges(ctx, builder);
  const std::size_t featureSamples = set.points.size();
  placeTriplets(ctx, builder);
  const std::size_t withLegs = set.points.size();
  sampleFaceInteriors(ctx, builder, params.seed);
  report.secondsSample = secondsSince(t);
  for (SampleKind k : set.kind) {
    if (k == SampleKind::Edge) ++report.edgeSamples;
    if (k == SampleKind::Corner) ++report.vertexSamples;
  }
  report.rungSamples = ctx.rungSamples;
  report.legSamples = withLegs - featureSamples - ctx.rungSamples;
  report.faceSamples = set.points.size() - withLegs;
  report.triplets = set.triplets.size();
  report.tripletsDropped = ctx.tripletsDropped;

  if (pointsReady) pointsReady(set.points);

  t = Clock::now();
  const ReconstructionReport rec = reconstructFaces(ctx, set);
  set.buildUmbrellas();
  report.surface = checkSurfaceMesh(set.points, set.triangles);
  report.secondsReconstruct = secondsSince(t);
  report.facesFailed = rec.facesFailed;
  report.orphanSamples = rec.orphanSamples;
  report.droppedTriangles = rec.droppedTriangles;
  report.flippedEdges = rec.flippedEdges;
  report.misalignedTriangles = rec.misalignedTriangles;
  report.worstFaceAreaError = rec.worstFaceAreaError;
  report.worstFace = rec.worstFace;

  GProp_GProps volume;
  BRepGProp::VolumeProperties(solid, volume);
  report.exactVolume = volume.Mass();
  for (const std::string& problem : rec.problems) report.warnings.push_back("reconstruction: " + problem);
  if (!report.surface.closedManifold())
    report.warnings.push_back("stitched surface is not a closed manifold: " +
                              std::to_string(report.surface.boundaryEdges) + " boundary edges, " +
                              std::to_string(report.surface.nonManifoldEdges) + " non-manifold edges, " +
                              std::to_string(report.surface.misorientedEdges) + " misoriented edges, " +
                              std::to_string(report.surface.nonManifoldVertices) + " non-manifold vertices");
  set.validate();
  return out;
}

}  // namespace cadmedial
