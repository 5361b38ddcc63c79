// Every set=dev public model samples and reconstructs without error.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "cadmedial/brep_io.hpp"
#include "cadmedial/sampling.hpp"
#include "model_fixtures.hpp"

namespace cadmedial {
namespace {

TEST(PublicModels, DevSetSamplesAndReconstructsClosedSurfaces) {
  const auto files = test::publicModels("set=dev");
  if (files.empty()) GTEST_SKIP() << "../shared/models/public not present";
  std::printf("%-36s %5s %8s %8s %6s %7s %7s %8s\n", "model", "solid", "samples", "triplets", "euler", "area%",
              "vol%", "seconds");
  for (const std::string& f : files) {
    const LoadedModel model = loadModel(test::publicModelsDir() + "/" + f);
    for (std::size_t i = 0; i < model.solids.size(); ++i) {
      const SolidSampling result = sampleSolid(model.solids[i]);
      const SamplingReport& r = result.report;
      std::printf("%-36s %5zu %8zu %8zu %6ld %7.3f %7.3f %8.3f\n", f.c_str(), i, result.samples.size(), r.triplets,
                  r.surface.eulerCharacteristic, 100 * (r.surface.area / r.exactArea - 1),
                  100 * (r.surface.enclosedVolume / r.exactVolume - 1),
                  r.secondsClassify + r.secondsSample + r.secondsReconstruct);
      EXPECT_EQ(r.facesFailed, 0) << f;
      EXPECT_TRUE(r.surface.closedManifold()) << f;
      EXPECT_EQ(r.surface.components, 1u) << f;
      EXPECT_LT(std::abs(r.surface.area / r.exactArea - 1), 0.01) << f;
    }
  }
}

}  // namespace
}  // namespace cadmedial
