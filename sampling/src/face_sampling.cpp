// Face interiors: Poisson-disk samples by dart throwing on the surface (area
// uniform), never a grid, kept clear of edge, corner and triplet samples.
#include <algorithm>
#include <cmath>
#include <random>

#include <BRepAdaptor_Surface.hxx>
#include <BRepGProp.hxx>
#include <BRepTools.hxx>
#include <BRepTopAdaptor_FClass2d.hxx>
#include <GProp_GProps.hxx>

#include "sampling_context.hpp"

namespace cadmedial {

namespace {
constexpr double kMinDistanceFraction = 0.75;  // Poisson radius = this × face spacing
constexpr double kDartsPerDisk = 12.0;         // candidates per expected sample
constexpr double kMaxDarts = 4e6;              // per face, to bound time on huge faces
}  // namespace

void sampleFaceInteriors(SamplingContext& ctx, SampleBuilder& builder, unsigned seed) {
  const SolidTopology& topo = ctx.topo;
  for (int f = 0; f < topo.faceCount(); ++f) {
    const TopoDS_Face& face = topo.face(f);
    const double radius = kMinDistanceFraction * ctx.faceSpacing[f];
    GProp_GProps props;
    BRepGProp::SurfaceProperties(face, props);
    const double area = props.Mass();
    if (!(area > 0)) continue;

    BRepAdaptor_Surface surf(face, true);
    double u0, u1, v0, v1;
    BRepTools::UVBounds(face, u0, u1, v0, v1);
    // Largest area element over the UV box, for rejection sampling.
    double maxJ = 0;
    constexpr int n = 12;
    for (int i = 0; i <= n; ++i)
      for (int j = 0; j <= n; ++j) {
        gp_Pnt p;
        gp_Vec su, sv;
        surf.D1(u0 + (u1 - u0) * i / n, v0 + (v1 - v0) * j / n, p, su, sv);
        maxJ = std::max(maxJ, su.Crossed(sv).Magnitude());
      }
    if (!(maxJ > 0)) continue;
    maxJ *= 1.5;

    BRepTopAdaptor_FClass2d classifier(face, 1e-9);
    std::mt19937_64 rng(seed * 1000003ull + static_cast<unsigned>(f));
    std::uniform_real_distribution<double> U(u0, u1), V(v0, v1), unit(0.0, 1.0);
    const double darts = std::min(kMaxDarts, kDartsPerDisk * area / (radius * radius));
    for (long k = 0; k < static_cast<long>(darts); ++k) {
      const double u = U(rng), v = V(rng);
      gp_Pnt p;
      gp_Vec su, sv;
      surf.D1(u, v, p, su, sv);
      if (unit(rng) * maxJ > su.Crossed(sv).Magnitude()) continue;
      if (!builder.isClear(p, radius)) continue;
      if (classifier.Perform(gp_Pnt2d(u, v)) != TopAbs_IN) continue;
      ctx.recordFaceUv(builder.add(p, SampleKind::Face, f, radius), gp_Pnt2d(u, v));
    }
  }
}

}  // namespace cadmedial
