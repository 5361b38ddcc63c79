#include "report_json.hpp"

namespace cadmedial {

nlohmann::json toJson(const FeatureCounts& c) {
  return {{"faces", c.faces},
          {"edges", c.edges},
          {"vertices", c.vertices},
          {"convex_edges", c.convexEdges},
          {"concave_edges", c.concaveEdges},
          {"smooth_edges", c.smoothEdges},
          {"seam_edges", c.seamEdges},
          {"degenerate_edges", c.degenerateEdges},
          {"free_edges", c.freeEdges},
          {"mixed_sign_edges", c.mixedSignEdges},
          {"convex_length", c.convexLength},
          {"concave_length", c.concaveLength},
          {"corners", c.corners},
          {"non_concave_corners", c.nonConcaveCorners}};
}

nlohmann::json toJson(const SurfaceMeshStats& s) {
  return {{"vertices", s.vertices},
          {"edges", s.edges},
          {"triangles", s.triangles},
          {"boundary_edges", s.boundaryEdges},
          {"non_manifold_edges", s.nonManifoldEdges},
          {"misoriented_edges", s.misorientedEdges},
          {"non_manifold_vertices", s.nonManifoldVertices},
          {"components", s.components},
          {"euler_characteristic", s.eulerCharacteristic},
          {"closed_manifold", s.closedManifold()},
          {"area", s.area},
          {"enclosed_volume", s.enclosedVolume}};
}

nlohmann::json toJson(const SamplingReport& r) {
  return {{"features", toJson(r.features)},
          {"samples",
           {{"face", r.faceSamples},
            {"edge", r.edgeSamples},
            {"vertex", r.vertexSamples},
            {"triplet_legs", r.legSamples},
            {"knife_edge_rungs", r.rungSamples},
            {"total", r.faceSamples + r.edgeSamples + r.vertexSamples + r.legSamples + r.rungSamples}}},
          {"triplets", r.triplets},
          {"triplets_dropped", r.tripletsDropped},
          {"reconstruction",
           {{"faces_failed", r.facesFailed},
            {"orphan_samples", r.orphanSamples},
            {"dropped_triangles", r.droppedTriangles},
            {"flipped_edges", r.flippedEdges},
            {"misaligned_triangles", r.misalignedTriangles},
            {"worst_face_area_error", r.worstFaceAreaError},
            {"worst_face", r.worstFace},
            {"surface", toJson(r.surface)},
            {"exact_area", r.exactArea},
            {"exact_volume", r.exactVolume}}},
          {"seconds", {{"classify", r.secondsClassify}, {"sample", r.secondsSample}, {"reconstruct", r.secondsReconstruct}}},
          {"warnings", r.warnings}};
}

}  // namespace cadmedial
