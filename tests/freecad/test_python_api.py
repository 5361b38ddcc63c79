"""Plain /usr/bin/python3 test of `import cadmedial` after plugin/install.sh
(run by run_freecad_test.sh: the package is found through the .pth file the
install put into the temporary HOME's user site-packages). No FreeCAD here."""

import copy
import importlib.util
import os
import sys
import threading
import time
import traceback

failures = []


def check(condition, what):
    print(("ok    " if condition else "FAIL  ") + what, flush=True)
    if not condition:
        failures.append(what)


def main():
    import numpy as np

    import cadmedial

    source_dir = os.environ["CADMEDIAL_SOURCE_DIR"]
    tmp = os.environ["CADMEDIAL_TEST_TMP"]
    models = os.path.join(source_dir, "models")
    check(os.path.realpath(cadmedial.__file__).startswith(os.path.realpath(os.environ["FREECAD_USER_HOME"])),
          f"cadmedial found through the .pth ({cadmedial.__file__})")
    check(importlib.util.find_spec("freecad") is None, "the install does not shadow FreeCAD's `freecad` package")
    check("FreeCAD" not in sys.modules, "no FreeCAD needed")

    (axis,) = cadmedial.compute(os.path.join(models, "l_bracket.step"))
    check(axis.vertices.ndim == 2 and axis.vertices.shape[1] == 3 and axis.vertices.dtype == np.float64,
          f"vertices {axis.vertices.shape}")
    check(axis.radius.shape == (axis.vertex_count,) and (axis.radius >= 0).all(), "one radius >= 0 per vertex")
    check(axis.offsets[0] == 0 and axis.offsets[-1] == axis.indices.size and (np.diff(axis.offsets) >= 3).all(),
          f"{axis.polygon_count} polygons as offsets + indices")
    check(axis.indices.min() >= 0 and axis.indices.max() < axis.vertex_count, "indices in range")
    check(axis.sheet.shape == (axis.polygon_count,) and axis.sheet.max() + 1 == axis.sheet_count,
          f"{axis.sheet_count} sheets")
    check(set(np.unique(axis.provenance)) <= {0, 1, 2, 3, 4}, "provenance codes 0..4")
    check(axis.summary["counts"]["medial_polygons"] == axis.polygon_count, "summary dict matches the arrays")
    check(axis.beta0 == 1, f"L-bracket: beta0 {axis.beta0}, beta1 {axis.beta1}")
    bracket = os.path.join(models, "l_bracket.step")
    report = cadmedial.evaluate(bracket, axis)
    check(report["pass"]["all"], "evaluate: the L-bracket axis passes every exact-geometry check: "
          + "; ".join(cadmedial.evaluation_lines(report)))
    # The same axis pushed off by 5 % of the diagonal must fail medialness.
    moved = copy.copy(axis)
    moved.vertices = axis.vertices + 0.05 * report["diagonal"] / np.sqrt(3.0)
    bad = cadmedial.evaluate(bracket, moved)
    check(not bad["pass"]["medialness"] and not bad["pass"]["all"],
          f"evaluate: a displaced axis fails (medialness median {100 * bad['medialness']['median']:.2f} % diag)")
    try:
        cadmedial.evaluate(bracket, axis, solid=1)
        check(False, "evaluate: solid out of range raises")
    except ValueError as e:
        check("out of range" in str(e), f"evaluate: solid out of range raises ValueError ({e})")
    tri, poly = axis.triangles()
    check(tri.shape[0] == int((np.diff(axis.offsets) - 2).sum()), f"{tri.shape[0]} fan triangles")

    (samples,) = cadmedial.sample(os.path.join(models, "box.step"))
    check(samples.points.shape[1] == 3 and samples.triangles.shape[1] == 3 and samples.triplets.shape[1] == 3,
          repr(samples))
    check(samples.report["reconstruction"]["surface"]["closed_manifold"], "box reconstruction closed")
    made = cadmedial.solids_brep(os.path.join(models, "box.step"))
    check(len(made["solids"]) == 1 and made["solids"][0].lstrip().startswith("CASCADE Topology") and not made["warnings"],
          "solids_brep: the box file's one solid as BREP text")
    box_text = made["solids"][0]
    check(len(cadmedial.solids_brep(box_text)["solids"]) == 1, "solids_brep: BREP text in, the same solid out")
    # Graded spacing is the default and reaches the sampler: recorded, and on
    # the lever (public, when ../shared is there) far fewer samples than one
    # spacing per face (graded_spacing=False).
    (uniform,) = cadmedial.sample(os.path.join(models, "box.step"), graded_spacing=False)
    check(samples.report["graded_spacing"] is True and uniform.report["graded_spacing"] is False,
          "sample: graded by default, graded_spacing recorded")
    try:
        cadmedial.sample(os.path.join(models, "box.step"), graded_spacing="yes")
        check(False, "sample: graded_spacing must be a bool")
    except ValueError as e:
        check("graded_spacing" in str(e), f"sample: graded_spacing must be a bool ({e})")
    (uniform_axis,) = cadmedial.compute(os.path.join(models, "box.step"), graded_spacing=False, check_inside=False)
    check(uniform_axis.summary["graded_spacing"] is False and axis.summary["graded_spacing"] is True,
          "compute: graded by default, graded_spacing recorded in the summary")
    lever = os.path.join(source_dir, "..", "shared", "models", "public", "bm2_ec_lever-A.stp")
    if os.path.exists(lever):
        (uniform_lever,) = cadmedial.sample(lever, graded_spacing=False)
        (graded_lever,) = cadmedial.sample(lever)
        n_uniform, n_graded = uniform_lever.points.shape[0], graded_lever.points.shape[0]
        check(n_graded < 0.8 * n_uniform, f"lever: {n_graded} samples graded, {n_uniform} with one spacing per face")
    (facts,) = cadmedial.inspect(os.path.join(models, "box.step"))
    check(abs(facts["default_spacing"] - facts["bbox_diagonal"] / 40) < 1e-9 * facts["bbox_diagonal"],
          f"inspect: default spacing {facts['default_spacing']:.4g}")

    for ext in ("ply", "obj", "ma"):
        path = os.path.join(tmp, f"l_bracket.{ext}")
        axis.write(path)
        check(os.path.getsize(path) > 0, f"write .{ext}")
    leftovers = [f for f in os.listdir(tmp) if ".tmp" in f]
    check(not leftovers, "no temporary files left")

    # MEDIAL on points alone: the box's samples as a closed mesh (inner axis),
    # as a bare cloud (whole axis), and from files by extension.
    (cloud_axis,) = cadmedial.compute_points((samples.points, samples.triangles))
    check(cloud_axis.summary["algorithm"] == "MEDIAL" and cloud_axis.summary["axis"] == "inner",
          f"closed mesh -> inner axis ({cloud_axis.summary['axis_note']})")
    check(cloud_axis.polygon_count > 100 and cloud_axis.beta0 == 1, repr(cloud_axis))
    check(abs(cloud_axis.summary["parameters"]["theta_deg"] - 22.5) < 1e-12, "point-cloud theta pi/8")
    box_lo, box_hi = samples.points.min(axis=0), samples.points.max(axis=0)
    check(bool(((cloud_axis.vertices >= box_lo - 1e-9) & (cloud_axis.vertices <= box_hi + 1e-9)).all()),
          "inner axis of the box lies in the box")
    (whole,) = cadmedial.compute(samples.points)
    check(whole.summary["axis"] == "whole", f"bare cloud -> whole axis ({whole.summary['axis_note']})")
    xyz = os.path.join(tmp, "box.xyz")
    np.savetxt(xyz, samples.points)
    (from_file,) = cadmedial.compute(xyz)
    check(from_file.summary["axis"] == "whole" and from_file.polygon_count == whole.polygon_count,
          ".xyz file gives the same axis as the array")
    try:
        cadmedial.compute_points(np.zeros((3, 3)))
        check(False, "3 points raise")
    except ValueError as e:
        check(isinstance(e, cadmedial.InputError), f"3 points: {e}")
    try:
        cadmedial.compute_points((samples.points, [[0, 1, 10**9]]))
        check(False, "bad triangle index raises")
    except ValueError as e:
        check("refers to vertex" in str(e), f"bad triangle: {e}")

    # The GIL is released while C++ runs: the main thread keeps going.
    done = threading.Event()
    box = os.path.join(models, "flange.step")
    worker = threading.Thread(target=lambda: (cadmedial.compute(box, spacing=1.5), done.set()))
    ticks = 0
    start = time.perf_counter()
    worker.start()
    while not done.is_set() and time.perf_counter() - start < 120:
        ticks += 1
        time.sleep(0.001)
    worker.join()
    seconds = time.perf_counter() - start
    check(done.is_set() and ticks > 0.3 * seconds / 0.0015,
          f"main thread ran {ticks} times during a {seconds:.2f} s computation")

    try:
        cadmedial.compute(os.path.join(models, "EXPECTED.md"))
        check(False, "bad file raises")
    except ValueError as e:
        check(isinstance(e, cadmedial.InputError) and "unknown extension" in str(e), f"bad file: {e}")


try:
    main()
except Exception:  # noqa: BLE001
    traceback.print_exc()
    failures.append("exception")
print(f"{len(failures)} failure(s)" + (": " + "; ".join(failures) if failures else ""), flush=True)
sys.exit(1 if failures else 0)
