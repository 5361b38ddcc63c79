"""Task panel of the Pair-Mesh command: spacing, progress and Cancel.

Same pattern as the Medial Axis panel (task_panel.py): the computation runs
in a worker thread (the C++ side releases the GIL), a QTimer polls it, and
the PairMesh objects are created in the main thread afterwards from the
worker's results (their first recompute finds them in the result cache).
"""

import time

import FreeCAD as App
import FreeCADGui as Gui
from PySide2 import QtCore, QtGui, QtWidgets

from . import icon
from .task_panel import STAGE_TEXT, _Job

#: The open panel (for scripts and tests: pair_mesh_panel.current.accept()).
current = None


class PairMeshTaskPanel:
    def __init__(self, objects):
        """objects: solid objects and/or MedialAxis objects (their source,
        solid and parameters are used)."""
        global current
        from cadmedial import pair_document

        self.doc = App.ActiveDocument
        # [(selected object, source, solid indices, params)]
        self.targets = []
        for obj in objects:
            source, indices, params = pair_document.pair_mesh_sources(obj)
            self.targets.append((obj, source, indices, params))
        self.job = None
        self.created = []
        self.last_error = None
        self.timer = QtCore.QTimer()
        self.timer.setInterval(100)
        self.timer.timeout.connect(self._poll)
        self.form = self._build_form()
        current = self

    def _solids(self):
        from cadmedial import document

        for obj, source, indices, params in self.targets:
            for i in indices:
                yield obj, source, i, params, document.source_solid(source, i)

    def _build_form(self):
        form = QtWidgets.QWidget()
        form.setWindowTitle("Pair-Mesh")
        form.setWindowIcon(QtGui.QIcon(icon("PairMesh.svg")))
        layout = QtWidgets.QVBoxLayout(form)
        labels = [s.Label + (f" solid {i + 1}" if len(idx) > 1 else "") for _, s, idx, _ in self.targets for i in idx]
        what = QtWidgets.QLabel(f"<b>{len(labels)} solid(s):</b> " + ", ".join(labels[:4])
                                + (" ..." if len(labels) > 4 else ""))
        what.setWordWrap(True)
        layout.addWidget(what)
        grid = QtWidgets.QFormLayout()
        solids = [solid for *_, solid in self._solids()]
        auto = max((s.BoundBox.DiagonalLength / 40.0 for s in solids), default=1.0)
        self.spacing = QtWidgets.QDoubleSpinBox()
        self.spacing.setRange(0.0, 1e6)
        self.spacing.setDecimals(4)
        self.spacing.setSingleStep(max(auto / 10.0, 1e-3))
        self.spacing.setSpecialValueText(f"automatic (~{auto:.3g})")
        self.spacing.setSuffix(" mm")
        self.spacing.setToolTip("Sample spacing h; 0 = bounding-box diagonal / 40 per solid. A medial axis "
                                "selected as the source gives its own spacing.")
        from_axis = [p for *_, p in self.targets if p]
        self.spacing.setValue(from_axis[0]["spacing"] if from_axis else 0.0)
        grid.addRow("Spacing", self.spacing)
        layout.addLayout(grid)
        note = QtWidgets.QLabel("Tetrahedra between the inner Voronoi diagram of the samples and the boundary "
                                "(face-vertex, edge-edge, vertex-face), as a FEM mesh with one group per type.")
        note.setWordWrap(True)
        layout.addWidget(note)
        self.progress = QtWidgets.QProgressBar()
        self.progress.setRange(0, 1000)
        self.progress.setVisible(False)
        layout.addWidget(self.progress)
        self.status = QtWidgets.QLabel("Press OK to compute.")
        self.status.setWordWrap(True)
        layout.addWidget(self.status)
        layout.addStretch(1)
        return form

    def getStandardButtons(self):
        return int(QtWidgets.QDialogButtonBox.Ok | QtWidgets.QDialogButtonBox.Cancel)

    def isAllowedAlterDocument(self):
        return False

    @property
    def running(self):
        return self.job is not None

    def _params(self, params):
        """Theta / rho / graded spacing of a selected medial axis, else the defaults; the spacing of the panel."""
        return (self.spacing.value(), params.get("theta", 5.0), params.get("rho", 8.0),
                params.get("graded_spacing", True))

    def accept(self):
        if self.job is not None:
            return False
        try:
            solids = list(self._solids())
            items = [(f"{source.Label}", solid.exportBrepToString()) for _, source, _, _, solid in solids]
        except Exception as e:  # noqa: BLE001
            self._fail(f"could not read the solids: {e}")
            return False
        # One parameter set per run (the first target's theta / rho).
        spacing, theta, rho, graded = self._params(self.targets[0][3])
        from cadmedial import pair_document

        # The FemMesh is built in the worker too (pure data, no document):
        # for large meshes it takes longer than the pair-mesh itself.
        self.job = _Job(items, spacing, theta, rho, False, pair_mesh=True, graded_spacing=graded,
                        prepare=lambda result: pair_document.prebuild_fem_mesh(result.pair_mesh))
        self.spacing.setEnabled(False)
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
            App.Console.PrintWarning("Medial Axis: pair-mesh cancelled\n")
        self._close()
        return True

    def _poll(self):
        job = self.job
        if job is None:
            self.timer.stop()
            return
        stage, k = job.stage
        label = job.items[min(k, len(job.items) - 1)][0]
        self.progress.setValue(int(1000 * job.fraction()))
        self.status.setText(f"{label}: {STAGE_TEXT.get(stage, stage)}... {time.monotonic() - job.started:.1f} s")
        if not job.finished:
            return
        self.timer.stop()
        self.job = None
        if job.error is not None:
            self.spacing.setEnabled(True)
            self.progress.setVisible(False)
            self._fail(str(job.error) or type(job.error).__name__)
            return
        self._finish(job)

    def _fail(self, message):
        self.last_error = message
        App.Console.PrintError(f"Medial Axis: {message}\n")
        self.status.setText(f"<span style='color:#b00020'>Error: {message}</span>")

    def _finish(self, job):
        from cadmedial import pair_document

        p = job.params
        doc = self.doc
        doc.openTransaction("Pair-Mesh")
        try:
            created, offset = [], 0
            for _obj, source, indices, _params in self.targets:
                results = [r.pair_mesh for r in job.results[offset:offset + len(indices)]]
                created += pair_document.add_pair_mesh(doc, source, spacing=p["spacing"], theta=p["theta"],
                                                       rho=p["rho"], solids=indices, results=results,
                                                       graded_spacing=p["graded_spacing"])
                offset += len(indices)
            doc.commitTransaction()
        except Exception as e:  # noqa: BLE001
            doc.abortTransaction()
            self.spacing.setEnabled(True)
            self.progress.setVisible(False)
            self._fail(str(e))
            return
        self.created = created
        for obj in created:
            mesh = pair_document.get_pair_mesh(obj)
            App.Console.PrintMessage(f"Medial Axis: {obj.Label}:\n")
            for line in pair_document.validity_lines(mesh):
                App.Console.PrintMessage(f"  {line}\n")
        App.Console.PrintMessage(f"Medial Axis: pair-mesh done in {time.monotonic() - job.started:.2f} s\n")
        self._close()

    def _close(self):
        global current
        self.timer.stop()
        if current is self:
            current = None
        Gui.Control.closeDialog()
