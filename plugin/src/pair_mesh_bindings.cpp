// CGAL (core) headers before OCCT's.
#include "pair_mesh_bindings.hpp"
#include "cadmedial/cell_classification.hpp"

#include <pybind11/numpy.h>

#include <algorithm>
#include <chrono>
#include <cstring>
#include <string>

#include <Standard_Failure.hxx>

#include "pair_mesh_io.hpp"
#include "pair_mesh_stage.hpp"
#include "without_gil.hpp"

namespace py = pybind11;

namespace cadmedial {

namespace {


// Which nodes lie on the boundary: the samples and the split points that
// boundary-edge splitting appends after the Voronoi nodes.
bool boundaryNode(const PairMesh& m, Index n) { return m.isBoundaryNode(n); }

template <class T, std::size_t N, class Out>
py::array_t<Out> rows(const std::vector<std::array<T, N>>& v) {
  py::array_t<Out> a({static_cast<py::ssize_t>(v.size()), static_cast<py::ssize_t>(N)});
  Out* d = a.mutable_data();
  for (std::size_t i = 0; i < v.size(); ++i)
    for (std::size_t k = 0; k < N; ++k) d[N * i + k] = static_cast<Out>(v[i][k]);
  return a;
}

template <class Out, class In>
py::array_t<Out> column(const std::vector<In>& v) {
  py::array_t<Out> a(static_cast<py::ssize_t>(v.size()));
  Out* d = a.mutable_data();
  for (std::size_t i = 0; i < v.size(); ++i) d[i] = static_cast<Out>(v[i]);
  return a;
}

using DoubleArray = py::array_t<double, py::array::c_style | py::array::forcecast>;
using IntArray = py::array_t<std::int64_t, py::array::c_style | py::array::forcecast>;
using ByteArray = py::array_t<std::uint8_t, py::array::c_style | py::array::forcecast>;

// A PairMesh from the arrays of pairMeshToDict (or of a stored result):
// enough for isoSurface and the writers, which read nodes, tets, type,
// onSheets and the boundary flag. Checks shapes and index ranges.
PairMesh pairMeshFromArrays(const DoubleArray& nodes, const IntArray& tets, const ByteArray& types,
                            const ByteArray* nodeIsBoundary = nullptr, const ByteArray* onSheets = nullptr) {
  if (nodes.ndim() != 2 || nodes.shape(1) != 3) throw py::value_error("nodes must be an N x 3 array");
  const auto nn = static_cast<std::size_t>(nodes.shape(0));
  const bool noTets = tets.size() == 0;
  if (!noTets && (tets.ndim() != 2 || tets.shape(1) != 4)) throw py::value_error("tets must be an M x 4 array");
  const std::size_t nt = noTets ? 0 : static_cast<std::size_t>(tets.shape(0));
  if (types.ndim() != 1 || static_cast<std::size_t>(types.shape(0)) != nt)
    throw py::value_error("types must have one value per tetrahedron");
  PairMesh m;
  m.nodes.resize(nn);
  const double* p = nodes.data();
  for (std::size_t i = 0; i < nn; ++i) m.nodes[i] = {p[3 * i], p[3 * i + 1], p[3 * i + 2]};
  m.tets.resize(nt);
  m.type.resize(nt);
  const std::int64_t* t = tets.data();
  for (std::size_t i = 0; i < nt; ++i) {
    for (int k = 0; k < 4; ++k) {
      const std::int64_t v = t[4 * i + k];
      if (v < 0 || static_cast<std::size_t>(v) >= nn)
        throw py::value_error("tetrahedron " + std::to_string(i) + " refers to node " + std::to_string(v) + " of " +
                              std::to_string(nn));
      m.tets[i][k] = static_cast<Index>(v);
    }
    const std::uint8_t type = types.data()[i];
    if (type > 2) throw py::value_error("types are 0 (face-vertex), 1 (edge-edge), 2 (vertex-face)");
    m.type[i] = static_cast<PairElementType>(type);
  }
  m.onSheets.assign(nt, 0);
  if (onSheets) {
    if (onSheets->ndim() != 1 || static_cast<std::size_t>(onSheets->shape(0)) != nt)
      throw py::value_error("on_sheets must have one value per tetrahedron");
    std::copy(onSheets->data(), onSheets->data() + nt, m.onSheets.begin());
  }
  if (nodeIsBoundary) {
    if (nodeIsBoundary->ndim() != 1 || static_cast<std::size_t>(nodeIsBoundary->shape(0)) != nn)
      throw py::value_error("node_is_boundary must have one value per node");
    // Samples lead; split points of boundary edges come after the Voronoi nodes.
    const std::uint8_t* b = nodeIsBoundary->data();
    m.sampleNodes = static_cast<std::size_t>(std::find(b, b + nn, 0) - b);
    m.boundaryNode.assign(b, b + nn);
  } else {
    // From the element types: the boundary corners of each kind.
    m.boundaryNode.assign(nn, 0);
    for (std::size_t i = 0; i < nt; ++i) {
      const auto& t = m.tets[i];
      switch (m.type[i]) {
        case PairElementType::FaceVertex: m.boundaryNode[t[0]] = 1; break;
        case PairElementType::EdgeEdge: m.boundaryNode[t[0]] = m.boundaryNode[t[1]] = 1; break;
        case PairElementType::VertexFace: m.boundaryNode[t[1]] = m.boundaryNode[t[2]] = m.boundaryNode[t[3]] = 1; break;
      }
    }
    m.sampleNodes = static_cast<std::size_t>(std::find(m.boundaryNode.begin(), m.boundaryNode.end(), 0) -
                                             m.boundaryNode.begin());
  }
  m.nodeCell.assign(nn, kNoIndex);
  return m;
}

py::dict isoSurfaceOf(const DoubleArray& nodes, const IntArray& tets, const ByteArray& types, double t) {
  if (!(t >= 0 && t <= 1)) throw py::value_error("t must be in [0, 1] (0 medial side, 1 boundary), got " + std::to_string(t));
  const PairMesh m = pairMeshFromArrays(nodes, tets, types);
  IsoSurface iso;
  withoutGil([&] { iso = isoSurface(m, t); });
  py::dict d;
  d["points"] = rows<double, 3, double>(iso.points);
  d["triangles"] = rows<Index, 3, std::int64_t>(iso.triangles);
  return d;
}

void writePairMesh(const std::string& path, const std::string& format, const DoubleArray& nodes,
                   const ByteArray& nodeIsBoundary, const IntArray& tets, const ByteArray& types,
                   const ByteArray& onSheets) {
  if (format != "vtu" && format != "tetgen")
    throw py::value_error("format must be 'vtu' or 'tetgen', got '" + format + "'");
  const PairMesh m = pairMeshFromArrays(nodes, tets, types, &nodeIsBoundary, &onSheets);
  withoutGil([&] {
    if (format == "vtu")
      writePairMeshVtu(path, m);
    else
      writePairMeshTetgen(path, m);
  });
}

}  // namespace

py::dict pairMeshToDict(const PairMeshRun& run) {
  const PairMesh& m = run.mesh;
  py::dict d;
  d["nodes"] = rows<double, 3, double>(m.nodes);
  py::array_t<std::uint8_t> boundary(static_cast<py::ssize_t>(m.nodes.size()));
  std::uint8_t* b = boundary.mutable_data();
  for (std::size_t n = 0; n < m.nodes.size(); ++n) b[n] = boundaryNode(m, static_cast<Index>(n)) ? 1 : 0;
  d["node_is_boundary"] = boundary;
  d["tets"] = rows<Index, 4, std::int64_t>(m.tets);
  d["types"] = column<std::uint8_t>(m.type);
  d["on_sheets"] = column<std::uint8_t>(m.onSheets);
  d["boundary_triangles"] = rows<Index, 3, std::int64_t>(m.boundaryTriangles);
  d["report"] = py::module_::import("json").attr("loads")(run.report.dump());
  return d;
}

void registerPairMeshFunctions(py::module_& m) {
  m.def("iso_surface", &isoSurfaceOf, py::arg("nodes"), py::arg("tets"), py::arg("types"), py::arg("t") = 0.5,
        R"(Iso-parametric surface of a pair-mesh at t in [0, 1] (seed 003 section 4.2):
0 the medial side, 1 the boundary (exactly the boundary triangles). Returns a
dict with points (K x 3) and triangles (T x 3), oriented toward the boundary.)");
  m.def("write_pair_mesh", &writePairMesh, py::arg("path"), py::arg("format"), py::arg("nodes"),
        py::arg("node_is_boundary"), py::arg("tets"), py::arg("types"), py::arg("on_sheets"),
        R"(Writes a pair-mesh with the command line's writers: format 'vtu' (VTK XML,
cell data type / on_sheets, point data boundary) to `path`, or 'tetgen'
(`path`.node / `path`.ele, 0-based, type as attribute).)");
}

}  // namespace cadmedial
