// Pair-mesh (DESIGN.md §5) for cadmedial._native: the CLI's pair-mesh stage
// (exact inner labels, construction, repair, validity against the exact
// volume) without the files, and the results as numpy arrays.
//
// CGAL (core) headers before OCCT's: OCCT's Handle macro breaks CGAL.
#pragma once

#include "cadmedial/medial.hpp"
#include "cadmedial/pair_mesh.hpp"

#include <pybind11/pybind11.h>

#include <TopoDS_Shape.hxx>
#include <nlohmann/json.hpp>

namespace cadmedial {

struct PairMeshRun {
  PairMesh mesh;
  nlohmann::json report;  // pairMeshReport + repair counts + seconds
};

// Runs without the GIL: classifies the cells of `dv` with OCCT's exact
// classifier, builds and repairs the pair-mesh and checks it.
PairMeshRun runPairMesh(const DelaunayVoronoi& dv, const SampleSet& samples, const TopoDS_Shape& solid,
                        const MedialComplex& axis);

// GIL held: nodes, node_is_boundary, tets, types, on_sheets,
// boundary_triangles (numpy) and report (dict).
pybind11::dict pairMeshToDict(const PairMeshRun& run);

// iso_surface(nodes, tets, types, t) and write_pair_mesh(path, format, ...).
void registerPairMeshFunctions(pybind11::module_& m);

}  // namespace cadmedial
