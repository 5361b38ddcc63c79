"""freecadcmd test of the PairMesh (Fem::FemMeshObjectPython) and
PairMeshIsoSurface objects (run by run_freecad_test.sh with the addon
installed into a temporary FreeCAD home).

Reference facts come from FreeCAD itself, not from cadmedial: the source is
a parametric Part::Box, its exact volume is Part's shape.Volume. Exits 1 on
any failure (freecadcmd exits 0 even when a script raises)."""

import os
import sys
import time
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
        return check(contains.lower() in str(e).lower(), f"{what}: {type(e).__name__}: {e}")
    except Exception as e:  # noqa: BLE001
        return check(False, f"{what}: unexpected {type(e).__name__}: {e}")
    return check(False, f"{what}: no error raised")


def healthy(obj):
    return not ({"Invalid", "Error", "Touched"} & set(obj.State))


def group_sizes(fem):
    return {fem.getGroupName(g): len(fem.getGroupElements(g)) for g in fem.Groups}


def main():
    import FreeCAD as App
    import numpy as np
    import Part
    import Points

    import cadmedial
    from cadmedial import pair_document

    tmp = os.environ["CADMEDIAL_TEST_TMP"]
    doc = App.newDocument("PairMeshTest")
    box = doc.addObject("Part::Box", "Box")
    box.Length, box.Width, box.Height = 40, 30, 20
    doc.recompute()

    start = time.perf_counter()
    (pm,) = pair_document.add_pair_mesh(doc, box)
    seconds = time.perf_counter() - start
    check(healthy(pm) and pm.TypeId == "Fem::FemMeshObjectPython", f"PairMesh object created in {seconds:.2f} s")
    fem = pm.FemMesh
    print(f"      {pm.Tetrahedra} tetrahedra ({pm.FaceVertex} FV, {pm.EdgeEdge} EE, {pm.VertexFace} VF), "
          f"{pm.Nodes} nodes, inverted {pm.Inverted}, volume error {pm.VolumeError:.3g} %, {pm.Seconds} s")
    result = pair_document.get_pair_mesh(pm)
    attempts = result.report.get("attempts")
    check(attempts is not None and len(attempts) == 1 and attempts[0]["kept"] and attempts[0]["valid"],
          f"valid at the spacing asked, sampled once: {attempts}")
    check(not any("sampled again" in line for line in pair_document.validity_lines(result)),
          "no 'sampled again' line in the report")
    # A pair-mesh that was sampled again (cli/solid_run.hpp) says so in the Report view, in the
    # words `cadmedial run` prints (one formatter, cli/solid_run.cpp resamplingLine).
    import copy
    resampled = copy.copy(result)
    resampled.report = dict(result.report, attempts=[
        {"spacing": 8.93, "spacing_factor": 1.0, "every_spacing": False, "inverted": 1, "valid": False,
         "kept": False},
        {"spacing": 8.6621, "spacing_factor": 0.97, "every_spacing": False, "inverted": 1, "valid": False,
         "kept": False},
        {"spacing": 8.3942, "spacing_factor": 0.94, "every_spacing": True, "inverted": 0, "valid": True,
         "kept": True}])
    last = pair_document.validity_lines(resampled)[-1]
    check(last == "not valid at spacing 8.93 (1 inverted), sampled again at 8.662 (1 inverted), 8.394 with every "
                  "spacing x 0.94 (valid); kept 8.394 with every spacing x 0.94", f"report line: {last!r}")
    # The same samples as the attempt before (curvature sets every spacing): not run again.
    resampled.report = dict(result.report, attempts=[
        {"spacing": 2.265, "spacing_factor": 1.0, "inverted": 1, "valid": False, "kept": True},
        {"spacing": 2.197, "spacing_factor": 0.97, "same_samples": True, "valid": False, "kept": False}])
    last = pair_document.validity_lines(resampled)[-1]
    check(last == "not valid at spacing 2.265 (1 inverted), sampled again at 2.197 (the same samples, not run "
                  "again); kept 2.265", f"report line with the same samples: {last!r}")
    # Not valid with 0 inverted (an open edge, say), and a sampling again that failed.
    resampled.report = dict(result.report, attempts=[
        {"spacing": 8.93, "inverted": 0, "valid": False, "kept": True},
        {"spacing": 8.6621, "error": "std::bad_alloc", "valid": False, "kept": False}])
    last = pair_document.validity_lines(resampled)[-1]
    check(last == "not valid at spacing 8.93 (not valid), sampled again at 8.662 (failed: std::bad_alloc); "
                  "kept 8.93", f"report line with a failed attempt: {last!r}")
    check(fem.VolumeCount == pm.Tetrahedra == result.tet_count and fem.TetraCount == pm.Tetrahedra,
          f"FemMesh holds {fem.VolumeCount} volumes = {pm.Tetrahedra} tetrahedra")
    check(fem.NodeCount == pm.Nodes == result.node_count, f"FemMesh holds {fem.NodeCount} nodes")
    check(pm.FaceVertex + pm.EdgeEdge + pm.VertexFace == pm.Tetrahedra and min(pm.FaceVertex, pm.EdgeEdge,
                                                                               pm.VertexFace) > 0,
          "counts per type add up")
    check(group_sizes(fem) == {"FaceVertex": pm.FaceVertex, "EdgeEdge": pm.EdgeEdge, "VertexFace": pm.VertexFace},
          f"one FEM volume group per type: {group_sizes(fem)}")
    exact = box.Shape.Volume
    check(abs(pm.ExactVolume - exact) <= 1e-9 * exact, f"ExactVolume {pm.ExactVolume} = Part volume {exact}")
    check(pm.Inverted == 0 and pm.Valid, f"no inverted element, valid (inverted before repair "
                                         f"{pm.InvertedBeforeRepair})")
    check(abs(pm.EnclosedVolume - exact) <= 0.01 * exact, f"enclosed {pm.EnclosedVolume:.6f} within 1 % of {exact}")
    # The FEM mesh itself (its nodes and element connectivity) fills the box:
    # signed volumes from FemMesh data add up to Part's volume, none negative.
    coords = {i: (v.x, v.y, v.z) for i, v in fem.Nodes.items()}
    quads = np.array([[coords[n] for n in fem.getElementNodes(e)] for e in fem.Volumes])
    signed = np.einsum("ij,ij->i", quads[:, 1] - quads[:, 0],
                       np.cross(quads[:, 2] - quads[:, 0], quads[:, 3] - quads[:, 0])) / 6.0
    check(abs(signed.sum() - exact) <= 0.01 * exact and signed.min() > -1e-9,
          f"FemMesh elements: volume {signed.sum():.6f}, min element volume {signed.min():.3g}")
    # A FEM node at the same place as the array node (ids = index + 1).
    k = result.node_count // 2
    node = fem.Nodes[k + 1]
    check(np.allclose([node.x, node.y, node.z], result.nodes[k]), "node ids are array index + 1")

    # --- element filter: only the FemMesh changes ------------------------------------
    pm.Elements = "EdgeEdge"
    check(pm.FemMesh.VolumeCount == pm.EdgeEdge and list(group_sizes(pm.FemMesh)) == ["EdgeEdge"],
          f"Elements = EdgeEdge: {pm.FemMesh.VolumeCount} volumes")
    pm.Elements = "All"
    check(pm.FemMesh.VolumeCount == pm.Tetrahedra, "Elements = All again")

    # --- iso-surfaces -------------------------------------------------------------------
    iso = pair_document.add_iso_surface(doc, pm, 1.0)
    check(healthy(iso) and iso.Mesh.CountFacets == pm.BoundaryTriangles,
          f"iso T=1: {iso.Mesh.CountFacets} facets = {pm.BoundaryTriangles} boundary triangles")
    check(abs(iso.Mesh.Volume - exact) <= 0.01 * exact, f"iso T=1 mesh volume {iso.Mesh.Volume:.3f}")
    iso.T = 0.5
    doc.recompute()
    check(healthy(iso) and 0 < iso.Mesh.Volume < 0.99 * exact and iso.Mesh.isSolid(),
          f"iso T=0.5: {iso.Mesh.CountFacets} facets, closed, volume {iso.Mesh.Volume:.1f}")
    expect_error(lambda: pair_document.add_iso_surface(doc, pm, 2.0), ValueError, "[0, 1]", "iso t=2")

    # --- parametric: source and spacing changes recompute -----------------------------
    old_tets = pm.Tetrahedra
    box.Length = 50
    doc.recompute()
    check(healthy(pm) and healthy(iso), "after a source change: objects recomputed")
    check(abs(pm.ExactVolume - box.Shape.Volume) <= 1e-9 * box.Shape.Volume and abs(pm.ExactVolume - 30000) < 1e-6,
          f"ExactVolume follows the source ({pm.ExactVolume})")
    check(abs(pm.EnclosedVolume - 30000) <= 300 and pm.FemMesh.VolumeCount == pm.Tetrahedra != old_tets,
          f"new mesh: {pm.Tetrahedra} tetrahedra, enclosed {pm.EnclosedVolume:.3f}")
    check(40 < iso.Mesh.BoundBox.XMax < 50, f"iso-surface follows the pair-mesh (x max {iso.Mesh.BoundBox.XMax:.2f})")
    before = pm.Tetrahedra
    pm.Spacing = 1.2  # finer than the automatic diagonal / 40 = 1.54
    doc.recompute()
    check(healthy(pm) and pm.Tetrahedra > before and abs(pm.SpacingUsed.Value - 1.2) < 1e-9,
          f"Spacing 1.2: {pm.Tetrahedra} tetrahedra (was {before}), inverted {pm.Inverted}")
    # An unchanged recompute reuses the stored result.
    pm.touch()
    start = time.perf_counter()
    doc.recompute()
    elapsed = time.perf_counter() - start
    # Computing costs pm.Seconds and rebuilding the FemMesh about 1 s here; reuse costs neither.
    check(elapsed < 0.6 and healthy(pm),
          f"unchanged recompute reuses the result ({elapsed:.2f} s; computing took {pm.Seconds:.2f} s)")

    # --- export ----------------------------------------------------------------------------
    vtu = pair_document.export_pair_mesh(pm, os.path.join(tmp, "pm.vtu"))
    node, ele = pair_document.export_pair_mesh(pm, os.path.join(tmp, "pm.node"))
    with open(ele) as f:
        header = [line for line in f if not line.startswith("#")][0].split()
    check(os.path.getsize(vtu) > 0 and int(header[0]) == pm.Tetrahedra, f"exported {vtu}, {ele}")

    # --- from a medial axis: its source and parameters ---------------------------------------
    doc2 = App.newDocument("FromAxis")
    block = doc2.addObject("Part::Box", "Block")
    block.Length, block.Width, block.Height = 20, 10, 6
    doc2.recompute()
    (axis,) = cadmedial.add_to_document(doc2, block, spacing=1.5)
    (pm2,) = cadmedial.add_pair_mesh(doc2, axis)  # the package-level helper
    check(pm2.Source == block and pm2.Spacing.Value == 1.5 and healthy(pm2) and pm2.Inverted == 0,
          f"pair-mesh of a medial axis' solid: spacing {pm2.Spacing.Value}, {pm2.Tetrahedra} tetrahedra")
    check(abs(pm2.EnclosedVolume - 1200) <= 12, f"block: enclosed {pm2.EnclosedVolume:.3f} vs 1200")

    # --- bad sources --------------------------------------------------------------------------
    face = doc.addObject("Part::Feature", "Face")
    face.Shape = Part.makePlane(10, 10)
    cloud = doc.addObject("Points::Feature", "Cloud")
    cloud.Points = Points.Points([App.Vector(*p) for p in np.random.default_rng(2).random((40, 3)).tolist()])
    doc.recompute()
    expect_error(lambda: pair_document.add_pair_mesh(doc, face), ValueError, "no solid", "a face")
    expect_error(lambda: pair_document.add_pair_mesh(doc, cloud), ValueError, "B-rep", "a point cloud")
    expect_error(lambda: pair_document.add_pair_mesh(doc, pm), ValueError, "pair-mesh result", "a pair-mesh")
    doc.removeObject(face.Name)
    doc.removeObject(cloud.Name)

    # --- save / reopen ---------------------------------------------------------------------------
    path = os.path.join(tmp, "pair_mesh.FCStd")
    tets, volumes = pm.Tetrahedra, pm.FemMesh.VolumeCount
    doc.saveAs(path)
    App.closeDocument(doc.Name)
    from cadmedial import document

    document._results.clear()  # the in-memory cache: force the arrays to come from the file
    doc = App.openDocument(path)
    pm = next(o for o in doc.Objects if pair_document.is_pair_mesh(o))
    iso = next(o for o in doc.Objects if pair_document.is_iso_surface(o))
    check(pm.Tetrahedra == tets and pm.FemMesh.VolumeCount == volumes and len(pm.FemMesh.Groups) == 3,
          f"reopened: {pm.FemMesh.VolumeCount} volumes, {len(pm.FemMesh.Groups)} groups")
    loaded = pair_document.get_pair_mesh(pm)
    check(loaded is not None and loaded.tet_count == tets, "reopened: arrays from ResultData")
    iso.T = 0.25
    doc.recompute()
    check(healthy(iso) and iso.Triangles > 0 and healthy(pm), "reopened: iso-surface recomputes from the stored arrays")

    build_pair_mesh(tmp)


def build_pair_mesh(tmp):
    """MedialAxis.BuildPairMesh: a PairMesh child that follows the axis.
    Reference: models/box.step is a 40 x 30 x 20 box (volume 24000); checked
    against Part's own volume and bounding box, not against cadmedial."""
    import FreeCAD as App
    import Part

    import cadmedial
    from cadmedial import document, pair_document

    print("--- MedialAxis.BuildPairMesh", flush=True)
    source_dir = os.environ["CADMEDIAL_SOURCE_DIR"]
    doc = App.newDocument("BuildPairMesh")
    doc.UndoMode = 1
    box = doc.addObject("Part::Feature", "BoxStep")
    box.Shape = Part.read(os.path.join(source_dir, "models", "box.step"))
    doc.recompute()
    bb = box.Shape.BoundBox
    exact = 24000.0
    check(abs(bb.XLength * bb.YLength * bb.ZLength - exact) < 1e-6 and abs(box.Shape.Volume - exact) < 1e-6,
          f"box.step: {bb.XLength:g} x {bb.YLength:g} x {bb.ZLength:g}, Part volume {box.Shape.Volume:.6f}")
    (axis,) = cadmedial.add_to_document(doc, box, check_inside=False)
    check("BuildPairMesh" in axis.PropertiesList and axis.BuildPairMesh is False
          and axis.getGroupOfProperty("BuildPairMesh") == axis.getGroupOfProperty("Spacing")
          and axis.getDocumentationOfProperty("BuildPairMesh"),
          "MedialAxis has BuildPairMesh (default False, group of Spacing, tooltip)")
    check(not pair_document.pair_mesh_children(axis) and not any(pair_document.is_pair_mesh(o) for o in doc.Objects),
          "no pair-mesh before BuildPairMesh")

    # --- True: the child is created at once (outside the recompute), computed by the next one
    doc.openTransaction("Build pair-mesh")
    axis.BuildPairMesh = True
    doc.commitTransaction()
    kids = pair_document.pair_mesh_children(axis)
    check(len(kids) == 1 and kids[0].MedialAxis == axis and kids[0].Source == box,
          f"BuildPairMesh = True: one PairMesh child linked to the axis ({[k.Label for k in kids]})")
    doc.recompute()
    pm = kids[0]
    check(healthy(pm) and healthy(axis), "recompute computes the child")
    print(f"      {pm.Tetrahedra} tetrahedra, inverted {pm.Inverted}, enclosed {pm.EnclosedVolume:.6f}, "
          f"spacing used {pm.SpacingUsed.Value:.4g} (axis {axis.SpacingUsed.Value:.4g})", flush=True)
    check(abs(pm.EnclosedVolume - exact) <= 0.01 * exact and abs(pm.ExactVolume - exact) < 1e-6,
          f"child: enclosed volume {pm.EnclosedVolume:.6f} within 1 % of {exact:g}")
    check(pm.Inverted == 0 and pm.Valid and pm.FemMesh.VolumeCount == pm.Tetrahedra > 0,
          f"child: 0 inverted, valid, FemMesh with {pm.FemMesh.VolumeCount} volumes")
    check(abs(pm.SpacingUsed.Value - axis.SpacingUsed.Value) < 1e-9, "child uses the axis' spacing")
    check(pm.GradedSpacing and pm.InputSignature.endswith("|graded"), "child graded like its axis (the default)")
    axis.GradedSpacing = False
    doc.recompute()
    check(not pm.GradedSpacing and not pm.InputSignature.endswith("|graded") and healthy(pm) and pm.Valid,
          "child follows the axis' GradedSpacing (recomputed uniform, valid)")
    check(pm.getEditorMode("GradedSpacing") == ["ReadOnly"], "child: GradedSpacing read-only")
    axis.GradedSpacing = True
    doc.recompute()
    check(pm.GradedSpacing and healthy(pm), "... and back")
    check(pm.getEditorMode("Spacing") == ["ReadOnly"] and pm.getEditorMode("Source") == ["ReadOnly"],
          "child: followed parameters read-only")
    vp = document.ViewProviderMedialAxis.__new__(document.ViewProviderMedialAxis)
    vp.Object = axis
    claimed = vp.claimChildren()
    check(pm in claimed and all(document.is_sheet(o) or o == pm for o in claimed) and len(claimed) > 1,
          f"the axis' view provider claims the child and its sheets ({len(claimed)} children)")
    axis.BuildPairMesh = True  # again: still one child
    check(pair_document.pair_mesh_children(axis) == [pm], "BuildPairMesh = True twice: still one child")

    # --- undo / redo of the property change take the child with them
    doc.undo()
    check(not axis.BuildPairMesh and not any(pair_document.is_pair_mesh(o) for o in doc.Objects),
          "undo: BuildPairMesh False and the child gone")
    doc.redo()
    kids = pair_document.pair_mesh_children(axis)
    check(axis.BuildPairMesh and len(kids) == 1, "redo: child back")
    pm = kids[0]
    doc.recompute()
    check(healthy(pm) and pm.Inverted == 0 and abs(pm.EnclosedVolume - exact) <= 0.01 * exact,
          "redo: child recomputes")

    # --- the axis' Spacing drives the child
    before = pm.Tetrahedra
    axis.Spacing = 2.0  # coarser than the automatic diagonal / 40 = 1.35
    doc.recompute()
    check(healthy(pm) and healthy(axis) and pm.Spacing.Value == 2.0 and abs(pm.SpacingUsed.Value - 2.0) < 1e-9,
          f"axis Spacing 2: child follows (Spacing {pm.Spacing.Value}, used {pm.SpacingUsed.Value})")
    check(pm.Tetrahedra < before and pm.FemMesh.VolumeCount == pm.Tetrahedra,
          f"child recomputed: {pm.Tetrahedra} tetrahedra (was {before})")
    check(pm.Inverted == 0 and abs(pm.EnclosedVolume - exact) <= 0.01 * exact,
          f"child at spacing 2: 0 inverted ({pm.Inverted}), enclosed {pm.EnclosedVolume:.6f}")

    # --- save and reopen: link kept, arrays from the file
    path = os.path.join(tmp, "build_pair_mesh.FCStd")
    tets = pm.Tetrahedra
    doc.saveAs(path)
    App.closeDocument(doc.Name)
    document._results.clear()
    doc = App.openDocument(path)
    axis = next(o for o in doc.Objects if document.is_medial(o))
    box = doc.getObject("BoxStep")
    kids = pair_document.pair_mesh_children(axis)
    check(axis.BuildPairMesh and len(kids) == 1 and kids[0].MedialAxis == axis,
          "reopened: BuildPairMesh True, child linked to the axis")
    pm = kids[0]
    loaded = pair_document.get_pair_mesh(pm)
    check(healthy(pm) and pm.Tetrahedra == tets and pm.FemMesh.VolumeCount == tets and loaded is not None
          and loaded.tet_count == tets and pm.Inverted == 0,
          f"reopened: child valid, {pm.FemMesh.VolumeCount} volumes, arrays from ResultData")
    # The source drives it after reopening (through the axis and its own Source link).
    box.Shape = Part.makeBox(50, 30, 20)
    doc.recompute()
    check(healthy(pm) and abs(pm.ExactVolume - 30000) < 1e-6 and abs(pm.EnclosedVolume - 30000) <= 300
          and pm.Inverted == 0,
          f"reopened, source 50 x 30 x 20: child enclosed {pm.EnclosedVolume:.6f}, exact {pm.ExactVolume:.6f}")
    axis.Spacing = 2.5
    doc.recompute()
    check(healthy(pm) and abs(pm.SpacingUsed.Value - 2.5) < 1e-9, "reopened: axis Spacing still drives the child")
    # Another source object on the axis: the child's Source link follows (set in its execute).
    other = doc.addObject("Part::Box", "Other")
    other.Length, other.Width, other.Height = 20, 10, 6
    axis.Source = other
    doc.recompute()
    check(healthy(pm) and healthy(axis) and pm.Source == other and abs(pm.ExactVolume - 1200) < 1e-6
          and abs(pm.EnclosedVolume - 1200) <= 12 and pm.Inverted == 0,
          f"axis Source -> a 20 x 10 x 6 box: child follows (enclosed {pm.EnclosedVolume:.6f})")
    axis.Source = box
    doc.recompute()
    check(healthy(pm) and pm.Source == box and abs(pm.ExactVolume - 30000) < 1e-6, "and back")

    # --- False: the child is removed (derived data, recomputable) ...
    name = pm.Name
    axis.BuildPairMesh = False
    check(doc.getObject(name) is None and not pair_document.pair_mesh_children(axis),
          "BuildPairMesh = False: child removed")
    doc.recompute()
    check(healthy(axis), "axis fine without its child")
    # ... unless something uses it: then it stays, standalone, with its last parameters.
    axis.BuildPairMesh = True
    doc.recompute()
    (pm,) = pair_document.pair_mesh_children(axis)
    iso = pair_document.add_iso_surface(doc, pm, 0.5)
    axis.BuildPairMesh = False
    kept = doc.getObject(pm.Name)
    check(kept is not None and kept.MedialAxis is None and not pair_document.pair_mesh_children(axis)
          and kept.getEditorMode("Spacing") == [] and iso.PairMesh == kept,
          "BuildPairMesh = False with an iso-surface on the child: kept as a standalone PairMesh")
    axis.Spacing = 3.0
    doc.recompute()
    check(healthy(kept) and abs(kept.SpacingUsed.Value - 2.5) < 1e-9 and healthy(iso),
          "the released PairMesh no longer follows the axis")

    # --- set during a recompute (expression): created after it by the observer
    (axis2,) = cadmedial.add_to_document(doc, box, spacing=2.5, check_inside=False)
    axis2.setExpression("BuildPairMesh", "SolidIndex + 1")  # bound to an expression: set in the recompute
    doc.recompute()
    kids = pair_document.pair_mesh_children(axis2)
    check(axis2.BuildPairMesh and len(kids) == 1, "BuildPairMesh set by an expression: child created after the "
                                                 "recompute")
    doc.recompute()
    check(len(kids) == 1 and healthy(kids[0]) and kids[0].Inverted == 0
          and abs(kids[0].EnclosedVolume - 30000) <= 300, "and computed by the next recompute")

    # --- a document saved before BuildPairMesh existed still opens and gets it
    # (Spacing 2: at 3 this 50 x 30 x 20 box keeps 1 inverted element, a pair-mesh limit, not this feature.)
    axis.Spacing = 2.0
    doc.recompute()
    axis.removeProperty("BuildPairMesh")
    check("BuildPairMesh" not in axis.PropertiesList, "simulated old MedialAxis without BuildPairMesh")
    old, axis_name = os.path.join(tmp, "old_axis.FCStd"), axis.Name
    doc.saveAs(old)
    App.closeDocument(doc.Name)
    doc = App.openDocument(old)
    axis = doc.getObject(axis_name)
    check(axis is not None and "BuildPairMesh" in axis.PropertiesList and axis.BuildPairMesh is False,
          "old document: BuildPairMesh added on restore, False")
    axis.BuildPairMesh = True
    doc.recompute()
    kids = pair_document.pair_mesh_children(axis)
    check(len(kids) == 1 and healthy(kids[0]) and kids[0].Inverted == 0, "old document: BuildPairMesh works")
    App.closeDocument(doc.Name)


def run():
    try:
        main()
    except Exception:  # noqa: BLE001
        traceback.print_exc()
        failures.append("exception")
    print(f"{len(failures)} failure(s)" + (": " + "; ".join(failures) if failures else ""), flush=True)
    sys.stdout.flush()
    os._exit(1 if failures else 0)


run()
