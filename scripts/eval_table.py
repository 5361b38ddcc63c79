#!/usr/bin/python3
"""The exact-geometry eval table (DESIGN.md §6) of `cadmedial run` + `cadmedial eval`
on the bundled models and, with --public, the set=dev public models
(../shared/models/public, MANIFEST.tsv). Prints a markdown table on stdout.

    scripts/eval_table.py [--build build] [--public] [--out DIR] [-- RUN OPTIONS]

Every row is measured against OCCT's exact B-rep, never against the samples.
Columns: samples, run seconds (sampling + medial, without the oracle check),
inside share of the sheet area, median / p90 of |dist - r| as % of the
bounding-box diagonal, share of vertices with two contacts ≥ 10° apart, coverage of 20 000 boundary points at tol = 0.5 % of the
diagonal, convex-edge attachment by length, attached / all non-concave corners,
β0, β1 of the axis (solid's in brackets) and the verdict (failed checks named).
"""

import argparse
import json
import pathlib
import subprocess
import sys
import tempfile

REPO = pathlib.Path(__file__).resolve().parent.parent
PUBLIC = REPO.parent / "shared" / "models" / "public"
BUNDLED = ["box", "l_bracket", "cylinder", "plate_hole", "flange", "fillet_chamfer_block", "torus", "thin_wall"]


def public_dev_models():
    manifest = PUBLIC / "MANIFEST.tsv"
    if not manifest.exists():
        return []
    out = []
    for line in manifest.read_text().splitlines()[1:]:
        cols = line.split("\t")
        if len(cols) > 8 and "set=dev" in cols[8] and (PUBLIC / cols[0]).exists():
            out.append(PUBLIC / cols[0])
    return out


def verdict(p):
    failed = [k for k in ("inside", "medialness", "two_contacts", "coverage", "edges", "corners", "topology")
              if not p[k]]
    return "PASS" if not failed else "FAIL: " + ", ".join(failed)


def evaluate(exe, model, outdir, run_options):
    run = subprocess.run([exe, "run", str(model), "-o", str(outdir), *run_options], capture_output=True, text=True)
    if run.returncode != 0:
        return [f"| {model.name} | run failed (exit {run.returncode}): {run.stderr.strip().splitlines()[0][:100]} |"]
    ev = subprocess.run([exe, "eval", str(model), str(outdir)], capture_output=True, text=True)
    if ev.returncode not in (0, 1):
        return [f"| {model.name} | eval failed (exit {ev.returncode}): {ev.stderr.strip().splitlines()[0][:100]} |"]
    rows = []
    for solid_dir in sorted(pathlib.Path(outdir).glob("solid_*")):
        s = json.loads((solid_dir / "summary.json").read_text())
        e = json.loads((solid_dir / "eval.json").read_text())
        name = model.name + ("" if solid_dir.name == "solid_0" and not (outdir / "solid_1").exists()
                             else f" [{solid_dir.name}]")
        seconds = s["seconds"].get("end_to_end") or sum(
            s["seconds"].get(k, 0.0) for k in ("read", "classify", "sample", "reconstruct", "medial_total", "write"))
        m, t, a = e["medialness"], e["topology"], e["attachment"]
        rows.append(
            f"| {name} | {s['counts']['samples']} | {seconds:.2f} | {100 * e['inside']['share']:.2f} | "
            f"{100 * m['median']:.3f} / {100 * m['p90']:.3f} | {100 * m['two_contact_share']:.2f} | "
            f"{100 * e['coverage']['share']:.2f} | "
            f"{100 * a['edge_share']:.2f} | {a['attached_corners']}/{a['corners']} | "
            f"{t['medial']['beta0']}, {t['medial']['beta1']} ({t['solid']['beta0']}, {t['solid']['beta1']}) | "
            f"{verdict(e['pass'])} |")
    return rows


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--build", default=str(REPO / "build"))
    ap.add_argument("--public", action="store_true", help="also the set=dev public models")
    ap.add_argument("--out", help="keep the outputs here (default: a temporary folder)")
    ap.add_argument("run_options", nargs="*", help="after --: options for every `cadmedial run`")
    args = ap.parse_args()
    exe = str(pathlib.Path(args.build) / "cli" / "cadmedial")
    if not pathlib.Path(exe).exists():
        sys.exit(f"eval_table: {exe} not found; build first (scripts/setup.sh)")
    run_options = args.run_options or ["--no-oracle"]
    models = [REPO / "models" / f"{m}.step" for m in BUNDLED]
    if args.public:
        models += public_dev_models()
    print("| model | samples | run s | inside % | \\|d−r\\|/diag % median / p90 | two contacts % | coverage % | "
          "convex edges % | corners | β0, β1 (solid) | verdict |")
    print("|---|---|---|---|---|---|---|---|---|---|---|")
    with tempfile.TemporaryDirectory() as tmp:
        base = pathlib.Path(args.out or tmp)
        for model in models:
            for row in evaluate(exe, model, base / model.stem, run_options):
                print(row, flush=True)


if __name__ == "__main__":
    main()
