"""Writes CAD parts unlike the bundled and public models, for a robustness
sweep of `cadmedial run --pair-mesh` and `cadmedial eval` (curved-only
solids, 1-D medial axes, B-spline faces, fillets, thin and small features).

    CADMEDIAL_PARTS_DIR=OUTDIR freecadcmd scripts/robustness_parts.py
    (OUTDIR as an argument works too; freecadcmd then also says it cannot open it)
    for f in OUTDIR/*.step; do n=$(basename $f .step)
      build/cli/cadmedial run $f --no-oracle --pair-mesh -o sweep/$n && build/cli/cadmedial eval $f sweep/$n
    done

What the sweep of 2026-12-02 found with them is in ARCHITECTURE.md ("Known
gaps") and the issue notes: thin_ring needed the third sampling attempt
(every spacing finer), eval did not finish on box_fillet_variable and
helix_spring (B-spline search) and misread t_pipe's branch axis (both
mended); two contacts on box_fillet_all (51 %) and t_pipe (85 %) rose to
74 % and 95 % with the fringe thinning (box_fillet_all still under 90 %);
since mended: cone_apex (edges, with edges following their faces' spacing),
sharp_wedge (knife-edge rungs and the weld of coincident Voronoi vertices),
small_step (narrow faces); still open (2026-12-03): shallow convex edges on
loft_circle_square and box_fillet_variable, two contacts on box_fillet_all.
"""
import math
import os
import sys

import FreeCAD
import Part

V = FreeCAD.Vector


def groove():
    """A revolved profile with a concave circular groove."""
    edges = [Part.LineSegment(V(0, 0, 0), V(30, 0, 0)).toShape(),
             Part.LineSegment(V(30, 0, 0), V(30, 0, 20)).toShape(),
             Part.Arc(V(30, 0, 20), V(22, 0, 30), V(30, 0, 40)).toShape(),
             Part.LineSegment(V(30, 0, 40), V(30, 0, 60)).toShape(),
             Part.LineSegment(V(30, 0, 60), V(0, 0, 60)).toShape(),
             Part.LineSegment(V(0, 0, 60), V(0, 0, 0)).toShape()]
    return Part.Face(Part.Wire(edges)).revolve(V(0, 0, 0), V(0, 0, 1), 360)


def loft():
    circle = Part.Wire(Part.makeCircle(20, V(0, 0, 0)))
    square = Part.makePolygon([V(-15, -15, 40), V(15, -15, 40), V(15, 15, 40), V(-15, 15, 40), V(-15, -15, 40)])
    return Part.makeLoft([circle, square], True, False)


def twisted_loft():
    rectangle = Part.makePolygon([V(-10, -5, 0), V(10, -5, 0), V(10, 5, 0), V(-10, 5, 0), V(-10, -5, 0)])
    wires = []
    for i in range(9):
        w = rectangle.copy()
        w.rotate(V(0, 0, 0), V(0, 0, 1), 90.0 * i / 8)
        w.translate(V(0, 0, 60.0 * i / 8))
        wires.append(w)
    return Part.makeLoft(wires, True, False)


def t_pipe():
    main = Part.makeCylinder(10, 100, V(-50, 0, 0), V(1, 0, 0))
    branch = Part.makeCylinder(8, 50, V(0, 0, 0), V(0, 0, 1))
    return main.fuse(branch).removeSplitter()


def plate_with_holes():
    plate = Part.makeBox(100, 100, 2)
    for x, y, r in [(20, 20, 5), (80, 20, 8), (50, 50, 12), (20, 80, 3), (80, 80, 6)]:
        plate = plate.cut(Part.makeCylinder(r, 4, V(x, y, -1)))
    return plate


def hollow_shell():
    box = Part.makeBox(50, 40, 30)
    top = [f for f in box.Faces if abs(f.CenterOfMass.z - 30) < 1e-6]
    return box.makeThickness(top, -2, 1e-3)


def star_prism():
    points = []
    for i in range(24):
        r = 30 if i % 2 == 0 else 18
        points.append(V(r * math.cos(math.pi * i / 12), r * math.sin(math.pi * i / 12), 0))
    return Part.Face(Part.makePolygon(points + [points[0]])).extrude(V(0, 0, 15))


def sharp_wedge():
    a, length = math.radians(8), 60.0
    points = [V(0, 0, 0), V(length, 0, 0), V(length, length * math.tan(a), 0), V(0, 0, 0)]
    return Part.Face(Part.makePolygon(points)).extrude(V(0, 0, 30))


def helix_spring():
    helix = Part.makeHelix(12, 36, 20)
    circle = Part.Wire(Part.Circle(V(20, 0, 0), V(0, 1, 0), 3).toShape())
    return Part.Wire(helix).makePipeShell([circle], True, True)


PARTS = {
    "sphere": lambda: Part.makeSphere(25),
    "cone_apex": lambda: Part.makeCone(20, 0, 50),
    "cone_trunc": lambda: Part.makeCone(25, 10, 40),
    "revolve_groove": groove,
    "loft_circle_square": loft,
    "twisted_loft": twisted_loft,
    "box_sphere_pocket": lambda: Part.makeBox(60, 60, 40).cut(Part.makeSphere(20, V(30, 30, 40))),
    "t_pipe": t_pipe,
    "thin_plate_holes": plate_with_holes,
    "hollow_shell": hollow_shell,
    "box_fillet_all": lambda: (lambda b: b.makeFillet(3.0, b.Edges))(Part.makeBox(60, 40, 30)),
    "box_fillet_variable": lambda: (lambda b: b.makeFillet(1.5, 5.0, b.Edges))(Part.makeBox(60, 40, 30)),
    "box_internal_void": lambda: Part.makeBox(40, 40, 40).cut(Part.makeBox(20, 20, 20, V(10, 10, 10))),
    "tangent_box_cyl": lambda: Part.makeBox(40, 20, 20).fuse(
        Part.makeCylinder(10, 20, V(40, 10, 0), V(0, 0, 1))).removeSplitter(),
    "small_step": lambda: Part.makeBox(100, 100, 50).fuse(Part.makeBox(50, 100, 0.2, V(0, 0, 50))).removeSplitter(),
    "thin_rod": lambda: Part.makeBox(200, 3, 3),
    "thin_ring": lambda: Part.makeTorus(30, 2),
    "star_prism": star_prism,
    "sharp_wedge": sharp_wedge,
    "helix_spring": helix_spring,
}


def main():
    args = [a for a in sys.argv[1:] if not a.endswith(".py")]
    out = args[0] if args else os.environ.get("CADMEDIAL_PARTS_DIR", "robustness_parts")
    os.makedirs(out, exist_ok=True)
    for name, build in PARTS.items():
        try:
            shape = build()
            if shape.ShapeType != "Solid" and len(shape.Solids) == 1:
                shape = shape.Solids[0]
            shape.exportStep(os.path.join(out, name + ".step"))
            print(f"{name:22s} valid={shape.isValid()} volume={shape.Volume:.1f} faces={len(shape.Faces)}")
        except Exception as e:  # noqa: BLE001 - one part failing must not stop the others
            print(f"{name:22s} not built: {e}")


main()
