"""Fits the two densities of cadmedial.estimate_samples on the bundled models.

    python3 plugin/tools/calibrate_estimate.py [models dir]

Needs FreeCAD's Python modules (/usr/lib/freecad-python3/lib) and an
installed cadmedial (plugin/install.sh). Prints the fitted densities and the
relative error of the estimate per model and spacing.
"""

import glob
import os
import sys
import time

sys.path.append("/usr/lib/freecad-python3/lib")
import numpy as np  # noqa: E402
import FreeCAD  # noqa: E402,F401  (before Part, or Part crashes)
import Part  # noqa: E402

import cadmedial  # noqa: E402
from cadmedial import api  # noqa: E402

models = sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), "..", "..", "models")
rows, counts, names, seconds = [], [], [], []
for path in sorted(glob.glob(os.path.join(models, "*.step"))):
    shape = Part.read(path)
    for solid in shape.Solids:
        auto = solid.BoundBox.DiagonalLength / 40
        for factor in (0.5, 1.0, 2.0):
            h = auto * factor
            api._FACE_DENSITY, api._EDGE_DENSITY = 1.0, 0.0
            face_term = api.estimate_samples(solid, h) - len(solid.Vertexes)
            api._FACE_DENSITY, api._EDGE_DENSITY = 0.0, 1.0
            edge_term = api.estimate_samples(solid, h) - len(solid.Vertexes)
            t = time.perf_counter()
            # The estimate models one spacing per face: fit it to uniform sampling.
            n = len(cadmedial.compute(solid, spacing=h, graded_spacing=False)[0].radius) and \
                cadmedial.sample(solid, spacing=h, graded_spacing=False)[0].points.shape[0]
            seconds.append(time.perf_counter() - t)
            rows.append([face_term, edge_term])
            counts.append(n - len(solid.Vertexes))
            names.append(f"{os.path.basename(path)} h={h:.3g}")
a, b = np.linalg.lstsq(np.array(rows), np.array(counts, dtype=float), rcond=None)[0]
print(f"_FACE_DENSITY = {a:.4f}\n_EDGE_DENSITY = {b:.4f}")
for name, (f, e), n in zip(names, rows, counts):
    est = a * f + b * e
    print(f"{name:40s} samples {n:7d} estimate {est:9.0f} error {100 * (est / n - 1):+6.1f} %")
total = np.array(counts).sum()
print(f"seconds per sample (compute + sample, check_inside on): {sum(seconds) / total:.2e}")
