// `cadmedial eval MODEL -o OUTDIR`: measures each solid's medial axis
// (OUTDIR/solid_<i>/medial.ply, written by `cadmedial run`) against the exact
// B-rep (DESIGN.md §6), writes OUTDIR/solid_<i>/eval.json and prints a table.
#pragma once

#include <cstdio>
#include <string>

#include <nlohmann/json.hpp>

#include "cadmedial/medial_evaluation.hpp"

namespace cadmedial {

struct EvalCommandOptions {
  std::string model;
  std::string outDir;
  double tolerance = 0.005;  // tol as a fraction of the bounding-box diagonal
  bool strict = false;       // exit code 1 when a solid fails a threshold
  bool quiet = false;        // no table on stdout
};

// Returns the exit code. Throws InputError: model unreadable / without solid
// (from loadModel), a missing or malformed medial.ply (kExitUnreadableInput,
// checked for every solid before any work), outputs not writable.
int runEvalCommand(const EvalCommandOptions& options);

nlohmann::json toJson(const EvaluationReport& report);

// Fixed-width table: one header, one row per solid.
void printEvaluationHeader(std::FILE* out);
void printEvaluationRow(std::FILE* out, const std::string& solid, const EvaluationReport& report);

}  // namespace cadmedial
