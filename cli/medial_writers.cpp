#include "medial_writers.hpp"

#include "number_text.hpp"
#include "record_writer.hpp"

#include "cadmedial/unique_edges.hpp"

#include <tbb/parallel_invoke.h>

#include <algorithm>
#include <array>
#include <charconv>
#include <cstdint>
#include <string>
#include <vector>

namespace cadmedial {

namespace {

// A vertex's numbers as text, "x y z" and the radius, formatted once for
// both files (in a fixed buffer: a string would allocate per vertex).
struct VertexText {
  char position[3 * 32], radius[32];
  std::size_t positionLength = 0, radiusLength = 0;
};

VertexText vertexText(const MedialComplex& c, std::size_t i) {
  VertexText t;
  char* at = t.position;
  for (int k = 0; k < 3; ++k) {
    if (k > 0) *at++ = ' ';
    at = std::to_chars(at, t.position + sizeof t.position, c.vertices[i][k]).ptr;
  }
  t.positionLength = static_cast<std::size_t>(at - t.position);
  t.radiusLength = static_cast<std::size_t>(std::to_chars(t.radius, t.radius + sizeof t.radius, c.radius[i]).ptr - t.radius);
  return t;
}

// "v x y z" then `between` then the radius. OBJ has no radius: it goes in
// a comment (between = " # r "); .ma has it as a fifth number (" ").
void appendVertexLine(std::string& out, const VertexText& t, const char* between) {
  out += "v ";
  out.append(t.position, t.positionLength);
  out += between;
  out.append(t.radius, t.radiusLength);
  out += '\n';
}
constexpr const char* kObjRadius = " # r ";
constexpr const char* kMaRadius = " ";

void writeObjHeader(std::ostream& stream, const MedialComplex& c) {
  stream << "# cadmedial inner medial axis: " + std::to_string(c.vertices.size()) + " vertices, " +
                std::to_string(c.polygonCount()) + " polygons, " + std::to_string(c.sheetCount) + " sheets\n";
}

void writeObjPolygons(std::ostream& stream, const MedialComplex& c) {
  // Polygons ordered by sheet so each group is written once.
  std::vector<std::size_t> order(c.polygonCount());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return c.sheet[a] < c.sheet[b]; });
  writeRecords(stream, order.size(), [&](std::size_t i, std::string& out) {
    const std::size_t p = order[i];
    if (i == 0 || c.sheet[order[i - 1]] != c.sheet[p]) {
      out += "g sheet_";
      appendInteger(out, c.sheet[p]);
      out += '\n';
    }
    out += 'f';
    for (Index k = c.polygonOffsets[p]; k < c.polygonOffsets[p + 1]; ++k) {
      out += ' ';
      appendInteger(out, c.polygonVertices[k] + 1);
    }
    out += '\n';
  });
}

// The .ma form's triangles (each polygon fanned from its first vertex) and
// their distinct edges, numbered in order of first use.
struct MaMesh {
  std::vector<std::array<Index, 3>> triangles;
  std::vector<std::array<Index, 2>> edges;
};

MaMesh maMesh(const MedialComplex& c) {
  MaMesh m;
  for (std::size_t p = 0; p < c.polygonCount(); ++p) {
    const Index b = c.polygonOffsets[p], e = c.polygonOffsets[p + 1];
    for (Index k = b + 1; k + 1 < e; ++k)
      m.triangles.push_back({c.polygonVertices[b], c.polygonVertices[k], c.polygonVertices[k + 1]});
  }
  std::vector<std::array<Index, 2>> sides;
  sides.reserve(3 * m.triangles.size());
  for (const auto& t : m.triangles)
    for (int i = 0; i < 3; ++i) sides.push_back({t[i], t[(i + 1) % 3]});
  m.edges = findUniqueEdges(c.vertices.size(), sides).edges;
  return m;
}

void writeMaHeader(std::ostream& stream, const MedialComplex& c, const MaMesh& m) {
  stream << std::to_string(c.vertices.size()) + ' ' + std::to_string(m.edges.size()) + ' ' +
                std::to_string(m.triangles.size()) + '\n';
}

void writeMaEdgesAndTriangles(std::ostream& stream, const MaMesh& m) {
  auto appendIndices = [](std::string& out, char tag, const Index* idx, int n) {
    out += tag;
    for (int k = 0; k < n; ++k) {
      out += ' ';
      appendInteger(out, idx[k]);
    }
    out += '\n';
  };
  writeRecords(stream, m.edges.size(),
               [&](std::size_t i, std::string& out) { appendIndices(out, 'e', m.edges[i].data(), 2); });
  writeRecords(stream, m.triangles.size(),
               [&](std::size_t i, std::string& out) { appendIndices(out, 'f', m.triangles[i].data(), 3); });
}

}  // namespace

void writeMedialObj(std::ostream& stream, const MedialComplex& c) {
  writeObjHeader(stream, c);
  writeRecords(stream, c.vertices.size(),
               [&](std::size_t i, std::string& out) { appendVertexLine(out, vertexText(c, i), kObjRadius); });
  writeObjPolygons(stream, c);
}

void writeMedialMa(std::ostream& stream, const MedialComplex& c) {
  const MaMesh m = maMesh(c);
  writeMaHeader(stream, c, m);
  writeRecords(stream, c.vertices.size(),
               [&](std::size_t i, std::string& out) { appendVertexLine(out, vertexText(c, i), kMaRadius); });
  writeMaEdgesAndTriangles(stream, m);
}

void writeMedialObjAndMa(std::ostream& obj, std::ostream& ma, const MedialComplex& c) {
  const MaMesh m = maMesh(c);
  writeObjHeader(obj, c);
  writeMaHeader(ma, c, m);
  writeRecordsTo<2>({&obj, &ma}, c.vertices.size(), [&](std::size_t i, std::array<std::string, 2>& texts) {
    const VertexText t = vertexText(c, i);
    appendVertexLine(texts[0], t, kObjRadius);
    appendVertexLine(texts[1], t, kMaRadius);
  });
  tbb::parallel_invoke([&] { writeObjPolygons(obj, c); }, [&] { writeMaEdgesAndTriangles(ma, m); });
}

}  // namespace cadmedial
