"""Shared helpers of the batch end-to-end tests (run by ctest, see CMakeLists.txt).

Configuration comes from the environment ctest sets: CADMEDIAL (executable),
CADMEDIAL_MODELS_DIR, CADMEDIAL_PUBLIC_MODELS_DIR, CADMEDIAL_PYTHON_DIR.
"""

import json
import os
import shutil
import subprocess
import sys
import tempfile
import time
import unittest

CADMEDIAL = os.environ.get("CADMEDIAL", "")
MODELS_DIR = os.environ.get("CADMEDIAL_MODELS_DIR", "")
PUBLIC_DIR = os.environ.get("CADMEDIAL_PUBLIC_MODELS_DIR", "")
PYTHON_DIR = os.environ.get("CADMEDIAL_PYTHON_DIR", "")
SOLID_FILES = ("medial.ply", "medial.obj", "medial.ma", "summary.json")
# Fast enough for a test suite: the exact-classifier check is what takes time.
FAST = ["--no-oracle"]


def bundled_models():
    return sorted(os.path.join(MODELS_DIR, f) for f in os.listdir(MODELS_DIR) if f.endswith(".step"))


def public_models(tag):
    """Public models whose MANIFEST.tsv notes contain `tag`; [] when the folder is missing."""
    manifest = os.path.join(PUBLIC_DIR, "MANIFEST.tsv")
    if not os.path.isfile(manifest):
        return []
    with open(manifest, encoding="utf-8") as f:
        rows = [line.rstrip("\n").split("\t") for line in f][1:]
    return [os.path.join(PUBLIC_DIR, r[0]) for r in rows if len(r) > 8 and tag in r[8].split("; ")]


def public_model(name):
    path = os.path.join(PUBLIC_DIR, name)
    return path if os.path.isfile(path) else None


def write_bad_files(folder):
    """{path: expected exit code} of deliberately broken inputs."""
    os.makedirs(folder, exist_ok=True)
    with open(os.path.join(MODELS_DIR, "box.step"), "rb") as f:
        box = f.read()
    files = {"empty.step": b"", "text.STP": b"this is not a STEP file\n", "truncated.step": box[: len(box) // 3],
             "garbage.brep": os.urandom(4096)}
    for name, data in files.items():
        with open(os.path.join(folder, name), "wb") as f:
            f.write(data)
    return {os.path.join(folder, n): 3 for n in files}


def read_records(out_dir):
    path = os.path.join(out_dir, "results.jsonl")
    if not os.path.exists(path):
        return []
    with open(path, encoding="utf-8") as f:
        return [json.loads(line) for line in f]  # every line must parse: nothing torn


def last_records(out_dir):
    return {r["path"]: r for r in read_records(out_dir)}


def processes_mentioning(text):
    """pids whose command line mentions `text` (e.g. an OUTDIR): leftover children."""
    pids = []
    for pid in os.listdir("/proc"):
        if pid.isdigit() and int(pid) != os.getpid():
            try:
                with open("/proc/%s/cmdline" % pid, "rb") as f:
                    if text.encode() in f.read():
                        pids.append(int(pid))
            except OSError:
                pass
    return pids


def wait_for(predicate, timeout, interval=0.05):
    deadline = time.monotonic() + timeout
    while time.monotonic() < deadline:
        value = predicate()
        if value:
            return value
        time.sleep(interval)
    return predicate()


class BatchTestCase(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.mkdtemp(prefix="cadmedial_batch_test_")

    def tearDown(self):
        shutil.rmtree(self.tmp, ignore_errors=True)

    def batch(self, args, **kw):
        return subprocess.run([CADMEDIAL, "batch"] + args, capture_output=True, text=True, **kw)

    def assert_outputs_match_records(self, out_dir, unrecorded_allowed=0):
        """Outputs exist exactly for files whose last record is ok, and are complete.

        A batch killed by SIGKILL between publishing a file's outputs and
        appending its record leaves that one folder unrecorded (complete all
        the same): `unrecorded_allowed` says how many such folders may exist."""
        last = {r["output"]: r for r in read_records(out_dir)}
        for output, r in last.items():
            folder = os.path.join(out_dir, output)
            if r["status"] != "ok":
                self.assertFalse(os.path.exists(folder), "outputs of a failed file: " + folder)
                continue
            self.assertTrue(r["solids"], output)
            for s in r["solids"]:
                d = os.path.join(folder, "solid_%d" % s["solid"])
                for name in SOLID_FILES:
                    self.assertTrue(os.path.isfile(os.path.join(d, name)), os.path.join(d, name))
                with open(os.path.join(d, "summary.json"), encoding="utf-8") as f:
                    self.assertEqual(json.load(f)["counts"], s["counts"])
        # Every output folder belongs to an ok record (no half-written leftovers).
        unrecorded = set()
        for root, dirs, files in os.walk(out_dir):
            dirs[:] = [d for d in dirs if not d.startswith(".")]
            if "summary.json" in files:
                output = os.path.relpath(os.path.dirname(root), out_dir)
                if output not in last:
                    unrecorded.add(output)
                    for name in SOLID_FILES:
                        self.assertTrue(os.path.isfile(os.path.join(root, name)), "half-written: " + root)
                    continue
                self.assertEqual(last[output]["status"], "ok", root)
        self.assertLessEqual(len(unrecorded), unrecorded_allowed, "outputs without a record: %s" % sorted(unrecorded))
        self.assertFalse([n for n in os.listdir(out_dir) if n.endswith(".tmp")])


def main():
    if not CADMEDIAL or not os.access(CADMEDIAL, os.X_OK):
        sys.exit("set CADMEDIAL to the cadmedial executable")
    # Test class names on the command line select what runs (ctest runs one class per test).
    unittest.main(module="__main__", verbosity=2)
