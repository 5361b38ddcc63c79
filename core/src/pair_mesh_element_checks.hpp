// Private to the pair-mesh repair: what counts as an element to repair.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <vector>

#include "cadmedial/sample_set.hpp"

namespace cadmedial {

// Inverted (negative orientation, CGAL's exact predicate), or flat with four
// distinct corners: the iso-surface cut of such an element is a flat fin
// lying on its neighbours' cuts, which crosses them. Flat elements with two
// coincident corners (welded Voronoi nodes) cut to nothing and are fine.
bool elementNeedsRepair(const std::vector<Vec3>& nodes, const std::array<Index, 4>& tet);

// flags[i] = elementNeedsRepair for the elements i >= first (in parallel;
// flags is resized to one entry per element, those before `first` kept):
// the whole mesh with first = 0, or the elements an edit appended.
void flagElementsNeedingRepair(const std::vector<Vec3>& nodes, const std::vector<std::array<Index, 4>>& tets,
                               std::vector<std::uint8_t>& flags, std::size_t first = 0);

// Elements needing repair among `tets`.
std::size_t countElementsNeedingRepair(const std::vector<Vec3>& nodes, const std::vector<std::array<Index, 4>>& tets);

// How many of 0 .. count-1 pass `test` (in parallel: these scans run over
// every element several times per repair).
std::size_t countElements(std::size_t count, const std::function<bool(std::size_t)>& test);

// Those of 0 .. count-1 that pass `test`, in increasing order (tested in
// parallel).
std::vector<std::size_t> selectElements(std::size_t count, const std::function<bool(std::size_t)>& test);

// Two corners at the same position (welded Voronoi nodes): exactly flat.
// Tested before an orientation predicate, which would go to exact
// arithmetic on every such element.
bool hasCoincidentCorners(const std::vector<Vec3>& nodes, const std::array<Index, 4>& tet);

// Signed volume of the tetrahedron (positive = valid orientation), in doubles.
double signedTetVolume(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d);

}  // namespace cadmedial
