#pragma once

#include <string>
#include <vector>

#include "cadmedial/medial_params.hpp"

namespace cadmedial {

struct RunCommandOptions {
  std::string model;
  std::string outDir;
  double spacing = 0;
  bool gradedSpacing = true;    // SamplingParams::gradedSpacing
  MedialParams params = MedialParams::cad();
  bool checkWithOracle = true;  // count walk-vs-exact-classifier disagreements
  bool thetaGiven = false;      // else point clouds / meshes use MedialParams::pointCloud()'s θ
  bool pairMesh = false;        // also build the pair-mesh (B-rep inputs only)
  std::vector<double> isoValues{0.5};  // iso-parametric surfaces written with the pair-mesh
};

// `cadmedial run`: per solid, medial.ply, medial.obj, medial.ma and
// summary.json under OUTDIR/solid_<i>/, and a summary line on stdout; with
// pairMesh also pairmesh.vtu, pairmesh.node/.ele and iso_<t>.ply.
// Point clouds and meshes (point_input.hpp) go to runPointMedialCommand.
int runRunCommand(const RunCommandOptions& options);

}  // namespace cadmedial
