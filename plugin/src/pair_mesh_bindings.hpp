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

#include "pair_mesh_stage.hpp"

namespace cadmedial {

// Runs without the GIL: exact labels, build, repair, check; the CLI's own
// stage (cli/pair_mesh_stage.hpp), without files.
using PairMeshRun = PairMeshStage;

// GIL held: nodes, node_is_boundary, tets, types, on_sheets,
// boundary_triangles (numpy) and report (dict).
pybind11::dict pairMeshToDict(const PairMeshRun& run);

// iso_surface(nodes, tets, types, t) and write_pair_mesh(path, format, ...).
void registerPairMeshFunctions(pybind11::module_& m);

}  // namespace cadmedial
