"""GUI smoke test of the Medial Axis workbench, run as `xvfb-run -a freecad
test_gui.py` by run_freecad_test.sh (addon installed into a temporary home).

Activates the workbench, opens models/flange.step, selects it, runs the
*Medial Axis* command through Gui.runCommand, accepts its task panel (the
computation runs in a worker thread while this script keeps the event loop
going), checks the objects, tries a bad selection, and saves an isometric
screenshot of the 3D view to $CADMEDIAL_SCREENSHOT. Ends FreeCAD with exit
code 1 if anything is missing.
"""

import os
import sys
import time
import traceback

import FreeCAD as App
import FreeCADGui as Gui
from PySide2 import QtCore, QtGui, QtWidgets

failures = []


def check(condition, what):
    print(("ok    " if condition else "FAIL  ") + what, flush=True)
    if not condition:
        failures.append(what)
    return condition


def wait_until(condition, timeout):
    start = time.monotonic()
    while not condition():
        if time.monotonic() - start > timeout:
            return False
        QtWidgets.QApplication.processEvents(QtCore.QEventLoop.AllEvents, 50)
        time.sleep(0.01)
    return True


def image_is_rich(path):
    """The image exists and shows more than a background: many distinct colours."""
    image = QtGui.QImage(path)
    if image.isNull():
        return False, 0
    colours = set()
    for y in range(0, image.height(), 4):
        for x in range(0, image.width(), 4):
            colours.add(image.pixel(x, y))
    return len(colours) > 200, len(colours)


def main():
    import Part

    from cadmedial import document

    source_dir = os.environ["CADMEDIAL_SOURCE_DIR"]
    screenshot = os.environ.get("CADMEDIAL_SCREENSHOT") or os.path.join(os.environ["CADMEDIAL_TEST_TMP"], "gui.png")
    if os.path.exists(screenshot):
        os.remove(screenshot)

    Gui.activateWorkbench("MedialAxisWorkbench")
    check(type(Gui.activeWorkbench()).__name__ == "MedialAxisWorkbench", "workbench activated")
    commands = set(Gui.listCommands())
    for name in ("MedialAxis_Compute", "MedialAxis_Export", "MedialAxis_Evaluate", "MedialAxis_PairMesh",
                 "MedialAxis_IsoSurface", "MedialAxis_ExportPairMesh"):
        check(name in commands, f"command {name} registered")

    doc = App.newDocument("GuiTest")
    flange = doc.addObject("Part::Feature", "Flange")
    flange.Shape = Part.read(os.path.join(source_dir, "models", "flange.step"))
    doc.recompute()
    Gui.SendMsgToActiveView("ViewFit")

    from freecad.medial_axis import commands as wb_commands
    from freecad.medial_axis import task_panel

    check(not wb_commands.IsoSurfaceCommand().IsActive(), "Iso-surface is inactive without a selected pair-mesh")

    # A bad selection: an error in the Report view, no task panel, no object.
    face = doc.addObject("Part::Feature", "JustAFace")
    face.Shape = Part.makePlane(10, 10, App.Vector(200, 200, 0))
    doc.recompute()
    Gui.Selection.clearSelection()
    Gui.Selection.addSelection(doc.Name, face.Name)
    count = len(doc.Objects)
    Gui.runCommand("MedialAxis_Compute")
    wait_until(lambda: False, 0.3)
    check(task_panel.current is None and len(doc.Objects) == count, "a face selection opens nothing and adds nothing")
    doc.removeObject(face.Name)

    # Cancel during a long run: the panel closes at once, nothing is created,
    # and the worker stops at its next stage boundary.
    Gui.Selection.clearSelection()
    Gui.Selection.addSelection(doc.Name, flange.Name)
    Gui.runCommand("MedialAxis_Compute")
    check(wait_until(lambda: task_panel.current is not None, 10), "task panel opens (cancel run)")
    panel = task_panel.current
    if panel is None:
        return
    panel.spacing.setValue(0.6)
    panel.accept()
    wait_until(lambda: False, 0.3)
    job = panel.job
    check(job is not None and not job.finished, "a long run is under way")
    start = time.monotonic()
    panel.reject()  # what the Cancel button calls
    check(task_panel.current is None and time.monotonic() - start < 1.0, "Cancel closes the panel at once")
    check(not any(document.is_medial(o) for o in doc.Objects), "a cancelled run creates nothing")
    if job is not None:
        check(wait_until(lambda: job.finished, 120), "the worker stops after Cancel")
        import cadmedial

        check(isinstance(job.error, cadmedial.Cancelled), f"the worker ended with Cancelled ({job.error!r})")

    # A failing computation: the error is shown, the panel stays open, no crash.
    import cadmedial

    real_compute = cadmedial.compute

    def failing_compute(*args, **kwargs):
        raise RuntimeError("simulated failure in the C++ pipeline")

    Gui.Selection.clearSelection()
    Gui.Selection.addSelection(doc.Name, flange.Name)
    Gui.runCommand("MedialAxis_Compute")
    wait_until(lambda: task_panel.current is not None, 10)
    panel = task_panel.current
    cadmedial.compute = failing_compute
    try:
        panel.accept()
        wait_until(lambda: panel.job is None, 30)
    finally:
        cadmedial.compute = real_compute
    check(task_panel.current is panel and "simulated failure" in (panel.last_error or ""),
          f"an error stays in the open panel ({panel.last_error})")
    panel.reject()
    check(task_panel.current is None, "the panel closes after the error")

    # The real run.
    Gui.Selection.clearSelection()
    Gui.Selection.addSelection(doc.Name, flange.Name)
    Gui.runCommand("MedialAxis_Compute")
    check(wait_until(lambda: task_panel.current is not None, 10), "Medial Axis opens its task panel")
    panel = task_panel.current
    if panel is None:
        return
    check("samples" in panel.estimate.text(), f"live estimate: {panel.estimate.text()}")
    panel.spacing.setValue(2.5)
    wait_until(lambda: False, 0.3)
    check("samples" in panel.estimate.text(), f"estimate follows the spacing: {panel.estimate.text()}")
    start = time.monotonic()
    panel.accept()
    polled = []
    check(wait_until(lambda: task_panel.current is None or polled.append(panel.progress.value()), 180),
          f"computation finished in {time.monotonic() - start:.1f} s with the GUI responsive "
          f"({len(polled)} event-loop rounds)")
    check(panel.last_error is None, f"no error ({panel.last_error})")
    axes = [o for o in doc.Objects if document.is_medial(o)]
    check(len(axes) == 1, "one MedialAxis object")
    if not axes:
        return
    axis = axes[0]
    wait_until(lambda: False, 0.5)  # deferred sheet updates
    sheets = document.sheet_children(axis)
    check(axis.Polygons > 1000 and axis.Sheets >= 1, f"{axis.Polygons} polygons, {axis.Sheets} sheets")
    check(len(sheets) == min(axis.Sheets, axis.MaxSheetObjects), f"{len(sheets)} sheet objects")
    check(axis.ViewObject.Coloring, "axis coloured (per-vertex radius)")
    check(doc.UndoCount >= 1 and "Medial Axis" in doc.UndoNames, f"undo transaction {doc.UndoNames[:3]}")
    check(axis.Spacing.Value == 2.5, "task panel spacing stored")

    # Screenshot: isometric, fitted, the flange see-through around the coloured axis.
    gui_doc = Gui.getDocument(doc.Name)
    flange_view = gui_doc.getObject(flange.Name)
    flange_view.Transparency = 80
    flange_view.ShapeColor = (0.75, 0.78, 0.82)
    flange_view.LineColor = (0.25, 0.27, 0.30)
    Gui.Selection.clearSelection()
    view = gui_doc.ActiveView
    view.viewIsometric()
    view.fitAll()
    camera = view.getCameraNode()
    if hasattr(camera, "height"):  # orthographic: fill the frame a little more than fitAll does
        camera.height.setValue(camera.height.getValue() * 0.72)
    Gui.updateGui()
    wait_until(lambda: False, 0.5)
    view.saveImage(screenshot, 1600, 1200, "Current")
    rich, colours = image_is_rich(screenshot)
    check(os.path.isfile(screenshot) and rich, f"screenshot {screenshot} ({colours} colours)")

    # Parametric change from the GUI side.
    axis.Rho = 7.0
    doc.recompute()
    wait_until(lambda: False, 0.5)
    check(not ({"Invalid", "Touched"} & set(axis.State)), "recompute after a property change")

    # Editing: double-click opens the panel for the object; OK recomputes it.
    axis.ViewObject.Proxy.doubleClicked(axis.ViewObject)
    check(wait_until(lambda: task_panel.current is not None, 10) and task_panel.current.edit == axis,
          "double-click opens the task panel in edit mode")
    if task_panel.current is not None:
        panel = task_panel.current
        check(panel.graded.isChecked() is True and panel.graded in panel._inputs(),
              "the panel shows GradedSpacing (on)")
        panel.color_by.setCurrentText("Sheet")
        panel.theta.setValue(6.0)
        panel.graded.setChecked(False)
        panel.accept()
        check(wait_until(lambda: task_panel.current is None, 120), "edit run finished")
        wait_until(lambda: False, 0.5)
        check(axis.Theta.Value == 6.0 and axis.ColorBy == "Sheet", "edited parameters stored")
        check(not axis.GradedSpacing and document.get_result(axis).summary.get("graded_spacing") is False,
              "uniform spacing from the panel: stored and computed with")
        check(not ({"Invalid", "Touched"} & set(axis.State)), "edited object up to date")
        axis.ColorBy = "Radius"
        axis.GradedSpacing = True
        doc.recompute()

    Gui.Selection.clearSelection()
    Gui.Selection.addSelection(doc.Name, axis.Name)
    from freecad.medial_axis import commands

    commands.last_evaluation.clear()
    Gui.runCommand("MedialAxis_Evaluate")
    lines = commands.last_evaluation.get(axis.Name, [])
    check(any(line.strip() == "verdict: PASS" for line in lines),
          "Evaluate measures the axis against the exact solid: " + (lines[-1].strip() if lines else "no output"))

    # Saved from the GUI and reopened: view providers, colours and tree intact.
    copy = os.path.join(os.environ["CADMEDIAL_TEST_TMP"], "gui_copy.FCStd")
    doc.saveCopy(copy)
    reopened = App.openDocument(copy)
    wait_until(lambda: False, 0.5)
    again = next(o for o in reopened.Objects if document.is_medial(o))
    check(isinstance(again.ViewObject.Proxy, document.ViewProviderMedialAxis), "reopened: view provider restored")
    check(again.ViewObject.Coloring and len(again.Colors) > 0, "reopened: still coloured")
    check(len(again.ViewObject.Proxy.claimChildren()) == len(sheets), "reopened: sheets under the axis in the tree")
    App.closeDocument(reopened.Name)
    App.setActiveDocument(doc.Name)

    # Undo: the edit, then the creation (each one transaction).
    names = list(doc.UndoNames)
    check(names[:2] == ["Medial Axis", "Medial Axis"], f"undo stack {names}")
    for _ in names:
        doc.undo()
    wait_until(lambda: False, 0.3)
    check(not any(document.is_medial(o) or document.is_sheet(o) for o in doc.Objects),
          "undo removes the medial axis and its sheets")


def run():
    code = 1
    try:
        main()
        code = 1 if failures else 0
    except Exception:  # noqa: BLE001
        traceback.print_exc()
    print(f"{len(failures)} failure(s)" + (": " + "; ".join(failures) if failures else ""), flush=True)
    sys.stdout.flush()
    sys.stderr.flush()
    os._exit(code)


QtCore.QTimer.singleShot(500, run)
