// The corner classification, the spacing fields and the face darts run on
// TBB threads (feature_classification.cpp, edge_sampling.cpp,
// narrow_faces.cpp, face_sampling.cpp). The samples must be those of the
// serial reference, down to the last bit: darts evaluated one at a time on
// one thread (SamplingParams::oneDartAtATime) against the parallel batches on
// four threads. Each thread has its own ray intersector, surface adaptor and
// UV classifier, and the darts of a batch are kept in the order thrown.
#include <gtest/gtest.h>

#include <string>

#include <BRepAlgoAPI_Cut.hxx>
#include <BRepAlgoAPI_Fuse.hxx>
#include <BRepBuilderAPI_NurbsConvert.hxx>
#include <BRepPrimAPI_MakeBox.hxx>
#include <BRepPrimAPI_MakeCylinder.hxx>
#include <gp_Ax2.hxx>
#include <tbb/global_control.h>
#include <tbb/task_arena.h>

#include "cadmedial/brep_io.hpp"
#include "cadmedial/sampling.hpp"
#include "model_fixtures.hpp"

namespace cadmedial {
namespace {

constexpr int kThreads = 4;  // more than the machine has is fine: the threads still interleave

SampleSet sampleIn(tbb::task_arena& arena, const TopoDS_Shape& solid, const SamplingParams& params) {
  SampleSet samples;
  arena.execute([&] { samples = sampleSolid(solid, params).samples; });
  return samples;
}

bool sameTriplet(const Triplet& a, const Triplet& b) {
  return a.s == b.s && a.sLeft == b.sLeft && a.sRight == b.sRight && a.prev == b.prev && a.next == b.next &&
         a.edge == b.edge;
}

void expectSameAsOneDartAtATime(const TopoDS_Shape& solid, const std::string& what) {
  const tbb::global_control allowThreads(tbb::global_control::max_allowed_parallelism, kThreads);
  tbb::task_arena oneThread(1), threads(kThreads);
  SamplingParams reference;
  reference.oneDartAtATime = true;
  const SampleSet serial = sampleIn(oneThread, solid, reference);
  const SampleSet parallel = sampleIn(threads, solid, SamplingParams{});
  ASSERT_GT(serial.size(), 1000u) << what;
  ASSERT_EQ(serial.size(), parallel.size()) << what;
  Index differing = 0;
  for (Index i = 0; i < serial.size(); ++i)
    if (serial.points[i] != parallel.points[i] || serial.kind[i] != parallel.kind[i] ||
        serial.owner[i] != parallel.owner[i] || serial.onConvexEdge[i] != parallel.onConvexEdge[i] ||
        serial.isNonConcaveCorner[i] != parallel.isNonConcaveCorner[i])
      ++differing;
  EXPECT_EQ(differing, 0u) << what << ": samples differ between one dart at a time and " << kThreads
                           << " threads";
  EXPECT_EQ(serial.triangles, parallel.triangles) << what;
  ASSERT_EQ(serial.triplets.size(), parallel.triplets.size()) << what;
  std::size_t tripletsDiffering = 0;
  for (std::size_t i = 0; i < serial.triplets.size(); ++i)
    if (!sameTriplet(serial.triplets[i], parallel.triplets[i])) ++tripletsDiffering;
  EXPECT_EQ(tripletsDiffering, 0u) << what;
}

// The flange: bolt holes (faces with inner wires, convex edges grading
// their faces) and a thin wall probed by rays.
TEST(ParallelSampling, FlangeSamplesAreThoseOfOneDartAtATime) {
  const LoadedModel model = loadModel(test::bundledPath(test::bundledModel("flange")));
  expectSameAsOneDartAtATime(model.solids.at(0), "flange");
}

// A torus as a rational B-spline of several spans each way: OCCT's
// B-spline adaptors cache one span, so threads sharing one adaptor would
// read a span another thread just cached.
TEST(ParallelSampling, BSplineFacesSampleAsOneDartAtATime) {
  const LoadedModel model = loadModel(test::bundledPath(test::bundledModel("torus")));
  BRepBuilderAPI_NurbsConvert convert(model.solids.at(0), true);
  ASSERT_TRUE(convert.IsDone());
  expectSameAsOneDartAtATime(convert.Shape(), "torus as a B-spline");
}

// Narrow faces (narrow_faces.cpp, in parallel over faces): a 0.5 mm step on
// a block's top and a hole 0.3 mm from a plate's side.
TEST(ParallelSampling, NarrowFacesSampleAsOneDartAtATime) {
  const TopoDS_Shape step = BRepAlgoAPI_Fuse(BRepPrimAPI_MakeBox(100, 100, 50).Shape(),
                                             BRepPrimAPI_MakeBox(gp_Pnt(0, 0, 50), 50, 100, 0.5).Shape())
                                .Shape();
  expectSameAsOneDartAtATime(step, "step");
  const TopoDS_Shape plate =
      BRepAlgoAPI_Cut(BRepPrimAPI_MakeBox(100, 60, 10).Shape(),
                      BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(50, 10.3, 0), gp_Dir(0, 0, 1)), 10, 10).Shape())
          .Shape();
  expectSameAsOneDartAtATime(plate, "plate with a hole near its side");
}

}  // namespace
}  // namespace cadmedial
