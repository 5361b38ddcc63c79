"""Parametric FreeCAD objects for the pair-mesh (DESIGN.md sections 5, 5b).

PairMesh (Fem::FemMeshObjectPython)
    The pair-mesh of one solid of a source object (Source, SolidIndex) at
    Spacing / Theta / Rho (the CAD_MEDIAL parameters decide which elements are
    "on sheets"). Its FemMesh holds the tetrahedra (node ids = array index + 1,
    element ids = tetrahedron index + 1) with one FEM volume group per element
    type: FaceVertex, EdgeEdge, VertexFace. `Elements` picks which types the
    FemMesh holds, to look at one type on its own (the stored result and the
    export always hold all). Read-only statistics: counts per type, validity
    (Inverted, OverlapError, GapError, Valid), EnclosedVolume against the
    exact OCCT ExactVolume (VolumeError, in %), repair counts, Seconds. The
    arrays are kept in ResultData (an .npz inside the .FCStd).
PairMeshIsoSurface (Mesh::FeaturePython)
    The iso-parametric surface of a PairMesh at T in [0, 1] (0 the medial
    side, 1 the boundary surface).

Changing the source shape or a parameter recomputes the pair-mesh; a
recompute whose inputs are unchanged reuses the stored result.

A PairMesh may follow a MedialAxis (its `MedialAxis` link, set by the
MedialAxis' BuildPairMesh property): then Source, SolidIndex, Spacing, Theta
and Rho are read-only copies of the MedialAxis' values, refreshed at every
recompute, and the link makes FreeCAD recompute the pair-mesh after its
MedialAxis. sync_pair_mesh() creates / releases that child.
"""

import tempfile
import os

import FreeCAD as App
import numpy as np

from . import api
from .document import (
    GRADED_SPACING_DOC,
    FeatureProxy,
    _ViewProviderBase,
    _add_property,
    _mesh,
    cached_result,
    input_signature,
    is_medial,
    remember_result,
    source_solid,
    source_solids,
)

PAIR_MESH_TYPE = "PairMesh"
ISO_TYPE = "PairMeshIsoSurface"
#: FEM group names per element type code.
GROUP_NAMES = ("FaceVertex", "EdgeEdge", "VertexFace")
ELEMENT_CHOICES = ["All"] + list(GROUP_NAMES)
#: Element colours per type in the 3D view (face-vertex blue, edge-edge orange, vertex-face green).
TYPE_COLORS = ((0.26, 0.52, 0.96), (1.0, 0.6, 0.2), (0.3, 0.75, 0.35))


def is_pair_mesh(obj):
    return _proxy_type(obj) == PAIR_MESH_TYPE


def is_iso_surface(obj):
    return _proxy_type(obj) == ISO_TYPE


def _proxy_type(obj):
    try:
        return getattr(obj.Proxy, "Type", None)
    except Exception:  # noqa: BLE001 - deleted objects, objects without Proxy
        return None


def pair_signature(brep, spacing, theta, rho, graded_spacing=False):
    return "pair|" + input_signature(brep, spacing, theta, rho, False, graded_spacing)


def get_pair_mesh(obj):
    """The api.PairMesh of a PairMesh object (or of an iso-surface's PairMesh):
    from memory, else from its ResultData file; None if never computed."""
    if is_iso_surface(obj):
        obj = obj.PairMesh
    if obj is None or not is_pair_mesh(obj):
        return None
    mesh = cached_result(obj.InputSignature) if obj.InputSignature else None
    if mesh is None and obj.ResultData and os.path.isfile(obj.ResultData):
        mesh = api.PairMesh.from_npz(obj.ResultData)
        if obj.InputSignature:
            remember_result(obj.InputSignature, mesh)
    return mesh


def validity_lines(mesh):
    """The validity of an api.PairMesh as readable lines (Report view)."""
    r = mesh.report
    c = mesh.counts()
    seconds = mesh.seconds
    err = r.get("volume_error")
    lines = [
        f"{mesh.node_count} nodes ({int(mesh.node_is_boundary.sum())} on the boundary), {mesh.tet_count} tetrahedra: "
        f"{c['face_vertex']} face-vertex, {c['edge_edge']} edge-edge, {c['vertex_face']} vertex-face; "
        f"{r.get('on_sheets', 0)} on the medial sheets",
        f"inverted: {r.get('inverted')} (before repair {r.get('inverted_before_repair')}, "
        f"{r.get('moved_voronoi_nodes')} Voronoi nodes moved), degenerate {r.get('degenerate')}",
        f"overlap error {r.get('overlap_error', float('nan')):.3g}, gap error {r.get('gap_error', float('nan')):.3g}, "
        f"boundary: {r.get('boundary_triangles')} triangles, "
        f"{r.get('boundary_triangles_not_in_one_vertex_face')} not in one vertex-face element, "
        f"{r.get('boundary_edges_not_shared')} open edges",
        f"enclosed volume {r.get('enclosed_volume', 0):.6g}, exact (OCCT) {r.get('exact_volume', 0):.6g}, "
        f"error {'n/a' if err is None else f'{100 * err:.3g} %'}",
        f"time: classify cells {seconds.get('classify_cells', 0):.2f} s, build {seconds.get('build', 0):.2f} s, "
        f"repair {seconds.get('repair', 0):.2f} s, check {seconds.get('check', 0):.2f} s",
        "verdict: " + ("valid" if mesh.valid else "NOT valid") + (", PASS" if r.get("pass") else ", FAIL"),
    ]
    attempts = r.get("attempts") or []
    if len(attempts) > 1:  # not valid at the spacing asked: sampled again finer (cli/solid_run.hpp)
        lines.append(api.resampling_line(attempts))
    return lines


def fem_mesh(mesh, elements="All"):
    """A Fem.FemMesh of an api.PairMesh: node id = index + 1, element id =
    tetrahedron index + 1, one volume group per element type present.
    elements: "All" or one of GROUP_NAMES (only that type)."""
    import Fem

    fm = Fem.FemMesh()
    for i, (x, y, z) in enumerate(mesh.nodes.tolist(), start=1):
        fm.addNode(x, y, z, i)
    keep = np.ones(mesh.tet_count, dtype=bool)
    if elements != "All":
        keep = mesh.types == GROUP_NAMES.index(elements)
    ids = np.flatnonzero(keep)
    for i, quad in zip(ids.tolist(), (mesh.tets[ids] + 1).tolist()):
        fm.addVolume(quad, i + 1)
    types = mesh.types[ids]
    for code, name in enumerate(GROUP_NAMES):
        members = ids[types == code] + 1
        if members.size:
            group = fm.addGroup(name, "Volume")
            fm.addGroupElements(group, members.tolist())
    return fm


def prebuild_fem_mesh(mesh):
    """Builds the "All" FemMesh and the compressed ResultData file of an
    api.PairMesh ahead of time (a GUI does it in its worker thread);
    PairMeshFeature takes them instead of making them in the main thread."""
    mesh.prebuilt_fem = fem_mesh(mesh, "All")
    handle, path = tempfile.mkstemp(prefix="pairmesh_", suffix=".npz")
    os.close(handle)
    mesh.to_npz(path)
    mesh.prebuilt_npz = path
    return mesh.prebuilt_fem


class PairMeshFeature(FeatureProxy):
    Type = PAIR_MESH_TYPE

    def __init__(self, obj):
        obj.Proxy = self
        self.setup(obj)

    def setup(self, obj):
        p = _add_property
        p(obj, "App::PropertyLink", "Source", "Pair Mesh", "The object whose solid is meshed")
        p(obj, "App::PropertyInteger", "SolidIndex", "Pair Mesh", "Which solid of the source (0 = first)", 0)
        p(obj, "App::PropertyLength", "Spacing", "Pair Mesh",
          "Target sample spacing in model units; 0 = automatic (bounding-box diagonal / 40)", 0.0)
        p(obj, "App::PropertyBool", "GradedSpacing", "Pair Mesh", GRADED_SPACING_DOC, False)
        p(obj, "App::PropertyAngle", "Theta", "Pair Mesh", "Angle condition of CAD_MEDIAL (for OnSheets)", 5.0)
        p(obj, "App::PropertyFloat", "Rho", "Pair Mesh", "Ratio condition of CAD_MEDIAL (for OnSheets)", 8.0)
        p(obj, "App::PropertyLink", "MedialAxis", "Pair Mesh",
          "The MedialAxis whose BuildPairMesh made this object: source and parameters follow it", None, 1)
        set_follow_modes(obj)
        if "Elements" not in obj.PropertiesList:
            obj.addProperty("App::PropertyEnumeration", "Elements", "Display",
                            "Element types the FEM mesh holds (to look at one type alone); export holds all")
            obj.Elements = ELEMENT_CHOICES
            obj.Elements = "All"
        stats = "Statistics"
        for name, doc in (("Nodes", "Nodes (samples and Voronoi nodes)"),
                          ("BoundaryNodes", "Nodes on the boundary (samples)"),
                          ("Tetrahedra", "All tetrahedra"), ("FaceVertex", "Face-vertex tetrahedra"),
                          ("EdgeEdge", "Edge-edge tetrahedra"), ("VertexFace", "Vertex-face tetrahedra"),
                          ("OnSheets", "Tetrahedra whose medial simplex is on the CAD_MEDIAL sheets"),
                          ("BoundaryTriangles", "Triangles of the boundary surface"),
                          ("Inverted", "Tetrahedra with negative volume after the repair (must be 0)"),
                          ("InvertedBeforeRepair", "Negative tetrahedra before the repair"),
                          ("MovedNodes", "Voronoi nodes moved by the repair")):
            p(obj, "App::PropertyInteger", name, stats, doc, 0, 1)
        p(obj, "App::PropertyFloat", "OverlapError", stats, "(sum |vol| - |sum vol|) / enclosed volume", 0.0, 1)
        p(obj, "App::PropertyFloat", "GapError", stats, "|sum vol - enclosed| / enclosed volume", 0.0, 1)
        p(obj, "App::PropertyFloat", "EnclosedVolume", stats, "Volume enclosed by the boundary triangles", 0.0, 1)
        p(obj, "App::PropertyFloat", "ExactVolume", stats, "Exact volume of the solid (OCCT)", 0.0, 1)
        p(obj, "App::PropertyFloat", "VolumeError", stats, "|enclosed - exact| / exact, in percent", 0.0, 1)
        p(obj, "App::PropertyBool", "Valid", stats,
          "No inverted element, no overlap, no gap, closed boundary", False, 1)
        p(obj, "App::PropertyFloat", "Seconds", stats, "Wall time of the last computation", 0.0, 1)
        p(obj, "App::PropertyLength", "SpacingUsed", stats, "Sample spacing used", 0.0, 1)
        p(obj, "App::PropertyFileIncluded", "ResultData", "Result", "The pair-mesh arrays (.npz)", None, 2)
        p(obj, "App::PropertyString", "InputSignature", "Result", "Inputs of the stored result", None, 2)

    def onChanged(self, obj, prop):
        # Only the FemMesh changes: no new computation.
        if prop == "Elements" and "Restore" not in obj.State and "ResultData" in obj.PropertiesList:
            mesh = get_pair_mesh(obj) if obj.ResultData else None
            if mesh is not None:
                obj.FemMesh = fem_mesh(mesh, obj.Elements)

    def execute(self, obj):
        import time

        follow_medial_axis(obj)
        solid = source_solid(obj.Source, obj.SolidIndex)
        spacing, theta, rho = float(obj.Spacing.Value), float(obj.Theta.Value), float(obj.Rho)
        brep = solid.exportBrepToString()
        graded = bool(obj.GradedSpacing)
        signature = pair_signature(brep, spacing, theta, rho, graded)
        mesh = get_pair_mesh(obj) if signature == obj.InputSignature else None
        if mesh is None:
            mesh = cached_result(signature)
        fresh = mesh is None
        if fresh:
            start = time.perf_counter()
            results = api.compute(brep, spacing=spacing, theta=theta, rho=rho, check_inside=False, pair_mesh=True,
                                  graded_spacing=graded)
            if not results:
                raise ValueError(f"{obj.Label}: no closed solid in '{obj.Source.Label}'")
            mesh = results[0].pair_mesh
            mesh.report["wall_seconds"] = time.perf_counter() - start
            remember_result(signature, mesh)
        # Same inputs and the FemMesh already built: nothing to redo (building
        # the FemMesh costs about as much as computing a small pair-mesh).
        unchanged = signature == obj.InputSignature and obj.ResultData and self._fem_matches(obj, mesh)
        if signature != obj.InputSignature or not obj.ResultData:
            self.store(obj, mesh, signature)
        if not unchanged:
            self.apply(obj, mesh)
        if fresh:
            report = App.Console.PrintMessage if mesh.valid else App.Console.PrintWarning
            report(f"{obj.Label}: pair-mesh\n")
            for line in validity_lines(mesh):
                report(f"  {line}\n")

    @staticmethod
    def _fem_matches(obj, mesh):
        wanted = mesh.tet_count if obj.Elements == "All" else int(
            (mesh.types == GROUP_NAMES.index(obj.Elements)).sum())
        return obj.FemMesh.VolumeCount == wanted and obj.FemMesh.NodeCount == mesh.node_count and obj.Tetrahedra == \
            mesh.tet_count

    def store(self, obj, mesh, signature):
        path = getattr(mesh, "prebuilt_npz", None)
        mesh.prebuilt_npz = None  # used once
        if path is None or not os.path.isfile(path):
            handle, path = tempfile.mkstemp(prefix="pairmesh_", suffix=".npz")
            os.close(handle)
            mesh.to_npz(path)
        try:
            obj.ResultData = path  # FreeCAD copies it into the document
        finally:
            os.remove(path)
        obj.InputSignature = signature

    def apply(self, obj, mesh):
        prebuilt = getattr(mesh, "prebuilt_fem", None) if obj.Elements == "All" else None
        obj.FemMesh = prebuilt if prebuilt is not None else fem_mesh(mesh, obj.Elements)
        mesh.prebuilt_fem = None  # used once; the object holds its own copy
        r = mesh.report
        c = mesh.counts()
        obj.Nodes = mesh.node_count
        obj.BoundaryNodes = int(mesh.node_is_boundary.sum())
        obj.Tetrahedra = mesh.tet_count
        obj.FaceVertex, obj.EdgeEdge, obj.VertexFace = c["face_vertex"], c["edge_edge"], c["vertex_face"]
        obj.OnSheets = int(mesh.on_sheets.sum())
        obj.BoundaryTriangles = int(mesh.boundary_triangles.shape[0])
        obj.Inverted = int(r.get("inverted", -1))
        obj.InvertedBeforeRepair = int(r.get("inverted_before_repair", -1))
        obj.MovedNodes = int(r.get("moved_voronoi_nodes", 0))
        obj.OverlapError = float(r.get("overlap_error", 0.0))
        obj.GapError = float(r.get("gap_error", 0.0))
        obj.EnclosedVolume = float(r.get("enclosed_volume", 0.0))
        obj.ExactVolume = float(r.get("exact_volume", 0.0))
        err = r.get("volume_error")
        obj.VolumeError = -1.0 if err is None else 100.0 * float(err)
        obj.Valid = mesh.valid
        obj.Seconds = round(float(r.get("wall_seconds", mesh.seconds.get("total", 0.0))), 3)
        obj.SpacingUsed = float(r.get("spacing", 0.0))


FOLLOWED = ("Source", "SolidIndex", "Spacing", "GradedSpacing", "Theta", "Rho")
# Followed properties that documents saved before them lack (a MedialAxis
# restored after its PairMesh may not have them yet), with the value they
# stood for then.
ADDED_LATER = {"GradedSpacing": False}


def set_follow_modes(obj):
    """The copied parameters are read-only while the object follows a MedialAxis
    (an edit would be overwritten at the next recompute)."""
    following = getattr(obj, "MedialAxis", None) is not None
    for name in FOLLOWED:
        if name in obj.PropertiesList:
            obj.setEditorMode(name, 1 if following else 0)


def follow_medial_axis(obj):
    """Copies Source, SolidIndex, Spacing, GradedSpacing, Theta, Rho from the linked MedialAxis
    (if any) into a PairMesh object; only values that differ are set."""
    medial = getattr(obj, "MedialAxis", None)
    if medial is None:
        return
    if not is_medial(medial):
        raise ValueError(f"{obj.Label}: its MedialAxis link is not a MedialAxis object")
    if medial.Source is None or "Shape" not in medial.Source.PropertiesList:
        raise ValueError(f"{obj.Label}: '{medial.Label}' has no B-rep source; {api.PAIR_MESH_MESSAGE}")
    if obj.Source != medial.Source:
        obj.Source = medial.Source
    for name in FOLLOWED[1:]:
        value = getattr(medial, name, ADDED_LATER[name]) if name in ADDED_LATER else getattr(medial, name)
        value = getattr(value, "Value", value)  # Quantity -> float
        if getattr(getattr(obj, name), "Value", getattr(obj, name)) != value:
            setattr(obj, name, value)


def pair_mesh_children(medial):
    """The PairMesh objects that follow a MedialAxis (made by its BuildPairMesh)."""
    return [o for o in medial.InList if is_pair_mesh(o) and getattr(o, "MedialAxis", None) == medial]


def release_pair_mesh(pm):
    """Stops a PairMesh following its MedialAxis and removes it, unless another
    object uses it (an iso-surface, a FEM analysis): then it stays as a
    standalone PairMesh with the last parameters and the user is told."""
    medial = pm.MedialAxis
    users = [o for o in pm.InList if o != medial]
    if users:
        pm.MedialAxis = None
        set_follow_modes(pm)
        App.Console.PrintMessage(
            f"{pm.Label}: kept as a standalone pair-mesh (used by {', '.join(o.Label for o in users)}); "
            f"it no longer follows '{medial.Label if medial else '?'}'\n")
        return False
    pm.Document.removeObject(pm.Name)
    return True


def sync_pair_mesh(medial):
    """Makes the pair-mesh child of a MedialAxis match its BuildPairMesh: creates
    one (not computed: the next recompute does that) or releases it. Returns the
    child or None. Call it outside a recompute (MedialAxisFeature.onChanged
    does, or the document observer after the recompute)."""
    kids = pair_mesh_children(medial)
    if not getattr(medial, "BuildPairMesh", False):
        for pm in kids:
            release_pair_mesh(pm)
        return None
    if kids:
        return kids[0]
    source = medial.Source
    if source is None or "Shape" not in source.PropertiesList:
        raise ValueError(f"'{medial.Label}' was made from points or a mesh; {api.PAIR_MESH_MESSAGE}")
    doc = medial.Document
    pm = doc.addObject("Fem::FemMeshObjectPython", "PairMesh")
    PairMeshFeature(pm)
    if App.GuiUp:
        ViewProviderPairMesh(pm.ViewObject)
    pm.Label = f"{medial.Label} pair-mesh"
    pm.MedialAxis = medial
    follow_medial_axis(pm)
    set_follow_modes(pm)
    return pm


class IsoSurfaceFeature(FeatureProxy):
    Type = ISO_TYPE

    def __init__(self, obj):
        obj.Proxy = self
        self.setup(obj)

    def setup(self, obj):
        p = _add_property
        p(obj, "App::PropertyLink", "PairMesh", "Iso-surface", "The PairMesh object")
        if "T" not in obj.PropertiesList:
            obj.addProperty("App::PropertyFloatConstraint", "T", "Iso-surface",
                            "Parameter of the surface: 0 the medial side, 1 the boundary surface")
            obj.T = (0.5, 0.0, 1.0, 0.05)
        p(obj, "App::PropertyInteger", "Triangles", "Statistics", "Triangles of the surface", 0, 1)

    def execute(self, obj):
        mesh = get_pair_mesh(obj.PairMesh)
        if mesh is None:
            raise ValueError(f"{obj.Label}: link a computed PairMesh object")
        points, triangles = api.iso_surface(mesh, float(obj.T))
        obj.Mesh = _mesh(points, triangles)
        obj.Triangles = int(triangles.shape[0])


# ---------------------------------------------------------------------------
# View providers (GUI only)


class ViewProviderPairMesh:
    """Colours the elements by type (face-vertex blue, edge-edge orange,
    vertex-face green)."""

    def __init__(self, vobj):
        vobj.Proxy = self

    def attach(self, vobj):
        self.Object = vobj.Object

    def getIcon(self):
        from .document import icon_path

        return icon_path("PairMesh.svg")

    def updateData(self, obj, prop):
        if prop == "FemMesh":
            self.color_by_type(obj)

    @staticmethod
    def color_by_type(obj):
        vobj = getattr(obj, "ViewObject", None)
        mesh = get_pair_mesh(obj) if obj.ResultData else None
        if vobj is None or mesh is None or not hasattr(vobj, "ElementColor"):
            return
        ids = np.arange(1, mesh.tet_count + 1)
        if obj.Elements != "All":
            ids = ids[mesh.types == GROUP_NAMES.index(obj.Elements)]
        try:
            types = mesh.types[ids - 1].tolist()
            vobj.ElementColor = {i: TYPE_COLORS[k] for i, k in zip(ids.tolist(), types)}
        except Exception as e:  # noqa: BLE001 - colours are cosmetic
            App.Console.PrintWarning(f"{obj.Label}: no colours by element type ({e})\n")

    def onChanged(self, vobj, prop):
        return None

    def claimChildren(self):
        obj = getattr(self, "Object", None)
        if obj is None:
            return []
        return [o for o in obj.InList if is_iso_surface(o)]

    def onDelete(self, vobj, subelements):
        # Deleting the child of a MedialAxis in the GUI also switches its
        # BuildPairMesh off, or the property would claim a pair-mesh that is
        # gone. Unlink first, so the MedialAxis' onChanged finds no child to
        # release (the delete command removes this object itself).
        obj = vobj.Object
        medial = getattr(obj, "MedialAxis", None)
        if medial is not None:
            obj.MedialAxis = None
            if getattr(medial, "BuildPairMesh", False):
                medial.BuildPairMesh = False
        return True

    def __getstate__(self):
        return None

    def __setstate__(self, state):
        return None

    def dumps(self):
        return None

    def loads(self, state):
        return None


class ViewProviderIsoSurface(_ViewProviderBase):
    icon = "IsoSurface.svg"


def ensure_view_provider(obj):
    """Our view provider for objects saved without the GUI (see document.ensure_view_provider)."""
    if not App.GuiUp:
        return
    from PySide2 import QtCore

    doc_name, name = obj.Document.Name, obj.Name

    def attach():
        doc = App.listDocuments().get(doc_name)
        target = doc.getObject(name) if doc is not None else None
        vobj = getattr(target, "ViewObject", None) if target is not None else None
        if vobj is None or isinstance(getattr(vobj, "Proxy", None), (ViewProviderPairMesh, ViewProviderIsoSurface)):
            return
        proxy = ViewProviderPairMesh(vobj) if is_pair_mesh(target) else ViewProviderIsoSurface(vobj)
        if getattr(proxy, "Object", None) is None:
            proxy.attach(vobj)
        if is_pair_mesh(target):
            ViewProviderPairMesh.color_by_type(target)
        target.touch()
        target.purgeTouched()

    QtCore.QTimer.singleShot(0, attach)


# ---------------------------------------------------------------------------
# Creating objects


def pair_mesh_sources(obj):
    """(source, solid indices, parameters) for a solid object or a MedialAxis
    object (its source, solid and parameters); ValueError with the reason
    otherwise."""
    if is_medial(obj):
        if obj.Source is None:
            raise ValueError(f"'{obj.Label}' has no source solid")
        if "Shape" not in obj.Source.PropertiesList:
            raise ValueError(f"'{obj.Label}' was made from points or a mesh; {api.PAIR_MESH_MESSAGE}")
        return obj.Source, [obj.SolidIndex], dict(spacing=float(obj.Spacing.Value), theta=float(obj.Theta.Value),
                                                  rho=float(obj.Rho),
                                                  graded_spacing=bool(getattr(obj, "GradedSpacing", False)))
    if is_pair_mesh(obj) or is_iso_surface(obj):
        raise ValueError(f"'{obj.Label}' is a pair-mesh result itself; select a solid or a medial axis")
    from .document import is_point_object

    if is_point_object(obj):
        raise ValueError(f"'{obj.Label}' is a points/mesh object: {api.PAIR_MESH_MESSAGE}")
    return obj, list(range(len(source_solids(obj)))), {}


def add_pair_mesh(doc, source, spacing=None, theta=None, rho=None, solids=None, results=None, recompute=True,
                  graded_spacing=None):
    """One PairMesh object per solid of `source` (a solid object, or a
    MedialAxis object: its source, solid and, unless given, its spacing,
    theta, rho and graded spacing are used; else 0 = automatic, 5, 8, on); returns them.
    solids: solid indices (default: all of a solid object). results: optional
    precomputed api.PairMesh per solid (a GUI computes them in a worker thread
    first) for the same parameters. Raises ValueError for a source without a
    B-rep solid and whatever the computation raises."""
    if doc is None:
        raise ValueError("no document")
    source, indices, params = pair_mesh_sources(source)
    spacing = params.get("spacing", 0.0) if spacing is None else float(spacing)
    theta = params.get("theta", 5.0) if theta is None else float(theta)
    rho = params.get("rho", 8.0) if rho is None else float(rho)
    graded_spacing = params.get("graded_spacing", True) if graded_spacing is None else bool(graded_spacing)
    if solids is not None:
        indices = list(solids)
    if results is not None:
        if len(results) != len(indices):
            raise ValueError(f"{len(results)} results for {len(indices)} solid(s)")
        for index, mesh in zip(indices, results):
            brep = source_solid(source, index).exportBrepToString()
            remember_result(pair_signature(brep, spacing, theta, rho, graded_spacing), mesh)
    created = []
    many = len(source_solids(source)) > 1
    for index in indices:
        obj = doc.addObject("Fem::FemMeshObjectPython", "PairMesh")
        PairMeshFeature(obj)
        if App.GuiUp:
            ViewProviderPairMesh(obj.ViewObject)
        obj.Label = f"{source.Label} pair-mesh" + (f" {index + 1}" if many else "")
        obj.Source = source
        obj.SolidIndex = index
        obj.Spacing = float(spacing)
        obj.GradedSpacing = graded_spacing
        obj.Theta = float(theta)
        obj.Rho = float(rho)
        created.append(obj)
    if recompute:
        doc.recompute()
        failed = [o for o in created if "Invalid" in o.State or "Error" in o.State]
        if failed:
            raise RuntimeError(f"the pair-mesh of '{source.Label}' could not be computed; see the Report view")
    return created


def add_iso_surface(doc, pair_obj, t=0.5, recompute=True):
    """A PairMeshIsoSurface object at parameter t for a PairMesh object."""
    if not is_pair_mesh(pair_obj):
        raise ValueError(f"'{getattr(pair_obj, 'Label', pair_obj)}' is not a pair-mesh object")
    if isinstance(t, bool) or not isinstance(t, (int, float)) or not 0.0 <= t <= 1.0:
        raise ValueError(f"t must be in [0, 1], got {t!r}")
    obj = doc.addObject("Mesh::FeaturePython", "IsoSurface")
    IsoSurfaceFeature(obj)
    if App.GuiUp:
        ViewProviderIsoSurface(obj.ViewObject)
    obj.PairMesh = pair_obj
    obj.T = float(t)
    obj.Label = f"{pair_obj.Label} iso t={t:g}"
    if recompute:
        doc.recompute()
        if "Invalid" in obj.State or "Error" in obj.State:
            raise RuntimeError(f"the iso-surface of '{pair_obj.Label}' could not be computed")
    return obj


def export_pair_mesh(obj, path, format=None):
    """Writes the pair-mesh of a PairMesh object to .vtu or TetGen .node/.ele."""
    mesh = get_pair_mesh(obj)
    if mesh is None:
        raise ValueError(f"'{obj.Label}' has no result yet; recompute it first")
    return mesh.write(path, format)
