// cadmedial._native: the C++ pipeline (sampling/, core/) for Python.
//
// Shapes come in as BREP text (FreeCAD's Shape.exportBrepToString()) or as a
// path to a .step/.stp/.iges/.igs/.brep file; results go out as dicts of numpy
// arrays. The GIL is released while C++ runs, so a GUI can poll a worker
// thread. The pure-Python package `cadmedial` (plugin/cadmedial/) wraps this.
//
// CGAL (core) headers come before any OCCT header: OCCT's `Handle` macro
// breaks CGAL's own `Handle` templates.
#include "cadmedial/compute_medial.hpp"
#include "cadmedial/medial.hpp"
#include "cadmedial/sample_and_triangulate.hpp"
#include "pair_mesh_bindings.hpp"
#include "without_gil.hpp"

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstring>
#include <exception>
#include <fstream>
#include <optional>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include <BRepBndLib.hxx>
#include <BRepGProp.hxx>
#include <BRepTools.hxx>
#include <Bnd_Box.hxx>
#include <GProp_GProps.hxx>
#include <Standard_Failure.hxx>
#include <TopoDS_Solid.hxx>

#include "atomic_file.hpp"
#include "eval_command.hpp"
#include "medial_mesh_conversion.hpp"
#include "topology_check.hpp"
#include "cadmedial/brep_io.hpp"
#include "cadmedial/errors.hpp"
#include "cadmedial/sampling.hpp"
#include "medial_summary.hpp"
#include "medial_writers.hpp"
#include "point_input.hpp"
#include "report_json.hpp"
#include "solid_run.hpp"

namespace py = pybind11;

namespace cadmedial {
namespace {

// Raised (as cadmedial.Cancelled) when the progress callback asks to stop.
struct CancelledError : std::runtime_error {
  CancelledError() : std::runtime_error("cancelled") {}
};

using Clock = std::chrono::steady_clock;
double secondsSince(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

// ---------------------------------------------------------------------------
// Input: BREP text or a file name.

bool looksLikeBrepText(const std::string& s) {
  // BRepTools::Write starts with "DBRep_DrawableShape" and/or "CASCADE Topology V";
  // a file name never holds a newline.
  return s.find('\n') != std::string::npos || s.rfind("CASCADE Topology", 0) == 0 ||
         s.rfind("DBRep_DrawableShape", 0) == 0;
}

std::string describeShape(const ShapeCensus& c) {
  if (c.faces == 0) return "it holds nothing (no faces)";
  std::string s = "it holds ";
  if (c.solids > 0) s += std::to_string(c.solids) + " solid(s) without a closed shell, ";
  s += std::to_string(c.shells) + " shell(s) (" + std::to_string(c.openShells) + " open), " +
       std::to_string(c.faces) + " face(s)";
  return s;
}

struct Input {
  std::string name;  // file name or "BREP text"
  std::vector<TopoDS_Solid> solids;
  std::vector<std::string> warnings;
};

Input readInput(const std::string& source) {
  Input in;
  if (source.empty()) throw InputError(kExitUnreadableInput, "empty input: expected BREP text or a file name");
  if (looksLikeBrepText(source)) {
    in.name = "BREP text";
    const TopoDS_Shape shape = readBrepString(source);
    std::string sewing;
    in.solids = closedSolidsOf(shape, &in.warnings, &sewing);
    if (in.solids.empty())
      throw InputError(kExitNoSolid, "the shape has no closed solid; " + describeShape(takeCensus(shape)) +
                                         (sewing.empty() ? "" : "; " + sewing));
  } else {
    LoadedModel model = loadModel(source);
    in.name = source;
    in.solids = std::move(model.solids);
    in.warnings = std::move(model.warnings);
  }
  return in;
}

// ---------------------------------------------------------------------------
// Progress: progress(stage: str, solid: int, solids: int) -> bool | None,
// called with the GIL held between stages; False stops the run.

class Progress {
 public:
  explicit Progress(py::object callback) : callback_(std::move(callback)) {}

  // Called without the GIL. Throws CancelledError if the callback says stop
  // (or raised: its exception is kept and rethrown by rethrowPending()).
  void report(const char* stage, std::size_t solid, std::size_t solids) {
    if (callback_.is_none()) return;
    bool stop = false;
    {
      py::gil_scoped_acquire gil;
      try {
        py::object r = callback_(stage, solid, solids);
        stop = !r.is_none() && !r.cast<bool>();
      } catch (...) {
        pending_ = std::current_exception();
        stop = true;
      }
    }
    if (stop) throw CancelledError();
  }

  // With the GIL held: rethrows an exception raised by the callback itself.
  void rethrowPending() {
    if (pending_) {
      std::exception_ptr e = pending_;
      pending_ = nullptr;
      std::rethrow_exception(e);
    }
  }

 private:
  py::object callback_;
  std::exception_ptr pending_;
};

// Runs `work` without the GIL; a callback's pending error (progress,
// cancel) goes first, then the work's own.
template <class Work>
void runWithoutGil(Progress& progress, Work&& work) {
  std::exception_ptr error;
  try {
    withoutGil(std::forward<Work>(work));
  } catch (...) {
    error = std::current_exception();
  }
  progress.rethrowPending();
  if (error) std::rethrow_exception(error);
}

// ---------------------------------------------------------------------------
// numpy helpers (GIL held).

template <class T>
py::array_t<T> toArray(const std::vector<T>& v) {
  py::array_t<T> a(static_cast<py::ssize_t>(v.size()));
  if (!v.empty()) std::memcpy(a.mutable_data(), v.data(), v.size() * sizeof(T));
  return a;
}

template <class T, std::size_t N, class Out = T>
py::array_t<Out> toArray2(const std::vector<std::array<T, N>>& v) {
  py::array_t<Out> a({static_cast<py::ssize_t>(v.size()), static_cast<py::ssize_t>(N)});
  auto m = a.template mutable_unchecked<2>();
  for (std::size_t i = 0; i < v.size(); ++i)
    for (std::size_t k = 0; k < N; ++k) m(static_cast<py::ssize_t>(i), static_cast<py::ssize_t>(k)) = static_cast<Out>(v[i][k]);
  return a;
}

template <class Out, class In>
py::array_t<Out> castArray(const std::vector<In>& v) {
  py::array_t<Out> a(static_cast<py::ssize_t>(v.size()));
  Out* d = a.mutable_data();
  for (std::size_t i = 0; i < v.size(); ++i) d[i] = static_cast<Out>(v[i]);
  return a;
}

py::object jsonToPython(const nlohmann::json& j) {
  return py::module_::import("json").attr("loads")(j.dump());
}

py::list toList(const std::vector<std::string>& v) {
  py::list l;
  for (const auto& s : v) l.append(py::str(s));
  return l;
}

// ---------------------------------------------------------------------------
// compute / sample

struct SolidRun {
  SolidResult result;  // secondsAxis: wall time from sampling to the axis (stages overlap)
  double secondsRead = 0;
  double secondsSolid = 0;  // runSolid's wall time, every sampling of the pair-mesh included
};

py::list compute(const std::string& source, double spacing, double theta, double rho, bool checkInside,
                 py::object progressCallback, bool pairMesh, bool gradedSpacing) {
  if (!(spacing >= 0)) throw py::value_error("spacing must be >= 0 (0 = automatic), got " + std::to_string(spacing));
  if (!(theta >= 0 && theta < 90)) throw py::value_error("theta must be in [0, 90) degrees, got " + std::to_string(theta));
  if (!(rho > 0)) throw py::value_error("rho must be > 0, got " + std::to_string(rho));
  MedialParams params = MedialParams::cad();
  params.thetaDeg = theta;
  params.rho = rho;

  Progress progress(std::move(progressCallback));
  Input input;
  std::vector<SolidRun> runs;
  runWithoutGil(progress, [&] {
    progress.report("read", 0, 0);
    const auto t = Clock::now();
    input = readInput(source);
    const double secondsRead = secondsSince(t);
    const std::size_t n = input.solids.size();
    runs.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
      runs[i].secondsRead = secondsRead;
      SamplingParams sp;
      sp.spacing = spacing;
      sp.gradedSpacing = gradedSpacing;
      const auto solidStart = Clock::now();
      runs[i].result = runSolid(input.solids[i], sp, params, checkInside, pairMesh,
                                [&](const char* stage) { progress.report(stage, i, n); });
      runs[i].secondsSolid = secondsSince(solidStart);
    }
    progress.report("done", n, n);
  });

  py::list out;
  for (std::size_t i = 0; i < runs.size(); ++i) {
    const SolidResult& run = runs[i].result;
    const MedialResult& m = run.medial;
    const SolidSampling& s = run.sampled;
    nlohmann::json summary = medialSummaryJson(s.report, m, params);
    summary["model"] = input.name;
    summary["solid"] = i;
    summary["spacing"] = s.samples.spacing;
    summary["graded_spacing"] = gradedSpacing;
    summary["seconds"]["read"] = runs[i].secondsRead;
    const double seconds = run.secondsAxis;
    summary["seconds"]["total"] = seconds;
    // As `cadmedial run`'s summary: from the read to this solid's result,
    // all samplings included (a pair-mesh may sample the solid again).
    summary["seconds"]["end_to_end"] = runs[i].secondsRead + runs[i].secondsSolid;
    const std::string topologyWarning = recordSolidTopology(summary, input.solids[i], m.topology, s.samples.spacing);

    py::dict d;
    d["solid"] = i;
    d["vertices"] = toArray2<double, 3>(m.vertices);
    d["radius"] = toArray(m.radius);
    d["offsets"] = castArray<std::int64_t>(m.polygonOffsets);
    d["indices"] = castArray<std::int64_t>(m.polygonVertices);
    d["sheet"] = castArray<std::int64_t>(m.sheet);
    d["provenance"] = castArray<std::uint8_t>(m.provenance);
    d["sheet_count"] = m.sheetCount;
    d["samples"] = s.samples.size();
    d["spacing"] = s.samples.spacing;
    d["beta0"] = m.topology.beta0;
    d["beta1"] = m.topology.beta1;
    d["seconds"] = seconds;
    std::vector<std::string> warnings = input.warnings;
    warnings.insert(warnings.end(), s.report.warnings.begin(), s.report.warnings.end());
    if (!topologyWarning.empty()) warnings.push_back(topologyWarning);
    d["warnings"] = toList(warnings);
    if (run.pairMesh) {
      d["pair_mesh"] = pairMeshToDict(*run.pairMesh);
      summary["pair_mesh"] = run.pairMesh->report;
    }
    d["summary"] = jsonToPython(summary);
    out.append(d);
  }
  return out;
}

py::list sample(const std::string& source, double spacing, py::object progressCallback, bool gradedSpacing) {
  if (!(spacing >= 0)) throw py::value_error("spacing must be >= 0 (0 = automatic), got " + std::to_string(spacing));
  Progress progress(std::move(progressCallback));
  Input input;
  std::vector<SolidSampling> runs;
  runWithoutGil(progress, [&] {
    progress.report("read", 0, 0);
    input = readInput(source);
    const std::size_t n = input.solids.size();
    runs.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
      progress.report("sample", i, n);
      SamplingParams sp;
      sp.spacing = spacing;
      sp.gradedSpacing = gradedSpacing;
      runs[i] = sampleSolid(input.solids[i], sp);
    }
    progress.report("done", n, n);
  });

  py::list out;
  for (std::size_t i = 0; i < runs.size(); ++i) {
    const SampleSet& s = runs[i].samples;
    std::vector<std::array<Index, 3>> triplets;
    triplets.reserve(s.triplets.size());
    for (const Triplet& t : s.triplets) triplets.push_back({t.s, t.sLeft, t.sRight});
    py::dict d;
    d["solid"] = i;
    d["points"] = toArray2<double, 3>(s.points);
    d["kind"] = castArray<std::uint8_t>(s.kind);
    d["owner"] = toArray(s.owner);
    d["on_convex_edge"] = toArray(s.onConvexEdge);
    d["nonconcave_corner"] = toArray(s.isNonConcaveCorner);
    d["triplets"] = toArray2<Index, 3, std::int64_t>(triplets);
    d["triangles"] = toArray2<Index, 3, std::int64_t>(s.triangles);
    d["triangle_face"] = toArray(s.triangleFace);
    d["spacing"] = s.spacing;
    std::vector<std::string> warnings = input.warnings;
    warnings.insert(warnings.end(), runs[i].report.warnings.begin(), runs[i].report.warnings.end());
    d["warnings"] = toList(warnings);
    nlohmann::json report = toJson(runs[i].report);
    report["graded_spacing"] = gradedSpacing;
    d["report"] = jsonToPython(report);
    out.append(d);
  }
  return out;
}

// ---------------------------------------------------------------------------
// MEDIAL on points (point clouds, mesh vertices): seed 000, no B-rep.

py::dict computePoints(const py::array_t<double, py::array::c_style | py::array::forcecast>& points,
                       const py::object& trianglesObject, double theta, double rho, py::object progressCallback) {
  if (points.ndim() != 2 || points.shape(1) != 3) throw py::value_error("points must be an N x 3 array");
  if (!(theta > 0 && theta < 90)) throw py::value_error("theta must be in (0, 90) degrees, got " + std::to_string(theta));
  if (!(rho > 0)) throw py::value_error("rho must be > 0, got " + std::to_string(rho));
  PointInput input;
  input.format = "array";
  const auto n = static_cast<std::size_t>(points.shape(0));
  input.points.resize(n);
  for (std::size_t i = 0; i < n; ++i)
    input.points[i] = {points.data()[3 * i], points.data()[3 * i + 1], points.data()[3 * i + 2]};
  if (!trianglesObject.is_none()) {
    const auto tri = trianglesObject.cast<py::array_t<std::int64_t, py::array::c_style | py::array::forcecast>>();
    if (tri.size() > 0 && (tri.ndim() != 2 || tri.shape(1) != 3)) throw py::value_error("triangles must be an M x 3 array");
    for (py::ssize_t k = 0; k < (tri.size() > 0 ? tri.shape(0) : 0); ++k) {
      std::array<Index, 3> t;
      for (int c = 0; c < 3; ++c) {
        const std::int64_t v = tri.data()[3 * k + c];
        if (v < 0 || static_cast<std::size_t>(v) >= n)
          throw py::value_error("triangle " + std::to_string(k) + " refers to vertex " + std::to_string(v) + " of " +
                                std::to_string(n));
        t[c] = static_cast<Index>(v);
      }
      input.triangles.push_back(t);
    }
    input.isMesh = !input.triangles.empty();
  }
  if (n < 4) throw InputError(kExitUnreadableInput, std::to_string(n) + " points; a medial axis needs at least 4");
  MedialParams params = MedialParams::pointCloud();
  params.thetaDeg = theta;
  params.rho = rho;
  Progress progress(std::move(progressCallback));
  PointMedialResult m;
  runWithoutGil(progress, [&] {
    progress.report("medial", 0, 1);
    m = computeMedial(input.points, params, input.triangles);
    progress.report("done", 1, 1);
  });
  nlohmann::json summary = pointMedialSummaryJson(input, m, params);
  summary["solid"] = 0;
  summary["seconds"]["total"] = m.times.total;
  py::dict d;
  d["solid"] = 0;
  d["vertices"] = toArray2<double, 3>(m.vertices);
  d["radius"] = toArray(m.radius);
  d["offsets"] = castArray<std::int64_t>(m.polygonOffsets);
  d["indices"] = castArray<std::int64_t>(m.polygonVertices);
  d["sheet"] = castArray<std::int64_t>(m.sheet);
  d["provenance"] = castArray<std::uint8_t>(m.provenance);
  d["sheet_count"] = m.sheetCount;
  d["samples"] = n;
  d["spacing"] = 0.0;
  d["beta0"] = m.topology.beta0;
  d["beta1"] = m.topology.beta1;
  d["seconds"] = m.times.total;
  d["axis"] = m.cloud.part == MedialAxisPart::Inner ? "inner" : "whole";
  d["axis_note"] = m.cloud.axisNote;
  d["warnings"] = py::list();
  d["summary"] = jsonToPython(summary);
  return d;
}

// Points (N x 3) and triangles (M x 3, empty for a point cloud) of a file
// `cadmedial run` accepts as a point input.
py::dict readPoints(const std::string& path) {
  Progress none{py::none()};
  PointInput in;
  runWithoutGil(none, [&] { in = readPointInput(path); });
  py::dict d;
  d["points"] = toArray2<double, 3>(in.points);
  d["triangles"] = toArray2<Index, 3, std::int64_t>(in.triangles);
  d["format"] = in.format;
  d["warnings"] = toList(in.warnings);
  return d;
}

// Cheap facts per solid (no sampling): for spacing defaults and estimates.
py::list inspect(const std::string& source) {
  Progress none{py::none()};
  Input input;
  struct Facts {
    double spacing, area, volume, diagonal;
  };
  std::vector<Facts> facts;
  runWithoutGil(none, [&] {
    input = readInput(source);
    for (const TopoDS_Solid& solid : input.solids) {
      GProp_GProps surface, volume;
      BRepGProp::SurfaceProperties(solid, surface);
      BRepGProp::VolumeProperties(solid, volume);
      Bnd_Box box;
      BRepBndLib::Add(solid, box);
      facts.push_back({defaultSpacing(solid), surface.Mass(), volume.Mass(),
                       box.IsVoid() ? 0.0 : std::sqrt(box.SquareExtent())});
    }
  });
  py::list out;
  for (std::size_t i = 0; i < facts.size(); ++i) {
    py::dict d;
    d["solid"] = i;
    d["default_spacing"] = facts[i].spacing;
    d["area"] = facts[i].area;
    d["volume"] = facts[i].volume;
    d["bbox_diagonal"] = facts[i].diagonal;
    d["warnings"] = toList(input.warnings);
    out.append(d);
  }
  return out;
}

// The closed solids of a source as BREP text, one string each: the solids
// it holds, or (a shape without one: a closed shell, loose faces, IGES
// trimmed surfaces) the solids its faces sew into, as the command line
// makes them. For the workbench, whose objects take their solids from
// FreeCAD's shape; InputError when there is none.
py::dict solidsBrep(const std::string& source) {
  Progress none{py::none()};
  Input input;
  std::vector<std::string> texts;
  runWithoutGil(none, [&] {
    input = readInput(source);
    for (const TopoDS_Solid& solid : input.solids) {
      std::ostringstream text;
      BRepTools::Write(solid, text);
      texts.push_back(text.str());
    }
  });
  py::dict out;
  py::list solids;
  for (const std::string& t : texts) solids.append(py::str(t));
  out["solids"] = solids;
  out["warnings"] = toList(input.warnings);
  return out;
}

// ---------------------------------------------------------------------------
// Writers shared with the command line (OBJ grouped per sheet, Q-MAT .ma).

MedialComplex complexFromArrays(const py::array_t<double, py::array::c_style | py::array::forcecast>& vertices,
                                const py::array_t<double, py::array::c_style | py::array::forcecast>& radius,
                                const py::array_t<std::int64_t, py::array::c_style | py::array::forcecast>& offsets,
                                const py::array_t<std::int64_t, py::array::c_style | py::array::forcecast>& indices,
                                const py::array_t<std::int64_t, py::array::c_style | py::array::forcecast>& sheet,
                                const std::int64_t* provenance = nullptr) {
  if (vertices.ndim() != 2 || vertices.shape(1) != 3) throw py::value_error("vertices must be an N x 3 array");
  const auto nv = static_cast<std::size_t>(vertices.shape(0));
  if (radius.ndim() != 1 || static_cast<std::size_t>(radius.shape(0)) != nv)
    throw py::value_error("radius must have one value per vertex");
  if (offsets.ndim() != 1 || offsets.shape(0) < 1) throw py::value_error("offsets must be a 1-D array starting with 0");
  const auto np = static_cast<std::size_t>(offsets.shape(0) - 1);
  if (sheet.ndim() != 1 || static_cast<std::size_t>(sheet.shape(0)) != np)
    throw py::value_error("sheet must have one value per polygon");
  MedialComplex c;
  c.vertices.resize(nv);
  c.radius.assign(radius.data(), radius.data() + nv);
  const double* v = vertices.data();
  for (std::size_t i = 0; i < nv; ++i) c.vertices[i] = {v[3 * i], v[3 * i + 1], v[3 * i + 2]};
  const std::int64_t* o = offsets.data();
  const std::int64_t* ix = indices.data();
  const auto ni = static_cast<std::int64_t>(indices.size());
  c.polygonOffsets.assign(1, 0);
  std::size_t sheets = 0;
  for (std::size_t p = 0; p < np; ++p) {
    if (o[p] < 0 || o[p + 1] < o[p] + 3 || o[p + 1] > ni)
      throw py::value_error("offsets are not increasing by at least 3 within the index array");
    c.polygonOffsets.push_back(static_cast<Index>(o[p + 1]));
    if (sheet.data()[p] < 0) throw py::value_error("negative sheet id");
    c.sheet.push_back(static_cast<Index>(sheet.data()[p]));
    sheets = std::max(sheets, static_cast<std::size_t>(sheet.data()[p]) + 1);
    const std::int64_t origin = provenance ? provenance[p] : 0;
    if (origin < 0 || origin > 4) throw py::value_error("provenance values are 0..4");
    c.provenance.push_back(static_cast<PolygonProvenance>(origin));
  }
  for (std::int64_t k = 0; k < ni; ++k) {
    if (ix[k] < 0 || static_cast<std::size_t>(ix[k]) >= nv) throw py::value_error("vertex index out of range");
    c.polygonVertices.push_back(static_cast<Index>(ix[k]));
  }
  c.sheetCount = sheets;
  return c;
}

void writeMedial(const std::string& path, const std::string& format,
                 const py::array_t<double, py::array::c_style | py::array::forcecast>& vertices,
                 const py::array_t<double, py::array::c_style | py::array::forcecast>& radius,
                 const py::array_t<std::int64_t, py::array::c_style | py::array::forcecast>& offsets,
                 const py::array_t<std::int64_t, py::array::c_style | py::array::forcecast>& indices,
                 const py::array_t<std::int64_t, py::array::c_style | py::array::forcecast>& sheet) {
  if (format != "obj" && format != "ma") throw py::value_error("format must be 'obj' or 'ma', got '" + format + "'");
  const MedialComplex c = complexFromArrays(vertices, radius, offsets, indices, sheet);
  Progress none{py::none()};
  runWithoutGil(none, [&] {
    writeFileAtomically(path, [&](std::ofstream& out) {
      if (format == "obj")
        writeMedialObj(out, c);
      else
        writeMedialMa(out, c);
    });
  });
}

// ---------------------------------------------------------------------------
// evaluate: the DESIGN.md §6 metrics of `cadmedial eval` for one solid's axis.

py::object evaluate(const std::string& source, std::size_t solid,
                    const py::array_t<double, py::array::c_style | py::array::forcecast>& vertices,
                    const py::array_t<double, py::array::c_style | py::array::forcecast>& radius,
                    const py::array_t<std::int64_t, py::array::c_style | py::array::forcecast>& offsets,
                    const py::array_t<std::int64_t, py::array::c_style | py::array::forcecast>& indices,
                    const py::array_t<std::int64_t, py::array::c_style | py::array::forcecast>& sheet,
                    const py::array_t<std::int64_t, py::array::c_style | py::array::forcecast>& provenance,
                    double tolerance, double theta) {
  if (!(tolerance > 0 && tolerance < 1))
    throw py::value_error("tolerance must be a fraction of the bounding-box diagonal in (0, 1)");
  if (!(theta >= 0 && theta < 90)) throw py::value_error("theta must be in [0, 90) degrees, got " + std::to_string(theta));
  if (provenance.ndim() != 1 || provenance.shape(0) != sheet.shape(0))
    throw py::value_error("provenance must have one value per polygon");
  const MedialComplex c = complexFromArrays(vertices, radius, offsets, indices, sheet, provenance.data());
  Progress none{py::none()};
  EvaluationReport report;
  runWithoutGil(none, [&] {
    const Input input = readInput(source);
    if (solid >= input.solids.size())
      throw py::value_error("solid " + std::to_string(solid) + " out of range: the source has " +
                            std::to_string(input.solids.size()) + " closed solid(s)");
    EvaluationParams params;
    params.toleranceFraction = tolerance;
    params.thetaDeg = theta;
    report = evaluateMedial(input.solids[solid], toMedialMesh(c), params);
  });
  return jsonToPython(toJson(report));
}

}  // namespace
}  // namespace cadmedial

PYBIND11_MODULE(_native, m) {
  using namespace cadmedial;
  m.doc() = "cadmedial C++ pipeline: sampling of OCCT solids and the CAD_MEDIAL inner medial axis";

  static py::exception<InputError> inputError(m, "InputError", PyExc_ValueError);
  static py::exception<CancelledError> cancelled(m, "Cancelled", PyExc_RuntimeError);
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const InputError& e) {
      py::object err = py::handle(inputError.ptr())(e.what());
      err.attr("exit_code") = static_cast<int>(e.code());
      PyErr_SetObject(inputError.ptr(), err.ptr());
    } catch (const CancelledError& e) {
      cancelled(e.what());
    }
  });

  m.def("compute", &compute, py::arg("source"), py::arg("spacing") = 0.0, py::arg("theta") = 5.0,
        py::arg("rho") = 8.0, py::arg("check_inside") = true, py::arg("progress") = py::none(),
        py::arg("pair_mesh") = false, py::arg("graded_spacing") = true,
        R"(Inner medial axis of every closed solid in `source` (BREP text or a file name).

Returns a list with one dict per solid: vertices (N x 3), radius (N),
offsets (P+1) and indices (polygon i = indices[offsets[i]:offsets[i+1]]),
sheet (P), provenance (P; 0 facet, 1 convex-edge, 2 convex-edge fill,
3 corner triangle, 4 short hole closed), sheet_count, samples, spacing, beta0, beta1, seconds,
warnings and summary (the summary.json of `cadmedial run`).
spacing 0 = automatic (bounding-box diagonal / 40); theta in degrees.
check_inside counts disagreements of the walk with OCCT's exact classifier.
progress(stage, solid, solids) is called between stages with the GIL held;
returning False raises Cancelled. The GIL is released while C++ runs.
pair_mesh: also build the pair-mesh (DESIGN.md section 5) on the same
triangulation, with exact inner labels (stage "pair_mesh"); each dict then has
pair_mesh: nodes (N x 3), node_is_boundary (N), tets (M x 4), types (M; 0
face-vertex, 1 edge-edge, 2 vertex-face), on_sheets (M), boundary_triangles
(K x 3) and report (counts, validity, exact volume, repair, seconds).
A pair-mesh that is not valid makes the solid be sampled again at 0.97 times
the spacing, then with every spacing 0.94 times (the stages come again;
report["attempts"]).
graded_spacing: grade the sample spacing within each face (the default;
False = `cadmedial run --uniform-spacing`, one spacing per face).
Raises InputError (a ValueError) for unreadable input or no closed solid.)");
  m.def("sample", &sample, py::arg("source"), py::arg("spacing") = 0.0, py::arg("progress") = py::none(),
        py::arg("graded_spacing") = true,
        R"(Boundary samples of every closed solid in `source`: points (N x 3), kind (0 face,
1 edge, 2 vertex), owner, on_convex_edge, nonconcave_corner, triplets (T x 3:
s, s_left, s_right), triangles (M x 3, the stitched reconstruction),
triangle_face, spacing, warnings and report (the sampling.json dict).)");
  m.def("inspect", &inspect, py::arg("source"),
        "Per closed solid: default_spacing, area, volume, bbox_diagonal (no sampling).");
  m.def("solids_brep", &solidsBrep, py::arg("source"),
        "The closed solids of `source` as BREP text each, with the reading's warnings: a shape without "
        "a solid has its faces sewn into solids, as the command line does. Raises InputError if none.");
  m.def("write_medial", &writeMedial, py::arg("path"), py::arg("format"), py::arg("vertices"), py::arg("radius"),
        py::arg("offsets"), py::arg("indices"), py::arg("sheet"),
        "Writes a medial axis as 'obj' (groups per sheet) or 'ma' (Q-MAT), atomically, in the "
        "command line's format.");
  m.def("evaluate", &evaluate, py::arg("source"), py::arg("solid"), py::arg("vertices"), py::arg("radius"),
        py::arg("offsets"), py::arg("indices"), py::arg("sheet"), py::arg("provenance"), py::arg("tolerance") = 0.005,
        py::arg("theta") = 5.0,
        R"(Measures a medial axis of solid `solid` of `source` against the exact B-rep
(DESIGN.md section 6), as `cadmedial eval` does: returns its eval.json dict
(inside, medialness, coverage, attachment, topology, thresholds, pass).
tolerance: the fraction of the bounding-box diagonal used as tol; theta: the
Angle threshold the axis was computed with (creases turning by less than
2 theta are measured apart from the edge attachment).)");
  m.def("compute_points", &computePoints, py::arg("points"), py::arg("triangles") = py::none(),
        py::arg("theta") = 22.5, py::arg("rho") = 8.0, py::arg("progress") = py::none(),
        R"(MEDIAL (seed 000) on points alone: a point cloud (triangles None) gives the whole
medial axis, inner and outer; the vertices of a closed, consistently oriented
mesh (triangles M x 3) give its inner axis. Returns one dict with the keys of
compute() plus axis ("inner" | "whole") and axis_note.)");
  m.def("read_points", &readPoints, py::arg("path"),
        "Points (N x 3) and triangles (M x 3) of a .xyz/.pts/.ply/.stl/.obj/.off file, as `cadmedial run` reads it.");
  m.def("is_point_input", &isPointInputPath, py::arg("path"),
        "True if `cadmedial run` treats this file name as a point cloud or mesh (.xyz .pts .ply .stl .obj .off).");
  m.def(
      "resampling_line",
      [](const std::string& attemptsJson) { return resamplingLine(nlohmann::json::parse(attemptsJson)); },
      py::arg("attempts_json"),
      "The pair-mesh report's attempts (a JSON list) as the one line `cadmedial run` prints; empty when the "
      "solid was sampled once.");
  registerPairMeshFunctions(m);
  m.attr("PAIR_MESH_AVAILABLE") = true;
}
