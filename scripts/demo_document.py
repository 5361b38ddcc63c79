"""Saves a FreeCAD document with the medial axis of a STEP model, headless.

    freecadcmd scripts/demo_document.py    (reads CADMEDIAL_DEMO_MODEL and CADMEDIAL_DEMO_FCSTD)

freecadcmd exits 0 even when a script raises, so the caller checks that the
.FCStd exists; it is written under a temporary name and renamed when saved.
"""
import os
import sys

import FreeCAD as App
import Part

import cadmedial

model = os.environ["CADMEDIAL_DEMO_MODEL"]
target = os.environ["CADMEDIAL_DEMO_FCSTD"]
try:
    doc = App.newDocument("MedialAxisDemo")
    source = doc.addObject("Part::Feature", os.path.splitext(os.path.basename(model))[0])
    source.Shape = Part.read(model)
    doc.recompute()
    for axis in cadmedial.add_to_document(doc, source):
        print(f"{axis.Label}: {axis.Samples} samples, {axis.Polygons} polygons, {axis.Sheets} sheets")
    partial = target + ".part.FCStd"
    doc.saveAs(partial)
    os.replace(partial, target)
    print("saved", target)
except Exception as error:  # report and leave no document behind
    print(f"error: {error}", file=sys.stderr)
    sys.exit(1)
