#include "point_input.hpp"

#include <CGAL/IO/polygon_soup_io.h>
#include <CGAL/Polygon_mesh_processing/repair_polygon_soup.h>
#include <CGAL/Simple_cartesian.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "cadmedial/errors.hpp"

namespace cadmedial {

namespace {

std::string lowerExtension(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  return ext.empty() ? ext : ext.substr(1);
}

[[noreturn]] void fail(const std::string& path, const std::string& what) {
  throw InputError(kExitUnreadableInput, path + ": " + what);
}

// x y z per line; '#' comments and blank lines skipped; further columns
// (normals, intensity, colour) ignored. CGAL's read_XYZ takes a 4th column
// as the start of a normal and fails on the intensity column of .pts files,
// hence this reader.
void readXyzText(const std::string& path, PointInput& in) {
  std::ifstream file(path);
  if (!file) fail(path, "cannot open the file");
  std::string line;
  std::size_t lineNo = 0, declared = 0;
  bool firstData = true;
  while (std::getline(file, line)) {
    ++lineNo;
    const auto start = line.find_first_not_of(" \t\r");
    if (start == std::string::npos || line[start] == '#') continue;
    std::istringstream fields(line);
    std::vector<std::string> tokens;
    for (std::string t; fields >> t;) tokens.push_back(t);
    if (firstData && tokens.size() == 1) {  // the point count of .pts / some .xyz files
      firstData = false;
      try {
        std::size_t used = 0;
        const long long n = std::stoll(tokens[0], &used);
        if (used != tokens[0].size() || n < 0) throw std::invalid_argument("");
        declared = static_cast<std::size_t>(n);
        continue;
      } catch (const std::exception&) {
        fail(path, "line " + std::to_string(lineNo) + ": expected x y z, got '" + tokens[0] + "'");
      }
    }
    firstData = false;
    if (tokens.size() < 3) fail(path, "line " + std::to_string(lineNo) + ": expected x y z");
    Vec3 p;
    for (int k = 0; k < 3; ++k) {
      std::size_t used = 0;
      try {
        p[k] = std::stod(tokens[k], &used);
      } catch (const std::exception&) {
        used = 0;
      }
      if (used != tokens[k].size())
        fail(path, "line " + std::to_string(lineNo) + ": '" + tokens[k] + "' is not a number");
    }
    in.points.push_back(p);
  }
  if (file.bad()) fail(path, "read error");
  if (declared > 0 && declared != in.points.size())
    in.warnings.push_back("the header announces " + std::to_string(declared) + " points, the file holds " +
                          std::to_string(in.points.size()));
}

void readPolygonSoup(const std::string& path, PointInput& in) {
  using Point = CGAL::Simple_cartesian<double>::Point_3;
  std::vector<Point> points;
  std::vector<std::vector<std::size_t>> polygons;
  bool ok = false;
  try {
    ok = CGAL::IO::read_polygon_soup(path, points, polygons);
  } catch (const std::exception& e) {
    fail(path, std::string("not a readable ") + in.format + " file (" + e.what() + ")");
  }
  if (!ok || points.empty()) fail(path, "not a readable " + in.format + " file (no points found)");
  // OBJ/OFF/PLY exporters often repeat a vertex per face; welding equal
  // points keeps a closed mesh closed (the samples are the distinct points).
  if (!polygons.empty()) {
    for (const auto& poly : polygons)
      for (std::size_t v : poly)
        if (v >= points.size())
          fail(path, "a face refers to vertex " + std::to_string(v) + " of " + std::to_string(points.size()));
    const std::size_t merged = CGAL::Polygon_mesh_processing::merge_duplicate_points_in_polygon_soup(points, polygons);
    if (merged > 0 && in.format != "stl")
      in.warnings.push_back(std::to_string(merged) + " repeated vertices welded");
  }
  in.points.reserve(points.size());
  for (const Point& p : points) in.points.push_back({p.x(), p.y(), p.z()});
  std::size_t small = 0;
  for (const auto& poly : polygons) {
    if (poly.size() < 3) {
      ++small;
      continue;
    }
    for (std::size_t k = 1; k + 1 < poly.size(); ++k)  // fan: keeps the polygon's orientation
      in.triangles.push_back({static_cast<Index>(poly[0]), static_cast<Index>(poly[k]), static_cast<Index>(poly[k + 1])});
  }
  if (small > 0) in.warnings.push_back(std::to_string(small) + " faces with fewer than 3 vertices ignored");
  in.isMesh = !in.triangles.empty();
}

}  // namespace

bool isPointInputPath(const std::string& path) {
  static const char* kExtensions[] = {"xyz", "pts", "ply", "stl", "obj", "off"};
  const std::string ext = lowerExtension(path);
  return std::find(std::begin(kExtensions), std::end(kExtensions), ext) != std::end(kExtensions);
}

PointInput readPointInput(const std::string& path) {
  PointInput in;
  in.path = path;
  in.format = lowerExtension(path);
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) fail(path, "no such file");
  if (std::filesystem::file_size(path, ec) == 0) fail(path, "the file is empty");
  if (in.format == "xyz" || in.format == "pts") readXyzText(path, in);
  else readPolygonSoup(path, in);  // CGAL reads .stl/.obj/.off/.ply (ASCII and binary), case-insensitive
  for (std::size_t i = 0; i < in.points.size(); ++i)
    for (double c : in.points[i])
      if (!std::isfinite(c)) fail(path, "point " + std::to_string(i) + " has a non-finite coordinate");
  if (in.points.size() < 4)
    fail(path, "holds " + std::to_string(in.points.size()) + " points; a medial axis needs at least 4");
  if (in.points.size() >= kNoIndex) fail(path, "too many points for 32-bit indices");
  return in;
}

}  // namespace cadmedial
