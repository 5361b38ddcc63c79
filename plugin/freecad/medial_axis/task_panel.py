"""Task panel of the Medial Axis command: parameters, a live sample-count
estimate, progress and Cancel.

The computation runs in a worker thread (the C++ side releases the GIL); a
QTimer in the main thread polls it, so the window stays responsive. Document
objects are created in the main thread afterwards, from the results the worker
computed (the objects' first recompute finds them in the result cache).
Cancel stops the run at the next stage boundary (reading, sampling, medial
axis of each solid); a stage already running finishes in the background and
its result is dropped.
"""

import threading
import time

import FreeCAD as App
import FreeCADGui as Gui
from PySide2 import QtCore, QtGui, QtWidgets

from . import icon

#: The open panel (for scripts and tests: task_panel.current.accept()).
current = None

STAGE_TEXT = {"read": "reading", "sample": "sampling", "medial": "medial axis", "pair_mesh": "pair-mesh",
              "again": "pair-mesh not valid, sampling again finer",
              "prepare": "building the FEM mesh", "done": "done"}
STAGE_START = {"read": 0.0, "sample": 0.05, "medial": 0.35, "done": 1.0}
#: With the pair-mesh, the medial stage is shorter than the pair-mesh stage (exact cell labels).
PAIR_MESH_STAGE_START = {"read": 0.0, "sample": 0.05, "medial": 0.2, "pair_mesh": 0.35, "again": 0.5,
                         "prepare": 0.7, "done": 1.0}


class _Job:
    """One run in a worker thread: a list of (label, BREP text) to compute."""

    def __init__(self, items, spacing, theta, rho, check_inside, pair_mesh=False, prepare=None, graded_spacing=True):
        """prepare(result): optional work on each result in the worker thread
        (e.g. building a FEM mesh) so the main thread has less to do."""
        self.items = items
        self.prepare = prepare
        self.params = dict(spacing=spacing, theta=theta, rho=rho, check_inside=check_inside,
                           graded_spacing=bool(graded_spacing))
        if pair_mesh:
            self.params["pair_mesh"] = True
        self.stage_start = PAIR_MESH_STAGE_START if pair_mesh else STAGE_START
        self.cancel = threading.Event()
        self.results = []
        self.error = None
        self.stage = ("read", 0)
        self.started = time.monotonic()
        self.thread = threading.Thread(target=self._run, name="cadmedial-worker", daemon=True)

    def start(self):
        self.thread.start()

    def _run(self):
        import cadmedial

        try:
            for k, (_label, brep) in enumerate(self.items):

                last = {}

                def progress(stage, solid, solids, k=k, last=last):
                    # After a solid's pair-mesh, its stages come again when it was not
                    # valid (sampled again finer, cli/solid_run.hpp): one "again" stage.
                    if stage != "done" and last.get(solid) in ("pair_mesh", "again"):
                        stage = "again"
                    last[solid] = stage
                    self.stage = (stage, k)

                start = time.perf_counter()
                results = cadmedial.compute(brep, cancel=self.cancel, progress=progress, **self.params)
                results[0].seconds = time.perf_counter() - start  # wall time, as a recompute measures it
                if self.prepare is not None:
                    self.stage = ("prepare", k)
                    self.prepare(results[0])
                self.results.append(results[0])
        except BaseException as e:  # noqa: BLE001 - reported in the main thread
            self.error = e

    @property
    def finished(self):
        return not self.thread.is_alive()

    def fraction(self):
        stage, k = self.stage
        return min(1.0, (k + self.stage_start.get(stage, 0.0)) / max(1, len(self.items)))


class MedialAxisTaskPanel:
    def __init__(self, sources=None, edit=None):
        global current
        self.edit = edit  # a MedialAxis object to change, or None to create new ones
        self.sources = [edit.Source] if edit is not None else list(sources or [])
        self.doc = edit.Document if edit is not None else App.ActiveDocument
        self.job = None
        self.timer = QtCore.QTimer()
        self.timer.setInterval(100)
        self.timer.timeout.connect(self._poll)
        self.estimate_timer = QtCore.QTimer()
        self.estimate_timer.setSingleShot(True)
        self.estimate_timer.setInterval(150)
        self.estimate_timer.timeout.connect(self._update_estimate)
        self.created = []
        self.last_error = None
        self._solids = self._collect_solids()
        self.form = self._build_form()
        self._update_estimate()
        current = self

    # -- inputs ---------------------------------------------------------------
    def _collect_solids(self):
        """[(label, solid shape)] for every solid to compute."""
        from cadmedial import document

        solids = []
        for source in self.sources:
            shapes = document.source_solids(source)
            if self.edit is not None:
                shapes = [document.source_solid(source, self.edit.SolidIndex)]
            for i, solid in enumerate(shapes):
                label = source.Label if len(shapes) == 1 else f"{source.Label} solid {i + 1}"
                solids.append((label, solid))
        return solids

    def _build_form(self):
        form = QtWidgets.QWidget()
        form.setWindowTitle("Medial Axis")
        form.setWindowIcon(QtGui.QIcon(icon("MedialAxis.svg")))
        layout = QtWidgets.QVBoxLayout(form)

        names = ", ".join(label for label, _ in self._solids[:4]) + (" ..." if len(self._solids) > 4 else "")
        what = QtWidgets.QLabel(f"<b>{len(self._solids)} solid(s):</b> {names}")
        what.setWordWrap(True)
        layout.addWidget(what)

        grid = QtWidgets.QFormLayout()
        auto = max((s.BoundBox.DiagonalLength / 40.0 for _, s in self._solids), default=1.0)
        self.spacing = QtWidgets.QDoubleSpinBox()
        self.spacing.setRange(0.0, 1e6)
        self.spacing.setDecimals(4)
        self.spacing.setSingleStep(max(auto / 10.0, 1e-3))
        self.spacing.setSpecialValueText(f"automatic (~{auto:.3g})")
        self.spacing.setSuffix(" mm")
        self.spacing.setToolTip("Target sample spacing h; 0 = bounding-box diagonal / 40 per solid. "
                                "Curved faces are refined down to 0.2 x their radius.")
        self.theta = QtWidgets.QDoubleSpinBox()
        self.theta.setRange(0.0, 89.0)
        self.theta.setDecimals(2)
        self.theta.setSuffix(" \u00b0")
        self.theta.setToolTip("Angle condition of CAD_MEDIAL (default 5\u00b0)")
        self.rho = QtWidgets.QDoubleSpinBox()
        self.rho.setRange(0.1, 1000.0)
        self.rho.setDecimals(2)
        self.rho.setToolTip("Ratio condition of CAD_MEDIAL (default 8)")
        from cadmedial.document import GRADED_SPACING_DOC

        self.graded = QtWidgets.QCheckBox("graded within each face")
        self.graded.setToolTip(GRADED_SPACING_DOC)
        self.graded.setChecked(True)  # the default for new objects
        self.color_by = QtWidgets.QComboBox()
        self.color_by.addItems(["Radius", "Sheet"])
        self.color_by.setToolTip("Colour the sheets by medial radius or give every sheet its own colour")
        self.check_inside = QtWidgets.QCheckBox("check inner/outer with the exact classifier")
        self.check_inside.setToolTip("Counts disagreements of the walk with OCCT's classifier (slower)")
        grid.addRow("Spacing", self.spacing)
        grid.addRow("", self.graded)
        grid.addRow("Theta", self.theta)
        grid.addRow("Rho", self.rho)
        grid.addRow("Colour by", self.color_by)
        grid.addRow("", self.check_inside)
        layout.addLayout(grid)

        self.estimate = QtWidgets.QLabel()
        layout.addWidget(self.estimate)
        self.progress = QtWidgets.QProgressBar()
        self.progress.setRange(0, 1000)
        self.progress.setValue(0)
        self.progress.setVisible(False)
        layout.addWidget(self.progress)
        self.status = QtWidgets.QLabel("Press OK to compute.")
        self.status.setWordWrap(True)
        layout.addWidget(self.status)
        layout.addStretch(1)

        if self.edit is not None:
            self.spacing.setValue(self.edit.Spacing.Value)
            self.graded.setChecked(bool(getattr(self.edit, "GradedSpacing", False)))
            self.theta.setValue(self.edit.Theta.Value)
            self.rho.setValue(self.edit.Rho)
            self.color_by.setCurrentText(self.edit.ColorBy)
            self.check_inside.setChecked(self.edit.CheckInside)
        else:
            self.spacing.setValue(0.0)
            self.theta.setValue(5.0)
            self.rho.setValue(8.0)
            self.check_inside.setChecked(True)
        self.spacing.valueChanged.connect(lambda _v: self.estimate_timer.start())
        self.graded.toggled.connect(lambda _v: self.estimate_timer.start())
        return form

    def _update_estimate(self):
        from cadmedial import estimate_samples

        try:
            total = sum(estimate_samples(solid, self.spacing.value()) for _, solid in self._solids)
            seconds = total * 1.2e-4  # measured on the bundled models (2 cores, check on)
            # The estimate models one spacing per face; graded sampling takes at
            # most that many (far fewer on cones and thin flanges).
            bound = "up to " if self.graded.isChecked() else ""
            self.estimate.setText(f"Estimate: {bound}~{total:,} samples, ~{max(seconds, 0.1):.1f} s")
        except Exception as e:  # noqa: BLE001
            self.estimate.setText(f"Estimate not available ({e})")

    # -- task dialog interface ------------------------------------------------------
    def getStandardButtons(self):
        return int(QtWidgets.QDialogButtonBox.Ok | QtWidgets.QDialogButtonBox.Cancel)

    def isAllowedAlterDocument(self):
        return False

    def accept(self):
        """Starts the run; the dialog closes when the objects exist."""
        if self.job is not None:
            return False
        try:
            items = [(label, solid.exportBrepToString()) for label, solid in self._solids]
        except Exception as e:  # noqa: BLE001
            self._fail(f"could not read the solids: {e}")
            return False
        self.job = _Job(items, self.spacing.value(), self.theta.value(), self.rho.value(),
                        self.check_inside.isChecked(), graded_spacing=self.graded.isChecked())
        for w in self._inputs():
            w.setEnabled(False)
        self.progress.setVisible(True)
        self.progress.setValue(0)
        self.status.setText("Computing... (Cancel stops at the next stage)")
        self.last_error = None
        self.job.start()
        self.timer.start()
        return False

    def reject(self):
        if self.job is not None and not self.job.finished:
            self.job.cancel.set()
            App.Console.PrintWarning("Medial Axis: cancelled\n")
        self._close()
        return True

    @property
    def running(self):
        return self.job is not None

    # -- worker polling -----------------------------------------------------------
    def _poll(self):
        job = self.job
        if job is None:
            self.timer.stop()
            return
        stage, k = job.stage
        elapsed = time.monotonic() - job.started
        label = job.items[min(k, len(job.items) - 1)][0]
        self.progress.setValue(int(1000 * job.fraction()))
        self.status.setText(f"{label}: {STAGE_TEXT.get(stage, stage)}... {elapsed:.1f} s")
        if not job.finished:
            return
        self.timer.stop()
        self.job = None
        if job.error is not None:
            for w in self._inputs():
                w.setEnabled(True)
            self.progress.setVisible(False)
            self._fail(f"{type(job.error).__name__}: {job.error}" if not str(job.error) else str(job.error))
            return
        self._finish(job)

    def _inputs(self):
        """The widgets of the parameters, disabled while a run goes on."""
        return (self.spacing, self.graded, self.theta, self.rho, self.color_by, self.check_inside)

    def _fail(self, message):
        self.last_error = message
        App.Console.PrintError(f"Medial Axis: {message}\n")
        self.status.setText(f"<span style='color:#b00020'>Error: {message}</span>")

    def _finish(self, job):
        from cadmedial import document

        p = job.params
        color_by = self.color_by.currentText()
        doc = self.doc
        doc.openTransaction("Medial Axis")
        try:
            if self.edit is None:
                created = []
                offset = 0
                for source in self.sources:
                    n = len(document.source_solids(source))
                    created += document.add_to_document(
                        doc, source, spacing=p["spacing"], theta=p["theta"], rho=p["rho"],
                        check_inside=p["check_inside"], color_by=color_by, graded_spacing=p["graded_spacing"],
                        results=job.results[offset:offset + n])
                    offset += n
                    self._show_inside(source)
                self.created = created
            else:
                obj = self.edit
                solid = document.source_solid(obj.Source, obj.SolidIndex)
                document.remember_result(
                    document.input_signature(solid.exportBrepToString(), p["spacing"], p["theta"], p["rho"],
                                             p["check_inside"], p["graded_spacing"]), job.results[0])
                obj.Spacing = p["spacing"]
                obj.GradedSpacing = p["graded_spacing"]
                obj.Theta = p["theta"]
                obj.Rho = p["rho"]
                obj.CheckInside = p["check_inside"]
                obj.ColorBy = color_by
                doc.recompute()
                document.sync_sheets(obj)
                self.created = [obj]
            doc.commitTransaction()
        except Exception as e:  # noqa: BLE001
            doc.abortTransaction()
            self._fail(str(e))
            for w in self._inputs():
                w.setEnabled(True)
            self.progress.setVisible(False)
            return
        Gui.Selection.clearSelection()  # the selection colour would hide the radius colours
        seconds = time.monotonic() - job.started
        for obj in self.created:
            App.Console.PrintMessage(
                f"Medial Axis: {obj.Label}: {obj.Samples} samples, {obj.Polygons} polygons, {obj.Sheets} sheets, "
                f"beta0/beta1 {obj.Beta0}/{obj.Beta1}\n")
        App.Console.PrintMessage(f"Medial Axis: done in {seconds:.2f} s\n")
        self._close()

    def _show_inside(self, source):
        """Makes an opaque source see-through, so the axis inside is visible."""
        vobj = getattr(source, "ViewObject", None)
        if vobj is not None and "Transparency" in vobj.PropertiesList and vobj.Transparency == 0:
            vobj.Transparency = 75

    def _close(self):
        global current
        self.timer.stop()
        self.estimate_timer.stop()
        if current is self:
            current = None
        Gui.Control.closeDialog()
        if self.edit is not None and Gui.ActiveDocument is not None:
            Gui.ActiveDocument.resetEdit()
