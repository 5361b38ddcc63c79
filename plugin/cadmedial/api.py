"""compute / sample / inspect: the C++ pipeline behind a small Python API.

Nothing here needs FreeCAD: a source is BREP text, a file name, or anything
with ``exportBrepToString()`` (a FreeCAD ``Part.Shape``) or a ``Shape``
attribute (a FreeCAD document object).
"""

import json
import math
import os

import numpy as np

try:
    from . import _native
except ImportError as _error:  # pragma: no cover - depends on the installation
    raise ImportError(
        "cadmedial: the compiled module cadmedial._native is missing or does not load "
        f"({_error}). Build the CMake target cadmedial_python and run plugin/install.sh."
    ) from _error

#: Unreadable input or no closed solid (a ValueError; ``exit_code`` as in the CLI).
InputError = _native.InputError
#: Raised when a progress callback returns False or a cancel token is set.
Cancelled = _native.Cancelled

PROVENANCE_NAMES = (
    "delaunay_edge_facet", "convex_edge_triangle", "convex_edge_fill", "corner_triangle", "short_hole_fill")

#: Why a point cloud or mesh gets no pair-mesh (compute(..., pair_mesh=True) raises ValueError).
PAIR_MESH_MESSAGE = (
    "the pair-mesh needs a B-rep solid (a STEP/IGES/BREP file, a Part shape or a solid object): its inner "
    "Voronoi cells are decided by OpenCASCADE's exact solid classifier; point clouds and meshes have no B-rep"
)
#: Element types of the pair-mesh, by code (PairMesh.types).
PAIR_ELEMENT_TYPES = ("face_vertex", "edge_edge", "vertex_face")


def _label(obj):
    return getattr(obj, "Label", None) or getattr(obj, "Name", None) or type(obj).__name__


def to_source(source):
    """BREP text or a file name for the C++ side.

    Accepts a FreeCAD document object (its ``Shape``), a ``Part.Shape``, a
    path (str or os.PathLike), BREP text (str or bytes)."""
    if source is None:
        raise ValueError("no source given: expected a solid, a shape, a file name or BREP text")
    if hasattr(source, "exportBrepToString"):
        if source.isNull():
            raise ValueError("the shape is empty (null shape)")
        return source.exportBrepToString()
    if hasattr(source, "TypeId") and hasattr(source, "Document"):  # a FreeCAD document object
        shape = getattr(source, "Shape", None)
        if shape is None:
            raise ValueError(f"'{_label(source)}' ({source.TypeId}) has no shape, so no solid")
        if shape.isNull():
            raise ValueError(f"'{_label(source)}' has an empty shape (recompute it first?)")
        return shape.exportBrepToString()
    if isinstance(source, bytes):
        return source.decode("utf-8", errors="replace")
    if isinstance(source, os.PathLike):
        return os.fspath(source)
    if isinstance(source, str):
        return source
    raise TypeError(
        f"cannot use a {type(source).__name__} as a source: expected a FreeCAD shape or object, "
        "a file name or BREP text"
    )


def _with_cancel(progress, cancel):
    """One callback for the C++ side out of a progress callback and a cancel
    token (anything with is_set(), e.g. threading.Event)."""
    if cancel is None:
        return progress

    def callback(stage, solid, solids):
        if cancel.is_set():
            return False
        if progress is not None:
            return progress(stage, solid, solids)
        return None

    return callback


class MedialAxisResult:
    """The inner medial axis of one solid.

    Arrays: ``vertices`` (N x 3), ``radius`` (N), polygons as ``offsets``
    (P + 1) and ``indices`` (polygon i = indices[offsets[i]:offsets[i+1]]),
    ``sheet`` (P), ``provenance`` (P, see PROVENANCE_NAMES). Numbers:
    ``sheet_count``, ``samples``, ``spacing``, ``beta0``, ``beta1``,
    ``seconds`` (sampling to axis, of the sampling kept); ``warnings``;
    ``summary`` (the dict of summary.json; its ``seconds["end_to_end"]`` runs
    from the read to the result, every sampling of a pair-mesh included)."""

    ARRAYS = ("vertices", "radius", "offsets", "indices", "sheet", "provenance")

    def __init__(self, data, theta=5.0, rho=8.0):
        self.solid = int(data.get("solid", 0))
        self.vertices = np.asarray(data["vertices"], dtype=np.float64).reshape(-1, 3)
        self.radius = np.asarray(data["radius"], dtype=np.float64)
        self.offsets = np.asarray(data["offsets"], dtype=np.int64)
        self.indices = np.asarray(data["indices"], dtype=np.int64)
        self.sheet = np.asarray(data["sheet"], dtype=np.int64)
        self.provenance = np.asarray(data["provenance"], dtype=np.uint8)
        self.sheet_count = int(data.get("sheet_count", int(self.sheet.max()) + 1 if self.sheet.size else 0))
        self.samples = int(data.get("samples", 0))
        self.spacing = float(data.get("spacing", 0.0))
        self.beta0 = int(data.get("beta0", -1))
        self.beta1 = int(data.get("beta1", -1))
        self.seconds = float(data.get("seconds", 0.0))
        self.warnings = list(data.get("warnings", []))
        self.summary = dict(data.get("summary", {}))
        self.theta = float(theta)
        self.rho = float(rho)
        self._triangles = None
        #: The PairMesh when computed with pair_mesh=True, else None.
        self.pair_mesh = PairMesh(data["pair_mesh"]) if data.get("pair_mesh") is not None else None

    # -- sizes ---------------------------------------------------------------
    @property
    def polygon_count(self):
        return int(self.offsets.size - 1)

    @property
    def vertex_count(self):
        return int(self.vertices.shape[0])

    def polygon(self, i):
        return self.indices[self.offsets[i] : self.offsets[i + 1]]

    def __repr__(self):
        return (
            f"<MedialAxisResult solid {self.solid}: {self.vertex_count} vertices, {self.polygon_count} polygons, "
            f"{self.sheet_count} sheets, beta0/beta1 {self.beta0}/{self.beta1}, {self.samples} samples>"
        )

    # -- triangles -------------------------------------------------------------
    def triangles(self):
        """Fan triangulation of the polygons: (triangles T x 3, polygon of each
        triangle T). Triangles with a repeated vertex are left out."""
        if self._triangles is None:
            sizes = np.diff(self.offsets)
            fan = np.maximum(sizes - 2, 0)
            polygon = np.repeat(np.arange(sizes.size, dtype=np.int64), fan)
            first = self.offsets[:-1][polygon]
            within = np.arange(polygon.size, dtype=np.int64) - np.repeat(np.cumsum(fan) - fan, fan)
            tri = np.stack(
                [self.indices[first], self.indices[first + 1 + within], self.indices[first + 2 + within]], axis=1
            )
            keep = (tri[:, 0] != tri[:, 1]) & (tri[:, 1] != tri[:, 2]) & (tri[:, 0] != tri[:, 2])
            self._triangles = (tri[keep], polygon[keep])
        return self._triangles

    def sheet_sizes(self):
        """Polygons per sheet id."""
        return np.bincount(self.sheet, minlength=self.sheet_count)

    def sheet_ranks(self):
        """Rank of every sheet id by size (0 = the sheet with most polygons)."""
        order = np.argsort(-self.sheet_sizes(), kind="stable")
        ranks = np.empty_like(order)
        ranks[order] = np.arange(order.size)
        return ranks

    def submesh(self, polygon_mask):
        """(points K x 3, triangles T x 3 into points, global vertex ids K) of
        the polygons selected by a boolean mask, with unused vertices dropped."""
        tri, poly = self.triangles()
        tri = tri[polygon_mask[poly]]
        used, inverse = np.unique(tri.reshape(-1), return_inverse=True)
        return self.vertices[used], inverse.reshape(-1, 3), used

    def subset(self, polygon_mask):
        """A MedialAxisResult with only the selected polygons (vertices renumbered;
        sheet ids, provenance and the summary kept)."""
        polygon_mask = np.asarray(polygon_mask, dtype=bool)
        sizes = np.diff(self.offsets)
        slot_mask = np.repeat(polygon_mask, sizes)
        kept = self.indices[slot_mask]
        used, inverse = np.unique(kept, return_inverse=True)
        data = {
            "solid": self.solid,
            "vertices": self.vertices[used],
            "radius": self.radius[used],
            "offsets": np.concatenate([[0], np.cumsum(sizes[polygon_mask])]),
            "indices": inverse,
            "sheet": self.sheet[polygon_mask],
            "provenance": self.provenance[polygon_mask],
            "sheet_count": self.sheet_count,
            "samples": self.samples,
            "spacing": self.spacing,
            "beta0": self.beta0,
            "beta1": self.beta1,
            "seconds": self.seconds,
            "warnings": self.warnings,
            "summary": self.summary,
        }
        return MedialAxisResult(data, self.theta, self.rho)

    # -- output ------------------------------------------------------------------
    def write(self, path, format=None):
        """Writes .ply (radius per vertex, sheet and provenance per polygon),
        .obj (groups per sheet) or .ma (Q-MAT); atomically."""
        from .export import write_medial

        return write_medial(self, path, format)

    def to_mesh(self, polygon_mask=None):
        """A FreeCAD Mesh.Mesh of the (selected) polygons, fan-triangulated,
        with the vertices in the order of self.vertices (all of them if no
        mask is given). Needs FreeCAD."""
        from .document import _mesh

        if polygon_mask is None:
            return _mesh(self.vertices, self.triangles()[0])
        points, tri, _ = self.submesh(polygon_mask)
        return _mesh(points, tri)

    def to_npz(self, path):
        import json

        np.savez_compressed(
            path,
            **{name: getattr(self, name) for name in self.ARRAYS},
            meta=np.frombuffer(
                json.dumps(
                    {
                        "solid": self.solid,
                        "sheet_count": self.sheet_count,
                        "samples": self.samples,
                        "spacing": self.spacing,
                        "beta0": self.beta0,
                        "beta1": self.beta1,
                        "seconds": self.seconds,
                        "warnings": self.warnings,
                        "summary": self.summary,
                        "theta": self.theta,
                        "rho": self.rho,
                    }
                ).encode("utf-8"),
                dtype=np.uint8,
            ),
        )

    @classmethod
    def from_npz(cls, path):
        import json

        with np.load(path) as z:
            meta = json.loads(bytes(z["meta"]).decode("utf-8"))
            data = dict(meta)
            for name in cls.ARRAYS:
                data[name] = z[name]
        return cls(data, meta.get("theta", 5.0), meta.get("rho", 8.0))


class PairMesh:
    """The pair-mesh of one solid (DESIGN.md section 5): tetrahedra linking the
    inner Voronoi diagram of the samples to the boundary surface.

    Arrays: ``nodes`` (N x 3 float64), ``node_is_boundary`` (N uint8: 1 on the
    boundary, i.e. a sample; 0 a Voronoi node), ``tets`` (M x 4 int64, positive
    orientation when valid), ``types`` (M uint8: 0 face-vertex, 1 edge-edge,
    2 vertex-face; see PAIR_ELEMENT_TYPES), ``on_sheets`` (M uint8: 1 if the
    element's medial simplex is on the CAD_MEDIAL sheets), ``boundary_triangles``
    (K x 3 int64 into nodes, outward). ``report``: counts, validity, exact
    volume, repair and seconds (the "pair_mesh" block of summary.json)."""

    ARRAYS = ("nodes", "node_is_boundary", "tets", "types", "on_sheets", "boundary_triangles")
    #: The keys of report that say whether the complex is valid.
    VALIDITY_KEYS = ("valid", "pass", "inverted", "degenerate", "overlap_error", "gap_error",
                     "boundary_triangles_not_in_one_vertex_face", "boundary_edges_not_shared",
                     "enclosed_volume", "exact_volume", "volume_error",
                     "inverted_before_repair", "moved_voronoi_nodes", "welded_voronoi_nodes",
                     "split_boundary_edges", "retriangulated_voronoi_polygons", "relabelled_flat_cells",
                     "relabelled_boundary_cells",
                     "inverted_after_repair")

    def __init__(self, data):
        self.nodes = np.asarray(data["nodes"], dtype=np.float64).reshape(-1, 3)
        self.node_is_boundary = np.asarray(data["node_is_boundary"], dtype=np.uint8)
        self.tets = np.asarray(data["tets"], dtype=np.int64).reshape(-1, 4)
        self.types = np.asarray(data["types"], dtype=np.uint8)
        self.on_sheets = np.asarray(data["on_sheets"], dtype=np.uint8)
        self.boundary_triangles = np.asarray(data["boundary_triangles"], dtype=np.int64).reshape(-1, 3)
        self.report = dict(data.get("report", {}))

    @property
    def validity(self):
        """dict: valid (a partition: no inverted element, no overlap, no gap,
        closed boundary), pass (valid and enclosed volume within 1 % of the
        exact solid volume), inverted, overlap_error, gap_error, enclosed_volume,
        exact_volume (OCCT), volume_error, repair counts."""
        return {k: self.report[k] for k in self.VALIDITY_KEYS if k in self.report}

    @property
    def valid(self):
        return bool(self.report.get("valid", False))

    @property
    def seconds(self):
        """dict: classify_cells, build, repair, check, total."""
        return dict(self.report.get("seconds", {}))

    @property
    def node_count(self):
        return int(self.nodes.shape[0])

    @property
    def tet_count(self):
        return int(self.tets.shape[0])

    def counts(self):
        """Tetrahedra per type name."""
        n = np.bincount(self.types, minlength=3)
        return {name: int(n[i]) for i, name in enumerate(PAIR_ELEMENT_TYPES)}

    def volumes(self):
        """Signed volume of every tetrahedron (positive = valid)."""
        p = self.nodes[self.tets]
        return np.einsum("ij,ij->i", p[:, 1] - p[:, 0], np.cross(p[:, 2] - p[:, 0], p[:, 3] - p[:, 0])) / 6.0

    def iso_surface(self, t=0.5):
        """(points K x 3, triangles T x 3) of the iso-parametric surface at t in
        [0, 1]: 0 the medial side, 1 the boundary (exactly boundary_triangles)."""
        return iso_surface(self, t)

    def write(self, path, format=None):
        """Writes .vtu (VTK XML: cell data type / on_sheets, point data boundary)
        or TetGen (.node + .ele next to each other; `path` may end in either or
        in neither); atomically, with the command line's writers. Returns the
        path(s) written."""
        stem, ext = os.path.splitext(os.fspath(path))
        format = (format or ext.lstrip(".") or "vtu").lower()
        if format in ("node", "ele"):
            format = "tetgen"
        if format not in ("vtu", "tetgen"):
            raise ValueError(f"pair-mesh formats are 'vtu' and 'tetgen' (.node/.ele), got {format!r}")
        base = stem if format == "tetgen" and ext.lower() in (".node", ".ele") else os.fspath(path)
        _native.write_pair_mesh(base, format, self.nodes, self.node_is_boundary, self.tets, self.types,
                                self.on_sheets)
        return (base + ".node", base + ".ele") if format == "tetgen" else base

    def to_npz(self, path):
        import json

        np.savez_compressed(path, **{name: getattr(self, name) for name in self.ARRAYS},
                            meta=np.frombuffer(json.dumps({"report": self.report}).encode("utf-8"), dtype=np.uint8))

    @classmethod
    def from_npz(cls, path):
        import json

        with np.load(path) as z:
            data = {name: z[name] for name in cls.ARRAYS}
            data.update(json.loads(bytes(z["meta"]).decode("utf-8")))
        return cls(data)

    def __repr__(self):
        c = self.counts()
        return (f"<PairMesh {self.node_count} nodes, {self.tet_count} tetrahedra ({c['face_vertex']} face-vertex, "
                f"{c['edge_edge']} edge-edge, {c['vertex_face']} vertex-face), {self.report.get('inverted', '?')} "
                f"inverted, {'valid' if self.valid else 'NOT valid'}>")


def iso_surface(result, t=0.5):
    """Iso-parametric surface of a pair-mesh (a PairMesh, or a MedialAxisResult
    computed with pair_mesh=True) at t in [0, 1]: (points K x 3, triangles T x 3)."""
    mesh = result.pair_mesh if isinstance(result, MedialAxisResult) else result
    if mesh is None:
        raise ValueError("this result has no pair-mesh; compute it with pair_mesh=True")
    if not isinstance(mesh, PairMesh):
        raise TypeError(f"expected a PairMesh or a MedialAxisResult, got {type(result).__name__}")
    if isinstance(t, bool) or not isinstance(t, (int, float)) or not 0.0 <= t <= 1.0:
        raise ValueError(f"t must be a number in [0, 1] (0 medial side, 1 boundary), got {t!r}")
    d = _native.iso_surface(mesh.nodes, mesh.tets, mesh.types, float(t))
    return d["points"], d["triangles"]


class SampleResult:
    """Boundary samples of one solid: ``points`` (N x 3), ``kind`` (0 face,
    1 edge, 2 vertex), ``owner``, ``on_convex_edge``, ``nonconcave_corner``,
    ``triplets`` (T x 3), ``triangles`` (M x 3, the stitched boundary
    reconstruction), ``triangle_face``, ``spacing``, ``warnings``, ``report``."""

    def __init__(self, data):
        self.__dict__.update(data)

    def __len__(self):
        return int(self.points.shape[0])

    def __repr__(self):
        return (
            f"<SampleResult solid {self.solid}: {len(self)} samples, {self.triplets.shape[0]} triplets, "
            f"{self.triangles.shape[0]} boundary triangles, spacing {self.spacing:.4g}>"
        )


def _check_params(spacing, theta, rho):
    for name, value in (("spacing", spacing), ("theta", theta), ("rho", rho)):
        if not isinstance(value, (int, float)) or isinstance(value, bool) or not math.isfinite(value):
            raise ValueError(f"{name} must be a finite number, got {value!r}")


def _check_flags(**flags):
    for name, value in flags.items():
        if not isinstance(value, (bool, np.bool_)):
            raise ValueError(f"{name} must be True or False, got {value!r}")


#: File name endings that `cadmedial run` and compute() treat as point clouds / meshes.
POINT_EXTENSIONS = (".xyz", ".pts", ".ply", ".stl", ".obj", ".off")
#: MEDIAL's Angle threshold for point clouds (pi/8, seed 000); CAD_MEDIAL uses 5 degrees.
POINT_CLOUD_THETA = 22.5


def _vectors_to_array(vectors):
    return np.array([[v.x, v.y, v.z] for v in vectors], dtype=np.float64).reshape(-1, 3)


def point_source(source):
    """(points N x 3, triangles M x 3 or None) if `source` is a point cloud or
    a mesh, else None. Accepts an N x 3 array, a (points, triangles) pair, a
    .xyz/.pts/.ply/.stl/.obj/.off file name, a FreeCAD Points or Mesh object
    (Points::Feature, Mesh::Feature: global coordinates, their Placement
    applied) or a Points.Points / Mesh.Mesh kernel object."""
    if isinstance(source, np.ndarray):
        return np.asarray(source, dtype=np.float64).reshape(-1, 3), None
    if isinstance(source, tuple) and len(source) == 2:
        points, triangles = source
        return (np.asarray(points, dtype=np.float64).reshape(-1, 3),
                None if triangles is None else np.asarray(triangles, dtype=np.int64).reshape(-1, 3))
    if isinstance(source, (str, os.PathLike)):
        path = os.fspath(source)
        if "\n" not in path and path.lower().endswith(POINT_EXTENSIONS):
            data = _native.read_points(path)
            triangles = data["triangles"]
            return data["points"], (triangles if triangles.shape[0] else None)
        return None
    if hasattr(source, "TypeId") and hasattr(source, "Document"):  # a FreeCAD document object
        for name in ("Mesh", "Points"):
            if name in getattr(source, "PropertiesList", ()) and "Shape" not in source.PropertiesList:
                kernel = getattr(source, name).copy()
                placement = getattr(source, "Placement", None)
                if placement is not None and hasattr(kernel, "Placement"):
                    kernel.Placement = placement  # the object's placement: global coordinates
                return point_source(kernel)
        return None
    if hasattr(source, "Topology") and hasattr(source, "Facets"):  # Mesh.Mesh
        vertices, facets = source.Topology
        return _vectors_to_array(vertices), np.asarray(facets, dtype=np.int64).reshape(-1, 3)
    if hasattr(source, "Points") and hasattr(source, "addPoints"):  # Points.Points
        return _vectors_to_array(source.Points), None
    return None


def compute_points(source, theta=POINT_CLOUD_THETA, rho=8.0, progress=None, cancel=None):
    """MEDIAL (seed 000) on points alone; one MedialAxisResult in a list.

    source: see point_source(). A bare point cloud gives the whole medial
    axis, inner and outer (result.summary["axis"] == "whole"); a closed,
    consistently oriented mesh gives its inner axis ("inner");
    result.summary["axis_note"] says why.
    """
    _check_params(0.0, theta, rho)
    data = point_source(source)
    if data is None:
        raise TypeError(f"cannot use a {type(source).__name__} as a point source: expected an N x 3 array, "
                        "(points, triangles), a point/mesh file or a FreeCAD Points/Mesh object")
    points, triangles = data
    raw = _native.compute_points(points, triangles, float(theta), float(rho), _with_cancel(progress, cancel))
    return [MedialAxisResult(raw, theta, rho)]


def compute(source, spacing=0.0, theta=None, rho=8.0, pair_mesh=False, check_inside=True, progress=None, cancel=None,
            graded_spacing=True):
    """Inner medial axis of every closed solid of `source`; one MedialAxisResult per solid.
    Point clouds and meshes (see point_source) go to compute_points (MEDIAL).

    source: FreeCAD object / Part.Shape / file name / BREP text.
    spacing: sample spacing in model units (0 = bounding-box diagonal / 40).
    theta (degrees), rho: the Angle and Ratio conditions of CAD_MEDIAL
      (theta None: 5 for solids, 22.5 for point clouds and meshes).
    pair_mesh: also build the pair-mesh (DESIGN.md section 5) on the same
      triangulation; each result then has .pair_mesh (a PairMesh). Needs a
      B-rep solid: ValueError for point clouds and meshes. Adds the stage
      "pair_mesh" (exact OCCT inner labels, construction, repair, validity).
      A pair-mesh that is not valid at the spacing asked makes the solid be
      sampled again at 0.97 times it, then with every spacing 0.94 times (the
      stages "sample", "medial", "pair_mesh" come again; only "sample" for an
      attempt that gives the samples of the one before, which stops there);
      the first valid attempt is returned, axis and
      pair-mesh together (.spacing is the one kept), and
      pair_mesh.report["attempts"] lists every attempt.
    check_inside: count disagreements of the inner/outer walk with OCCT's exact
      classifier (summary["diagnostics"]["walk_oracle_disagreements"]).
    progress(stage, solid, solids): called between stages ("read", "sample",
      "medial", "pair_mesh", "done"); return False to stop (raises Cancelled).
    cancel: a threading.Event (or anything with is_set()); when set, the run
      stops at the next stage boundary with Cancelled.
    graded_spacing: grade the sample spacing within each face, fine only where
      curvature or a thin wall needs it (the default); False samples each face
      at one spacing, the finest it needs anywhere (`cadmedial run
      --uniform-spacing`, the behaviour before 2026-12-02).

    The GIL is released while C++ runs, so this can run in a worker thread.
    Raises InputError (a ValueError) for unreadable input or no closed solid.
    """
    _check_flags(pair_mesh=pair_mesh, graded_spacing=graded_spacing)
    if not (hasattr(source, "exportBrepToString") or isinstance(source, bytes)) and point_source(source) is not None:
        if pair_mesh:
            raise ValueError(PAIR_MESH_MESSAGE)
        return compute_points(source, POINT_CLOUD_THETA if theta is None else theta, rho, progress, cancel)
    theta = 5.0 if theta is None else theta
    _check_params(spacing, theta, rho)
    raw = _native.compute(
        to_source(source), float(spacing), float(theta), float(rho), bool(check_inside), _with_cancel(progress, cancel),
        pair_mesh=bool(pair_mesh), graded_spacing=bool(graded_spacing),
    )
    return [MedialAxisResult(d, theta, rho) for d in raw]


def evaluate(source, result, solid=None, tolerance=0.005):
    """Measures `result` (a MedialAxisResult) against the exact B-rep of solid
    `solid` of `source` (default: result.solid), as `cadmedial eval` does
    (DESIGN.md section 6). Returns the eval.json dict: inside, medialness,
    coverage, attachment, topology, thresholds and pass (per check and "all").
    tol = tolerance x the bounding-box diagonal. Convex creases turning by
    less than 2 theta (result's theta) are left out of the edge attachment
    and reported apart (attachment: shallow_length)."""
    index = result.solid if solid is None else int(solid)
    if index < 0:
        raise ValueError(f"solid must be >= 0, got {index}")
    return _native.evaluate(
        to_source(source), index, result.vertices, result.radius, result.offsets, result.indices,
        result.sheet, result.provenance, float(tolerance), float(result.theta),
    )


def resampling_line(attempts):
    """A pair-mesh report's "attempts" as one line ("not valid at spacing 8.93
    (1 inverted), sampled again at 8.662 (valid); kept 8.662"), the line
    `cadmedial run` prints; "" when the solid was sampled once."""
    return _native.resampling_line(json.dumps(list(attempts)))


def evaluation_lines(report):
    """The eval.json dict of evaluate() as readable lines (the eval table)."""
    def mark(key):
        return "ok" if report["pass"][key] else "FAIL"

    med, cov, att, top = report["medialness"], report["coverage"], report["attachment"], report["topology"]
    shallow = []
    if att["shallow_length"] > 0 or att["shallow_corners"] > 0:
        attached = 100 * att["shallow_attached_length"] / att["shallow_length"] if att["shallow_length"] > 0 else 100
        shallow = [
            f"shallow creases (turning < {att['shallow_below_deg']:g} deg = 2 theta; left out of the edge and "
            f"corner figures): {att['shallow_length']:.4g} of {att['convex_length']:.4g} convex length, "
            f"{attached:.1f} % attached; {att['shallow_attached_corners']}/{att['shallow_corners']} corners"
        ]
    return [
        f"tol = {report['tolerance']:.4g} ({100 * report['tolerance_fraction']:.2g} % of the diagonal "
        f"{report['diagonal']:.4g})",
        f"inside: {100 * report['inside']['share']:.2f} % of the sheet area [{mark('inside')}]",
        f"medialness |d - r| / diagonal: median {100 * med['median']:.3f} %, p90 {100 * med['p90']:.3f} %, "
        f"max {100 * med['max']:.3f} % [{mark('medialness')}]",
        f"two contacts: {100 * med['two_contact_share']:.1f} % of vertices [{mark('two_contacts')}]",
        f"coverage: {100 * cov['share']:.2f} % of {cov['points']} boundary points [{mark('coverage')}]",
        f"convex edges attached: {100 * att['edge_share']:.2f} % of their steep length [{mark('edges')}]",
        *shallow,
        f"non-concave corners attached: {att['attached_corners']}/{att['corners']} [{mark('corners')}]",
        f"topology: beta0 {top['medial']['beta0']}, beta1 {top['medial']['beta1']} "
        f"(solid {top['solid']['beta0']}, {top['solid']['beta1']}) [{mark('topology')}]",
        "verdict: " + ("PASS" if report["pass"]["all"] else "FAIL"),
    ]


def sample(source, spacing=0.0, progress=None, cancel=None, graded_spacing=True):
    """Boundary samples of every closed solid of `source`; one SampleResult per solid.
    graded_spacing: as for compute()."""
    _check_params(spacing, 5.0, 8.0)
    _check_flags(graded_spacing=graded_spacing)
    raw = _native.sample(to_source(source), float(spacing), _with_cancel(progress, cancel),
                         graded_spacing=bool(graded_spacing))
    return [SampleResult(d) for d in raw]


def solids_brep(source):
    """The closed solids of `source` as BREP text, one string each, and the
    reading's warnings: {"solids": [...], "warnings": [...]}. A shape without
    a solid (a closed shell, loose faces, IGES trimmed surfaces) has its
    faces sewn into solids, as `cadmedial run` does. Raises InputError if
    there is none."""
    return _native.solids_brep(to_source(source))


def inspect(source):
    """Per closed solid: default_spacing, area, volume, bbox_diagonal (fast, no sampling)."""
    return _native.inspect(to_source(source))


# Sample counts per unit of area / h_face^2 and of edge length / h_edge,
# fitted on the bundled models at 0.5, 1 and 2 x the default spacing
# (plugin/tools/calibrate_estimate.py: within 10 %, mostly within 2 %).
_FACE_DENSITY = 1.0056
_EDGE_DENSITY = 1.0281
_MIN_SPACING_FRACTION = 1.0 / 16


def _face_min_radius(face):
    """Smallest principal radius of curvature of a face (inf if flat), from the
    surface type where it is known, else from a 5 x 5 UV probe."""
    surface = face.Surface
    kind = type(surface).__name__
    if kind == "Plane":
        return math.inf
    if kind in ("Cylinder", "Sphere"):
        return float(surface.Radius)
    if kind == "Cone":
        return max(float(surface.Radius), 1e-9) if surface.Radius > 0 else math.inf
    if kind == "Toroid":
        return float(surface.MinorRadius)
    u0, u1, v0, v1 = face.ParameterRange
    best = math.inf
    for i in range(5):
        for j in range(5):
            u = u0 + (u1 - u0) * (i + 0.5) / 5
            v = v0 + (v1 - v0) * (j + 0.5) / 5
            try:
                k1, k2 = face.curvatureAt(u, v)
            except Exception:  # noqa: BLE001 - undefined curvature at a pole
                continue
            k = max(abs(k1), abs(k2))
            if k > 1e-12:
                best = min(best, 1.0 / k)
    return best


def estimate_samples(shape, spacing=0.0):
    """Quick estimate of the sample count of a FreeCAD solid at `spacing`
    (0 = default), from face areas, curvature and edge lengths; no sampling.
    Follows the uniform spacing rules of sampling/ (curved faces down to 0.2 x
    radius, never below h/16): an upper bound for the default graded sampling."""
    box = shape.BoundBox
    h = float(spacing) if spacing and spacing > 0 else box.DiagonalLength / 40.0
    if h <= 0:
        return 0
    face_count = 0.0
    for face in shape.Faces:
        hf = min(h, 0.2 * _face_min_radius(face))
        hf = max(hf, h * _MIN_SPACING_FRACTION)
        face_count += _FACE_DENSITY * face.Area / (hf * hf)
    edge_count = 0.0
    for edge in shape.Edges:
        radius = math.inf
        try:
            curve = edge.Curve
            if hasattr(curve, "Radius"):
                radius = float(curve.Radius)
        except Exception:  # noqa: BLE001
            pass
        he = max(min(h, 0.2 * radius), h * _MIN_SPACING_FRACTION)
        edge_count += _EDGE_DENSITY * edge.Length / he
    return int(round(face_count + edge_count + len(shape.Vertexes)))
