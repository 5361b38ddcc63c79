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
The second sweep (2026-12-04, chamfer_block and after): 16 of 17 evaluated
parts PASS; steinmetz fails edges (88 %: shallow convex edges, where its
edges turn tangent); hole_grid's eval did not finish in 15 min, and PASSes
in 83 s since the point-in-face test asks one hole (2026-12-05;
ARCHITECTURE.md, Known gaps). perforated_tube (2026-12-05): PASS.
The third sweep (2026-12-06, needle and after): needle, pin_boss and
tiny_void PASS at the --spacing their warning names; pinhole stays
FAIL:topology there; boss and thread PASS; blend_box_hole fails two
contacts (80 %), knurl edges (87 %); foil is warned of (wall 0.1).
Since eval measures convex creases turning by less than 2θ apart
(2026-12-06), steinmetz, loft_circle_square and box_fillet_variable reach
100 % edges (box_fillet_variable still fails topology, 2,0).
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


# The second sweep (2026-12-04): scale, position, orientation, compounds,
# B-spline and revolved faces, many holes.
def micro_part():
    """60 x 40 x 20 micrometres with a hole."""
    return Part.makeBox(0.06, 0.04, 0.02).cut(Part.makeCylinder(0.008, 0.04, V(0.03, 0.02, -0.01)))


def far_part():
    """5 m long, 200 m from the origin, with a hole."""
    box = Part.makeBox(5000, 3000, 800, V(1e5, -2e5, 5e4))
    return box.cut(Part.makeCylinder(600, 2000, V(1e5 + 2500, -2e5 + 1500, 5e4 - 500)))


def ellipsoid():
    """A sphere stretched to semi-axes 30, 15, 10: one B-spline face."""
    m = FreeCAD.Matrix()
    m.scale(3, 1.5, 1)
    return Part.makeSphere(10).transformGeometry(m)


def vase():
    """A revolved B-spline profile."""
    bs = Part.BSplineCurve()
    bs.interpolate([V(10, 0, 0), V(18, 0, 15), V(8, 0, 35), V(12, 0, 50)])
    profile = Part.Wire([Part.LineSegment(V(0, 0, 0), V(10, 0, 0)).toShape(), bs.toShape(),
                         Part.LineSegment(V(12, 0, 50), V(0, 0, 50)).toShape(),
                         Part.LineSegment(V(0, 0, 50), V(0, 0, 0)).toShape()])
    return Part.Face(profile).revolve(V(0, 0, 0), V(0, 0, 1), 360)


def pyramid():
    """Four triangles meeting at an apex: a corner of four convex edges."""
    base = [V(0, 0, 0), V(0, 40, 0), V(40, 40, 0), V(40, 0, 0)]
    apex = V(20, 20, 30)
    faces = [Part.Face(Part.makePolygon(base + [base[0]]))]
    for i in range(4):
        a, b = base[(i + 1) % 4], base[i]
        faces.append(Part.Face(Part.makePolygon([a, b, apex, a])))
    return Part.makeSolid(Part.makeShell(faces))


def slot_block():
    slot = Part.makeBox(40, 10, 30, V(20, 15, -5)).fuse(Part.makeCylinder(5, 30, V(20, 20, -5)))
    slot = slot.fuse(Part.makeCylinder(5, 30, V(60, 20, -5)))
    return Part.makeBox(80, 40, 20).cut(slot).removeSplitter()


def countersunk():
    plate = Part.makeBox(60, 60, 10).cut(Part.makeCylinder(4, 20, V(30, 30, -5)))
    return plate.cut(Part.makeCone(4, 10, 6, V(30, 30, 4))).removeSplitter()


def steinmetz():
    """Common of three cylinders r 10: curved convex edges only."""
    r, length = 10, 40
    a = Part.makeCylinder(r, length, V(-length / 2, 0, 0), V(1, 0, 0))
    b = Part.makeCylinder(r, length, V(0, -length / 2, 0), V(0, 1, 0))
    c = Part.makeCylinder(r, length, V(0, 0, -length / 2), V(0, 0, 1))
    return a.common(b).common(c)


def fillet_pocket():
    block = Part.makeBox(60, 60, 30).cut(Part.makeBox(30, 30, 20, V(15, 15, 15)))
    floor = [e for e in block.Edges if abs(e.BoundBox.ZMin - 15) < 1e-6 and abs(e.BoundBox.ZMax - 15) < 1e-6]
    return block.makeFillet(4.0, floor)


def hole_grid():
    """100 holes r 1.5 in a 100 x 100 x 5 plate."""
    holes = [Part.makeCylinder(1.5, 10, V(10 + 9 * i, 10 + 9 * j, -2)) for i in range(10) for j in range(10)]
    return Part.makeBox(100, 100, 5).cut(Part.makeCompound(holes))


def cross_drilled():
    c = Part.makeCylinder(15, 60).cut(Part.makeCylinder(5, 80, V(0, 0, -10)))
    return c.cut(Part.makeCylinder(3, 40, V(-20, 0, 30), V(1, 0, 0)))


def perforated_tube():
    """A tube (R 20, wall 4) with 48 radial holes r 2: faces periodic in u with many holes."""
    tube = Part.makeCylinder(20, 80).cut(Part.makeCylinder(16, 90, V(0, 0, -5)))
    holes = []
    for k in range(8):
        for j in range(6):
            a = 2 * math.pi * (k + 0.5 * (j % 2)) / 8
            holes.append(Part.makeCylinder(2, 30, V(0, 0, 12 + 11 * j), V(math.cos(a), math.sin(a), 0)))
    return tube.cut(Part.makeCompound(holes))


def knurl():
    """A 20 x 20 x 3 plate under 10 x 10 pyramids 2 mm wide, 0.8 mm high:
    saddle vertices where four convex ridges meet four concave valleys."""
    base, top = V(0, 0, 3), V(0.99, 0.99, 3.8)
    square = lambda o, w: Part.makePolygon([o, o + V(w, 0, 0), o + V(w, w, 0), o + V(0, w, 0), o])
    pyramid_ = Part.makeLoft([square(base, 2), square(top, 0.02)], True, True)
    part = Part.makeBox(20, 20, 3)
    for i in range(10):
        for j in range(10):
            p = pyramid_.copy()
            p.translate(V(2 * i, 2 * j, 0))
            part = part.fuse(p)
    return part.removeSplitter()


def thread():
    """A coarse triangular thread swept along a helix, fused to its core."""
    pitch, height, r = 1.5, 7.5, 4.2
    profile = Part.makePolygon([V(r, 0, -0.6), V(r + 0.8, 0, 0), V(r, 0, 0.6), V(r, 0, -0.6)])
    sweep = Part.Wire(Part.makeHelix(pitch, height, r)).makePipeShell([profile], True, True)
    return Part.makeCylinder(r + 0.05, height + 1.2, V(0, 0, -0.6)).fuse(sweep).removeSplitter()


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
    "chamfer_block": lambda: (lambda b: b.makeChamfer(4.0, b.Edges))(Part.makeBox(60, 40, 30)),
    "micro_part": micro_part,
    "far_part": far_part,
    "ellipsoid": ellipsoid,
    "two_boxes": lambda: Part.makeCompound([Part.makeBox(20, 20, 20), Part.makeBox(10, 30, 5, V(40, 0, 0))]),
    "touching_boxes": lambda: Part.makeCompound([Part.makeBox(20, 20, 20), Part.makeBox(20, 20, 20, V(20, 0, 0))]),
    "vase": vase,
    "pyramid": pyramid,
    "slot_block": slot_block,
    "hemisphere": lambda: Part.makeSphere(20).common(Part.makeBox(50, 50, 25, V(-25, -25, 0))),
    "countersunk": countersunk,
    "mirrored_l": lambda: Part.makeBox(50, 10, 30).fuse(Part.makeBox(10, 40, 30)).removeSplitter().mirror(
        V(0, 0, 0), V(1, 0, 0)),
    "steinmetz": steinmetz,
    "fillet_pocket": fillet_pocket,
    "hole_grid": hole_grid,
    "cross_drilled": cross_drilled,
    "reversed_box": lambda: Part.makeBox(30, 20, 10).reversed(),
    "perforated_tube": perforated_tube,
    # 2026-12-06: features below the finest spacing (h/16; the needle and the
    # pin crashed the face triangulation before), and convex edges ending
    # among concave ones.
    "needle": lambda: Part.makeCylinder(0.05, 200),
    "pin_boss": lambda: Part.makeBox(200, 200, 10).fuse(Part.makeCylinder(0.05, 1, V(100, 100, 10))),
    "pinhole": lambda: Part.makeBox(20, 20, 10).cut(Part.makeCylinder(0.05, 10, V(10, 10, 0))),
    "tiny_void": lambda: Part.makeBox(100, 100, 100).cut(Part.makeSphere(0.05, V(50, 50, 50))),
    "foil": lambda: Part.makeBox(100, 100, 0.1),
    "boss": lambda: Part.makeBox(40, 40, 5).fuse(Part.makeBox(10, 10, 10, V(15, 15, 5))).removeSplitter(),
    "blend_box_hole": lambda: (lambda b: b.makeFillet(3, b.Edges))(Part.makeBox(30, 20, 10)).cut(
        Part.makeCylinder(3, 10, V(15, 10, 0))),
    "knurl": knurl,
    "thread": thread,
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
