// CGAL (core) headers before OCCT's (medial_ply_io pulls in sampling/).
#include "medial_outputs.hpp"

#include <tbb/parallel_invoke.h>

#include "atomic_file.hpp"
#include "medial_mesh_conversion.hpp"
#include "medial_ply_io.hpp"
#include "medial_writers.hpp"

#include "cadmedial/errors.hpp"

namespace cadmedial {

void writeMedialFiles(const std::string& dir, const MedialComplex& medial) {
  // The files are independent: format and write them side by side (each is
  // still written to a temporary name and renamed). OBJ and .ma share their
  // vertex lines' numbers, so one task writes both; the .ma is renamed into
  // place only once the OBJ's text is all written and flushed.
  tbb::parallel_invoke([&] { writeMedialPlyFile(dir + "/medial.ply", toMedialMesh(medial)); },
                       [&] {
                         writeFileAtomically(dir + "/medial.obj", [&](std::ofstream& obj) {
                           writeFileAtomically(dir + "/medial.ma", [&](std::ofstream& ma) {
                             writeMedialObjAndMa(obj, ma, medial);
                             obj.flush();
                             if (!obj)
                               throw InputError(kExitOutputFailed, "write failed for " + dir + "/medial.obj (disk full?)");
                           });
                         });
                       });
}

}  // namespace cadmedial
