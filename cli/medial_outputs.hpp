// The per-solid axis files of `cadmedial run` (medial.ply, medial.obj,
// medial.ma), each written atomically; shared by the CAD and point paths.
#pragma once

#include <string>

#include "cadmedial/polygon_complex.hpp"

namespace cadmedial {

void writeMedialFiles(const std::string& dir, const MedialComplex& medial);

}  // namespace cadmedial
