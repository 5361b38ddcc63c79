#pragma once

#include "run_command.hpp"

namespace cadmedial {

// `cadmedial run` on a point cloud or a triangle mesh (point_input.hpp):
// MEDIAL (seed 000) on the points, OUTDIR/solid_0/{medial.ply, medial.obj,
// medial.ma, summary.json} as for CAD models. Closed, consistently oriented
// meshes give the inner axis; point clouds and other meshes the whole axis
// (summary.json "axis" and stdout say which).
int runPointMedialCommand(const RunCommandOptions& options);

}  // namespace cadmedial
