#!/usr/bin/python3
"""`cadmedial run --pair-mesh` and `cadmedial eval` on the bundled models and the
smaller set=dev public models (skipped without ../shared): the pair-mesh is a
valid partition of the volume its boundary encloses, that volume is within 1 %
of OCCT's exact solid volume, ParaView's reader (VTK) reads pairmesh.vtu, the
iso-surface at t = 1 is the boundary, and eval re-checks the files it reads.

    CADMEDIAL=build/cli/cadmedial CADMEDIAL_MODELS_DIR=models \
    CADMEDIAL_PUBLIC_MODELS_DIR=../shared/models/public tests/pairmesh/test_pair_mesh_cli.py
"""

import glob
import json
import os
import shutil
import subprocess
import sys
import tempfile
import unittest

CADMEDIAL = os.environ.get("CADMEDIAL", "build/cli/cadmedial")
MODELS_DIR = os.environ.get("CADMEDIAL_MODELS_DIR", "models")
PUBLIC_DIR = os.environ.get("CADMEDIAL_PUBLIC_MODELS_DIR", "../shared/models/public")
# Public dev models above this many bytes (bottle.brep: 8.4 M tetrahedra,
# valid, about 50 s to run measured 2026-12-01) take too long for the suite.
# The lever (198 kB, its zero-angle cusp) and NIST CTC-01 (235 kB, about
# 22 s with eval, coarse sampling) are in: they are the cases the
# boundary-cell relabelling exists for.
PUBLIC_MAX_BYTES = 250_000
# Models whose pair-mesh, at the default (graded) spacing, is valid only once
# sampled again finer (cli/solid_run.hpp). The lever (2 inverted at its
# zero-angle cusp) and NIST CTC-01 (2 where facets bridge a 15 mm step) were,
# until faces were graded from finer convex edges (2026-12-02); with those
# samples both are valid at once. The repair is held to them at one spacing
# per face in test_public_models_at_other_spacings too.
RESAMPLED_AT_DEFAULT = set()
# Known gap (ARCHITECTURE.md, "Pair-mesh: the rounded iso-surface"): whether
# sliver elements make the exact iso-surface at t = 0.5 cut itself depends on
# the samples too. On the lever, one spacing per face gives 0 crossing pairs
# at h = 8.6 and 7 at 9.0; graded (faces graded from finer convex edges,
# 2026-12-02) 14 at its default h, 0 at 0.97 h and 1.03 h, 3 at 0.94 h, all
# 14 between elements on two boundary edges the repair split (before that
# grading: 4 at its default, kept at 0.97 h). With edges following their
# faces' spacing along their length (2026-12-03; 20.5 k samples instead of
# 23.1 k): 37 at its default h, 10 at 0.97 h, 3 at 1.03 h, 4 at 0.94 h.
# Those crossings were the split's doing (2026-12-03): it bent edges on a knife
# edge between a plane and a tangent cylinder, 0.005 mm thick there, through
# the other side, so the boundary enclosed slivers twice. Since the split may
# not fold the boundary, the lever gives 0 at its default h and at 0.94, 0.97
# and 1.03 h. Every model is held to 0.
ISO_CROSSINGS_ALLOWED = {}
# Every model run here (NIST CTC-01 included since 2026-12-01: its last 5
# inverted elements went with 8 outer cells relabelled inner; bottle.brep,
# 8.4 M tetrahedra, stays out for time) is held to a valid mesh: 0 inverted,
# no overlap, and an iso-surface at t = 0.5 that does not cut itself (exact
# arithmetic; the rounded points of the written file may show crossings of
# sliver cuts, printed), but for ISO_CROSSINGS_ALLOWED.


def public_dev_models():
    manifest = os.path.join(PUBLIC_DIR, "MANIFEST.tsv")
    if not os.path.isfile(manifest):
        return []
    models = []
    with open(manifest, encoding="utf-8") as f:
        lines = f.readlines()
    for line in lines:
        cols = line.rstrip("\n").split("\t")
        if len(cols) > 8 and "set=dev" in cols[8]:
            path = os.path.join(PUBLIC_DIR, cols[0])
            if os.path.isfile(path) and os.path.getsize(path) <= PUBLIC_MAX_BYTES:
                models.append(path)
    return models


def load_json(path):
    with open(path, encoding="utf-8") as f:
        return json.load(f)


def read_vtu(path):
    import vtk  # python3-vtk9
    reader = vtk.vtkXMLUnstructuredGridReader()
    reader.SetFileName(path)
    reader.Update()
    return reader.GetOutput()


def ply_face_count(path):
    with open(path, encoding="ascii") as f:
        for line in f:
            if line.startswith("element face"):
                return int(line.split()[2])
            if line.startswith("end_header"):
                break
    raise AssertionError(path + ": no face element")


class PairMeshCli(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.mkdtemp(prefix="cadmedial_pairmesh_")

    def tearDown(self):
        shutil.rmtree(self.tmp, ignore_errors=True)

    def check_model(self, model):
        out = os.path.join(self.tmp, os.path.basename(model))
        run = subprocess.run([CADMEDIAL, "run", model, "-o", out, "--pair-mesh", "--iso", "0.5", "--iso", "1",
                              "--no-oracle"], capture_output=True, text=True, timeout=600)
        self.assertEqual(run.returncode, 0, run.stderr)
        ev = subprocess.run([CADMEDIAL, "eval", model, out], capture_output=True, text=True, timeout=600)
        self.assertEqual(ev.returncode, 0, ev.stderr)
        self.assertIn("pair-mesh:", ev.stdout)
        for solid in sorted(glob.glob(os.path.join(out, "solid_*"))):
            name = os.path.basename(model) + "/" + os.path.basename(solid)
            pm = load_json(os.path.join(solid, "summary.json"))["pair_mesh"]
            print("%-45s tets %8d FV %7d EE %7d VF %6d inverted %d (before repair %d) gap %.1e overlap %.1e "
                  "volume error %.4f %%  classify %.2fs build %.2fs" % (
                      name, pm["tetrahedra"], pm["face_vertex"], pm["edge_edge"], pm["vertex_face"],
                      pm["inverted"], pm["inverted_before_repair"], pm["gap_error"], pm["overlap_error"],
                      100 * pm["volume_error"], pm["seconds"]["classify_cells"], pm["seconds"]["build"]))
            sys.stdout.flush()
            with self.subTest(solid=name):
                self.assertGreater(pm["tetrahedra"], 0)
                self.assertEqual(pm["inverted"], 0)
                # Valid at the spacing asked: the repair alone, no sampling again.
                if os.path.basename(model) not in RESAMPLED_AT_DEFAULT:
                    self.assertEqual(len(pm["attempts"]), 1, pm["attempts"])
                self.assertLessEqual(pm["gap_error"], 1e-9)
                self.assertLessEqual(pm["overlap_error"], 1e-12)
                self.assertEqual(pm["boundary_triangles_not_in_one_vertex_face"], 0)
                self.assertEqual(pm["boundary_edges_not_shared"], 0)
                self.assertLessEqual(pm["volume_error"], 0.01)
                self.assertEqual(pm["vertex_face"], pm["boundary_triangles"])
                # eval read the files back and found the same mesh.
                ej = load_json(os.path.join(solid, "eval.json"))["pair_mesh"]
                for key in ("tetrahedra", "inverted", "boundary_triangles", "exact_volume"):
                    self.assertEqual(ej[key], pm[key], key)
                # CGAL's self-intersection test on the t = 0.5 iso-surface (eval).
                # Known gap: flat elements along convex edges leave a few crossings.
                print("    iso 0.5: %d crossing pairs (%d on the rounded points), %d flat triangles; "
                      "split edges %d, welded nodes %d" % (
                          ej["iso_0.5_self_intersections"], ej["iso_0.5_rounded_crossings"],
                          ej["iso_0.5_degenerate_triangles"], pm["split_boundary_edges"],
                          pm["welded_voronoi_nodes"]))
                self.assertLessEqual(ej["iso_0.5_self_intersections"],
                                     ISO_CROSSINGS_ALLOWED.get(os.path.basename(model), 0))
                self.assertAlmostEqual(ej["enclosed_volume"], pm["enclosed_volume"],
                                       delta=1e-12 * pm["exact_volume"])
                # ParaView's reader: every cell a tetrahedron with its type and sheet flag.
                grid = read_vtu(os.path.join(solid, "pairmesh.vtu"))
                self.assertEqual(grid.GetNumberOfCells(), pm["tetrahedra"])
                self.assertEqual(grid.GetNumberOfPoints(), pm["nodes"])
                self.assertEqual(grid.GetCellType(0), 10)  # VTK_TETRA
                self.assertEqual(grid.GetCellType(grid.GetNumberOfCells() - 1), 10)
                types = grid.GetCellData().GetArray("type")
                self.assertIsNotNone(types)
                self.assertIsNotNone(grid.GetCellData().GetArray("on_sheets"))
                counts = [0, 0, 0]
                for i in range(types.GetNumberOfTuples()):
                    counts[int(types.GetValue(i))] += 1
                self.assertEqual(counts, [pm["face_vertex"], pm["edge_edge"], pm["vertex_face"]])
                # t = 1 is the boundary surface; t = 0.5 has one cut per element or more.
                self.assertEqual(ply_face_count(os.path.join(solid, "iso_1.ply")), pm["boundary_triangles"])
                self.assertGreater(ply_face_count(os.path.join(solid, "iso_0.5.ply")), pm["boundary_triangles"])

    def test_bundled_models(self):
        models = sorted(glob.glob(os.path.join(MODELS_DIR, "*.step")))
        self.assertGreaterEqual(len(models), 8)
        for model in models:
            self.check_model(model)

    def test_public_dev_models(self):
        models = public_dev_models()
        if not models:
            self.skipTest("no ../shared/models/public")
        for model in models:
            self.check_model(model)
        # Two last-resort steps are exercised here: the boundary-edge split
        # (seed 003 §4.1, second case; the plate and face_recognition parts
        # need it) and the boundary-cell relabelling (pmi1 2 cells, lever 89
        # going outer, CTC-01 8 going inner; without it they keep 2, 34 and 5
        # inverted elements).
        splits = relabelled = 0
        for summary in glob.glob(os.path.join(self.tmp, "*", "solid_*", "summary.json")):
            splits += load_json(summary)["pair_mesh"]["split_boundary_edges"]
            relabelled += load_json(summary)["pair_mesh"]["relabelled_boundary_cells"]
        self.assertGreater(splits, 0)
        self.assertGreater(relabelled, 0)

    def test_public_models_at_other_spacings(self):
        # Validity must not hold only at the default spacing, and must come
        # from the repair, not from sampling again: one spacing per face
        # (--uniform-spacing), each valid at the first attempt. Each of the
        # explicit spacings failed before 2026-12-02: lever 8.6 and 9.0 kept
        # 1 and 2 inverted elements (the passes of the last resort ended at
        # three, with whole-set trials only); lever 9.3 and CTC-01 22.9 had 0
        # inverted but one boundary triangle twice, back to back (both
        # polygons across a split edge kept the edge's own triangle). None =
        # the default spacing (diagonal / 40). CTC-01 at its default spacing
        # is valid at the first attempt no more since the triplets that
        # rounding had dropped are placed (2026-12-04: 1 inverted element
        # left): it is the case of the next test, whose case before, the
        # lever at 10, is valid at once since.
        cases = [("bm2_ec_lever-A.stp", s) for s in (None, "8.6", "9.0", "9.3", "10")] + [
            ("nist_ctc_01_asme1_rd.stp", "22.9")]
        models = [(os.path.join(PUBLIC_DIR, m), s) for m, s in cases]
        if not all(os.path.isfile(m) for m, _ in models):
            self.skipTest("no ../shared/models/public")
        for model, spacing in models:
            out = os.path.join(self.tmp, os.path.basename(model) + "_" + str(spacing))
            run = subprocess.run([CADMEDIAL, "run", model, "-o", out, "--pair-mesh", "--no-oracle", "--uniform-spacing"]
                                 + (["--spacing", spacing] if spacing else []),
                                 capture_output=True, text=True, timeout=600)
            self.assertEqual(run.returncode, 0, run.stderr)
            summary = load_json(os.path.join(out, "solid_0", "summary.json"))
            pm = summary["pair_mesh"]
            print("%-28s h %5s: inverted %d, relabelled %d, split %d, repair %.1fs" % (
                os.path.basename(model), spacing or "def", pm["inverted"], pm["relabelled_boundary_cells"],
                pm["split_boundary_edges"], pm["seconds"]["repair"]))
            with self.subTest(model=os.path.basename(model), spacing=spacing):
                self.assertFalse(summary["graded_spacing"])
                self.assertEqual(pm["inverted"], 0)
                self.assertEqual(pm["boundary_triangles_not_in_one_vertex_face"], 0)
                self.assertEqual(pm["boundary_edges_not_shared"], 0)
                self.assertLessEqual(pm["overlap_error"], 1e-12)
                self.assertTrue(pm["valid"])
                self.assertEqual(len(pm["attempts"]), 1, pm["attempts"])

    def test_not_valid_at_the_spacing_asked_samples_again_finer(self):
        # NIST CTC-01 at its default spacing (h = 23.25), one spacing per
        # face, keeps 1 inverted element, and at 0.97 h too; with every
        # spacing x 0.94 it is valid (since 2026-12-04, when the triplets
        # that rounding had dropped were placed; before, the lever at h = 10
        # was the case, and h = 8.93 until the edge split stopped folding
        # the boundary). The run keeps that one: axis and pair-mesh of the
        # same samples, every attempt in the summary, a line on stdout.
        model = os.path.join(PUBLIC_DIR, "nist_ctc_01_asme1_rd.stp")
        if not os.path.isfile(model):
            self.skipTest("no ../shared/models/public")
        out = os.path.join(self.tmp, "ctc01")
        run = subprocess.run([CADMEDIAL, "run", model, "-o", out, "--pair-mesh", "--no-oracle", "--uniform-spacing"],
                             capture_output=True, text=True, timeout=600)
        self.assertEqual(run.returncode, 0, run.stderr)
        summary = load_json(os.path.join(out, "solid_0", "summary.json"))
        pm = summary["pair_mesh"]
        print(run.stdout)
        attempts = pm["attempts"]
        self.assertEqual([a["spacing_factor"] for a in attempts], [1.0, 0.97, 0.94])
        self.assertEqual([a["valid"] for a in attempts], [False, False, True])
        self.assertEqual([a["kept"] for a in attempts], [False, False, True])
        self.assertGreater(attempts[0]["inverted"], 0)
        self.assertAlmostEqual(attempts[0]["spacing"], 23.25, places=2)
        self.assertAlmostEqual(summary["spacing"], 0.94 * attempts[0]["spacing"])
        self.assertEqual(summary["counts"]["samples"], attempts[2]["samples"])
        self.assertTrue(pm["valid"])
        self.assertEqual(pm["inverted"], 0)
        self.assertIn("not valid at spacing 23.25 (1 inverted), sampled again at", run.stdout)
        self.assertIn("; kept %.4g " % attempts[2]["spacing"], run.stdout)
        # The files are those of the attempt kept (eval would take 80 s more).
        with open(os.path.join(out, "solid_0", "pairmesh.ele"), encoding="ascii") as f:
            line = f.readline()
            while line.startswith("#"):  # TetGen comment lines
                line = f.readline()
            self.assertEqual(int(line.split()[0]), pm["tetrahedra"])
        with open(os.path.join(out, "solid_0", "medial.ply"), encoding="ascii") as f:
            header = f.read(2000)
        self.assertIn("element vertex %d\n" % summary["counts"]["medial_vertices"], header)

    def test_point_cloud_pair_mesh_is_refused_with_a_warning(self):
        cloud = os.path.join(self.tmp, "cloud.xyz")
        with open(cloud, "w") as f:
            for i in range(200):
                f.write("%g %g %g\n" % ((i * 0.37) % 1, (i * 0.61) % 1, (i * 0.83) % 1))
        run = subprocess.run([CADMEDIAL, "run", cloud, "-o", os.path.join(self.tmp, "c"), "--pair-mesh"],
                             capture_output=True, text=True, timeout=120)
        self.assertEqual(run.returncode, 0, run.stderr)
        self.assertIn("--pair-mesh needs a B-rep", run.stderr)
        self.assertFalse(glob.glob(os.path.join(self.tmp, "c", "*", "pairmesh*")))


if __name__ == "__main__":
    unittest.main(argv=[sys.argv[0]] + sys.argv[1:], verbosity=2)
