// Outputs are written under a temporary name and renamed when complete, so a
// killed run never leaves a half-written file that looks finished.
#pragma once

#include <fstream>
#include <functional>
#include <string>

namespace cadmedial {

// Calls write(stream) on a temporary file next to `path`, then renames it to
// `path`. Throws InputError(kExitOutputFailed) if anything fails; the
// temporary file is removed on failure.
void writeFileAtomically(const std::string& path, const std::function<void(std::ofstream&)>& write,
                         bool binary = false);

// Creates the output folder `dir` and its parents if missing. Throws
// InputError(kExitOutputFailed) with one line when it cannot (no
// permission, a file in the way, a read-only file system), so an unwritable
// -o says so with the documented exit code (before any work for -o itself;
// a solid_<i> folder in the way is found when that solid is written).
void createOutputDirectory(const std::string& dir);

}  // namespace cadmedial
