#include "medial_writers.hpp"

#include "number_text.hpp"
#include "record_writer.hpp"

#include "cadmedial/unique_edges.hpp"

#include <algorithm>
#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace cadmedial {

namespace {

// "x y z" of vertex i then `between` then its radius.
void appendVertex(std::string& out, const MedialComplex& c, std::size_t i, const char* between) {
  for (int k = 0; k < 3; ++k) {
    if (k > 0) out += ' ';
    appendNumber(out, c.vertices[i][k]);
  }
  out += between;
  appendNumber(out, c.radius[i]);
  out += '\n';
}

}  // namespace

void writeMedialObj(std::ostream& stream, const MedialComplex& c) {
  const std::string header = "# cadmedial inner medial axis: " + std::to_string(c.vertices.size()) + " vertices, " +
                             std::to_string(c.polygonCount()) + " polygons, " + std::to_string(c.sheetCount) +
                             " sheets\n";
  stream << header;
  writeRecords(stream, c.vertices.size(), [&](std::size_t i, std::string& out) {
    out += "v ";
    appendVertex(out, c, i, " # r ");
  });
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

void writeMedialMa(std::ostream& stream, const MedialComplex& c) {
  std::vector<std::array<Index, 3>> triangles;
  for (std::size_t p = 0; p < c.polygonCount(); ++p) {
    const Index b = c.polygonOffsets[p], e = c.polygonOffsets[p + 1];
    for (Index k = b + 1; k + 1 < e; ++k)
      triangles.push_back({c.polygonVertices[b], c.polygonVertices[k], c.polygonVertices[k + 1]});
  }
  std::vector<std::array<Index, 2>> sides;
  sides.reserve(3 * triangles.size());
  for (const auto& t : triangles)
    for (int i = 0; i < 3; ++i) sides.push_back({t[i], t[(i + 1) % 3]});
  const std::vector<std::array<Index, 2>> edges = findUniqueEdges(c.vertices.size(), sides).edges;
  stream << std::to_string(c.vertices.size()) + ' ' + std::to_string(edges.size()) + ' ' +
                std::to_string(triangles.size()) + '\n';
  writeRecords(stream, c.vertices.size(), [&](std::size_t i, std::string& out) {
    out += "v ";
    appendVertex(out, c, i, " ");
  });
  auto appendIndices = [](std::string& out, char tag, const Index* idx, int n) {
    out += tag;
    for (int k = 0; k < n; ++k) {
      out += ' ';
      appendInteger(out, idx[k]);
    }
    out += '\n';
  };
  writeRecords(stream, edges.size(),
               [&](std::size_t i, std::string& out) { appendIndices(out, 'e', edges[i].data(), 2); });
  writeRecords(stream, triangles.size(),
               [&](std::size_t i, std::string& out) { appendIndices(out, 'f', triangles[i].data(), 3); });
}

}  // namespace cadmedial
