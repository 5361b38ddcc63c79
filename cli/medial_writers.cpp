#include "medial_writers.hpp"

#include "number_text.hpp"

#include <algorithm>
#include <array>
#include <cstdint>
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
  // Unique undirected edges (a < b) in first-seen order, in linear time:
  // uses bucketed by a (counting sort), duplicates found within each small
  // bucket, the first use of each edge kept. Sorting all 3T uses was the
  // largest part of the write at 10^6 samples.
  const std::size_t uses = 3 * triangles.size();
  auto endpoints = [&](std::size_t u) {
    const auto& t = triangles[u / 3];
    Index a = t[u % 3], b = t[(u % 3 + 1) % 3];
    if (a > b) std::swap(a, b);
    return std::array<Index, 2>{a, b};
  };
  std::vector<std::size_t> start(c.vertices.size() + 1, 0);
  for (std::size_t u = 0; u < uses; ++u) ++start[endpoints(u)[0] + 1];
  for (std::size_t i = 0; i < c.vertices.size(); ++i) start[i + 1] += start[i];
  std::vector<std::uint32_t> byLow(uses);  // use ids, grouped by low endpoint, ascending within a group
  {
    std::vector<std::size_t> fill(start.begin(), start.end() - 1);
    for (std::size_t u = 0; u < uses; ++u) byLow[fill[endpoints(u)[0]]++] = static_cast<std::uint32_t>(u);
  }
  std::vector<std::uint8_t> first(uses, 0);
  for (std::size_t i = 0; i < c.vertices.size(); ++i)
    for (std::size_t x = start[i]; x < start[i + 1]; ++x) {
      const Index b = endpoints(byLow[x])[1];
      bool seen = false;
      for (std::size_t y = start[i]; y < x && !seen; ++y) seen = endpoints(byLow[y])[1] == b;
      if (!seen) first[byLow[x]] = 1;  // uses within a group ascend, so this is the first use
    }
  std::vector<std::array<Index, 2>> edges;
  for (std::size_t u = 0; u < uses; ++u)
    if (first[u]) edges.push_back(endpoints(u));
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
