#!/usr/bin/python3
"""Pair-mesh cost per model (issue #4): `cadmedial run --pair-mesh` against the
same run without it, on the bundled models and any public ones named.

For each model: the pair-mesh stage times from summary.json (exact cell
labels, construction, repair, validity check, files), their ratio to CGAL's
Delaunay time on the same points (target: build + repair + labels <= DT), the
extra peak memory over the run without --pair-mesh, and the validity figures.
Writes the table into bench/RESULTS.md between the pair-mesh markers (the
rest of the file is left as it is), or prints it.

    /usr/bin/python3 bench/pair_mesh_bench.py --repeat 3 --public bug3883_xr2-ct-214_plate.stp --out bench/RESULTS.md
"""
import argparse
import json
import os
import pathlib
import shutil
import subprocess
import tempfile
import time

REPO = pathlib.Path(__file__).resolve().parent.parent
PUBLIC = REPO.parent / "shared" / "models" / "public"
MODELS = ["box", "l_bracket", "cylinder", "plate_hole", "flange", "fillet_chamfer_block", "torus", "thin_wall"]
BEGIN, END = "<!-- pair-mesh bench: begin -->", "<!-- pair-mesh bench: end -->"


def run(exe, model, workdir, pair_mesh):
    out = pathlib.Path(workdir) / "out"
    shutil.rmtree(out, ignore_errors=True)
    cmd = [str(exe), "run", str(model), "-o", str(out), "--no-oracle"] + (["--pair-mesh"] if pair_mesh else [])
    proc = subprocess.Popen(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
    _, status, usage = os.wait4(proc.pid, 0)
    if status != 0:
        raise RuntimeError(f"{' '.join(cmd)} failed: {proc.stderr.read().decode()}")
    summaries = [json.loads(p.read_text()) for p in sorted(out.glob("solid_*/summary.json"))]
    return summaries, usage.ru_maxrss / 1024.0


def measure(exe, name, model, workdir, repeat):
    best = None
    for _ in range(repeat):
        with_pm, rss_pm = run(exe, model, workdir, True)
        _, rss_plain = run(exe, model, workdir, False)
        s = with_pm[0]  # first solid
        pm = s["pair_mesh"]
        sec = pm["seconds"]
        dt = max(s["seconds"]["delaunay"], 1e-9)
        r = {"model": name, "samples": s["counts"]["samples"], "tets": pm["tetrahedra"], "dt": dt,
             "labels": sec["classify_cells"], "build": sec["build"], "repair": sec["repair"], "check": sec["check"],
             "write": sec.get("write", 0.0), "exact": pm["cells_classified_exactly"],
             "inverted": pm["inverted"], "before": pm["inverted_before_repair"],
             "split": pm.get("split_boundary_edges", 0), "relabelled": pm.get("relabelled_boundary_cells", 0),
             "volume_error": pm["volume_error"],
             # Samplings the run took (cli/solid_run.hpp: sampled again while not valid); the
             # stage times above are those of the one kept, end_to_end counts them all.
             "samplings": len(pm.get("attempts", [None])), "end_to_end": s["seconds"]["end_to_end"],
             "rss_extra": max(rss_pm - rss_plain, 0.0), "rss": rss_pm}
        r["core_ratio"] = (r["build"] + r["repair"]) / dt
        r["with_labels_ratio"] = (r["labels"] + r["build"] + r["repair"]) / dt
        if best is None or r["with_labels_ratio"] < best["with_labels_ratio"]:
            best = r
    print(f"{name:34s} n={best['samples']:7d} tets={best['tets']:8d} DT={best['dt']:.3f}s "
          f"labels={best['labels']:.3f}s build+repair={best['build'] + best['repair']:.3f}s "
          f"(x{best['core_ratio']:.2f} DT, x{best['with_labels_ratio']:.2f} with labels) "
          f"+{best['rss_extra']:.0f} MiB inverted {best['inverted']}", flush=True)
    return best


def table(rows):
    head = ["model", "samples", "tetrahedra", "DT s", "labels s (exact queries)", "build s", "repair s",
            "check s", "write s", "(build+repair)/DT", "(labels+build+repair)/DT", "extra peak MiB",
            "inverted (before repair)", "split edges", "relabelled cells", "volume error", "samplings",
            "solid s (all samplings)"]
    lines = ["| " + " | ".join(head) + " |", "|" + "---|" * len(head)]
    for r in rows:
        lines.append("| " + " | ".join([
            r["model"], str(r["samples"]), str(r["tets"]), f"{r['dt']:.3f}", f"{r['labels']:.3f} ({r['exact']})",
            f"{r['build']:.3f}", f"{r['repair']:.3f}", f"{r['check']:.3f}", f"{r['write']:.3f}",
            f"{r['core_ratio']:.2f}", f"{r['with_labels_ratio']:.2f}", f"{r['rss_extra']:.0f}",
            f"{r['inverted']} ({r['before']})", str(r["split"]), str(r["relabelled"]),
            f"{100 * r['volume_error']:.3g} %", str(r["samplings"]), f"{r['end_to_end']:.2f}"]) + " |")
    return "\n".join(lines)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--build", default=str(REPO / "build"))
    ap.add_argument("--repeat", type=int, default=3, help="runs per model; the row is the fastest (default 3)")
    ap.add_argument("--public", action="append", default=[], help="public model file name (repeatable)")
    ap.add_argument("--out", default=None, help="markdown file whose pair-mesh section is replaced")
    args = ap.parse_args()
    exe = pathlib.Path(args.build) / "cli" / "cadmedial"
    cases = [(m, REPO / "models" / f"{m}.step") for m in MODELS]
    cases += [(p, PUBLIC / p) for p in args.public if (PUBLIC / p).exists()]
    load_before = os.getloadavg()[0]
    with tempfile.TemporaryDirectory(prefix="cadmedial_pm_bench_") as workdir:
        rows = [measure(exe, name, model, workdir, args.repeat) for name, model in cases]
    text = "\n".join([
        BEGIN,
        "## Pair-mesh (`run --pair-mesh`, default spacing)",
        "",
        f"Command: `/usr/bin/python3 bench/pair_mesh_bench.py --repeat {args.repeat}"
        + "".join(f" --public {p}" for p in args.public) + " --out bench/RESULTS.md`; "
        + f"{time.strftime('%Y-%m-%d %H:%M UTC', time.gmtime())}, load average {load_before:.2f} before, "
        + f"{os.getloadavg()[0]:.2f} after. Times are the fastest of the runs, from summary.json; labels = the "
        + "exact inner/outer label of every Delaunay cell (OCCT classifier near the surface, the closed "
        + "reconstruction's side elsewhere); extra peak MiB = peak RSS with --pair-mesh minus without; "
        + "samplings = how many times the solid was sampled (again, finer, while the pair-mesh was not "
        + "valid): the stage times are those of the sampling kept, `solid s` (end to end) counts them all.",
        "",
        table(rows),
        END,
    ])
    if not args.out:
        print(text)
        return
    path = pathlib.Path(args.out)
    old = path.read_text() if path.exists() else ""
    if BEGIN in old and END in old:
        new = old[:old.index(BEGIN)] + text + old[old.index(END) + len(END):]
    else:
        new = old.rstrip("\n") + "\n\n" + text + "\n"
    tmp = path.with_suffix(".tmp")
    tmp.write_text(new)
    tmp.replace(path)
    print(f"wrote {path}")


if __name__ == "__main__":
    main()
