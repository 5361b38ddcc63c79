#pragma once

#include <string>

namespace cadmedial {

struct SampleCommandOptions {
  std::string model;
  std::string outDir;
  double spacing = 0;
  bool gradedSpacing = true;  // SamplingParams::gradedSpacing
  bool quiet = false;
};

// `cadmedial sample`: per solid, samples.ply, boundary.ply and sampling.json
// under OUTDIR/solid_<i>/, and a summary on stdout. Returns the exit code.
int runSampleCommand(const SampleCommandOptions& options);

}  // namespace cadmedial
