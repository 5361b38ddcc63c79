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

}  // namespace cadmedial
