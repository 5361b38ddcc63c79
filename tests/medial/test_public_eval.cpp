// Every set=dev public model (../shared/models/public, skipped when absent),
// default parameters, every solid: the DESIGN.md §6 metrics against OCCT's
// exact geometry. Inside, coverage, convex-edge attachment and medialness must
// meet the thresholds of the CAD_MEDIAL issue, and β0/β1 of the axis must equal
// the solid's (computed by OCCT from the B-rep, not from the axis) except on
// the parts listed in kKnownComponentGaps / kKnownLoopGaps (ARCHITECTURE.md, "Known gaps").
// Corner attachment is printed (scripts/eval_table.py --public).
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <set>
#include <string>

#include "cadmedial/medial.hpp"
#include "cadmedial/union_find.hpp"
// OCCT after CGAL (OCCT's Handle macro).
#include "cadmedial/brep_io.hpp"
#include "cadmedial/medial_evaluation.hpp"
#include "cadmedial/sampling.hpp"
#include "medial_mesh_conversion.hpp"
#include "model_fixtures.hpp"

namespace cadmedial {
namespace {

// Above this many samples a model is left to scripts/eval_table.py: its
// evaluation alone takes minutes, too long for the suite.
constexpr std::size_t kMaxSamplesInSuite = 100000;

// Parts whose axis still has extra components (β0) or loops (β1), issue #3;
// every other set=dev part must match the solid's β0 and β1.
const std::set<std::string> kKnownComponentGaps = {
    "nist_ctc_01_asme1_rd.stp",  // islands
    "bottle.brep",               // islands on smooth blends
};
const std::set<std::string> kKnownLoopGaps = {
    "bm2_ec_lever-A.stp",        // 4 loops at the ends of the zero-angle cusp (z = 10, 70)
    "nist_ctc_01_asme1_rd.stp",  // loops
    "bottle.brep",               // loops on smooth blends
};

// Components of the axis, other than the one with the most polygons, that
// have no Voronoi facet (forced triangles only): a completion whose sheet the
// filter pruned, which dropForcedOnlyIslands removes (NIST CTC-01 had 15).
std::size_t forcedOnlyIslands(const MedialComplex& mc) {
  UnionFind uf(mc.vertices.size());
  for (std::size_t p = 0; p < mc.polygonCount(); ++p)
    for (Index k = mc.polygonOffsets[p] + 1; k < mc.polygonOffsets[p + 1]; ++k)
      uf.unite(mc.polygonVertices[mc.polygonOffsets[p]], mc.polygonVertices[k]);
  std::vector<std::size_t> polygons(mc.vertices.size(), 0), facets(mc.vertices.size(), 0);
  for (std::size_t p = 0; p < mc.polygonCount(); ++p) {
    const Index root = uf.find(mc.polygonVertices[mc.polygonOffsets[p]]);
    ++polygons[root];
    facets[root] += mc.provenance[p] == PolygonProvenance::DelaunayEdgeFacet ? 1 : 0;
  }
  const std::size_t largest = std::max_element(polygons.begin(), polygons.end()) - polygons.begin();
  std::size_t count = 0;
  for (std::size_t r = 0; r < polygons.size(); ++r) count += r != largest && polygons[r] > 0 && facets[r] == 0;
  return count;
}

class PublicEvaluation : public ::testing::TestWithParam<std::string> {};

TEST_P(PublicEvaluation, MeetsTheGeometricThresholds) {
  const LoadedModel model = loadModel(test::publicModelsDir() + "/" + GetParam());
  ASSERT_FALSE(model.solids.empty());
  for (std::size_t i = 0; i < model.solids.size(); ++i) {
    const SolidSampling s = sampleSolid(model.solids[i]);
    if (s.samples.size() > kMaxSamplesInSuite) {
      std::printf("%-36s solid %zu: %zu samples, evaluation left to scripts/eval_table.py\n", GetParam().c_str(), i,
                  s.samples.size());
      continue;
    }
    const MedialResult m = computeCadMedial(s.samples);
    const EvaluationReport r = evaluateMedial(model.solids[i], toMedialMesh(m));
    std::printf("%-36s solid %zu: inside %.4f  medialness median %.4f%% diag  coverage %.4f  edges %.4f  "
                "corners %d/%d  b0,b1 %lld,%lld (solid %lld,%lld)\n",
                GetParam().c_str(), i, r.inside.share, 100 * r.medialness.median, r.coverage.share,
                r.attachment.edgeShare, r.attachment.attachedCorners, r.attachment.corners, r.topology.beta0,
                r.topology.beta1, r.topology.solidBeta0, r.topology.solidBeta1);
    EXPECT_GE(r.inside.share, 0.999) << "solid " << i;
    EXPECT_GE(r.coverage.share, 0.99) << "solid " << i;
    EXPECT_GE(r.attachment.edgeShare, 0.99) << "solid " << i;
    EXPECT_LE(r.medialness.median, 0.005) << "solid " << i;
    EXPECT_GE(r.topology.beta0, 1) << "solid " << i;
    EXPECT_EQ(forcedOnlyIslands(m), 0u) << "solid " << i;
    if (kKnownComponentGaps.count(GetParam()) == 0) EXPECT_EQ(r.topology.beta0, r.topology.solidBeta0) << "solid " << i;
    if (kKnownLoopGaps.count(GetParam()) == 0) EXPECT_EQ(r.topology.beta1, r.topology.solidBeta1) << "solid " << i;
    // No enclosed void the solid lacks: a hole closed over a pocket's mouth
    // (fillShortHoles) would show here (-1: the core was too big to count).
    if (r.topology.beta2 >= 0) EXPECT_EQ(r.topology.beta2, r.topology.solidBeta2) << "solid " << i;
  }
}

std::string testName(const ::testing::TestParamInfo<std::string>& info) {
  std::string name;
  for (char c : info.param) name += std::isalnum(static_cast<unsigned char>(c)) ? c : '_';
  return name;
}

INSTANTIATE_TEST_SUITE_P(Dev, PublicEvaluation, ::testing::ValuesIn(test::publicModels("set=dev")), testName);
GTEST_ALLOW_UNINSTANTIATED_PARAMETERIZED_TEST(PublicEvaluation);

}  // namespace
}  // namespace cadmedial
