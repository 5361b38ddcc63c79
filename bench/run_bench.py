#!/usr/bin/python3
"""Stage-by-stage timings of `cadmedial run` (DESIGN.md §7).

For every bundled model at three spacings (the default h, h/2, h/4), for
public models named with --public (e.g. bottle.brep, from ../shared/models/public),
and for a size series through the real pipeline (the bundled box.step at
spacing shrinking by sqrt(2), up to ~10^6 samples), runs the command line
in a fresh process with --no-oracle, reads its summary.json and the
process's peak memory (wait4 ru_maxrss), and reports two ratios:

  core/DT  = medial_total / delaunay: the core pipeline (Delaunay, Voronoi side
             arrays, umbrellas, filter, complete = convex edges + corners,
             cell sides, walk, complex, sheets) over CGAL's Delaunay
             insertion alone on the same points. The umbrella data and the
             cell-side inputs are built while the Delaunay runs (its own
             thread; prepared_alongside_delaunay s), and the Betti numbers of
             the result (topology, a diagnostic) while the files are written;
             neither is in medial_total;
  e2e/DT   = end_to_end / delaunay: the wall time of everything the command
             does for the solid (read, classify, sample, reconstruct, core,
             write medial.ply/.obj/.ma). Stages overlap (the Delaunay runs
             alongside the reconstruction), so this is less than their sum;
             summaries without end_to_end fall back to the sum.

Every case runs --repeat times (default 3); the row is the run with the
smallest end-to-end time (min of N, the usual way to damp noise from other
jobs on a shared machine). The series exponent is the least-squares slope of
log(time) against log(samples) over the series rows with >= 10^5 samples.

    /usr/bin/python3 bench/run_bench.py [--build build] [--repeat 3] [--quick]
        [--public bottle.brep] [--out bench/RESULTS.md]
"""
import argparse
import datetime
import json
import math
import os
import pathlib
import platform
import shutil
import subprocess
import sys
import tempfile
import time

REPO = pathlib.Path(__file__).resolve().parent.parent
PUBLIC = REPO.parent / "shared" / "models" / "public"
MODELS = ["box", "l_bracket", "cylinder", "plate_hole", "flange", "fillet_chamfer_block", "torus", "thin_wall"]
SAMPLING = ["read", "classify", "sample", "reconstruct"]
CORE = ["delaunay", "voronoi", "umbrellas", "filter", "convex_edges", "corners", "cell_sides", "walk", "complex",
        "sheets"]
STAGES = SAMPLING + CORE + ["write", "topology"]


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


def row(name, summary, wall, rss_mib):
    sec = summary["seconds"]
    stages = {s: sec.get(s, 0.0) for s in STAGES}
    core = sec["medial_total"]
    e2e = sec.get("end_to_end", sum(stages[s] for s in SAMPLING) + core + stages["write"])
    n = summary["counts"]["samples"]
    delaunay = max(sec["delaunay"], 1e-9)
    return {"model": name, "spacing": summary["spacing"], "samples": n, "stages": stages, "core": core, "e2e": e2e,
            "unlisted": core - sum(stages[s] for s in CORE), "wall": wall, "core_ratio": core / delaunay,
            "e2e_ratio": e2e / delaunay, "rss": rss_mib, "bytes_per_sample": rss_mib * 2**20 / max(n, 1)}


def best_of(exe, name, model, spacing, workdir, repeat):
    best = None
    for _ in range(repeat):
        r = row(name, *run_once(exe, model, spacing, workdir))
        best = r if best is None or r["e2e"] < best["e2e"] else best
    print(f"{name:22s} h={best['spacing']:<8.4g} n={best['samples']:8d} core={best['core']:.2f}s "
          f"e2e={best['e2e']:.2f}s core/DT={best['core_ratio']:.2f} e2e/DT={best['e2e_ratio']:.2f} "
          f"rss={best['rss']:.0f}MiB", flush=True)
    return best


def table(rows):
    head = (["model", "h", "samples"] + STAGES +
            ["core s", "e2e s", "wall s", "core/DT", "e2e/DT", "peak MiB", "B/sample"])
    lines = ["| " + " | ".join(head) + " |", "|" + "---|" * len(head)]
    for r in rows:
        cells = [r["model"], f"{r['spacing']:.4g}", str(r["samples"])]
        cells += [f"{r['stages'][s]:.3f}" for s in STAGES]
        cells += [f"{r['core']:.2f}", f"{r['e2e']:.2f}", f"{r['wall']:.2f}", f"{r['core_ratio']:.2f}",
                  f"{r['e2e_ratio']:.2f}", f"{r['rss']:.0f}", f"{r['bytes_per_sample']:.0f}"]
        lines.append("| " + " | ".join(cells) + " |")
    return "\n".join(lines)


def slope(rows, key):
    pts = [(math.log(r["samples"]), math.log(max(key(r), 1e-9))) for r in rows if r["samples"] >= 1e5]
    if len(pts) < 2:
        return float("nan")
    mx = sum(x for x, _ in pts) / len(pts)
    my = sum(y for _, y in pts) / len(pts)
    return sum((x - mx) * (y - my) for x, y in pts) / sum((x - mx) ** 2 for x, _ in pts)


def machine_notes():
    cpu = "unknown CPU"
    try:
        for line in open("/proc/cpuinfo"):
            if line.startswith("model name"):
                cpu = line.split(":", 1)[1].strip()
                break
    except OSError:
        pass
    mem = ""
    try:
        for line in open("/proc/meminfo"):
            if line.startswith("MemTotal"):
                mem = f", {int(line.split()[1]) / 2**20:.1f} GiB RAM"
    except OSError:
        pass
    commit = subprocess.run(["git", "-C", str(REPO), "rev-parse", "--short", "HEAD"], capture_output=True,
                            text=True).stdout.strip()
    return f"{os.cpu_count()} cores ({cpu}){mem}, {platform.system()} {platform.release()}, commit {commit}"


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--build", default=str(REPO / "build"))
    ap.add_argument("--repeat", type=int, default=3, help="runs per case; the row is the fastest (default 3)")
    ap.add_argument("--quick", action="store_true", help="series only up to ~2*10^5 samples")
    ap.add_argument("--public", action="append", default=[],
                    help="public model file name in ../shared/models/public, run at its default spacing")
    ap.add_argument("--out", default=None, help="write the markdown tables here")
    args = ap.parse_args()
    exe = pathlib.Path(args.build) / "cli" / "cadmedial"
    if not exe.exists():
        sys.exit(f"{exe} not found: build first (scripts/setup.sh demo)")

    load_before = os.getloadavg()
    started = datetime.datetime.now(datetime.timezone.utc)
    rows, public, series = [], [], []
    with tempfile.TemporaryDirectory() as work:
        for name in MODELS:
            model = REPO / "models" / f"{name}.step"
            base = None
            for factor in (1.0, 0.5, 0.25):
                r = best_of(exe, name, model, base * factor if base else 0, work, args.repeat)
                base = base or r["spacing"]
                rows.append(r)
        for name in args.public:
            model = PUBLIC / name
            if not model.exists():
                print(f"skipping {name}: {model} not found", flush=True)
                continue
            public.append(best_of(exe, name, model, 0, work, args.repeat))
        # Size series through the real pipeline: the box at shrinking spacing (samples ~ 1/h^2).
        model = REPO / "models" / "box.step"
        spacing = 2.0
        target = 2e5 if args.quick else 1e6
        while True:
            series.append(best_of(exe, "box", model, spacing, work, args.repeat))
            if series[-1]["samples"] * 2 > target:
                break
            spacing /= 2 ** 0.5
        # Last point at ~target samples (samples ~ 1/h^2).
        n = series[-1]["samples"]
        if n < 0.9 * target:
            series.append(best_of(exe, "box", model, spacing * (n / target) ** 0.5, work, args.repeat))
    load_after = os.getloadavg()

    growth = (f"log-log slope over the series rows with >= 10^5 samples: end to end "
              f"{slope(series, lambda r: r['e2e']):.2f}, core {slope(series, lambda r: r['core']):.2f}, "
              f"Delaunay alone {slope(series, lambda r: r['stages']['delaunay']):.2f} (1.00 = linear)")
    command = "/usr/bin/python3 bench/run_bench.py " + " ".join(sys.argv[1:])
    text = (f"Command: `{command}`\n\n"
            f"Machine: {machine_notes()}; started {started:%Y-%m-%d %H:%M} UTC; load average "
            f"{load_before[0]:.2f} before, {load_after[0]:.2f} after (other jobs share the cores, so times are "
            f"the min of {args.repeat} runs).\n\n"
            "Times in seconds from each run's summary.json; `core` = medial_total (delaunay ... sheets; the Betti "
            "numbers, `topology`, are computed beside the write), "
            "`e2e` = seconds.end_to_end, the wall time from read to write (the Delaunay runs alongside the "
            "reconstruction, so it is less than the stages' sum); `wall` = the whole process incl. "
            "start-up and OCCT shape loading; peak MiB = ru_maxrss of the process.\n\n"
            "## Bundled models at three spacings\n\n" + table(rows) + "\n\n")
    if public:
        text += "## Public models (default spacing)\n\n" + table(public) + "\n\n"
    text += ("## Size series (box.step through `cadmedial run`, spacing shrinking by √2)\n\n" + table(series) +
             f"\n\nGrowth: {growth}.\n")
    if args.out:
        write_between_markers(pathlib.Path(args.out), text)
    print(text)


BEGIN, END = "<!-- stage bench: begin -->", "<!-- stage bench: end -->"


def write_between_markers(path, text):
    """Replaces only this script's section: the hand-written notes and the
    other benches' sections of the same file stay."""
    block = BEGIN + "\n" + text.rstrip() + "\n" + END + "\n"
    old = path.read_text() if path.exists() else ""
    if BEGIN in old and END in old:
        new = old[:old.index(BEGIN)] + block + old[old.index(END) + len(END) + 1:]
    else:
        new = block + ("\n" + old if old else "")
    path.write_text(new)


if __name__ == "__main__":
    main()
