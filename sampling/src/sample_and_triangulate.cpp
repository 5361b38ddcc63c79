#include "cadmedial/sample_and_triangulate.hpp"

#include <future>
#include <stdexcept>
#include <system_error>
#include <vector>

namespace cadmedial {

TriangulatedSamples sampleAndTriangulate(const TopoDS_Shape& solid, const SamplingParams& params,
                                         bool prepareCellSides) {
  TriangulatedSamples out;
  std::future<std::unique_ptr<DelaunayVoronoi>> triangulation;
  out.sampled = sampleSolid(solid, params, [&](const std::vector<Vec3>& points) {
    auto triangulate = [points] { return std::make_unique<DelaunayVoronoi>(points); };
    try {
      triangulation = std::async(std::launch::async, triangulate);
    } catch (const std::system_error&) {  // no thread to spare: triangulate when asked
      triangulation = std::async(std::launch::deferred, triangulate);
    }
  });
  if (!triangulation.valid()) throw std::logic_error("sampling did not hand over its points");
  out.sampled.samples.validate();
  out.prepared =
      std::make_unique<PreparedSamples>(out.sampled.samples, prepareCellSides, &out.sampled.report.surface);
  out.triangulation = triangulation.get();
  return out;
}

}  // namespace cadmedial
