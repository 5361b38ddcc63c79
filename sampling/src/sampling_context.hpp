// State shared by the sampling stages of one solid (internal to sampling/).
#pragma once

#include <string>
#include <array>
#include <vector>

#include <gp_Pnt.hxx>
#include <gp_Pnt2d.hxx>

#include "cadmedial/sample_set.hpp"
#include "face_spacing_field.hpp"
#include "feature_classification.hpp"
#include "sample_builder.hpp"
#include "solid_topology.hpp"

namespace cadmedial {

struct SamplingContext {
  SamplingContext(const SolidTopology& t, const std::vector<EdgeFeature>& e, const std::vector<VertexFeature>& v)
      : topo(t), edgeFeatures(e), vertexFeatures(v) {}

  const SolidTopology& topo;
  const std::vector<EdgeFeature>& edgeFeatures;
  const std::vector<VertexFeature>& vertexFeatures;
  double spacing = 0;     // global target spacing h
  double minSpacing = 0;  // floor for curvature refinement
  bool gradedSpacing = true;  // SamplingParams::gradedSpacing
  double boundsScale = 1.0;   // SamplingParams::boundsScale
  bool oneDartAtATime = false;  // SamplingParams::oneDartAtATime
  std::vector<FaceSpacingField> faceSpacing;  // per face: one value, or graded over its UV box
  std::vector<double> edgeSpacing;   // per edge (target; its smallest along it)
  // Per edge: (arc length from its first vertex, spacing) along it where the
  // spacing varies (graded faces finer near one end); empty: even at edgeSpacing.
  std::vector<std::vector<std::array<double, 2>>> edgeSpacingAlong;
  double tightestEdgeRadius = 1e300;  // smallest radius of curvature found on an edge (computeSpacings)
  gp_Pnt tightestEdgeAt;              // where
  std::vector<double> cornerRadius;  // per vertex: corner-ball radius (0: no ball)
  std::vector<Index> vertexSample;   // per vertex: its sample
  std::vector<std::vector<double>> edgeParams;  // per edge: curve parameter of each sample in SampleSet::edges[e].samples
  std::vector<gp_Pnt2d> faceSampleUv;  // per sample: UV on its owner face (face samples only)
  int tripletsDropped = 0;           // convex-edge samples where no equal-leg pair fits on the faces
  std::size_t rungSamples = 0;       // knife-edge rungs (placeTriplets), counted with the legs

  void recordFaceUv(Index sample, const gp_Pnt2d& uv) {
    if (faceSampleUv.size() <= sample) faceSampleUv.resize(sample + 1);
    faceSampleUv[sample] = uv;
  }
};

// Face spacing fields from curvature and wall thickness (graded or not), edge
// spacing from curvature and the incident faces' fields along the edge,
// corner-ball radii from incident edge lengths.
void computeSpacings(SamplingContext& ctx);
// One sample per vertex, then every non-degenerate edge sampled by arc length
// between the corner balls of its ends. Fills SampleSet::edges and vertices.
void sampleVerticesAndEdges(SamplingContext& ctx, SampleBuilder& builder);
// Equal, perpendicular legs on both faces of every convex-edge sample.
void placeTriplets(SamplingContext& ctx, SampleBuilder& builder);
// Poisson-disk samples inside every face, clear of the feature samples.
void sampleFaceInteriors(SamplingContext& ctx, SampleBuilder& builder, unsigned seed);

struct ReconstructionReport {
  int facesFailed = 0;        // faces whose constrained triangulation could not be built
  int orphanSamples = 0;      // face samples left out of every triangle
  int droppedTriangles = 0;   // degenerate triangles dropped (pole fans, merged points)
  int flippedEdges = 0;       // edges flipped to bring triangles onto the surface
  int misalignedTriangles = 0;  // triangles still more than 45° off the surface normal
  std::vector<std::string> problems;  // one line per failed face
  double worstFaceAreaError = 0;      // max over faces of |mesh area / exact area - 1|
  int worstFace = -1;
};
// Constrained Delaunay triangulation of each face in its (metric-scaled) UV
// domain, boundary samples as constraints, holes removed; fills triangles.
ReconstructionReport reconstructFaces(SamplingContext& ctx, SampleSet& set);

}  // namespace cadmedial
