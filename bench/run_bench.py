#!/usr/bin/env python3
"""Stage-by-stage timings of `cadmedial run` (DESIGN.md §7).

For every bundled model at three spacings, and for a size series on one model
up to ~10^6 samples, runs the real command line in a fresh process, reads its
summary.json and the process's peak memory (wait4), and reports every run as a
ratio to CGAL's Delaunay time on the same points.

    python3 bench/run_bench.py [--build build] [--quick] [--out bench/RESULTS.md]
"""
import argparse
import json
import os
import pathlib
import shutil
import subprocess
import sys
import tempfile
import time

REPO = pathlib.Path(__file__).resolve().parent.parent
MODELS = ["box", "l_bracket", "cylinder", "plate_hole", "flange", "fillet_chamfer_block", "torus", "thin_wall"]
STAGES = ["read", "classify", "sample", "reconstruct", "delaunay", "voronoi", "umbrellas", "filter",
          "convex_edges", "corners", "walk", "complex", "sheets", "topology", "write"]


def run_once(exe, model, spacing, workdir):
    out = pathlib.Path(workdir) / "out"
    shutil.rmtree(out, ignore_errors=True)
    cmd = [str(exe), "run", str(model), "-o", str(out), "--no-oracle"]
    if spacing:
        cmd += ["--spacing", repr(spacing)]
    start = time.monotonic()
    proc = subprocess.Popen(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
    _, status, usage = os.wait4(proc.pid, 0)
    wall = time.monotonic() - start
    if status != 0:
        raise RuntimeError(f"{' '.join(cmd)} failed: {proc.stderr.read().decode()}")
    summary = json.loads((out / "solid_0" / "summary.json").read_text())
    return summary, wall, usage.ru_maxrss / 1024.0  # MiB


def row(name, spacing, summary, wall, rss_mib):
    sec = summary["seconds"]
    stages = {s: sec.get(s, 0.0) for s in STAGES}
    total = sum(stages.values())
    n = summary["counts"]["samples"]
    delaunay = max(sec["delaunay"], 1e-9)
    return {"model": name, "spacing": spacing, "samples": n, "stages": stages, "total": total, "wall": wall,
            "ratio": total / delaunay, "medial_ratio": sec["medial_total"] / delaunay, "rss": rss_mib,
            "bytes_per_sample": rss_mib * 2**20 / max(n, 1)}


def table(rows):
    head = ["model", "h", "samples"] + STAGES + ["total s", "total/DT", "medial/DT", "peak MiB", "B/sample"]
    lines = ["| " + " | ".join(head) + " |", "|" + "---|" * len(head)]
    for r in rows:
        cells = [r["model"], f"{r['spacing']:.4g}", str(r["samples"])]
        cells += [f"{r['stages'][s]:.3f}" for s in STAGES]
        cells += [f"{r['total']:.2f}", f"{r['ratio']:.2f}", f"{r['medial_ratio']:.2f}", f"{r['rss']:.0f}",
                  f"{r['bytes_per_sample']:.0f}"]
        lines.append("| " + " | ".join(cells) + " |")
    return "\n".join(lines)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--build", default=str(REPO / "build"))
    ap.add_argument("--quick", action="store_true", help="series only up to ~2*10^5 samples")
    ap.add_argument("--out", default=None, help="write the markdown tables here")
    args = ap.parse_args()
    exe = pathlib.Path(args.build) / "cli" / "cadmedial"
    if not exe.exists():
        sys.exit(f"{exe} not found: build first (scripts/setup.sh demo)")

    rows, series = [], []
    with tempfile.TemporaryDirectory() as work:
        for name in MODELS:
            model = REPO / "models" / f"{name}.step"
            base = None
            for factor in (1.0, 0.5, 0.25):
                summary, wall, rss = run_once(exe, model, base * factor if base else 0, work)
                if base is None:
                    base = summary["spacing"]
                rows.append(row(name, summary["spacing"], summary, wall, rss))
                print(f"{name:22s} h={summary['spacing']:.4g} n={rows[-1]['samples']:8d} "
                      f"total={rows[-1]['total']:.2f}s ratio={rows[-1]['ratio']:.2f} rss={rss:.0f}MiB", flush=True)
        # Size series: the box at shrinking spacing (samples ~ 1/h^2).
        model = REPO / "models" / "box.step"
        spacing = 2.0
        limit = 2e5 if args.quick else 1.1e6
        while True:
            summary, wall, rss = run_once(exe, model, spacing, work)
            series.append(row("box", spacing, summary, wall, rss))
            print(f"series h={spacing:.4g} n={series[-1]['samples']:8d} total={series[-1]['total']:.2f}s "
                  f"ratio={series[-1]['ratio']:.2f} rss={rss:.0f}MiB", flush=True)
            if series[-1]["samples"] * 2 > limit:
                break
            spacing /= 2 ** 0.5

    text = ("## Bundled models at three spacings\n\n" + table(rows) +
            "\n\n## Size series (box, spacing shrinking by √2)\n\n" + table(series) + "\n")
    if args.out:
        pathlib.Path(args.out).write_text(text)
    print(text)


if __name__ == "__main__":
    main()
