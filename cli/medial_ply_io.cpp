#include "medial_ply_io.hpp"

#include "number_text.hpp"
#include "record_writer.hpp"

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <sstream>
#include <vector>

#include "atomic_file.hpp"
#include "cadmedial/errors.hpp"

namespace cadmedial {

namespace {

constexpr const char* kVertexProperties[] = {"property double x", "property double y", "property double z",
                                             "property double radius"};
constexpr const char* kFaceProperties[] = {"property list uchar int vertex_indices", "property int sheet",
                                           "property uchar provenance"};
constexpr int kMaxProvenance = 4;

// Reads lines and numbers, and reports errors with the line number.
class Reader {
 public:
  Reader(std::istream& in, const std::string& name) : in_(in), name_(name) {}

  [[noreturn]] void fail(const std::string& what) const {
    throw InputError(kExitUnreadableInput, name_ + ": line " + std::to_string(line_) + ": " + what);
  }

  // Next line split into tokens; false at end of input.
  bool next(std::vector<std::string>& tokens) {
    std::string text;
    if (!std::getline(in_, text)) return false;
    ++line_;
    if (!text.empty() && text.back() == '\r') text.pop_back();
    tokens.clear();
    std::istringstream words(text);
    for (std::string w; words >> w;) tokens.push_back(w);
    return true;
  }
  void require(std::vector<std::string>& tokens, const char* what) {
    if (!next(tokens)) {
      ++line_;
      fail(std::string("file ends early, expected ") + what);
    }
  }

  double real(const std::string& token, const char* what) const {
    errno = 0;
    char* end = nullptr;
    const double value = std::strtod(token.c_str(), &end);
    if (end == token.c_str() || *end != '\0' || errno == ERANGE || !std::isfinite(value))
      fail(std::string("bad ") + what + " '" + token + "'");
    return value;
  }
  long long integer(const std::string& token, long long lo, long long hi, const char* what) const {
    errno = 0;
    char* end = nullptr;
    const long long value = std::strtoll(token.c_str(), &end, 10);
    if (end == token.c_str() || *end != '\0' || errno == ERANGE || value < lo || value > hi)
      fail(std::string("bad ") + what + " '" + token + "'");
    return value;
  }

 private:
  std::istream& in_;
  std::string name_;
  int line_ = 0;
};

std::string joined(const std::vector<std::string>& tokens) {
  std::string s;
  for (const std::string& t : tokens) s += (s.empty() ? "" : " ") + t;
  return s;
}

// Next header line that is not a comment.
std::string headerLine(Reader& r, std::vector<std::string>& tokens, const char* what) {
  do r.require(tokens, what);
  while (!tokens.empty() && (tokens[0] == "comment" || tokens[0] == "obj_info"));
  return joined(tokens);
}

std::size_t elementCount(Reader& r, std::vector<std::string>& tokens, const char* element) {
  const std::string expected = std::string("element ") + element;
  const std::string line = headerLine(r, tokens, expected.c_str());
  if (tokens.size() != 3 || tokens[0] != "element" || tokens[1] != element)
    r.fail("expected '" + expected + " <count>', found '" + line + "'");
  return static_cast<std::size_t>(r.integer(tokens[2], 0, std::numeric_limits<std::int32_t>::max(), "element count"));
}

void expectLine(Reader& r, std::vector<std::string>& tokens, const std::string& expected) {
  const std::string line = headerLine(r, tokens, expected.c_str());
  if (line != expected) r.fail("expected '" + expected + "', found '" + line + "'");
}

// PLY stores a face's corner count in a uchar: a polygon with more than 255
// corners (possible for Voronoi facets of cospherical samples) is written as
// a fan of pieces sharing its first corner, each with <= 255 corners. The
// pieces cover the same area, and the split adds as many edges as faces, so
// the Euler characteristic and Betti numbers do not change.
constexpr std::uint32_t kMaxCorners = 255;

std::uint32_t piecesOf(std::uint32_t corners) {
  return corners <= kMaxCorners ? 1 : 1 + (corners - kMaxCorners + (kMaxCorners - 2) - 1) / (kMaxCorners - 2);
}

}  // namespace

void writeMedialPly(std::ostream& out, const MedialMesh& mesh) {
  mesh.validate();
  std::size_t faces = 0;
  for (std::size_t i = 0; i < mesh.polygonCount(); ++i) faces += piecesOf(mesh.polygonOffsets[i + 1] - mesh.polygonOffsets[i]);
  // Numbers through std::to_chars (shortest text that reads back to the same
  // double): iostream / printf formatting was most of `run`'s write time.
  std::string text;
  text += "ply\nformat ascii 1.0\n"
          "comment cadmedial medial axis: radius = medial radius; provenance 0 Voronoi facet, 1 convex-edge "
          "triangle, 2 convex-edge fill, 3 corner triangle, 4 short hole closed\n"
          "element vertex ";
  appendInteger(text, mesh.vertices.size());
  text += '\n';
  for (const char* p : kVertexProperties) (text += p) += '\n';
  text += "element face ";
  appendInteger(text, faces);
  text += '\n';
  for (const char* p : kFaceProperties) (text += p) += '\n';
  text += "end_header\n";
  out << text;
  writeRecords(out, mesh.vertices.size(), [&](std::size_t v, std::string& line) {
    const auto& p = mesh.vertices[v];
    for (int k = 0; k < 3; ++k) {
      appendNumber(line, p[k]);
      line += ' ';
    }
    appendNumber(line, mesh.radius[v]);
    line += '\n';
  });
  writeRecords(out, mesh.polygonCount(), [&](std::size_t i, std::string& line) {
    const std::uint32_t b = mesh.polygonOffsets[i], e = mesh.polygonOffsets[i + 1];
    // Pieces: corners b, then [k, k + len) for consecutive windows overlapping by one corner.
    for (std::uint32_t k = b + 1; k + 1 < e;) {
      const std::uint32_t len = std::min<std::uint32_t>(kMaxCorners - 1, e - k);
      appendInteger(line, len + 1);
      line += ' ';
      appendInteger(line, mesh.polygonVertices[b]);
      for (std::uint32_t m = k; m < k + len; ++m) {
        line += ' ';
        appendInteger(line, mesh.polygonVertices[m]);
      }
      line += ' ';
      appendInteger(line, mesh.sheet[i]);
      line += ' ';
      appendInteger(line, static_cast<int>(mesh.provenance[i]));
      line += '\n';
      k += len - 1;
    }
  });
}

void writeMedialPlyFile(const std::string& path, const MedialMesh& mesh) {
  mesh.validate();  // before the file is opened, so a bad mesh leaves nothing behind
  writeFileAtomically(path, [&](std::ofstream& out) { writeMedialPly(out, mesh); });
}

MedialMesh readMedialPly(std::istream& in, const std::string& name) {
  Reader r(in, name);
  std::vector<std::string> tok;
  r.require(tok, "'ply'");
  if (joined(tok) != "ply") r.fail("not a PLY file (first line is not 'ply')");
  expectLine(r, tok, "format ascii 1.0");
  const std::size_t nv = elementCount(r, tok, "vertex");
  for (const char* p : kVertexProperties) expectLine(r, tok, p);
  const std::size_t nf = elementCount(r, tok, "face");
  for (const char* p : kFaceProperties) expectLine(r, tok, p);
  expectLine(r, tok, "end_header");

  MedialMesh mesh;
  mesh.vertices.reserve(nv);
  mesh.radius.reserve(nv);
  for (std::size_t v = 0; v < nv; ++v) {
    r.require(tok, "a vertex line");
    if (tok.size() != 4)
      r.fail("vertex " + std::to_string(v) + ": expected 4 numbers (x y z radius), found " + std::to_string(tok.size()));
    const double x = r.real(tok[0], "x"), y = r.real(tok[1], "y"), z = r.real(tok[2], "z");
    const double radius = r.real(tok[3], "radius");
    if (radius < 0) r.fail("vertex " + std::to_string(v) + ": negative radius");
    mesh.addVertex({x, y, z}, radius);
  }
  std::vector<std::uint32_t> corners;
  for (std::size_t f = 0; f < nf; ++f) {
    r.require(tok, "a face line");
    if (tok.empty()) r.fail("face " + std::to_string(f) + ": empty line");
    const std::size_t n = static_cast<std::size_t>(r.integer(tok[0], 3, 255, "corner count (3..255)"));
    if (tok.size() != n + 3)
      r.fail("face " + std::to_string(f) + ": expected " + std::to_string(n + 3) + " values (count, " +
             std::to_string(n) + " indices, sheet, provenance), found " + std::to_string(tok.size()));
    corners.clear();
    for (std::size_t k = 0; k < n; ++k)
      corners.push_back(static_cast<std::uint32_t>(r.integer(tok[1 + k], 0, static_cast<long long>(nv) - 1,
                                                             "vertex index")));
    const auto sheet = static_cast<std::int32_t>(r.integer(tok[n + 1], 0, std::numeric_limits<std::int32_t>::max(), "sheet"));
    const auto origin = static_cast<MedialProvenance>(r.integer(tok[n + 2], 0, kMaxProvenance, "provenance (0..4)"));
    mesh.addPolygon(corners, sheet, origin);
  }
  while (r.next(tok))
    if (!tok.empty()) r.fail("unexpected data after the last face");
  return mesh;
}

MedialMesh readMedialPlyFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(kExitUnreadableInput, "cannot open " + path);
  return readMedialPly(in, path);
}

}  // namespace cadmedial
