"""Medial axis of a STEP file, headless.

    python3 plugin/examples/medial_axis_of_step.py models/flange.step out/   # plain Python
    freecadcmd plugin/examples/medial_axis_of_step.py                       # FreeCAD (uses the defaults below)

Plain python3 writes PLY/OBJ/.ma per solid. Under FreeCAD (or python3 with
FreeCAD's lib folder importable) it also builds a document with parametric
MedialAxis objects, changes a parameter, recomputes and saves it.
Needs plugin/install.sh to have run.
"""

import os
import sys

import cadmedial

here = os.path.dirname(os.path.abspath(__file__))
args = [a for a in sys.argv[1:] if not a.endswith(".py")]
step = args[0] if args else os.path.join(here, "..", "..", "models", "flange.step")
out = args[1] if len(args) > 1 else os.path.join(os.getcwd(), "medial_out")
os.makedirs(out, exist_ok=True)

# 1. Plain arrays, no FreeCAD needed.
for axis in cadmedial.compute(step, spacing=0, theta=5, rho=8,
                              progress=lambda stage, solid, solids: print(f"  {stage} (solid {solid} of {solids})")):
    print(axis)
    print("  vertices", axis.vertices.shape, "radius", axis.radius.min(), "..", axis.radius.max())
    print("  polygon 0 =", axis.indices[axis.offsets[0]:axis.offsets[1]], "sheet", axis.sheet[0])
    print("  topology", axis.summary["topology"], "seconds", round(axis.seconds, 3))
    for ext in ("ply", "obj", "ma"):
        print("  wrote", axis.write(os.path.join(out, f"solid_{axis.solid}.{ext}")))

# 2. Parametric FreeCAD objects, when FreeCAD is importable.
try:
    import FreeCAD as App
    import Part
except ImportError:
    sys.exit(0)

doc = App.newDocument("MedialExample")
part = doc.addObject("Part::Feature", "Part")
part.Shape = Part.read(step)
doc.recompute()
(medial,) = cadmedial.add_to_document(doc, part, spacing=0, color_by="Sheet")
print(f"{medial.Label}: {medial.Samples} samples, {medial.Polygons} polygons, {medial.Sheets} sheets, "
      f"beta0/beta1 {medial.Beta0}/{medial.Beta1}, {medial.Seconds} s")
medial.Spacing = 0.5 * medial.SpacingUsed.Value   # finer sampling: recomputes on doc.recompute()
doc.recompute()
print(f"finer: {medial.Samples} samples, {len(cadmedial.document.sheet_children(medial))} sheet objects")
doc.saveAs(os.path.join(out, "medial_example.FCStd"))
print("saved", os.path.join(out, "medial_example.FCStd"))
sys.exit(0)
