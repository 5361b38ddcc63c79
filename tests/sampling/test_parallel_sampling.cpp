// The spacing fields and the face darts run on TBB threads (edge_sampling.cpp,
// narrow_faces.cpp, face_sampling.cpp). The samples must be the same on one
// thread as on all of them, down to the last bit: each thread has its own ray
// intersector, surface adaptor and UV classifier, and the darts of a batch
// are kept in the order they were thrown.
#include <gtest/gtest.h>

#include <string>

#include <BRepBuilderAPI_NurbsConvert.hxx>
#include <tbb/task_arena.h>

#include "cadmedial/brep_io.hpp"
#include "cadmedial/sampling.hpp"
#include "model_fixtures.hpp"

namespace cadmedial {
namespace {

SampleSet sampleIn(tbb::task_arena& arena, const TopoDS_Shape& solid) {
  SampleSet samples;
  arena.execute([&] { samples = sampleSolid(solid).samples; });
  return samples;
}

void expectSameSamples(const TopoDS_Shape& solid, const std::string& what) {
  tbb::task_arena oneThread(1), allThreads;
  const SampleSet serial = sampleIn(oneThread, solid);
  const SampleSet parallel = sampleIn(allThreads, solid);
  ASSERT_GT(serial.size(), 1000u) << what;
  ASSERT_EQ(serial.size(), parallel.size()) << what;
  Index differing = 0;
  for (Index i = 0; i < serial.size(); ++i)
    if (serial.points[i] != parallel.points[i] || serial.kind[i] != parallel.kind[i] ||
        serial.owner[i] != parallel.owner[i])
      ++differing;
  EXPECT_EQ(differing, 0u) << what << ": samples differ between one thread and " << allThreads.max_concurrency();
  EXPECT_EQ(serial.triangles, parallel.triangles) << what;
  EXPECT_EQ(serial.triplets.size(), parallel.triplets.size()) << what;
}

// The flange: bolt holes (faces with inner wires, convex edges grading
// their faces) and a thin wall probed by rays.
TEST(ParallelSampling, FlangeSamplesDoNotDependOnTheThreadCount) {
  const LoadedModel model = loadModel(test::bundledPath(test::bundledModel("flange")));
  expectSameSamples(model.solids.at(0), "flange");
}

// A torus as a rational B-spline of several spans each way: OCCT's
// B-spline adaptors cache one span, so threads sharing one adaptor would
// read a span another thread just cached.
TEST(ParallelSampling, BSplineFacesSampleTheSameOnAnyThreadCount) {
  const LoadedModel model = loadModel(test::bundledPath(test::bundledModel("torus")));
  BRepBuilderAPI_NurbsConvert convert(model.solids.at(0), true);
  ASSERT_TRUE(convert.IsDone());
  expectSameSamples(convert.Shape(), "torus as a B-spline");
}

}  // namespace
}  // namespace cadmedial
