// CGAL (core) headers before OCCT's (medial_ply_io pulls in sampling/).
#include "medial_outputs.hpp"

#include <tbb/parallel_invoke.h>

#include "atomic_file.hpp"
#include "medial_mesh_conversion.hpp"
#include "medial_ply_io.hpp"
#include "medial_writers.hpp"

namespace cadmedial {

void writeMedialFiles(const std::string& dir, const MedialComplex& medial) {
  // The files are independent: format and write them side by side (each is
  // still written to a temporary name and renamed). OBJ and .ma share their
  // vertex lines' numbers; if .ma fails, neither is kept.
  tbb::parallel_invoke([&] { writeMedialPlyFile(dir + "/medial.ply", toMedialMesh(medial)); },
                       [&] {
                         writeFileAtomically(dir + "/medial.obj", [&](std::ofstream& obj) {
                           writeFileAtomically(dir + "/medial.ma",
                                               [&](std::ofstream& ma) { writeMedialObjAndMa(obj, ma, medial); });
                         });
                       });
}

}  // namespace cadmedial
