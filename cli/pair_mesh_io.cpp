#include "pair_mesh_io.hpp"

#include <cstdio>
#include <fstream>
#include <sstream>

#include "atomic_file.hpp"
#include "cadmedial/errors.hpp"
#include "number_text.hpp"

namespace cadmedial {

namespace {

constexpr int kVtkTetra = 10;

void appendPoint(std::string& s, const Vec3& p) {
  appendNumber(s, p[0]);
  s += ' ';
  appendNumber(s, p[1]);
  s += ' ';
  appendNumber(s, p[2]);
}

}  // namespace

void writePairMeshVtu(const std::string& path, const PairMesh& m) {
  std::string s;
  s.reserve(64 * m.nodes.size() + 48 * m.size() + 1024);
  s += "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"LittleEndian\">\n";
  s += "<UnstructuredGrid>\n<Piece NumberOfPoints=\"";
  appendInteger(s, m.nodes.size());
  s += "\" NumberOfCells=\"";
  appendInteger(s, m.size());
  s += "\">\n<Points>\n<DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">\n";
  for (const Vec3& p : m.nodes) {
    appendPoint(s, p);
    s += '\n';
  }
  s += "</DataArray>\n</Points>\n<Cells>\n<DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n";
  for (const auto& t : m.tets) {
    for (int k = 0; k < 4; ++k) {
      appendInteger(s, t[k]);
      s += k < 3 ? ' ' : '\n';
    }
  }
  s += "</DataArray>\n<DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n";
  for (std::size_t i = 0; i < m.size(); ++i) {
    appendInteger(s, 4 * (i + 1));
    s += '\n';
  }
  s += "</DataArray>\n<DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">\n";
  for (std::size_t i = 0; i < m.size(); ++i) s += "10\n";
  static_assert(kVtkTetra == 10, "VTK_TETRA");
  s += "</DataArray>\n</Cells>\n<CellData Scalars=\"type\">\n";
  s += "<DataArray type=\"UInt8\" Name=\"type\" format=\"ascii\">\n";
  for (PairElementType t : m.type) {
    appendInteger(s, static_cast<int>(t));
    s += '\n';
  }
  s += "</DataArray>\n<DataArray type=\"UInt8\" Name=\"on_sheets\" format=\"ascii\">\n";
  for (std::uint8_t f : m.onSheets) {
    appendInteger(s, static_cast<int>(f));
    s += '\n';
  }
  s += "</DataArray>\n</CellData>\n<PointData>\n<DataArray type=\"UInt8\" Name=\"boundary\" format=\"ascii\">\n";
  for (std::size_t n = 0; n < m.nodes.size(); ++n) s += m.isBoundaryNode(static_cast<Index>(n)) ? "1\n" : "0\n";
  s += "</DataArray>\n</PointData>\n</Piece>\n</UnstructuredGrid>\n</VTKFile>\n";
  writeFileAtomically(path, [&](std::ofstream& out) { out << s; });
}

void writePairMeshTetgen(const std::string& basePath, const PairMesh& m) {
  std::string node;
  node.reserve(64 * m.nodes.size() + 64);
  node += "# cadmedial pair-mesh nodes: index x y z boundary(1 = sample or split point on a boundary edge, 0 = Voronoi node)\n";
  appendInteger(node, m.nodes.size());
  node += " 3 0 1\n";
  for (std::size_t n = 0; n < m.nodes.size(); ++n) {
    appendInteger(node, n);
    node += ' ';
    appendPoint(node, m.nodes[n]);
    node += m.isBoundaryNode(static_cast<Index>(n)) ? " 1\n" : " 0\n";
  }
  std::string ele;
  ele.reserve(48 * m.size() + 64);
  ele += "# cadmedial pair-mesh tetrahedra: index n0 n1 n2 n3 type(0 face-vertex, 1 edge-edge, 2 vertex-face)\n";
  appendInteger(ele, m.size());
  ele += " 4 1\n";
  for (std::size_t i = 0; i < m.size(); ++i) {
    appendInteger(ele, i);
    for (Index v : m.tets[i]) {
      ele += ' ';
      appendInteger(ele, v);
    }
    ele += ' ';
    appendInteger(ele, static_cast<int>(m.type[i]));
    ele += '\n';
  }
  writeFileAtomically(basePath + ".node", [&](std::ofstream& out) { out << node; });
  writeFileAtomically(basePath + ".ele", [&](std::ofstream& out) { out << ele; });
}

void writeIsoSurfacePly(const std::string& path, const IsoSurface& iso) {
  std::string s;
  s.reserve(64 * iso.points.size() + 32 * iso.triangles.size() + 256);
  s += "ply\nformat ascii 1.0\ncomment cadmedial iso-parametric surface of the pair-mesh\nelement vertex ";
  appendInteger(s, iso.points.size());
  s += "\nproperty double x\nproperty double y\nproperty double z\nelement face ";
  appendInteger(s, iso.triangles.size());
  s += "\nproperty list uchar int vertex_indices\nend_header\n";
  for (const Vec3& p : iso.points) {
    appendPoint(s, p);
    s += '\n';
  }
  for (const auto& t : iso.triangles) {
    s += '3';
    for (Index v : t) {
      s += ' ';
      appendInteger(s, v);
    }
    s += '\n';
  }
  writeFileAtomically(path, [&](std::ofstream& out) { out << s; });
}

std::string isoSurfaceFileName(double t) {
  char buf[48];
  std::snprintf(buf, sizeof buf, "iso_%g.ply", t);
  return buf;
}

namespace {

// Next line that is neither empty nor a comment.
bool dataLine(std::istream& in, std::istringstream& line) {
  std::string text;
  while (std::getline(in, text)) {
    const auto first = text.find_first_not_of(" \t\r");
    if (first == std::string::npos || text[first] == '#') continue;
    line.clear();
    line.str(text);
    return true;
  }
  return false;
}

[[noreturn]] void malformed(const std::string& path, const std::string& what) {
  throw InputError(kExitUnreadableInput, path + ": " + what);
}

}  // namespace

PairMesh readPairMeshTetgen(const std::string& basePath) {
  PairMesh m;
  const std::string nodePath = basePath + ".node", elePath = basePath + ".ele";
  std::ifstream nodes(nodePath), eles(elePath);
  if (!nodes) malformed(nodePath, "cannot open");
  if (!eles) malformed(elePath, "cannot open");
  std::istringstream line;
  std::size_t count = 0;
  int dim = 0, attributes = 0, markers = 0;
  if (!dataLine(nodes, line) || !(line >> count >> dim >> attributes >> markers) || dim != 3 || markers != 1)
    malformed(nodePath, "bad header (expected 'N 3 0 1')");
  m.nodes.resize(count);
  m.nodeCell.assign(count, kNoIndex);
  m.boundaryNode.assign(count, 0);
  bool voronoiSeen = false;
  for (std::size_t n = 0; n < count; ++n) {
    std::size_t index = 0;
    int boundary = 0;
    Vec3 p{};
    if (!dataLine(nodes, line) || !(line >> index >> p[0] >> p[1] >> p[2] >> boundary) || index != n)
      malformed(nodePath, "bad node line " + std::to_string(n));
    m.nodes[n] = p;
    if (boundary != 0 && boundary != 1) malformed(nodePath, "bad boundary marker on node " + std::to_string(n));
    m.boundaryNode[n] = static_cast<std::uint8_t>(boundary);
    // Samples first; boundary nodes after the Voronoi nodes are split points.
    if (boundary == 1 && !voronoiSeen) m.sampleNodes = n + 1;
    if (boundary == 0) voronoiSeen = true;
  }
  int corners = 0;
  if (!dataLine(eles, line) || !(line >> count >> corners >> attributes) || corners != 4 || attributes != 1)
    malformed(elePath, "bad header (expected 'M 4 1')");
  m.tets.resize(count);
  m.type.resize(count);
  m.onSheets.assign(count, 0);
  for (std::size_t i = 0; i < count; ++i) {
    std::size_t index = 0;
    int type = 0;
    auto& t = m.tets[i];
    if (!dataLine(eles, line) || !(line >> index >> t[0] >> t[1] >> t[2] >> t[3] >> type) || index != i ||
        type < 0 || type > 2)
      malformed(elePath, "bad element line " + std::to_string(i));
    for (Index v : t)
      if (v >= m.nodes.size()) malformed(elePath, "node index out of range in element " + std::to_string(i));
    m.type[i] = static_cast<PairElementType>(type);
    if (m.type[i] == PairElementType::VertexFace) m.boundaryTriangles.push_back({t[1], t[2], t[3]});
  }
  return m;
}

}  // namespace cadmedial
