#include "topology_check.hpp"

#include <cstdio>

namespace cadmedial {

std::string topologyMismatchWarning(const ComplexTopology& axis, const SolidBetti& solid, double spacing) {
  const bool beta1Known = axis.beta1 >= 0 && solid.beta1 >= 0;
  // β2 (enclosed voids) is known whenever β1 is computed; the axis of a solid with a
  // void surrounds it once, and a second bubble (a sub-spacing void) is as
  // wrong as a loop too many: eval's topology verdict compares it too.
  const bool beta2Differs = beta1Known && axis.beta2 >= 0 && axis.beta2 != solid.beta2;
  if (axis.beta0 == solid.beta0 && (!beta1Known || axis.beta1 == solid.beta1) && !beta2Differs) return {};
  char axisBetti[72], solidBetti[72];
  const char* names = "beta0";
  if (beta2Differs) {
    names = "beta0,beta1,beta2";
    std::snprintf(axisBetti, sizeof axisBetti, "%lld,%lld,%lld", axis.beta0, axis.beta1, axis.beta2);
    std::snprintf(solidBetti, sizeof solidBetti, "%lld,%lld,%lld", solid.beta0, solid.beta1, solid.beta2);
  } else if (beta1Known) {
    names = "beta0,beta1";
    std::snprintf(axisBetti, sizeof axisBetti, "%lld,%lld", axis.beta0, axis.beta1);
    std::snprintf(solidBetti, sizeof solidBetti, "%lld,%lld", solid.beta0, solid.beta1);
  } else {
    std::snprintf(axisBetti, sizeof axisBetti, "%lld", axis.beta0);
    std::snprintf(solidBetti, sizeof solidBetti, "%lld", solid.beta0);
  }
  char line[480];
  std::snprintf(line, sizeof line,
                "the axis has %s %s where the solid has %s: a feature may be finer than the spacing %.4g resolves (a "
                "small hole or void, a thin wall, a nearly flat edge); a spacing of %.4g or finer may resolve it",
                names, axisBetti, solidBetti, spacing, spacing / 2);
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
