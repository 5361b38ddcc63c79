// Which side of the sampled surface each Voronoi vertex lies on, from the
// samples alone (no OCCT): used to keep the inner/outer walk from leaking
// through facets that straddle the surface where the sampling is coarse.
#pragma once

#include <cstdint>
#include <memory>
#include <mutex>
#include <vector>

#include "cadmedial/delaunay.hpp"
#include "cadmedial/reconstruction_sides.hpp"
#include "cadmedial/sample_set.hpp"
#include "cadmedial/surface_mesh_checks.hpp"

namespace cadmedial {

namespace soup {
struct SoupTree;
}

// Per sample: area-weighted outward normal of its umbrella (zero if none).
std::vector<Vec3> outwardSampleNormals(const SampleSet& samples);

// Where a Voronoi vertex (cell circumcenter) lies relative to the sampled surface.
enum CellSide : std::uint8_t {
  kCellOutside = 0,      // outside, farther than the tolerance from the surface
  kCellInside = 1,       // inside
  kCellNearOutside = 2,  // outside but within the tolerance (chord error of the reconstruction)
  kCellNearInside = 3,   // inside but within the tolerance (only when asked for: markNearInside)
};

// True when no ball inside the solid can be this cell's empty ball: an
// inner ball fits in the samples' bounding box, so a radius above half its
// diagonal or a centre outside the box grown by `pad` is outside whatever
// else says (far centres of slivers and flat cells over the hull, ~1e15 away).
bool beyondSampledSolid(const DelaunayVoronoi& dv, const SampleSet& samples, Index cell, double pad);

// Per cell id, a CellSide. With a closed, manifold reconstruction: CGAL's
// point-in-mesh test on it, and the distance to it for centres outside.
// Otherwise a majority vote of the tangent planes at the cell's samples,
// sign((c - p_i) · n_i) (the empty ball touches the surface there), and no
// "near" class; ties, infinite cells, centres outside the bounding box and
// radii above half its diagonal count as outside.
// nearTolerance: outside centres closer than this to the reconstruction are
// kCellNearOutside (inner Voronoi vertices near curved convex faces can lie
// between the chords and the true surface).
// wanted (optional, per cell id): only cells with wanted[id] != 0 are tested,
// the others are left kCellOutside - the walk and the relabel only look at
// cells on selected facets' rings, and the point-in-mesh test is the costly part.
std::vector<std::uint8_t> classifyCellSides(const DelaunayVoronoi& dv, const SampleSet& samples,
                                            const std::vector<Vec3>& normals, double nearTolerance = 0,
                                            const std::vector<std::uint8_t>* wanted = nullptr,
                                            bool markNearInside = false);

// What classifyCellSides needs from the samples alone: the outward normals
// and, when the reconstruction is a closed manifold, its point-in-mesh tree
// (the surface check and the tree build are ~2 s at 10^6 samples). It needs
// no triangulation, so a caller can build it while the Delaunay runs.
// `surface`, if given, is checkSurfaceMesh of the samples' points and
// triangles, which the sampling has made already (1.2 s of CPU at 10^6
// samples to make again).
struct CellSideInputs {
  explicit CellSideInputs(const SampleSet& samples, const SurfaceMeshStats* surface = nullptr);
  CellSideInputs(const SampleSet& samples, std::vector<Vec3> normals, const SurfaceMeshStats* surface = nullptr);
  ~CellSideInputs();
  CellSideInputs(const CellSideInputs&) = delete;
  CellSideInputs& operator=(const CellSideInputs&) = delete;

  std::vector<Vec3> normals;              // outwardSampleNormals
  std::unique_ptr<soup::SoupTree> mesh;   // null unless the reconstruction is closed and manifold

  // Whether reconstructionSides(dv, inputs, ...) keeps the cells' link
  // groups it makes (reconstruction_sides.hpp) for the next question on the
  // same dv. Set by a caller that asks twice: `run --pair-mesh` (the
  // CAD_MEDIAL cell sides, then the pair-mesh labels). Off by default: the
  // groups hold 4 bytes a cell (26 MB at 10^6 samples).
  bool keepLinks = false;

  // The link groups kept for dv; null when none are (not kept, not made
  // yet, or made on another Delaunay). One inputs object serves one
  // triangulation of its samples; the address and cell count tell another
  // one apart.
  std::shared_ptr<const ReconstructionLinks> links(const DelaunayVoronoi& dv) const;
  void keep(const DelaunayVoronoi& dv, ReconstructionLinks links) const;

 private:
  mutable std::mutex linksMutex_;
  mutable const DelaunayVoronoi* linksOf_ = nullptr;
  mutable std::shared_ptr<const ReconstructionLinks> links_;
};

// reconstructionSides (reconstruction_sides.hpp) on inputs built from the
// same samples, with their tree and the link groups they keep for dv (made
// here, and kept when inputs.keepLinks, if they have none); every cell
// kReconstructionSkipped when inputs.mesh is null (not closed).
ReconstructionSides reconstructionSides(const DelaunayVoronoi& dv, const CellSideInputs& inputs,
                                        const std::vector<double>& deviation,
                                        const std::vector<std::uint8_t>* wanted = nullptr);

// The same, on inputs built beforehand from the same samples.
std::vector<std::uint8_t> classifyCellSides(const DelaunayVoronoi& dv, const SampleSet& samples,
                                            const CellSideInputs& inputs, double nearTolerance = 0,
                                            const std::vector<std::uint8_t>* wanted = nullptr,
                                            bool markNearInside = false);

}  // namespace cadmedial
