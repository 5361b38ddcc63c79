#include "medial_writers.hpp"

#include "number_text.hpp"

#include <algorithm>
#include <string>
#include <vector>

namespace cadmedial {

void writeMedialObj(std::ostream& stream, const MedialComplex& c) {
  std::string out;
  out.reserve(64 * (c.vertices.size() + c.polygonCount()));
  out += "# cadmedial inner medial axis: " + std::to_string(c.vertices.size()) + " vertices, " +
         std::to_string(c.polygonCount()) + " polygons, " + std::to_string(c.sheetCount) + " sheets\n";
  for (std::size_t i = 0; i < c.vertices.size(); ++i) {
    out += "v ";
    for (int k = 0; k < 3; ++k) {
      appendNumber(out, c.vertices[i][k]);
      out += ' ';
    }
    out += "# r ";
    appendNumber(out, c.radius[i]);
    out += '\n';
  }
  // Polygons ordered by sheet so each group is written once.
  std::vector<std::size_t> order(c.polygonCount());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return c.sheet[a] < c.sheet[b]; });
  Index currentSheet = kNoIndex;
  for (std::size_t p : order) {
    if (c.sheet[p] != currentSheet) {
      currentSheet = c.sheet[p];
      out += "g sheet_" + std::to_string(currentSheet) + "\n";
    }
    out += 'f';
    for (Index k = c.polygonOffsets[p]; k < c.polygonOffsets[p + 1]; ++k) {
      out += ' ';
      appendInteger(out, c.polygonVertices[k] + 1);
    }
    out += '\n';
  }
  stream.write(out.data(), static_cast<std::streamsize>(out.size()));
}

void writeMedialMa(std::ostream& stream, const MedialComplex& c) {
  std::vector<std::array<Index, 3>> triangles;
  for (std::size_t p = 0; p < c.polygonCount(); ++p) {
    const Index b = c.polygonOffsets[p], e = c.polygonOffsets[p + 1];
    for (Index k = b + 1; k + 1 < e; ++k)
      triangles.push_back({c.polygonVertices[b], c.polygonVertices[k], c.polygonVertices[k + 1]});
  }
  // Unique undirected edges in first-seen order. Sorting (key, position)
  // pairs beats a hash set several times over at 10^6 triangles.
  std::vector<std::pair<std::uint64_t, std::uint32_t>> uses;
  uses.reserve(3 * triangles.size());
  for (const auto& t : triangles)
    for (int k = 0; k < 3; ++k) {
      Index a = t[k], b = t[(k + 1) % 3];
      if (a > b) std::swap(a, b);
      uses.push_back({(static_cast<std::uint64_t>(a) << 32) | b, static_cast<std::uint32_t>(uses.size())});
    }
  std::sort(uses.begin(), uses.end());
  std::vector<std::uint32_t> firstUse;
  for (std::size_t i = 0; i < uses.size(); ++i)
    if (i == 0 || uses[i].first != uses[i - 1].first) firstUse.push_back(uses[i].second);
  std::sort(firstUse.begin(), firstUse.end());
  std::vector<std::array<Index, 2>> edges;
  edges.reserve(firstUse.size());
  for (std::uint32_t u : firstUse) {
    const auto& t = triangles[u / 3];
    Index a = t[u % 3], b = t[(u % 3 + 1) % 3];
    if (a > b) std::swap(a, b);
    edges.push_back({a, b});
  }
  std::string out;
  out.reserve(48 * (c.vertices.size() + edges.size() + triangles.size()));
  out += std::to_string(c.vertices.size()) + ' ' + std::to_string(edges.size()) + ' ' +
         std::to_string(triangles.size()) + '\n';
  for (std::size_t i = 0; i < c.vertices.size(); ++i) {
    out += 'v';
    for (int k = 0; k < 3; ++k) {
      out += ' ';
      appendNumber(out, c.vertices[i][k]);
    }
    out += ' ';
    appendNumber(out, c.radius[i]);
    out += '\n';
  }
  auto appendIndices = [&out](char tag, const Index* idx, int n) {
    out += tag;
    for (int k = 0; k < n; ++k) {
      out += ' ';
      appendInteger(out, idx[k]);
    }
    out += '\n';
  };
  for (const auto& e : edges) appendIndices('e', e.data(), 2);
  for (const auto& t : triangles) appendIndices('f', t.data(), 3);
  stream.write(out.data(), static_cast<std::streamsize>(out.size()));
}

}  // namespace cadmedial
