"""Parametric FreeCAD objects for medial axes (DESIGN.md section 5b).

MedialAxis (Mesh::FeaturePython)
    Links one solid of a source object (Source, SolidIndex) and holds the whole
    inner medial axis as a mesh coloured by medial radius or by sheet.
    Parameters: Spacing (0 = automatic), GradedSpacing, Theta, Rho, CheckInside; display:
    ColorBy, MaxSheetObjects. Read-only statistics: Samples, Vertices,
    Polygons, Sheets, Beta0, Beta1, Seconds, SpacingUsed, OracleDisagreements,
    Warnings. The full result (vertices, radius, polygons, sheets, provenance,
    summary) is kept in ResultData, a .npz file stored inside the .FCStd.
MedialSheet (Mesh::FeaturePython), children of a MedialAxis
    One per sheet, largest first (SheetRank 0 = most polygons); when a solid
    has more sheets than MaxSheetObjects, the last child holds all remaining
    ("other") sheets. A sheet takes its geometry from its MedialAxis, so it is
    recomputed after it.

A MedialAxis may also link a Points or Mesh object (a scan, an imported
STL): then MEDIAL (seed 000) runs on its points - the inner axis of a closed,
consistently oriented mesh, the whole axis (inner and outer) of a point cloud
or an open mesh - with Theta = 22.5 (pi/8) by default; Spacing is unused.

Changing the source shape or a parameter recomputes the MedialAxis and its
sheets (the result is reused when only display properties change). The
number of sheet objects is adjusted after each document recompute by a
document observer (sync_sheets), never during a recompute.

BuildPairMesh = True gives a MedialAxis a PairMesh child (pair_document)
that follows its source and parameters; False removes it again (or, if
another object uses it, leaves it as a standalone PairMesh). See
MedialAxisFeature.onChanged for when the child is created.

The proxies keep nothing but their type in the document, so a saved document
reopens wherever ``import cadmedial`` works (FreeCAD with the addon, or
python3 after plugin/install.sh).
"""

import collections
import hashlib
import os
import re
import tempfile

import FreeCAD as App
import numpy as np

from . import api, colors

MEDIAL_TYPE = "MedialAxis"
SHEET_TYPE = "MedialSheet"
COLOR_MODES = ["Radius", "Sheet"]
DEFAULT_MAX_SHEET_OBJECTS = 24

_ICON_DIR = os.path.join(
    os.path.dirname(os.path.dirname(os.path.realpath(__file__))), "freecad", "medial_axis", "resources", "icons"
)


def icon_path(name):
    return os.path.join(_ICON_DIR, name)


# ---------------------------------------------------------------------------
# Results: an in-memory LRU keyed by the input signature, and the object's own
# ResultData file for its last signature.

GRADED_SPACING_DOC = (
    "Grade the sample spacing within each face: finer where it curves or the solid is thin, up to Spacing "
    "elsewhere (fewer samples on cones, fillets, thin flanges); True for new objects. False = one spacing per "
    "face, the finest it needs anywhere (objects saved before this property keep False)"
)

_CACHE_SIZE = 16
_results = collections.OrderedDict()


def input_signature(brep, spacing, theta, rho, check_inside, graded_spacing=False):
    digest = hashlib.sha1(brep.encode("utf-8", errors="replace")).hexdigest()
    signature = f"{digest}|h={float(spacing)!r}|theta={float(theta)!r}|rho={float(rho)!r}|check={bool(check_inside)}"
    # Only when on: results stored by documents from before the switch keep their signature.
    return signature + "|graded" if graded_spacing else signature


def remember_result(signature, result):
    _results[signature] = result
    _results.move_to_end(signature)
    while len(_results) > _CACHE_SIZE:
        _results.popitem(last=False)


def cached_result(signature):
    result = _results.get(signature)
    if result is not None:
        _results.move_to_end(signature)
    return result


def is_medial(obj):
    return _proxy_type(obj) == MEDIAL_TYPE


def is_sheet(obj):
    return _proxy_type(obj) == SHEET_TYPE


def _proxy_type(obj):
    try:
        return getattr(obj.Proxy, "Type", None)
    except Exception:  # noqa: BLE001 - deleted objects, objects without Proxy
        return None


def get_result(obj):
    """The MedialAxisResult of a MedialAxis object (or of a sheet's parent):
    from memory, else from its ResultData file; None if never computed."""
    if is_sheet(obj):
        obj = obj.MedialAxis
    if obj is None or not is_medial(obj):
        return None
    result = cached_result(obj.InputSignature) if obj.InputSignature else None
    if result is None:
        path = obj.ResultData
        if path and os.path.isfile(path):
            result = api.MedialAxisResult.from_npz(path)
            if obj.InputSignature:
                remember_result(obj.InputSignature, result)
    return result


# ---------------------------------------------------------------------------
# Source solids


def source_shape(source):
    """The shape of a document object in global coordinates."""
    try:
        import Part

        return Part.getShape(source)
    except Exception:  # noqa: BLE001 - fall back on the plain Shape property
        return getattr(source, "Shape", None)


def describe_non_solid(source, shape):
    if shape is None:
        return f"'{source.Label}' ({source.TypeId}) has no shape"
    if shape.isNull():
        return f"'{source.Label}' has an empty shape"
    return (
        f"'{source.Label}' holds no solid ({len(shape.Shells)} shell(s), {len(shape.Faces)} face(s), "
        f"{len(shape.Edges)} edge(s)); select a closed solid"
    )


def is_point_object(obj):
    """A Points or Mesh document object (no B-rep): MEDIAL works on its points."""
    if not hasattr(obj, "TypeId") or not hasattr(obj, "Document") or is_medial(obj) or is_sheet(obj):
        return False
    props = getattr(obj, "PropertiesList", ())
    return "Shape" not in props and ("Points" in props or "Mesh" in props)


def point_signature(points, triangles, theta, rho):
    digest = hashlib.sha1(np.ascontiguousarray(points).tobytes())
    if triangles is not None:
        digest.update(np.ascontiguousarray(triangles).tobytes())
    return f"points:{digest.hexdigest()}|theta={float(theta)!r}|rho={float(rho)!r}"


def source_solids(source, warnings=None):
    """The solids of a document object, or ValueError saying what it holds.
    A Points or Mesh object counts as one source (its points), returned as
    [source]. `warnings`, a list, gets what reading the shape had to say:
    the sewing of a shape without a solid, as `cadmedial run` warns."""
    if source is None:
        raise ValueError("no source object")
    if not hasattr(source, "TypeId") or not hasattr(source, "Document"):
        raise ValueError(f"{source!r} is not a FreeCAD document object")
    if is_point_object(source):
        return [source]
    if "Shape" not in source.PropertiesList:
        raise ValueError(f"'{source.Label}' ({source.TypeId}) has no shape, so no solid; select a solid")
    shape = source_shape(source)
    if shape is None or shape.isNull() or not shape.Faces:
        raise ValueError(describe_non_solid(source, shape))
    if shape.Solids:
        return shape.Solids
    return sewn_solids(source, shape, warnings)


# Sewn solids by the BREP digest of the shape sewn: (BREP texts, warnings).
# The task panel, the commands and each recompute ask for a source's solids
# again; an IGES part of a few hundred faces takes OCCT's sewing a good
# fraction of a second each time.
_SEWN = collections.OrderedDict()
_SEWN_KEEP = 8


# A TShape's flags line in BREP text (free, modified, checked, ...): the
# view's meshing of a shape clears one, and the shape is the same.
_BREP_FLAGS = re.compile(rb"^[01]{7}$", re.MULTILINE)


def _sew(shape):
    """(BREP texts, warnings) of the solids a shape's faces sew into, or
    api.InputError saying what stayed open; each shape sewn once."""
    key = hashlib.sha1(_BREP_FLAGS.sub(b"", shape.exportBrepToString().encode())).hexdigest()
    if key not in _SEWN:
        try:
            made = api.solids_brep(shape)
            _SEWN[key] = (list(made["solids"]), [str(w) for w in made["warnings"]])
        except api.InputError as e:
            _SEWN[key] = e
        while len(_SEWN) > _SEWN_KEEP:
            _SEWN.popitem(last=False)
    _SEWN.move_to_end(key)
    if isinstance(_SEWN[key], Exception):
        raise _SEWN[key]
    return _SEWN[key]


def sewn_solids(source, shape, warnings=None):
    """The solids the faces of a shape without one sew into (a closed shell,
    an imported IGES file's trimmed surfaces), made by the native module as
    `cadmedial run` makes them; ValueError saying what is left open when
    none closes. The same shape is sewn once (its solids are remembered).
    `warnings`, a list, gets the sewing's."""
    import Part

    try:
        texts, said = _sew(shape)
    except api.InputError as e:
        sewing = str(e).rsplit("; ", 1)[-1]  # the native message ends with what the sewing did
        detail = f" (its faces, {sewing})" if sewing.startswith("sewn at") else ""
        raise ValueError(describe_non_solid(source, shape) + detail) from None
    if warnings is not None:
        warnings.extend(said)
    solids = []
    for text in texts:
        solid = Part.Shape()
        solid.importBrepFromString(text)
        solids.extend(solid.Solids)
    return solids


def source_solid(source, index, warnings=None):
    solids = source_solids(source, warnings)
    if not 0 <= index < len(solids):
        raise ValueError(f"'{source.Label}' has {len(solids)} solid(s); SolidIndex {index} does not exist")
    return solids[index]


# ---------------------------------------------------------------------------
# Colours


def _radius_max(result):
    return float(result.radius.max()) if result.radius.size else 0.0


def _vertex_colors(result, used):
    return colors.as_color_list(colors.radius_colors(result.radius[used], _radius_max(result)))


def _add_property(obj, kind, name, group, doc, value=None, mode=None):
    if name not in obj.PropertiesList:
        obj.addProperty(kind, name, group, doc)
        if value is not None:
            setattr(obj, name, value)
    if mode is not None:
        obj.setEditorMode(name, mode)


def _mesh(points, triangles):
    """A Mesh.Mesh with exactly these points and triangles, in this order.

    Built by reading a binary PLY: Mesh.Mesh((points, facets)) drops every
    facet on a non-manifold edge (medial axes have them at sheet junctions)
    and Mesh.Mesh(facet list) merges points, so colours would not line up."""
    import Mesh

    points = np.ascontiguousarray(points, dtype="<f4").reshape(-1, 3)
    triangles = np.asarray(triangles, dtype="<i4").reshape(-1, 3)
    if triangles.shape[0] == 0:
        return Mesh.Mesh()
    header = (
        "ply\nformat binary_little_endian 1.0\n"
        f"element vertex {points.shape[0]}\nproperty float x\nproperty float y\nproperty float z\n"
        f"element face {triangles.shape[0]}\nproperty list uchar int vertex_indices\nend_header\n"
    ).encode("ascii")
    faces = np.zeros(triangles.shape[0], dtype=[("n", "u1"), ("v", "<i4", (3,))])
    faces["n"] = 3
    faces["v"] = triangles
    handle, path = tempfile.mkstemp(prefix="medial_", suffix=".ply")
    try:
        with os.fdopen(handle, "wb") as f:
            f.write(header)
            f.write(points.tobytes())
            f.write(faces.tobytes())
        mesh = Mesh.Mesh(path)
    finally:
        os.remove(path)
    if mesh.CountPoints != points.shape[0] or mesh.CountFacets != triangles.shape[0]:
        App.Console.PrintWarning(
            f"cadmedial: the mesh has {mesh.CountPoints} points / {mesh.CountFacets} facets instead of "
            f"{points.shape[0]} / {triangles.shape[0]}; colours are left out\n"
        )
    return mesh


def _colors_fit(mesh, colors_list):
    return len(colors_list) in (mesh.CountPoints, mesh.CountFacets)


# ---------------------------------------------------------------------------
# MedialAxis


class FeatureProxy:
    """What every cadmedial feature proxy saves and does on restore: only its
    type is stored (the data lives in the object's properties), and a restored
    object gets any property added since and its view provider back."""

    def __getstate__(self):
        return {"Type": self.Type}

    def __setstate__(self, state):
        return None

    # Newer FreeCAD versions call these instead.
    def dumps(self):
        return self.__getstate__()

    def loads(self, state):
        return None

    def onDocumentRestored(self, obj):
        self.setup(obj)
        ensure_view_provider(obj)


class MedialAxisFeature(FeatureProxy):
    Type = MEDIAL_TYPE

    def __init__(self, obj):
        obj.Proxy = self
        self.setup(obj)

    def setup(self, obj):
        """Adds missing properties (also used on restore, for documents from older versions)."""
        p = _add_property
        p(obj, "App::PropertyLink", "Source", "Medial Axis", "The object whose solid is analysed")
        p(obj, "App::PropertyInteger", "SolidIndex", "Medial Axis", "Which solid of the source (0 = first)", 0)
        p(obj, "App::PropertyLength", "Spacing", "Medial Axis",
          "Target sample spacing in model units; 0 = automatic (bounding-box diagonal / 40)", 0.0)
        p(obj, "App::PropertyBool", "GradedSpacing", "Medial Axis", GRADED_SPACING_DOC, False)
        p(obj, "App::PropertyAngle", "Theta", "Medial Axis",
          "Angle condition of CAD_MEDIAL in degrees (larger keeps fewer, flatter facets)", 5.0)
        p(obj, "App::PropertyFloat", "Rho", "Medial Axis",
          "Ratio condition of CAD_MEDIAL: |pq| must exceed Rho x the umbrella circumradius", 8.0)
        p(obj, "App::PropertyBool", "CheckInside", "Medial Axis",
          "Check every inner/outer decision with OCCT's exact classifier (slower; see OracleDisagreements)", True)
        p(obj, "App::PropertyBool", "BuildPairMesh", "Medial Axis",
          "Also build the pair-mesh of this solid (a PairMesh child that follows Source, Spacing, GradedSpacing, Theta, Rho); "
          "False removes it (kept as a standalone PairMesh if another object uses it)", False)
        if "ColorBy" not in obj.PropertiesList:
            obj.addProperty("App::PropertyEnumeration", "ColorBy", "Display", "Colour by medial radius or by sheet")
            obj.ColorBy = COLOR_MODES
            obj.ColorBy = "Radius"
        p(obj, "App::PropertyInteger", "MaxSheetObjects", "Display",
          "At most this many sheet objects; the last one collects the remaining sheets", DEFAULT_MAX_SHEET_OBJECTS)
        stats = "Statistics"
        p(obj, "App::PropertyInteger", "Samples", stats, "Boundary samples", 0, 1)
        p(obj, "App::PropertyInteger", "Vertices", stats, "Medial vertices", 0, 1)
        p(obj, "App::PropertyInteger", "Polygons", stats, "Medial polygons", 0, 1)
        p(obj, "App::PropertyInteger", "Sheets", stats, "Sheets (manifold patches)", 0, 1)
        p(obj, "App::PropertyInteger", "Beta0", stats, "Connected components of the medial axis", 0, 1)
        p(obj, "App::PropertyInteger", "Beta1", stats, "First Betti number (independent loops); -1 if unknown", 0, 1)
        p(obj, "App::PropertyFloat", "Seconds", stats, "Wall time of the last computation", 0.0, 1)
        p(obj, "App::PropertyLength", "SpacingUsed", stats, "Sample spacing used", 0.0, 1)
        p(obj, "App::PropertyInteger", "OracleDisagreements", stats,
          "Inner/outer labels that differ from the exact classifier (-1: not checked)", -1, 1)
        p(obj, "App::PropertyStringList", "Warnings", stats, "Warnings of the last computation", None, 1)
        p(obj, "App::PropertyColorList", "Colors", "Display", "Per-vertex or per-face colours", None, 2)
        p(obj, "App::PropertyFileIncluded", "ResultData", "Result", "The full result (.npz)", None, 2)
        p(obj, "App::PropertyString", "InputSignature", "Result", "Inputs of the stored result", None, 2)

    def onChanged(self, obj, prop):
        if prop == "BuildPairMesh":
            self.pair_mesh_changed(obj)
        if prop == "ColorBy" and "ResultData" in obj.PropertiesList and "Restore" not in obj.State and obj.ResultData:
            result = get_result(obj)
            if result is not None:
                self.apply_colors(obj, result)

    @staticmethod
    def pair_mesh_changed(obj):
        """Creates / releases the pair-mesh child right away, in the same undo
        step as the property change, when that is safe: not while the document
        is being restored (the saved child comes back by itself), not during
        undo / redo (the transaction restores child and property together) and
        not during a recompute (FreeCAD 0.20 loses objects added or removed
        then; an expression-bound BuildPairMesh changes there): that case is
        left to the document observer, which runs after the recompute. Done in
        onChanged rather than on a timer, so freecadcmd (no event loop) and the
        GUI behave the same and the next recompute (the GUI's auto-recompute
        after a property edit, or doc.recompute()) computes the new child."""
        doc = getattr(obj, "Document", None)
        if doc is None or "Restore" in obj.State or doc.Transacting:
            return
        if doc.Recomputing:
            _pending_pair_mesh.add((doc.Name, obj.Name))
            return
        _sync_pair_mesh_reporting(obj)

    def execute(self, obj):
        import time

        if is_point_object(obj.Source):
            return self.execute_points(obj)
        reading = []  # the source's own warnings (its sewing)
        solid = source_solid(obj.Source, obj.SolidIndex, reading)
        spacing, theta, rho = float(obj.Spacing.Value), float(obj.Theta.Value), float(obj.Rho)
        brep = solid.exportBrepToString()
        graded = bool(obj.GradedSpacing)
        signature = input_signature(brep, spacing, theta, rho, obj.CheckInside, graded)
        result = None
        if signature == obj.InputSignature:
            result = get_result(obj)  # only display properties changed
        if result is None:
            result = cached_result(signature)
        fresh = result is None
        if fresh:
            start = time.perf_counter()
            results = api.compute(brep, spacing=spacing, theta=theta, rho=rho, check_inside=obj.CheckInside,
                                  graded_spacing=graded)
            if not results:
                raise ValueError(f"{obj.Label}: no closed solid in '{obj.Source.Label}'")
            result = results[0]
            result.seconds = time.perf_counter() - start
            remember_result(signature, result)
        if signature != obj.InputSignature or not obj.ResultData:
            self.store(obj, result, signature)
        self.apply(obj, result, reading)
        for w in reading + result.warnings if fresh else []:
            App.Console.PrintWarning(f"{obj.Label}: {w}\n")

    def execute_points(self, obj):
        """MEDIAL on the points of a Points / Mesh source (global coordinates)."""
        import time

        theta, rho = float(obj.Theta.Value), float(obj.Rho)
        points, triangles = api.point_source(obj.Source)
        signature = point_signature(points, triangles, theta, rho)
        result = get_result(obj) if signature == obj.InputSignature else None
        if result is None:
            result = cached_result(signature)
        if result is None:
            start = time.perf_counter()
            (result,) = api.compute_points((points, triangles), theta=theta, rho=rho)
            result.seconds = time.perf_counter() - start
            remember_result(signature, result)
            App.Console.PrintMessage(f"{obj.Label}: MEDIAL, {result.summary.get('axis_note', '')}\n")
        if signature != obj.InputSignature or not obj.ResultData:
            self.store(obj, result, signature)
        self.apply(obj, result)

    def store(self, obj, result, signature):
        handle, path = tempfile.mkstemp(prefix="medial_", suffix=".npz")
        os.close(handle)
        try:
            result.to_npz(path)
            obj.ResultData = path  # FreeCAD copies it into the document
        finally:
            os.remove(path)
        obj.InputSignature = signature

    def apply(self, obj, result, reading=()):
        """Shows a result; `reading`: the source's own warnings (its sewing)."""
        tri, _ = result.triangles()
        obj.Mesh = _mesh(result.vertices, tri)
        obj.Samples = result.samples
        obj.Vertices = result.vertex_count
        obj.Polygons = result.polygon_count
        obj.Sheets = result.sheet_count
        obj.Beta0 = result.beta0
        obj.Beta1 = result.beta1
        obj.Seconds = round(result.seconds, 3)
        obj.SpacingUsed = result.spacing
        diagnostics = result.summary.get("diagnostics", {})
        obj.OracleDisagreements = (
            int(diagnostics.get("walk_oracle_disagreements", -1)) if obj.CheckInside else -1
        )
        obj.Warnings = [str(w) for w in list(reading) + list(result.warnings)]
        self.apply_colors(obj, result)

    def apply_colors(self, obj, result):
        if obj.ColorBy == "Sheet":
            tri, polygon = result.triangles()
            ranks = result.sheet_ranks()[result.sheet[polygon]]
            palette = colors.SHEET_PALETTE[ranks % len(colors.SHEET_PALETTE)]
            values = colors.as_color_list(palette)
        else:
            values = _vertex_colors(result, np.arange(result.vertex_count))
        obj.Colors = values if _colors_fit(obj.Mesh, values) else []


# ---------------------------------------------------------------------------
# MedialSheet


class MedialSheetFeature(FeatureProxy):
    Type = SHEET_TYPE

    def __init__(self, obj):
        obj.Proxy = self
        self.setup(obj)

    def setup(self, obj):
        p = _add_property
        p(obj, "App::PropertyLink", "MedialAxis", "Sheet", "The MedialAxis object this sheet belongs to", None, 1)
        p(obj, "App::PropertyInteger", "SheetRank", "Sheet", "Rank by size (0 = the sheet with most polygons)", 0, 1)
        p(obj, "App::PropertyBool", "OtherSheets", "Sheet",
          "Holds all sheets from SheetRank on (more sheets than MaxSheetObjects)", False, 1)
        p(obj, "App::PropertyIntegerList", "SheetIds", "Sheet", "Sheet ids of the medial complex held here", None, 1)
        p(obj, "App::PropertyInteger", "Polygons", "Sheet", "Medial polygons in this object", 0, 1)
        p(obj, "App::PropertyFloat", "MinRadius", "Sheet", "Smallest medial radius on this sheet", 0.0, 1)
        p(obj, "App::PropertyFloat", "MaxRadius", "Sheet", "Largest medial radius on this sheet", 0.0, 1)
        p(obj, "App::PropertyColorList", "Colors", "Display", "Per-vertex or per-face colours", None, 2)

    def execute(self, obj):
        parent = obj.MedialAxis
        if parent is None or not is_medial(parent):
            raise ValueError(f"{obj.Label}: its MedialAxis object is gone; delete this sheet")
        result = get_result(parent)
        if result is None:
            raise ValueError(f"{obj.Label}: '{parent.Label}' has no result yet (recompute it)")
        ranks = result.sheet_ranks()
        polygon_rank = ranks[result.sheet]
        rank = obj.SheetRank
        mask = polygon_rank >= rank if obj.OtherSheets else polygon_rank == rank
        points, tri, used = result.submesh(mask)
        obj.Mesh = _mesh(points, tri)
        ids = np.flatnonzero(ranks >= rank) if obj.OtherSheets else np.flatnonzero(ranks == rank)
        obj.SheetIds = [int(i) for i in ids]
        obj.Polygons = int(mask.sum())
        r = result.radius[used]
        obj.MinRadius = float(r.min()) if r.size else 0.0
        obj.MaxRadius = float(r.max()) if r.size else 0.0
        if obj.OtherSheets:
            label = f"{parent.Label} other sheets ({len(ids)})"
        else:
            label = f"{parent.Label} sheet {rank + 1}"
        if obj.Label != label:
            obj.Label = label
        if parent.ColorBy == "Sheet":
            color = colors.OTHER_SHEETS_COLOR if obj.OtherSheets else colors.sheet_color(rank)
            values = [color] * tri.shape[0]
        else:
            values = _vertex_colors(result, used)
        obj.Colors = values if _colors_fit(obj.Mesh, values) else []


def sheet_children(medial):
    """The MedialSheet objects of a MedialAxis, by SheetRank."""
    kids = [o for o in medial.InList if is_sheet(o) and o.MedialAxis == medial]
    return sorted(kids, key=lambda o: o.SheetRank)


def _wanted_sheet_objects(medial):
    """(sheet objects wanted, sheets) from the stored statistics (no result loaded)."""
    if not medial.ResultData or not medial.InputSignature:
        return None
    total = int(medial.Sheets)
    return min(total, max(1, int(medial.MaxSheetObjects))), total


def sheets_in_sync(medial):
    wanted = _wanted_sheet_objects(medial)
    if wanted is None:
        return True
    count, total = wanted
    kids = sheet_children(medial)
    if len(kids) != count:
        return False
    return all(k.SheetRank == i and k.OtherSheets == (i == count - 1 and total > count) for i, k in enumerate(kids))


def sync_sheets(medial):
    """Creates / removes sheet objects so they match the MedialAxis' result;
    returns the sheet objects. Call it outside a recompute (the document
    observer does so after every recompute)."""
    wanted = _wanted_sheet_objects(medial)
    if wanted is None:
        return []
    count, total = wanted
    doc = medial.Document
    kids = sheet_children(medial)
    for extra in kids[count:]:
        doc.removeObject(extra.Name)
    kids = kids[:count]
    changed = []
    while len(kids) < count:
        sheet = doc.addObject("Mesh::FeaturePython", "MedialSheet")
        MedialSheetFeature(sheet)
        if App.GuiUp:
            ViewProviderMedialSheet(sheet.ViewObject)
            sheet.ViewObject.Visibility = False
        sheet.MedialAxis = medial
        kids.append(sheet)
    for i, k in enumerate(kids):
        other = i == count - 1 and total > count
        if k.SheetRank != i or k.OtherSheets != other or "Touched" in k.State or k.Mesh.CountFacets == 0:
            k.SheetRank = i
            k.OtherSheets = other
            changed.append(k)
    for k in changed:
        k.recompute()
        k.purgeTouched()
    return kids


#: (document, MedialAxis) names whose BuildPairMesh changed during a recompute.
_pending_pair_mesh = set()


def _sync_pair_mesh_reporting(medial):
    """pair_document.sync_pair_mesh; an error (a points source) goes to the
    Report view and BuildPairMesh back to False, never out of onChanged."""
    from . import pair_document

    try:
        pair_document.sync_pair_mesh(medial)
    except Exception as e:  # noqa: BLE001
        App.Console.PrintError(f"{medial.Label}: no pair-mesh: {e}\n")
        if medial.BuildPairMesh:
            medial.BuildPairMesh = False


def pair_mesh_children(medial):
    from . import pair_document

    return pair_document.pair_mesh_children(medial)


class _SheetObserver:
    """Adjusts the number of sheet objects after each recompute, and creates /
    releases the pair-mesh children asked for during it."""

    def __init__(self):
        self.busy = False

    def slotRecomputedDocument(self, doc):
        if self.busy:
            return
        try:
            stale = [o.Name for o in doc.Objects if is_medial(o) and "Invalid" not in o.State and not sheets_in_sync(o)]
        except Exception:  # noqa: BLE001 - never break a recompute
            return
        pending = sorted(n for d, n in _pending_pair_mesh if d == doc.Name)
        _pending_pair_mesh.difference_update((doc.Name, n) for n in pending)
        if not stale and not pending:
            return
        if App.GuiUp:
            from PySide2 import QtCore

            name = doc.Name
            QtCore.QTimer.singleShot(0, lambda: self.sync(name, stale, pending))
        else:
            self.sync(doc.Name, stale, pending)

    def sync(self, doc_name, names, pair_names=()):
        doc = App.listDocuments().get(doc_name)
        if doc is None:
            return
        self.busy = True
        try:
            for name in names:
                obj = doc.getObject(name)
                if obj is not None and is_medial(obj):
                    try:
                        sync_sheets(obj)
                    except Exception as e:  # noqa: BLE001
                        App.Console.PrintError(f"{obj.Label}: could not update its sheet objects: {e}\n")
            for name in pair_names:
                obj = doc.getObject(name)
                if obj is not None and is_medial(obj):
                    _sync_pair_mesh_reporting(obj)
        finally:
            self.busy = False


_observer = None


def install_observer():
    global _observer
    if _observer is None:
        _observer = _SheetObserver()
        App.addDocumentObserver(_observer)


install_observer()


# ---------------------------------------------------------------------------
# View providers (GUI only; harmless to import without it)


def ensure_view_provider(obj):
    """Gives an object our view provider when the GUI is up but the document
    was saved without one (by freecadcmd or plain python3). Runs after the
    GUI document is restored, which would otherwise overwrite it."""
    if not App.GuiUp:
        return
    from PySide2 import QtCore

    doc_name, name = obj.Document.Name, obj.Name

    def attach():
        doc = App.listDocuments().get(doc_name)
        target = doc.getObject(name) if doc is not None else None
        vobj = getattr(target, "ViewObject", None) if target is not None else None
        if vobj is None or isinstance(getattr(vobj, "Proxy", None), _ViewProviderBase):
            return
        if is_medial(target):
            proxy = ViewProviderMedialAxis(vobj)
        elif is_sheet(target):
            proxy = ViewProviderMedialSheet(vobj)
            vobj.Visibility = False
        else:
            return
        if getattr(proxy, "Object", None) is None:  # FreeCAD attaches only new view providers
            proxy.attach(vobj)
        # Redraw so the tree picks up icon and children.
        target.touch()
        target.purgeTouched()

    QtCore.QTimer.singleShot(0, attach)



class _ViewProviderBase:
    icon = "MedialAxis.svg"

    def __init__(self, vobj):
        vobj.Proxy = self

    def attach(self, vobj):
        self.Object = vobj.Object
        # Medial sheets have no outside: light both sides, or half the facets are dark.
        if "Lighting" in vobj.PropertiesList:
            vobj.Lighting = "Two side"
        colors_list = getattr(vobj.Object, "Colors", None)
        if colors_list and "Coloring" in vobj.PropertiesList:
            vobj.Coloring = False
            vobj.Coloring = True

    def getIcon(self):
        return icon_path(self.icon)

    def updateData(self, obj, prop):
        # The mesh view provider applies a colour list only when Coloring is
        # switched on; set it again after every new colour list.
        if prop == "Colors":
            vobj = getattr(obj, "ViewObject", None)
            if vobj is None or "Coloring" not in vobj.PropertiesList:
                return
            if vobj.Coloring:
                vobj.Coloring = False
            if obj.Colors:
                vobj.Coloring = True

    def onChanged(self, vobj, prop):
        return None

    def __getstate__(self):
        return None

    def __setstate__(self, state):
        return None

    def dumps(self):
        return None

    def loads(self, state):
        return None


class ViewProviderMedialAxis(_ViewProviderBase):
    icon = "MedialAxis.svg"

    def claimChildren(self):
        obj = getattr(self, "Object", None)
        if obj is None:
            return []
        try:
            return sheet_children(obj) + pair_mesh_children(obj)
        except Exception:  # noqa: BLE001
            return []

    def doubleClicked(self, vobj):
        import FreeCADGui as Gui

        Gui.ActiveDocument.setEdit(vobj.Object.Name, 0)
        return True

    def setEdit(self, vobj, mode=0):
        if mode != 0:
            return None
        import FreeCADGui as Gui

        from freecad.medial_axis import task_panel

        Gui.Control.showDialog(task_panel.MedialAxisTaskPanel(edit=vobj.Object))
        return True

    def unsetEdit(self, vobj, mode=0):
        import FreeCADGui as Gui

        Gui.Control.closeDialog()
        return True

    def onDelete(self, vobj, subelements):
        obj = vobj.Object
        for kid in sheet_children(obj):
            obj.Document.removeObject(kid.Name)
        _release_pair_meshes(obj)
        return True


class ViewProviderMedialSheet(_ViewProviderBase):
    icon = "MedialSheet.svg"


# ---------------------------------------------------------------------------
# Creating objects


def add_to_document(
    doc,
    source,
    spacing=0.0,
    theta=None,
    rho=8.0,
    color_by="Radius",
    max_sheet_objects=DEFAULT_MAX_SHEET_OBJECTS,
    check_inside=True,
    results=None,
    recompute=True,
    graded_spacing=True,
):
    """One MedialAxis object (with its sheet objects) per solid of `source`, a
    document object with a shape; returns the MedialAxis objects.

    results: optional precomputed MedialAxisResults, one per solid, for the
    same parameters (a GUI computes them in a worker thread first).
    theta None: 5 degrees for solids, 22.5 (pi/8) for Points / Mesh sources.
    graded_spacing: the spacing graded within each face (GradedSpacing).
    Raises ValueError if `source` holds no solid (the message says what it
    holds) and whatever the computation raises (InputError, ...)."""
    if doc is None:
        raise ValueError("no document")
    if color_by not in COLOR_MODES:
        raise ValueError(f"color_by must be one of {COLOR_MODES}, got {color_by!r}")
    if isinstance(source, str):
        name = source
        source = doc.getObject(name) or next(iter(doc.getObjectsByLabel(name)), None)
        if source is None:
            raise ValueError(f"no object named '{name}' in document '{doc.Name}'")
    solids = source_solids(source)
    points = is_point_object(source)
    if theta is None:
        theta = api.POINT_CLOUD_THETA if points else 5.0
    if points:
        results = None  # computed (and cached) by the object itself
        check_inside = False
    if results is not None:
        if len(results) != len(solids):
            raise ValueError(f"{len(results)} results for {len(solids)} solid(s) of '{source.Label}'")
        for solid, result in zip(solids, results):
            remember_result(
                input_signature(solid.exportBrepToString(), spacing, theta, rho, check_inside, graded_spacing), result
            )
    created = []
    for index in range(len(solids)):
        obj = doc.addObject("Mesh::FeaturePython", "MedialAxis")
        MedialAxisFeature(obj)
        if App.GuiUp:
            ViewProviderMedialAxis(obj.ViewObject)
        obj.Label = f"{source.Label} medial axis" + (f" {index + 1}" if len(solids) > 1 else "")
        obj.Source = source
        obj.SolidIndex = index
        obj.Spacing = float(spacing)
        obj.GradedSpacing = bool(graded_spacing) and not points
        obj.Theta = float(theta)
        obj.Rho = float(rho)
        obj.CheckInside = bool(check_inside)
        obj.ColorBy = color_by
        obj.MaxSheetObjects = int(max_sheet_objects)
        created.append(obj)
    if recompute:
        doc.recompute()
        failed = [o for o in created if "Invalid" in o.State or "Error" in o.State]
        if failed:
            raise RuntimeError(
                f"the medial axis of '{source.Label}' could not be computed; see the Report view / console"
            )
        for obj in created:
            sync_sheets(obj)
    return created


def sheet_polygon_mask(sheet_obj, result):
    ranks = result.sheet_ranks()[result.sheet]
    if sheet_obj.OtherSheets:
        return ranks >= sheet_obj.SheetRank
    return ranks == sheet_obj.SheetRank


def export(obj, path, format=None):
    """Writes a MedialAxis (whole axis) or a MedialSheet (its polygons) to
    .ply / .obj / .ma; returns the path."""
    result = get_result(obj)
    if result is None:
        raise ValueError(f"'{obj.Label}' has no result yet; recompute it first")
    if is_sheet(obj):
        result = result.subset(sheet_polygon_mask(obj, result))
    return result.write(path, format)


def evaluate(obj):
    """Lines of text: the checks available so far for a MedialAxis object."""
    result = get_result(obj)
    if result is None:
        raise ValueError(f"'{obj.Label}' has no result yet; recompute it first")
    summary = result.summary
    lines = [
        f"{result.samples} samples (spacing {result.spacing:.4g}), {result.vertex_count} vertices, "
        f"{result.polygon_count} polygons, {result.sheet_count} sheets",
    ]
    surface = summary.get("sampling", {}).get("reconstruction", {}).get("surface", {})
    if surface:
        components = int(surface.get("components", 0))
        euler = int(surface.get("euler_characteristic", 0))
        genus = (2 * components - euler) / 2 if components else float("nan")
        ok0 = result.beta0 == components
        ok1 = result.beta1 == genus
        lines.append(
            f"topology: medial beta0 = {result.beta0} (solid: {components} component(s)) "
            f"{'OK' if ok0 else 'MISMATCH'}; beta1 = {result.beta1} (solid genus {genus:g}) "
            f"{'OK' if ok1 else 'MISMATCH' if result.beta1 >= 0 else 'unknown'}"
        )
        lines.append(
            f"boundary reconstruction: {'closed manifold' if surface.get('closed_manifold') else 'NOT closed'}, "
            f"area {surface.get('area', 0):.6g} (exact {summary['sampling']['reconstruction'].get('exact_area', 0):.6g})"
        )
    diagnostics = summary.get("diagnostics", {})
    checked = int(diagnostics.get("walk_oracle_checked", 0))
    if checked:
        lines.append(
            f"inner/outer walk vs exact classifier: {diagnostics.get('walk_oracle_disagreements', 0)} "
            f"disagreement(s) in {checked} checks"
        )
    else:
        lines.append("inner/outer walk vs exact classifier: not checked (CheckInside is off)")
    lines.append(
        f"triplets not Delaunay: {diagnostics.get('triplets_not_delaunay', 0)}, "
        f"samples without umbrella: {diagnostics.get('samples_without_umbrella', 0)}"
    )
    solid = source_solid(obj.Source, obj.SolidIndex)
    report = api.evaluate(solid, result, solid=0)
    lines.append("exact-geometry evaluation (DESIGN.md section 6):")
    lines.extend("  " + line for line in api.evaluation_lines(report))
    return lines


def _release_pair_meshes(medial):
    from . import pair_document

    for pm in pair_mesh_children(medial):
        pair_document.release_pair_mesh(pm)


def remove(obj):
    """Removes a MedialAxis object, its sheet objects and its pair-mesh child
    (kept, unlinked, if another object uses it)."""
    doc = obj.Document
    for kid in sheet_children(obj):
        doc.removeObject(kid.Name)
    _release_pair_meshes(obj)
    doc.removeObject(obj.Name)
