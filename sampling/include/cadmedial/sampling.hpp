// Sampling a B-rep solid for CAD_MEDIAL (DESIGN.md §3, seed 002 §4.2.1/§4.2.4).
#pragma once

#include <functional>
#include <string>
#include <vector>

#include <TopoDS_Shape.hxx>

#include "cadmedial/sample_set.hpp"
#include "cadmedial/surface_mesh_checks.hpp"

namespace cadmedial {

struct SamplingParams {
  double spacing = 0;          // target spacing h in model units; 0 = defaultSpacing()
  double smoothAngleDeg = 1.0; // edges whose face normals stay within this angle are smooth
  double minSpacingFraction = 1.0 / 16;  // curvature refinement never goes below h × this
  unsigned seed = 1;           // face samples are random but reproducible
  // Face spacing graded within each face (FaceSpacingField) instead of one
  // minimum per face (false: the uniform spacing of before 2026-12-02). On
  // since a pair-mesh left not valid by the repair is sampled again
  // (cli/solid_run.hpp): the same or better verdicts on every bundled and
  // public dev model (with faces graded from finer convex edges, two contacts
  // pass on all of them), and a pointed cone gets 10 k samples and the right
  // topology instead of 115 k and β 13,3 (ARCHITECTURE.md, Spacings).
  bool gradedSpacing = true;
  // Multiplies the curvature and wall-thickness bounds on the spacing
  // (0.15 × radius of curvature, 0.4 × wall thickness). With `spacing` × f
  // as well, the whole sampling is f times finer, also on faces whose
  // spacing those bounds set below h: how a pair-mesh that is not valid is
  // sampled again (cli/solid_run.hpp). A torus of minor radius 2 and major
  // radius 30 got the same 27,009 samples at h, 0.97 h and 0.94 h before.
  double boundsScale = 1.0;
  // Face darts evaluated one at a time, in the order thrown, instead of in
  // parallel batches (face_sampling.cpp). The same samples either way,
  // only slower: the reference the tests hold the batches to.
  bool oneDartAtATime = false;
};

// Edge and vertex counts of a solid's features.
struct FeatureCounts {
  int faces = 0, edges = 0, vertices = 0;
  int convexEdges = 0, concaveEdges = 0, smoothEdges = 0, seamEdges = 0, degenerateEdges = 0, freeEdges = 0;
  int mixedSignEdges = 0;
  double convexLength = 0, concaveLength = 0;
  int corners = 0, nonConcaveCorners = 0;
};

struct SamplingReport {
  FeatureCounts features;  // of the split solid that was sampled
  std::size_t faceSamples = 0, edgeSamples = 0, vertexSamples = 0, legSamples = 0;
  std::size_t rungSamples = 0;  // knife-edge rungs: mirror pairs continuing the legs where faces meet at a small angle
  std::size_t triplets = 0, tripletsDropped = 0;
  int facesFailed = 0, orphanSamples = 0, droppedTriangles = 0;
  int flippedEdges = 0;         // UV-Delaunay edges flipped: a triangle stood > 45° off the exact surface
  int misalignedTriangles = 0;  // triangles still > 45° off the exact surface normal after the flips
  double worstFaceAreaError = 0;  // max over faces of |reconstructed area / exact area - 1|
  int worstFace = -1;
  SurfaceMeshStats surface;  // the stitched reconstruction
  double exactArea = 0, exactVolume = 0;  // BRepGProp of the solid
  double secondsClassify = 0, secondsSample = 0, secondsReconstruct = 0;
  std::vector<std::string> warnings;
};

struct SolidSampling {
  SampleSet samples;
  SamplingReport report;
};

// A spacing that gives a usable axis on typical parts in about a second.
double defaultSpacing(const TopoDS_Shape& solid);

// Called once with the final sample points, before the faces are
// reconstructed: a caller starts work that needs only the points (the
// Delaunay triangulation) on another thread, so that on two cores the
// reconstruction costs no wall time. The reference is valid only during the
// call: copy what outlives it.
using PointsReady = std::function<void(const std::vector<Vec3>& points)>;

// Samples one closed solid. Throws std::runtime_error if the solid cannot be
// sampled at all; partial problems are counted in the report.
SolidSampling sampleSolid(const TopoDS_Shape& solid, const SamplingParams& params = {},
                          const PointsReady& pointsReady = {});

// Classifies the edges and vertices of a solid as it is (no face splitting):
// the counts a CAD user sees. Seams and degenerate edges are counted apart.
FeatureCounts classifyFeatures(const TopoDS_Shape& solid, double smoothAngleDeg = 1.0);

}  // namespace cadmedial
