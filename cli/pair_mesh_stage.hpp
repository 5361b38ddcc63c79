// The pair-mesh step of `cadmedial run --pair-mesh` and its report in
// `cadmedial eval`: exact inner labels (OCCT classifier), construction,
// repair, validity against the exact solid volume, files.
#pragma once

// CGAL (core) headers before OCCT's.
#include "cadmedial/medial.hpp"
#include "cadmedial/pair_mesh.hpp"

#include <string>
#include <vector>

#include <TopoDS_Shape.hxx>
#include <nlohmann/json.hpp>

namespace cadmedial {

// A pair-mesh passes when it is a valid partition (PairMeshValidity::valid)
// and its enclosed volume is within this fraction of the exact solid volume.
constexpr double kPairMeshVolumeTolerance = 0.01;

// Exact inner labels, construction, repair and report (no files): the
// shared part of `run --pair-mesh` and the Python module.
struct PairMeshStage {
  PairMesh mesh;
  nlohmann::json report;  // pairMeshReport + labels, repair counts, times
};
// prepared: the CAD_MEDIAL run's cell-side inputs on the same samples and dv,
// if it made them (their tree and link groups serve the labels too).
PairMeshStage buildPairMeshStage(const DelaunayVoronoi& dv, const SampleSet& samples, const TopoDS_Shape& solid,
                                 const MedialComplex& axis, const CellSideInputs* prepared = nullptr);

// Writes pairmesh.vtu, pairmesh.node/.ele and iso_<t>.ply for each t into
// dir; adds "iso_files" and seconds.write to stage.report.
void writePairMeshFiles(PairMeshStage& stage, const std::vector<double>& isoValues, const std::string& dir);

// Validity, exact volume and verdict of a pair-mesh ("pair_mesh" in
// summary.json and eval.json).
nlohmann::json pairMeshReport(const PairMesh& mesh, const TopoDS_Shape& solid);

}  // namespace cadmedial
