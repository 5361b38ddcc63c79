"""freecadcmd integration test of the Medial Axis addon (run by
run_freecad_test.sh with the addon installed into a temporary FreeCAD home).

Creates MedialAxis objects from models/flange.step and a parametric box,
changes the source and the parameters, exports, saves and reopens, and
checks the errors for bad input. Exits 1 on any failure (freecadcmd itself
exits 0 even when a script raises).
"""

import os
import sys
import traceback

failures = []


def check(condition, what):
    print(("ok    " if condition else "FAIL  ") + what, flush=True)
    if not condition:
        failures.append(what)
    return condition


def expect_error(function, exception_types, contains, what):
    try:
        function()
    except exception_types as e:
        message = str(e)
        return check(contains.lower() in message.lower(), f"{what}: {type(e).__name__}: {message}")
    except Exception as e:  # noqa: BLE001
        return check(False, f"{what}: unexpected {type(e).__name__}: {e}")
    return check(False, f"{what}: no error raised")


def healthy(obj):
    return not ({"Invalid", "Error", "Touched"} & set(obj.State))


def close(a, b, rel):
    return abs(a - b) <= rel * max(abs(a), abs(b))


def main():
    import threading

    import FreeCAD as App
    import numpy as np
    import Part

    import cadmedial
    from cadmedial import document

    source_dir = os.environ["CADMEDIAL_SOURCE_DIR"]
    tmp = os.environ["CADMEDIAL_TEST_TMP"]
    user_home = os.path.realpath(os.environ["FREECAD_USER_HOME"])
    flange_path = os.path.join(source_dir, "models", "flange.step")

    # --- installation -------------------------------------------------------------
    check(os.path.realpath(cadmedial.__file__).startswith(user_home),
          f"cadmedial comes from the installed addon ({cadmedial.__file__})")
    import freecad.medial_axis  # noqa: F401

    check(True, "freecad.medial_axis imports in freecadcmd")

    # --- objects from the flange --------------------------------------------------------
    doc = App.newDocument("MedialTest")
    flange_shape = Part.read(flange_path)
    flange = doc.addObject("Part::Feature", "Flange")
    flange.Shape = flange_shape
    doc.recompute()
    axes = cadmedial.add_to_document(doc, flange)
    check(len(axes) == 1, "one MedialAxis per solid of the flange")
    axis = axes[0]
    check(healthy(axis), f"MedialAxis is up to date ({axis.State})")
    check(axis.Samples > 1000 and axis.Polygons > 1000, f"flange: {axis.Samples} samples, {axis.Polygons} polygons")
    check(axis.Sheets >= 1 and axis.Beta0 == 1, f"flange: {axis.Sheets} sheets, beta0 {axis.Beta0}, beta1 {axis.Beta1}")
    check(axis.Mesh.CountFacets == document.get_result(axis).triangles()[0].shape[0],
          f"axis mesh has all {axis.Mesh.CountFacets} triangles (non-manifold junctions kept)")
    check(len(axis.Colors) == axis.Mesh.CountPoints, "one colour per mesh point (ColorBy Radius)")
    check(axis.SpacingUsed.Value > 0 and axis.Seconds > 0, f"spacing used {axis.SpacingUsed}, {axis.Seconds} s")
    check(os.path.isfile(axis.ResultData), "ResultData file exists")
    sheets = document.sheet_children(axis)
    check(len(sheets) == min(axis.Sheets, axis.MaxSheetObjects), f"{len(sheets)} sheet objects for {axis.Sheets} sheets")
    check(all(healthy(s) and s.Mesh.CountFacets > 0 for s in sheets), "every sheet object has a mesh and is up to date")
    check(sum(s.Polygons for s in sheets) == axis.Polygons, "the sheet objects hold every polygon once")
    check([s.SheetRank for s in sheets] == list(range(len(sheets))), "sheets ordered by rank")
    check(all(len(s.Colors) == s.Mesh.CountPoints for s in sheets), "sheets coloured per vertex")

    headless = cadmedial.compute(flange.Shape)[0]
    check(headless.polygon_count == axis.Polygons and headless.samples == axis.Samples,
          f"cadmedial.compute(shape) matches the object ({headless.polygon_count} polygons)")
    from_file = cadmedial.compute(flange_path)[0]
    check(close(from_file.polygon_count, axis.Polygons, 0.02), f"compute(path): {from_file.polygon_count} polygons")

    # --- source change recomputes -------------------------------------------------------------
    before_size = axis.Mesh.BoundBox.XLength
    before_spacing = axis.SpacingUsed.Value
    bigger = flange_shape.copy()
    bigger.scale(1.5)
    flange.Shape = bigger
    doc.recompute()
    check(healthy(axis), "recomputed after the source shape changed")
    check(close(axis.Mesh.BoundBox.XLength, 1.5 * before_size, 0.05),
          f"axis grew with the source ({before_size:.1f} -> {axis.Mesh.BoundBox.XLength:.1f})")
    check(close(axis.SpacingUsed.Value, 1.5 * before_spacing, 0.01), "automatic spacing follows the source")
    check(all(close(s.Mesh.BoundBox.DiagonalLength, s.Mesh.BoundBox.DiagonalLength, 0) for s in sheets)
          and sum(s.Polygons for s in document.sheet_children(axis)) == axis.Polygons,
          "sheet objects follow the recomputed axis")

    # --- parameter changes -----------------------------------------------------------------
    samples = axis.Samples
    axis.Spacing = 2.0 * axis.SpacingUsed.Value
    doc.recompute()
    check(healthy(axis) and axis.Samples < samples, f"larger Spacing: {samples} -> {axis.Samples} samples")
    axis.Theta = 10.0
    axis.Rho = 6.0
    doc.recompute()
    check(healthy(axis) and cadmedial.document.get_result(axis).theta == 10.0, "Theta / Rho recompute")
    samples = axis.Samples
    check(axis.GradedSpacing is True and axis.getDocumentationOfProperty("GradedSpacing")
          and axis.InputSignature.endswith("|graded"), "GradedSpacing: on by default for a new object, with a tooltip")
    axis.GradedSpacing = False
    doc.recompute()
    uniform_result = cadmedial.document.get_result(axis)
    check(healthy(axis) and uniform_result.summary["graded_spacing"] is False
          and not axis.InputSignature.endswith("|graded") and axis.Samples != samples,
          f"GradedSpacing off recomputes with one spacing per face: {samples} -> {axis.Samples} samples")
    axis.GradedSpacing = True
    doc.recompute()
    check(healthy(axis) and axis.Samples == samples and axis.InputSignature.endswith("|graded"),
          "GradedSpacing on again: the graded result")
    if axis.Sheets > 3:
        axis.MaxSheetObjects = 3
        doc.recompute()
        sheets = document.sheet_children(axis)
        check(len(sheets) == 3 and sheets[-1].OtherSheets and not sheets[0].OtherSheets,
              "MaxSheetObjects 3: two sheets and one 'other sheets' object")
        check(sum(s.Polygons for s in sheets) == axis.Polygons, "... still holding every polygon once")
    signature, seconds = axis.InputSignature, axis.Seconds
    axis.ColorBy = "Sheet"
    doc.recompute()
    sheets = document.sheet_children(axis)
    check(axis.InputSignature == signature and axis.Seconds == seconds, "ColorBy does not recompute the axis")
    check(len(axis.Colors) == axis.Mesh.CountFacets == document.get_result(axis).triangles()[0].shape[0],
          "ColorBy Sheet: one colour per facet, no facet lost")
    check(all(len(set(s.Colors)) == 1 for s in sheets), "ColorBy Sheet: every sheet object has one colour")

    # --- a parametric box ---------------------------------------------------------------
    box = doc.addObject("Part::Box", "Box")
    box.Length, box.Width, box.Height = 30.0, 20.0, 10.0
    doc.recompute()
    (box_axis,) = cadmedial.add_to_document(doc, box, spacing=1.0)
    length = box_axis.Mesh.BoundBox.XLength
    box.Length = 60.0
    doc.recompute()
    check(healthy(box_axis) and box_axis.Mesh.BoundBox.XLength > length + 20,
          f"box Length 30 -> 60: axis length {length:.1f} -> {box_axis.Mesh.BoundBox.XLength:.1f}")

    # --- a compound of two solids: one MedialAxis per solid ---------------------------
    pair = doc.addObject("Part::Feature", "TwoBlocks")
    pair.Shape = Part.makeCompound([Part.makeBox(20, 10, 5), Part.makeBox(8, 8, 8, App.Vector(40, 0, 0))])
    doc.recompute()
    pair_axes = cadmedial.add_to_document(doc, pair)
    check(len(pair_axes) == 2 and [a.SolidIndex for a in pair_axes] == [0, 1] and all(map(healthy, pair_axes)),
          "two solids -> two MedialAxis objects (SolidIndex 0, 1)")
    check(pair_axes[1].Mesh.BoundBox.XMin > 35 and pair_axes[0].Mesh.BoundBox.XMax < 25,
          "each MedialAxis lies in its own solid")

    # --- a torus: thousands of tiny sheets, capped sheet objects -------------------------
    torus = doc.addObject("Part::Feature", "Torus")
    torus.Shape = Part.read(os.path.join(source_dir, "models", "torus.step"))
    doc.recompute()
    (torus_axis,) = cadmedial.add_to_document(doc, torus, max_sheet_objects=8)
    torus_sheets = document.sheet_children(torus_axis)
    check(healthy(torus_axis) and len(torus_sheets) == min(8, torus_axis.Sheets),
          f"torus: {torus_axis.Sheets} sheets in {len(torus_sheets)} objects, beta1 {torus_axis.Beta1}")
    check(sum(s.Polygons for s in torus_sheets) == torus_axis.Polygons, "torus: every polygon in some sheet object")

    # --- Points and Mesh objects: MEDIAL on their points ----------------------------------
    import Mesh
    import MeshPart
    import Points

    torus_mesh = MeshPart.meshFromShape(Shape=torus.Shape, LinearDeflection=0.2, AngularDeflection=0.15)
    mesh_obj = doc.addObject("Mesh::Feature", "TorusMesh")
    mesh_obj.Mesh = torus_mesh
    doc.recompute()
    check(document.is_point_object(mesh_obj) and not document.is_point_object(torus_axis),
          "Mesh::Feature is a point source, a MedialAxis is not")
    (mesh_axis,) = cadmedial.add_to_document(doc, mesh_obj)
    mesh_result = document.get_result(mesh_axis)
    check(healthy(mesh_axis) and abs(mesh_axis.Theta.Value - 22.5) < 1e-9 and mesh_axis.Polygons > 100,
          f"torus mesh: {mesh_axis.Samples} points, {mesh_axis.Polygons} polygons, theta {mesh_axis.Theta.Value}")
    closed = torus_mesh.isSolid() and not torus_mesh.hasNonManifolds()
    check(mesh_result.summary["axis"] == ("inner" if closed else "whole"),
          f"mesh axis part {mesh_result.summary['axis']} (closed: {closed}): {mesh_result.summary['axis_note']}")
    if closed:
        check(mesh_axis.Beta0 == 1 and mesh_axis.Beta1 == 1, f"torus mesh inner axis: beta0/beta1 "
              f"{mesh_axis.Beta0}/{mesh_axis.Beta1} (the core circle)")
    x_max = mesh_axis.Mesh.BoundBox.XMax
    mesh_obj.Placement.Base = App.Vector(500, 0, 0)
    doc.recompute()
    check(healthy(mesh_axis) and close(mesh_axis.Mesh.BoundBox.XMax, x_max + 500, 1e-6),
          "moving the mesh object moves its axis (global coordinates, recomputed)")
    cloud = doc.addObject("Points::Feature", "TorusCloud")
    cloud.Points = Points.Points([App.Vector(*p) for p in torus_mesh.Topology[0]])
    doc.recompute()
    (cloud_axis,) = cadmedial.add_to_document(doc, cloud)
    check(healthy(cloud_axis) and document.get_result(cloud_axis).summary["axis"] == "whole"
          and cloud_axis.Polygons > mesh_axis.Polygons,
          f"point cloud: whole axis ({cloud_axis.Polygons} polygons, outer part included)")

    # --- export ---------------------------------------------------------------------------
    from cadmedial.export import read_ply

    result = document.get_result(axis)
    for ext in ("ply", "obj", "ma"):
        path = os.path.join(tmp, f"axis.{ext}")
        document.export(axis, path)
        check(os.path.getsize(path) > 1000, f"export .{ext} ({os.path.getsize(path)} bytes)")
    back = read_ply(os.path.join(tmp, "axis.ply"))
    check(all(np.array_equal(back[k], getattr(result, k)) for k in result.ARRAYS), "PLY reads back identical")
    with open(os.path.join(tmp, "axis.ma")) as f:
        nv, ne, nf = map(int, f.readline().split())
    check(nv == result.vertex_count and nf == result.triangles()[0].shape[0], f".ma header {nv} {ne} {nf}")
    first = document.sheet_children(axis)[0]
    document.export(first, os.path.join(tmp, "sheet.ply"))
    check(len(read_ply(os.path.join(tmp, "sheet.ply"))["sheet"]) == first.Polygons, "a sheet exports its polygons")

    # --- save and reopen -------------------------------------------------------------------
    stats = {n: getattr(axis, n) for n in ("Samples", "Vertices", "Polygons", "Sheets", "Beta0", "Beta1", "Seconds")}
    facets = axis.Mesh.CountFacets
    sheet_facets = [s.Mesh.CountFacets for s in document.sheet_children(axis)]
    path = os.path.join(tmp, "medial.FCStd")
    doc.saveAs(path)
    App.closeDocument(doc.Name)
    doc = App.openDocument(path)
    axis = next(o for o in doc.Objects if document.is_medial(o) and o.Source and o.Source.Name == "Flange")
    check(isinstance(axis.Proxy, document.MedialAxisFeature), "reopened: MedialAxis proxy restored")
    check({n: getattr(axis, n) for n in stats} == stats, "reopened: statistics intact")
    check(axis.Mesh.CountFacets == facets, "reopened: axis mesh intact")
    check([s.Mesh.CountFacets for s in document.sheet_children(axis)] == sheet_facets, "reopened: sheet meshes intact")
    check(all(isinstance(s.Proxy, document.MedialSheetFeature) for s in document.sheet_children(axis)),
          "reopened: sheet proxies restored")
    check(all(healthy(o) for o in doc.Objects), "reopened: nothing to recompute")
    reloaded = document.get_result(axis)
    check(reloaded is not None and reloaded.polygon_count == stats["Polygons"], "reopened: ResultData loads")
    check(axis.Source.Name == "Flange", "reopened: Source link intact")
    axis.Rho = 8.0
    doc.recompute()
    check(healthy(axis) and all(healthy(s) for s in document.sheet_children(axis)), "reopened: recompute works")

    # --- errors -----------------------------------------------------------------------------------
    face = doc.addObject("Part::Feature", "JustAFace")
    face.Shape = Part.makePlane(10, 10)
    empty = doc.addObject("Part::Feature", "Empty")
    group = doc.addObject("App::DocumentObjectGroup", "Group")
    shell = doc.addObject("Part::Feature", "OpenShell")
    shell.Shape = Part.makeShell(Part.makeBox(5, 5, 5).Faces[1:])
    doc.recompute()
    count = len(doc.Objects)
    expect_error(lambda: cadmedial.add_to_document(doc, face), ValueError, "holds no solid", "a face is not a solid")
    expect_error(lambda: cadmedial.add_to_document(doc, shell), ValueError, "holds no solid", "an open shell")
    expect_error(lambda: cadmedial.add_to_document(doc, empty), ValueError, "empty shape", "an empty shape")
    expect_error(lambda: cadmedial.add_to_document(doc, group), ValueError, "has no shape", "a group")
    expect_error(lambda: cadmedial.add_to_document(doc, "NoSuchThing"), ValueError, "no object named", "unknown name")
    check(len(doc.Objects) == count, "failed calls create no objects")

    # A shape without a solid whose faces close up (a closed shell; loose
    # faces, as an IGES file of trimmed surfaces imports) is sewn into its
    # solid, exactly the box's: volume and the MedialAxis made from it.
    cube = Part.makeBox(8, 6, 4)
    closed_shell = doc.addObject("Part::Feature", "ClosedShell")
    closed_shell.Shape = Part.makeShell(cube.Faces)
    loose = doc.addObject("Part::Feature", "LooseFaces")
    loose.Shape = Part.makeCompound([f.copy() for f in cube.Faces])
    doc.recompute()
    for obj in (closed_shell, loose):
        check(not obj.Shape.Solids, f"{obj.Name}: the fixture holds no solid")
        solids = document.source_solids(obj)
        check(len(solids) == 1 and abs(solids[0].Volume - 192.0) < 1e-9, f"{obj.Name}: sewn into the 8x6x4 box")
        (sewn_axis,) = cadmedial.add_to_document(doc, obj)
        check(healthy(sewn_axis) and sewn_axis.Polygons > 0, f"{obj.Name}: MedialAxis from the sewn solid")
        sewing = [w for w in sewn_axis.Warnings if "sewn" in w]
        check(len(sewing) == 1 and "1 solid" in sewing[0], f"{obj.Name}: the sewing is in Warnings: {sewing}")
    # The same shape is sewn once: the commands, the task panel and every
    # recompute ask for a source's solids again.
    sewing_calls = []
    native_sew = cadmedial.api.solids_brep
    cadmedial.api.solids_brep = lambda shape: sewing_calls.append(1) or native_sew(shape)
    try:
        sewn_axis.Spacing = sewn_axis.SpacingUsed * 1.5
        doc.recompute()
        document.source_solids(loose)
        import MeshPart  # as the 3D view does: meshing flags the shape, which stays the same shape

        MeshPart.meshFromShape(Shape=loose.Shape, LinearDeflection=0.1)
        document.source_solids(loose)
        check(healthy(sewn_axis) and not sewing_calls, f"recomputed without sewing again ({len(sewing_calls)} calls)")
        for _ in range(2):
            expect_error(lambda: document.source_solids(shell), ValueError, "left open", "an open shell, asked again")
        check(len(sewing_calls) == 0, f"an open shell's failed sewing is remembered too ({len(sewing_calls)} calls)")
        loose.Shape = Part.makeCompound([f.copy() for f in Part.makeBox(8, 6, 5).Faces])
        doc.recompute()
        check(healthy(sewn_axis) and len(sewing_calls) == 1, f"a changed shape is sewn anew ({len(sewing_calls)})")
    finally:
        cadmedial.api.solids_brep = native_sew
    expect_error(lambda: cadmedial.compute(face.Shape), cadmedial.InputError, "no closed solid", "compute(face)")
    expect_error(lambda: cadmedial.compute("/no/such/file.step"), cadmedial.InputError, "no such file", "missing file")
    expect_error(lambda: cadmedial.compute(os.path.join(source_dir, "README.md")), ValueError, "unknown extension",
                 "not a CAD file")
    expect_error(lambda: cadmedial.compute("CASCADE Topology V1, (c) Matra-Datavision\nrubbish\n"),
                 cadmedial.InputError, "BREP", "corrupt BREP text")
    try:
        cadmedial.compute("/no/such/file.step")
    except cadmedial.InputError as e:
        check(e.exit_code == 3, "InputError carries the CLI exit code (3)")
    expect_error(lambda: cadmedial.compute(flange_path, spacing=-1), ValueError, "spacing", "negative spacing")
    expect_error(lambda: cadmedial.compute(flange_path, rho=0), ValueError, "rho", "rho 0")
    expect_error(lambda: cadmedial.compute(np.zeros((10, 3)) + np.arange(10)[:, None], pair_mesh=True), ValueError,
                 "B-rep solid", "pair_mesh=True on points")
    expect_error(lambda: cadmedial.compute(42), TypeError, "cannot use", "a number as source")
    stop = threading.Event()
    stop.set()
    expect_error(lambda: cadmedial.compute(flange_path, cancel=stop), cadmedial.Cancelled, "cancel", "cancel token")
    stages = []
    box = doc.getObject("Box")
    box_axis = next(o for o in doc.Objects if document.is_medial(o) and o.Source == box)
    cadmedial.compute(box.Shape, progress=lambda stage, i, n: stages.append(stage))
    check(stages == ["read", "sample", "medial", "done"], f"progress stages {stages}")

    # A MedialAxis whose source stops being a solid: an error state, no crash; and back.
    App.Console.PrintMessage("(an error about 'JustAFace' follows on purpose)\n")
    box_axis.Source = face
    doc.recompute()
    check("Invalid" in box_axis.State or "Error" in box_axis.State, f"non-solid source -> error state {box_axis.State}")
    box_axis.Source = box
    doc.recompute()
    check(healthy(box_axis), "source restored -> valid again")

    document.remove(box_axis)
    check(not any(document.is_sheet(o) and o.MedialAxis is None for o in doc.Objects), "remove() takes the sheets along")
    App.closeDocument(doc.Name)


try:
    main()
except Exception:  # noqa: BLE001
    traceback.print_exc()
    failures.append("exception")
print(f"{len(failures)} failure(s)" + (": " + "; ".join(failures) if failures else ""), flush=True)
sys.exit(1 if failures else 0)
