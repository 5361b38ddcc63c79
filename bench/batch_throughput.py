#!/usr/bin/python3
"""Files per minute of batch runs over the public dev models
(../shared/models/public, MANIFEST.tsv rows tagged set=dev):
`cadmedial batch -j 1`, `-j 2`, and the Dask driver on a LocalCluster of two
single-thread workers. Prints a markdown table on stdout.

    bench/batch_throughput.py [--build build] [--repeat 3] [--copies 3] [-- RUN OPTIONS]

RUN OPTIONS go to every `cadmedial run` (default: --no-oracle; the oracle
check dominates some models, e.g. minutes on bottle.brep). The wall time is
the whole command, so it includes process start-up and, for Dask, starting
the cluster; "per file" is the mean of the records' own wall seconds. With
only 14 files the slowest one bounds the wall time; --copies N runs N copies
of the set (symlinks in separate folders) to measure a steadier rate.
The system /usr/bin/python3 is used because the driver needs python3-distributed.
"""

import argparse
import json
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


def dev_models():
    rows = [line.rstrip("\n").split("\t") for line in open(PUBLIC / "MANIFEST.tsv", encoding="utf-8")][1:]
    return [str(PUBLIC / r[0]) for r in rows if len(r) > 8 and "set=dev" in r[8].split("; ")]


def measure(command, out, env=None):
    shutil.rmtree(out, ignore_errors=True)
    start = time.monotonic()
    p = subprocess.run(command, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True, env=env)
    wall = time.monotonic() - start
    if p.returncode not in (0, 1):
        sys.exit("failed (%d): %s\n%s" % (p.returncode, " ".join(command), p.stderr))
    records = [json.loads(line) for line in open(os.path.join(out, "results.jsonl"), encoding="utf-8")]
    return wall, records


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--build", default=str(REPO / "build"), help="build folder with cli/cadmedial")
    ap.add_argument("--repeat", type=int, default=1, help="runs per mode; the fastest counts")
    ap.add_argument("--copies", type=int, default=1, help="copies of the model set in one batch")
    ap.add_argument("run_options", nargs="*", help="options for cadmedial run (after --)")
    args = ap.parse_args()
    exe = os.path.join(args.build, "cli", "cadmedial")
    run_options = args.run_options or ["--no-oracle"]
    tmp_models = tempfile.TemporaryDirectory(prefix="cadmedial_throughput_models_")
    models = []
    for copy in range(args.copies):
        folder = os.path.join(tmp_models.name, "copy%d" % copy)
        os.makedirs(folder)
        for m in dev_models():
            models.append(os.path.join(folder, os.path.basename(m)))
            os.symlink(m, models[-1])
    dask_env = dict(os.environ, PYTHONPATH=str(REPO / "python"))
    modes = [
        ("cadmedial batch -j 1", lambda out: [exe, "batch", *models, "-o", out, "-j", "1", *run_options], None),
        ("cadmedial batch -j 2", lambda out: [exe, "batch", *models, "-o", out, "-j", "2", *run_options], None),
        ("dask_batch --local 2", lambda out: ["/usr/bin/python3", "-m", "cadmedial_batch.dask_batch", *models,
                                              "-o", out, "--local", "2", "--cadmedial", exe, *run_options], dask_env),
    ]
    commit = subprocess.run(["git", "-C", str(REPO), "rev-parse", "--short", "HEAD"], capture_output=True,
                            text=True).stdout.strip()
    # The load average says whether other work shared the cores during the measurement.
    print("Batch throughput on %d x the %d public dev models (run options: %s); %s, %d cores, load %.1f, commit %s"
          % (args.copies, len(models) // args.copies, " ".join(run_options), platform.node(), os.cpu_count(),
             os.getloadavg()[0], commit or "?"))
    print()
    print("| mode | files | ok | wall s | files/min | per file s (mean) |")
    print("|---|---:|---:|---:|---:|---:|")
    with tempfile.TemporaryDirectory(prefix="cadmedial_throughput_") as tmp:
        for name, command, env in modes:
            best = None
            for _ in range(args.repeat):
                wall, records = measure(command(os.path.join(tmp, "out")), os.path.join(tmp, "out"), env)
                if best is None or wall < best[0]:
                    best = (wall, records)
            wall, records = best
            ok = sum(r["status"] == "ok" for r in records)
            per_file = sum(r["wall_seconds"] or 0 for r in records) / max(1, len(records))
            print("| %s | %d | %d | %.1f | %.1f | %.2f |" % (name, len(records), ok, wall,
                                                            60.0 * len(records) / wall, per_file))
            sys.stdout.flush()


if __name__ == "__main__":
    main()
