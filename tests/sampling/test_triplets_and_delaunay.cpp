// Triplets are exact (equal legs perpendicular to the edge, points on their
// faces) and the sharp features survive in the 3D Delaunay triangulation.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_vertex_base_with_info_3.h>

#include <BRepAdaptor_Curve.hxx>
#include <BRepBuilderAPI_MakeVertex.hxx>
#include <BRepExtrema_DistShapeShape.hxx>
#include <Extrema_ExtPC.hxx>

#include "cadmedial/brep_io.hpp"
#include "cadmedial/sampling.hpp"
#include "model_fixtures.hpp"
#include "solid_topology.hpp"

namespace cadmedial {
namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Vb = CGAL::Triangulation_vertex_base_with_info_3<Index, K>;
using Tds = CGAL::Triangulation_data_structure_3<Vb, CGAL::Delaunay_triangulation_cell_base_3<K>>;
using Dt = CGAL::Delaunay_triangulation_3<K, Tds>;

gp_Pnt pnt(const Vec3& p) { return gp_Pnt(p[0], p[1], p[2]); }

struct DelaunayFeatureCheck {
  std::size_t triplets = 0, tripletsMissing = 0;
  std::size_t edgePairs = 0, edgePairsMissing = 0;
};

DelaunayFeatureCheck checkFeaturesInDelaunay(const SampleSet& s) {
  std::vector<std::pair<K::Point_3, Index>> pts;
  for (Index i = 0; i < s.size(); ++i) pts.emplace_back(K::Point_3(s.points[i][0], s.points[i][1], s.points[i][2]), i);
  Dt dt(pts.begin(), pts.end());
  std::vector<Dt::Vertex_handle> handle(s.size());
  for (auto v = dt.finite_vertices_begin(); v != dt.finite_vertices_end(); ++v) handle[v->info()] = v;
  DelaunayFeatureCheck out;
  for (const Triplet& t : s.triplets) {
    ++out.triplets;
    Dt::Cell_handle c;
    int i, j, k;
    if (!dt.is_facet(handle[t.s], handle[t.sLeft], handle[t.sRight], c, i, j, k)) ++out.tripletsMissing;
  }
  for (const EdgeInfo& e : s.edges) {
    if (e.kind == EdgeKind::Smooth) continue;
    for (std::size_t k = 0; k + 1 < e.samples.size(); ++k) {
      ++out.edgePairs;
      Dt::Cell_handle c;
      int i, j;
      if (!dt.is_edge(handle[e.samples[k]], handle[e.samples[k + 1]], c, i, j)) ++out.edgePairsMissing;
    }
  }
  return out;
}

class BundledTriplets : public ::testing::TestWithParam<std::string> {};

TEST_P(BundledTriplets, LegsAreEqualPerpendicularAndOnTheirFaces) {
  const LoadedModel model = loadModel(test::bundledPath(test::bundledModel(GetParam())));
  const SolidSampling result = sampleSolid(model.solids[0]);
  const SampleSet& s = result.samples;
  const SolidTopology topo = buildSolidTopology(model.solids[0]);  // same split, same face ids
  const double diag = s.bboxDiagonal();
  const std::size_t convexSamples = std::count(s.onConvexEdge.begin(), s.onConvexEdge.end(), 1);
  if (convexSamples > 0) EXPECT_GT(s.triplets.size(), 0u);
  for (const Triplet& t : s.triplets) {
    const gp_Pnt ps = pnt(s.points[t.s]), pl = pnt(s.points[t.sLeft]), pr = pnt(s.points[t.sRight]);
    const double ll = ps.Distance(pl), lr = ps.Distance(pr);
    ASSERT_GT(ll, 0);
    EXPECT_LT(std::abs(ll - lr) / ll, 1e-6);
    // Edge tangent at s, from the exact edge curve.
    BRepAdaptor_Curve curve(topo.edge(t.edge));
    Extrema_ExtPC ext(ps, curve);
    ASSERT_TRUE(ext.IsDone() && ext.NbExt() > 0);
    int best = 1;
    for (int k = 2; k <= ext.NbExt(); ++k)
      if (ext.SquareDistance(k) < ext.SquareDistance(best)) best = k;
    gp_Pnt onCurve;
    gp_Vec tangent;
    curve.D1(ext.Point(best).Parameter(), onCurve, tangent);
    tangent.Normalize();
    EXPECT_LT(std::abs(gp_Vec(ps, pl).Dot(tangent)) / ll, 1e-6);
    EXPECT_LT(std::abs(gp_Vec(ps, pr).Dot(tangent)) / lr, 1e-6);
    for (Index leg : {t.sLeft, t.sRight}) {
      BRepExtrema_DistShapeShape dist(BRepBuilderAPI_MakeVertex(pnt(s.points[leg])).Vertex(), topo.face(s.owner[leg]));
      ASSERT_TRUE(dist.IsDone());
      EXPECT_LT(dist.Value(), 1e-7 * diag);
    }
  }
}

TEST_P(BundledTriplets, TripletTrianglesAndSharpEdgesAreDelaunay) {
  const LoadedModel model = loadModel(test::bundledPath(test::bundledModel(GetParam())));
  const SolidSampling result = sampleSolid(model.solids[0]);
  const DelaunayFeatureCheck c = checkFeaturesInDelaunay(result.samples);
  std::printf("%s: %zu/%zu triplet triangles and %zu/%zu sharp-edge pairs not Delaunay, %zu triplets dropped\n",
              GetParam().c_str(), c.tripletsMissing, c.triplets, c.edgePairsMissing, c.edgePairs,
              result.report.tripletsDropped);
  EXPECT_EQ(c.tripletsMissing, 0u);
  EXPECT_EQ(c.edgePairsMissing, 0u);
  EXPECT_EQ(result.report.tripletsDropped, 0u);
}

INSTANTIATE_TEST_SUITE_P(Models, BundledTriplets, ::testing::ValuesIn(test::bundledModelNames()),
                         [](const auto& info) { return info.param; });

// Public models: report how many feature simplices are not Delaunay (not a
// pass/fail criterion; the paper relies on conservative sampling).
TEST(PublicTriplets, ReportFeaturesMissingFromDelaunay) {
  const auto files = test::publicModels("set=dev");
  if (files.empty()) GTEST_SKIP() << "../shared/models/public not present";
  for (const std::string& f : files) {
    const LoadedModel model = loadModel(test::publicModelsDir() + "/" + f);
    for (std::size_t i = 0; i < model.solids.size(); ++i) {
      const SolidSampling result = sampleSolid(model.solids[i]);
      const DelaunayFeatureCheck c = checkFeaturesInDelaunay(result.samples);
      std::printf("%-36s solid %zu: %5zu/%-5zu triplets, %5zu/%-5zu sharp-edge pairs not Delaunay; %zu dropped\n",
                  f.c_str(), i, c.tripletsMissing, c.triplets, c.edgePairsMissing, c.edgePairs,
                  result.report.tripletsDropped);
      EXPECT_LT(c.tripletsMissing, c.triplets / 10 + 1) << f;
    }
  }
}

}  // namespace
}  // namespace cadmedial

namespace cadmedial {
namespace {

// Face darts are thrown tile by tile (face_sampling.cpp): the samples must
// still be a Poisson-disk set that fills every face - no two face samples
// closer than their radius, and no hole much wider than a disk anywhere on a
// face (a tile skipped or mis-placed leaves a hole ~16 radii wide). Box faces
// of 40 x 30 mm at h = 0.3 are 4-6 tiles a side.
TEST(FaceSamples, PoissonDiskWithoutHolesAcrossTiles) {
  const LoadedModel model = loadModel(test::bundledPath(test::bundledModel("box")));
  SamplingParams params;
  params.spacing = 0.3;
  const SolidSampling sampled = sampleSolid(model.solids.at(0), params);
  const SampleSet& s = sampled.samples;
  const double radius = 0.75 * params.spacing;  // Poisson radius of face samples (face spacing = h on a box)

  std::vector<std::pair<K::Point_3, Index>> pts;
  for (Index i = 0; i < s.size(); ++i) pts.emplace_back(K::Point_3(s.points[i][0], s.points[i][1], s.points[i][2]), i);
  Dt dt(pts.begin(), pts.end());
  // The darts are the last samples (after vertices, edges and triplet legs).
  ASSERT_GT(sampled.report.faceSamples, 0u);
  const Index firstDart = static_cast<Index>(s.size() - sampled.report.faceSamples);
  double closestFacePair = 1e300;
  for (auto e = dt.finite_edges_begin(); e != dt.finite_edges_end(); ++e) {
    const Index a = e->first->vertex(e->second)->info(), b = e->first->vertex(e->third)->info();
    if (a < firstDart || b < firstDart) continue;
    closestFacePair = std::min(closestFacePair, std::sqrt(CGAL::squared_distance(pts[a].first, pts[b].first)));
  }
  // Probes on the six faces of the 40 x 30 x 20 box, every radius / 2.
  const double size[3] = {40, 30, 20};
  double widestHole = 0;
  std::size_t probes = 0;
  for (int axis = 0; axis < 3; ++axis)
    for (double level : {0.0, size[axis]}) {
      const int u = (axis + 1) % 3, v = (axis + 2) % 3;
      for (double a = 0; a <= size[u]; a += 0.5 * radius)
        for (double b = 0; b <= size[v]; b += 0.5 * radius) {
          double q[3];
          q[axis] = level;
          q[u] = a;
          q[v] = b;
          const K::Point_3 p(q[0], q[1], q[2]);
          widestHole = std::max(widestHole, std::sqrt(CGAL::squared_distance(p, dt.nearest_vertex(p)->point())));
          ++probes;
        }
    }
  std::printf("box h=0.3: %zu samples, closest face pair %.4f (radius %.4f), widest hole %.4f over %zu probes\n",
              s.size(), closestFacePair, radius, widestHole, probes);
  EXPECT_GE(closestFacePair, radius * (1 - 1e-9));
  EXPECT_LE(widestHole, 2.5 * radius);
}

}  // namespace
}  // namespace cadmedial
