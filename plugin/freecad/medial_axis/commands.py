"""Commands of the Medial Axis workbench.

MedialAxis_Compute    task panel, then one parametric MedialAxis per selected solid
MedialAxis_Export     selected medial axes / sheets to .ply, .obj or .ma
MedialAxis_Evaluate   the checks available so far (topology, walk vs exact classifier)
MedialAxis_PairMesh   task panel, then one parametric PairMesh (FEM mesh) per selected solid
                      or per selected medial axis (its source and parameters)
MedialAxis_IsoSurface an iso-surface (T = 0.5) of each selected PairMesh
MedialAxis_ExportPairMesh  selected PairMesh objects to .vtu or TetGen .node/.ele

Errors go to the Report view (and the status bar); commands never raise into
FreeCAD and never open a modal dialog on error.
"""

import os

import FreeCAD as App
import FreeCADGui as Gui

from . import icon

TOOLBAR = ["MedialAxis_Compute", "Separator", "MedialAxis_Export", "MedialAxis_Evaluate", "Separator",
           "MedialAxis_PairMesh", "MedialAxis_IsoSurface", "MedialAxis_ExportPairMesh"]
MENU = TOOLBAR
CONTEXT_MENU = ["MedialAxis_Compute", "MedialAxis_Export", "MedialAxis_Evaluate", "MedialAxis_PairMesh",
                "MedialAxis_IsoSurface", "MedialAxis_ExportPairMesh"]


def report_error(message):
    App.Console.PrintError(f"Medial Axis: {message}\n")
    try:
        Gui.getMainWindow().statusBar().showMessage(f"Medial Axis: {message}", 15000)
    except Exception:  # noqa: BLE001
        pass


def report_message(message):
    App.Console.PrintMessage(f"Medial Axis: {message}\n")
    try:
        Gui.getMainWindow().statusBar().showMessage(f"Medial Axis: {message}", 10000)
    except Exception:  # noqa: BLE001
        pass


def _document():
    return App.ActiveDocument


def selected_objects():
    if _document() is None:
        return []
    return list(Gui.Selection.getSelection())


def solid_sources(objects):
    """(sources with their solid counts, error messages for the rest)."""
    from cadmedial import document

    sources, errors = [], []
    for obj in objects:
        if document.is_medial(obj) or document.is_sheet(obj):
            errors.append(f"'{obj.Label}' is a medial axis itself; select the solid it was made from")
            continue
        try:
            sources.append((obj, len(document.source_solids(obj))))
        except ValueError as e:
            errors.append(str(e))
    return sources, errors


def selected_medial_objects():
    from cadmedial import document

    return [o for o in selected_objects() if document.is_medial(o) or document.is_sheet(o)]


class ComputeCommand:
    def GetResources(self):
        return {
            "Pixmap": icon("MedialAxis.svg"),
            "MenuText": "Medial Axis",
            "Accel": "M, A",
            "ToolTip": "Inner medial axis of the selected solids: one parametric MedialAxis object per solid, "
            "with one mesh per medial sheet. Opens a task panel for the sample spacing and the "
            "CAD_MEDIAL parameters (theta, rho). Points and Mesh objects get MEDIAL on their points "
            "directly (inner axis of a closed mesh, whole axis of a point cloud).",
        }

    def IsActive(self):
        return _document() is not None and bool(Gui.Selection.getSelection())

    def Activated(self):
        try:
            objects = selected_objects()
            if not objects:
                report_error("select one or more solids first")
                return
            from cadmedial import document

            # Points / Mesh objects (scans, STL imports): MEDIAL on their points,
            # with the point-cloud defaults; no task panel (no spacing to choose).
            point_objects = [o for o in objects if document.is_point_object(o)]
            for obj in point_objects:
                self.compute_points(obj)
            sources, errors = solid_sources([o for o in objects if o not in point_objects])
            for e in errors:
                report_error(e)
            if not sources:
                if not point_objects:
                    report_error("nothing to do: the selection holds no solid, points or mesh")
                return
            if Gui.Control.activeDialog():
                report_error("close the open task panel first")
                return
            from . import task_panel

            Gui.Control.showDialog(task_panel.MedialAxisTaskPanel(sources=[s for s, _ in sources]))
        except Exception as e:  # noqa: BLE001 - never let an exception reach FreeCAD
            report_error(f"{type(e).__name__}: {e}")


    @staticmethod
    def compute_points(obj):
        from cadmedial import document

        try:
            (axis,) = document.add_to_document(obj.Document, obj)
            result = document.get_result(axis)
            note = result.summary.get("axis_note", "") if result is not None else ""
            report_message(f"'{obj.Label}': MEDIAL on {axis.Samples} points, {axis.Polygons} polygons; {note}")
        except Exception as e:  # noqa: BLE001 - never let an exception reach FreeCAD
            report_error(f"'{obj.Label}': {type(e).__name__}: {e}")


class ExportCommand:
    FILTERS = "PLY, radius and sheet ids (*.ply);;Wavefront OBJ, groups per sheet (*.obj);;Q-MAT medial mesh (*.ma)"

    def GetResources(self):
        return {
            "Pixmap": icon("Export.svg"),
            "MenuText": "Export medial axis...",
            "ToolTip": "Write the selected medial axes or sheets to .ply (radius per vertex, sheet and "
            "provenance per polygon), .obj (groups per sheet) or .ma (Q-MAT)",
        }

    def IsActive(self):
        return bool(selected_medial_objects())

    def Activated(self):
        from PySide2 import QtWidgets

        from cadmedial import document

        objects = selected_medial_objects()
        if not objects:
            report_error("select a medial axis or a sheet to export")
            return
        start = os.path.join(_start_dir(), _safe_name(objects[0].Label) + ".ply")
        path, chosen = QtWidgets.QFileDialog.getSaveFileName(Gui.getMainWindow(), "Export medial axis", start,
                                                             self.FILTERS)
        if not path:
            return
        if not os.path.splitext(path)[1]:
            path += "." + ("obj" if "obj" in chosen else "ma" if ".ma" in chosen else "ply")
        stem, ext = os.path.splitext(path)
        for obj in objects:
            target = path if len(objects) == 1 else f"{stem}_{_safe_name(obj.Label)}{ext}"
            try:
                document.export(obj, target)
                report_message(f"wrote {target}")
            except Exception as e:  # noqa: BLE001
                report_error(f"could not export '{obj.Label}' to {target}: {e}")


def _start_dir():
    doc = _document()
    if doc is not None and doc.FileName:
        return os.path.dirname(doc.FileName)
    return os.path.expanduser("~")


def _safe_name(label):
    return "".join(c if c.isalnum() or c in "-_." else "_" for c in label) or "medial"


# Lines of the latest evaluation per MedialAxis object name (for scripts and tests).
last_evaluation = {}


class EvaluateCommand:
    def GetResources(self):
        return {
            "Pixmap": icon("Evaluate.svg"),
            "MenuText": "Evaluate medial axis",
            "ToolTip": "Measure the selected medial axes against the exact solid (inside share, medialness, "
            "coverage, convex-edge and corner attachment, topology) and show the table in the Report view.",
        }

    def IsActive(self):
        return bool(selected_medial_objects())

    def Activated(self):
        from cadmedial import document

        for obj in selected_medial_objects():
            if document.is_sheet(obj):
                obj = obj.MedialAxis
            try:
                lines = document.evaluate(obj)
            except Exception as e:  # noqa: BLE001
                report_error(f"could not evaluate '{obj.Label}': {e}")
                continue
            last_evaluation[obj.Name] = lines
            App.Console.PrintMessage(f"Medial Axis: evaluation of '{obj.Label}':\n")
            for line in lines:
                App.Console.PrintMessage(f"  {line}\n")
            report_message(f"evaluation of '{obj.Label}' written to the Report view")


def pair_mesh_targets(objects):
    """(objects a pair-mesh can be made of, error messages for the rest):
    solids and MedialAxis objects (a sheet stands for its MedialAxis)."""
    from cadmedial import document, pair_document

    targets, errors = [], []
    for obj in objects:
        if document.is_sheet(obj):
            obj = obj.MedialAxis
        if obj in targets:
            continue
        try:
            pair_document.pair_mesh_sources(obj)
            targets.append(obj)
        except ValueError as e:
            errors.append(str(e))
    return targets, errors


def selected_pair_meshes():
    from cadmedial import pair_document

    out = []
    for obj in selected_objects():
        if pair_document.is_iso_surface(obj):
            obj = obj.PairMesh
        if pair_document.is_pair_mesh(obj) and obj not in out:
            out.append(obj)
    return out


class PairMeshCommand:
    def GetResources(self):
        return {
            "Pixmap": icon("PairMesh.svg"),
            "MenuText": "Pair-Mesh",
            "ToolTip": "Pair-mesh of the selected solids (or of the solid of a selected medial axis): "
            "tetrahedra linking the inner Voronoi diagram of the samples to the boundary, as a parametric "
            "FEM mesh with one group per element type (face-vertex, edge-edge, vertex-face). Validity "
            "(inverted elements, volume against the exact solid) goes to the Report view.",
        }

    def IsActive(self):
        return _document() is not None and bool(Gui.Selection.getSelection())

    def Activated(self):
        try:
            targets, errors = pair_mesh_targets(selected_objects())
            for e in errors:
                report_error(e)
            if not targets:
                if not errors:
                    report_error("select a solid or a medial axis first")
                return
            if Gui.Control.activeDialog():
                report_error("close the open task panel first")
                return
            from . import pair_mesh_panel

            Gui.Control.showDialog(pair_mesh_panel.PairMeshTaskPanel(targets))
        except Exception as e:  # noqa: BLE001 - never let an exception reach FreeCAD
            report_error(f"{type(e).__name__}: {e}")


class IsoSurfaceCommand:
    def GetResources(self):
        return {
            "Pixmap": icon("IsoSurface.svg"),
            "MenuText": "Iso-surface",
            "ToolTip": "Iso-parametric surface of the selected pair-mesh at T = 0.5 (a parametric mesh; "
            "change T between 0, the medial side, and 1, the boundary, in its properties)",
        }

    def IsActive(self):
        return bool(selected_pair_meshes())

    def Activated(self):
        from cadmedial import pair_document

        objects = selected_pair_meshes()
        if not objects:
            report_error("select a pair-mesh first")
            return
        doc = _document()
        doc.openTransaction("Iso-surface")
        try:
            for obj in objects:
                iso = pair_document.add_iso_surface(doc, obj, 0.5)
                report_message(f"'{iso.Label}': {iso.Triangles} triangles")
            doc.commitTransaction()
        except Exception as e:  # noqa: BLE001
            doc.abortTransaction()
            report_error(f"{type(e).__name__}: {e}")


class ExportPairMeshCommand:
    FILTERS = "VTK unstructured grid, type per element (*.vtu);;TetGen .node/.ele (*.node)"

    def GetResources(self):
        return {
            "Pixmap": icon("Export.svg"),
            "MenuText": "Export pair-mesh...",
            "ToolTip": "Write the selected pair-meshes to .vtu (ParaView; cell data type and on_sheets, point "
            "data boundary) or TetGen .node/.ele",
        }

    def IsActive(self):
        return bool(selected_pair_meshes())

    def Activated(self):
        from PySide2 import QtWidgets

        from cadmedial import pair_document

        objects = selected_pair_meshes()
        if not objects:
            report_error("select a pair-mesh to export")
            return
        start = os.path.join(_start_dir(), _safe_name(objects[0].Label) + ".vtu")
        path, chosen = QtWidgets.QFileDialog.getSaveFileName(Gui.getMainWindow(), "Export pair-mesh", start,
                                                             self.FILTERS)
        if not path:
            return
        if not os.path.splitext(path)[1]:
            path += ".node" if "node" in chosen else ".vtu"
        stem, ext = os.path.splitext(path)
        for obj in objects:
            target = path if len(objects) == 1 else f"{stem}_{_safe_name(obj.Label)}{ext}"
            try:
                written = pair_document.export_pair_mesh(obj, target)
                report_message(f"wrote {written if isinstance(written, str) else ', '.join(written)}")
            except Exception as e:  # noqa: BLE001
                report_error(f"could not export '{obj.Label}' to {target}: {e}")


_registered = False


def register():
    global _registered
    if _registered:
        return
    Gui.addCommand("MedialAxis_Compute", ComputeCommand())
    Gui.addCommand("MedialAxis_Export", ExportCommand())
    Gui.addCommand("MedialAxis_Evaluate", EvaluateCommand())
    Gui.addCommand("MedialAxis_PairMesh", PairMeshCommand())
    Gui.addCommand("MedialAxis_IsoSurface", IsoSurfaceCommand())
    Gui.addCommand("MedialAxis_ExportPairMesh", ExportPairMeshCommand())
    _registered = True
