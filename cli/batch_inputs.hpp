// The files a `cadmedial batch` works on, and where each one's outputs go.
#pragma once

#include <string>
#include <vector>

namespace cadmedial {

struct BatchInput {
  std::string path;    // absolute path of the model file (not checked: `run` reports a missing file)
  std::string output;  // folder under OUTDIR for its outputs, also its identity in results.jsonl
};

// True for .step .stp .iges .igs .brep in any case: the files a folder contributes.
bool isCadFileName(const std::string& name);

// Expands the command-line INPUTs in order, dropping repeated files:
//  * a folder: every CAD file below it (recursive, sorted, hidden entries and
//    `skipFolder` left out); output = path relative to that folder;
//  * `@FILE`, `*.txt`, `*.lst`: a manifest, one path per line (blank lines and
//    `#` comments skipped, relative lines resolved against the manifest's
//    folder, folders expanded as above); output = path relative to the
//    manifest's folder;
//  * anything else is a model file, even if missing or oddly named, so that it
//    gets its own error record; output = path relative to the working folder.
// A path outside its base keeps its absolute path minus the leading '/'.
// Throws InputError(kExitUsage) for an unreadable manifest, no files at all,
// or two files that would share an output folder.
std::vector<BatchInput> collectBatchInputs(const std::vector<std::string>& arguments, const std::string& skipFolder);

}  // namespace cadmedial
