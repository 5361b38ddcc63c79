#include "topology_check.hpp"

#include <cstdio>

namespace cadmedial {

std::string topologyMismatchWarning(const ComplexTopology& axis, const SolidBetti& solid, double spacing) {
  const bool beta1Known = axis.beta1 >= 0 && solid.beta1 >= 0;
  if (axis.beta0 == solid.beta0 && (!beta1Known || axis.beta1 == solid.beta1)) return {};
  char axisBetti[48], solidBetti[48];
  if (beta1Known) {
    std::snprintf(axisBetti, sizeof axisBetti, "%lld,%lld", axis.beta0, axis.beta1);
    std::snprintf(solidBetti, sizeof solidBetti, "%lld,%lld", solid.beta0, solid.beta1);
  } else {
    std::snprintf(axisBetti, sizeof axisBetti, "%lld", axis.beta0);
    std::snprintf(solidBetti, sizeof solidBetti, "%lld", solid.beta0);
  }
  char line[320];
  std::snprintf(line, sizeof line,
                "the axis has %s %s where the solid has %s: a feature is finer than the spacing %.4g resolves (a "
                "small hole, a thin wall, a nearly flat edge); a spacing of %.4g or finer may resolve it",
                beta1Known ? "beta0,beta1" : "beta0", axisBetti, solidBetti, spacing, spacing / 2);
  return line;
}

std::string recordSolidTopology(nlohmann::json& summary, const TopoDS_Shape& solid, const ComplexTopology& axis,
                                double spacing) {
  const SolidBetti betti = solidBettiNumbers(solid);
  summary["topology"]["solid"] = {{"beta0", betti.beta0}, {"beta1", betti.beta1}, {"beta2", betti.beta2}};
  std::string warning = topologyMismatchWarning(axis, betti, spacing);
  summary["topology"]["warning"] = warning;
  return warning;
}

}  // namespace cadmedial
