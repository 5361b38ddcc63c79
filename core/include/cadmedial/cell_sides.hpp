// Which side of the sampled surface each Voronoi vertex lies on, from the
// samples alone (no OCCT): used to keep the inner/outer walk from leaking
// through facets that straddle the surface where the sampling is coarse.
#pragma once

#include <cstdint>
#include <vector>

#include "cadmedial/delaunay.hpp"
#include "cadmedial/sample_set.hpp"

namespace cadmedial {

// Per sample: area-weighted outward normal of its umbrella (zero if none).
std::vector<Vec3> outwardSampleNormals(const SampleSet& samples);

// Per cell id: 1 if the cell's circumcenter lies inside the sampled surface.
// With a closed, manifold reconstruction: CGAL's point-in-mesh test on it.
// Otherwise a majority vote of the tangent planes at the cell's samples,
// sign((c - p_i) · n_i) (the empty ball touches the surface there); ties,
// infinite cells, centres outside the bounding box and radii above half its
// diagonal count as outside.
// wanted (optional, per cell id): only cells with wanted[id] != 0 are tested,
// the others are left 0 - the walk only looks at cells on selected facets'
// rings, and the point-in-mesh test is the costly part.
std::vector<std::uint8_t> classifyCellSides(const DelaunayVoronoi& dv, const SampleSet& samples,
                                            const std::vector<Vec3>& normals,
                                            const std::vector<std::uint8_t>* wanted = nullptr);

}  // namespace cadmedial
