#!/usr/bin/python3
"""End-to-end tests of the Dask driver (python/cadmedial_batch) on a
LocalCluster of two worker processes on loopback.

    CADMEDIAL=build/cli/cadmedial CADMEDIAL_MODELS_DIR=models CADMEDIAL_PYTHON_DIR=python \
    tests/batch/test_dask_batch.py [TestClass...]
"""

import importlib.util
import os
import signal
import subprocess
import sys

from batch_testlib import (CADMEDIAL, FAST, MODELS_DIR, PYTHON_DIR, BatchTestCase, last_records, main,
                           processes_mentioning, public_model, read_records, wait_for, write_bad_files)

if importlib.util.find_spec("distributed") is None:
    print("python3-distributed is not installed: skipped")
    sys.exit(77)


def driver_command(inputs, out, *options):
    return [sys.executable, "-m", "cadmedial_batch.dask_batch"] + inputs + [
        "-o", out, "--local", "2", "--cadmedial", CADMEDIAL] + list(options)


def driver_env():
    return dict(os.environ, PYTHONPATH=PYTHON_DIR)


def eval_available():
    p = subprocess.run([CADMEDIAL, "eval", "--help"], capture_output=True, text=True)
    return p.returncode == 0 and "eval [OPTIONS]" in p.stdout


def bad_file(bad):
    return next(iter(bad))


class DaskStatuses(BatchTestCase):
    def test_models_and_bad_files_then_cpp_resume(self):
        models = [os.path.join(MODELS_DIR, m) for m in ("box.step", "l_bracket.step", "torus.step")]
        bad = write_bad_files(os.path.join(self.tmp, "bad"))
        expected = {m: ("ok", 0) for m in models}
        expected.update({p: ("error", code) for p, code in bad.items()})
        surfaces = public_model("bearing.iges")  # trimmed surfaces that stay open when sewn
        if surfaces:
            expected[surfaces] = ("error", 4)
        inputs = models + [os.path.join(self.tmp, "bad")] + ([surfaces] if surfaces else [])
        with_eval = ["--eval"] if eval_available() else []
        out = os.path.join(self.tmp, "out")

        p = subprocess.run(driver_command(inputs, out, "--spacing", "6", *FAST, *with_eval), env=driver_env(),
                           capture_output=True, text=True, timeout=240)
        self.assertEqual(p.returncode, 1, p.stderr)
        records = read_records(out)
        self.assertEqual(sorted(r["path"] for r in records), sorted(expected), "one record per input")
        for r in records:
            self.assertEqual((r["status"], r["exit_code"]), expected[r["path"]], r)
            if with_eval and r["status"] == "ok":
                self.assertIsNotNone(r["solids"][0]["eval"]["coverage_share"])
        self.assert_outputs_match_records(out)
        self.assertFalse(os.path.exists(os.path.join(out, ".batch-tmp")))
        # Output folders and records are those of the C++ batch: it can resume the driver's work.
        self.assertEqual(last_records(out)[models[0]]["output"], models[0].lstrip("/"))  # outside the cwd
        self.assertEqual(last_records(out)[bad_file(bad)]["output"], os.path.basename(bad_file(bad)))
        cpp = self.batch(inputs + ["-o", out, "--spacing", "6", "--resume"] + FAST + with_eval)
        self.assertEqual(cpp.returncode, 1, cpp.stderr)
        self.assertIn("resume: %d file(s) already done" % len(models), cpp.stderr)
        again = read_records(out)[len(records):]
        self.assertEqual(sorted(r["path"] for r in again), sorted(p for p, (s, _) in expected.items() if s != "ok"))
        self.assertEqual([list(r) for r in again], [list(records[0])] * len(again), "same fields, same order")


class DaskWorkerDeath(BatchTestCase):
    """A slow file (fine spacing) on one worker; the other gets a broken file."""

    def start(self, out):
        self.box = os.path.join(MODELS_DIR, "box.step")
        self.empty = list(write_bad_files(os.path.join(self.tmp, "bad")))[0]
        driver = subprocess.Popen(driver_command([self.box, self.empty], out, "--spacing", "0.12", *FAST),
                                  env=driver_env(), stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
        # The broken file's child also mentions OUTDIR and runs `run`: pick the box's
        # own child, else a slow machine may find (and kill the worker of) the wrong one.
        child = wait_for(lambda: [p for p in processes_mentioning(out)
                                  if "run" in self.cmdline(p) and self.box in self.cmdline(p)], 60)
        self.assertTrue(child, "the box never started on a worker")
        return driver, child[0]

    @staticmethod
    def cmdline(pid):
        try:
            with open("/proc/%d/cmdline" % pid, "rb") as f:
                return f.read().decode(errors="replace").split("\0")
        except OSError:
            return []

    def test_worker_killed_mid_file_is_a_crash(self):
        out = os.path.join(self.tmp, "out")
        driver, child = self.start(out)
        with open("/proc/%d/stat" % child) as f:
            worker = int(f.read().rsplit(")", 1)[1].split()[1])  # the worker process that started the child
        os.kill(worker, signal.SIGKILL)
        _, err = driver.communicate(timeout=120)
        self.assertEqual(driver.returncode, 1, err)
        records = last_records(out)
        self.assertEqual(len(read_records(out)), 2)
        self.assertEqual((records[self.box]["status"], records[self.box]["step"]), ("crash", "worker"))
        self.assertEqual(records[self.empty]["status"], "error")
        self.assertTrue(wait_for(lambda: processes_mentioning(out) == [], 5), "the child outlived its worker")
        self.assert_outputs_match_records(out)
        self.assertFalse(os.path.exists(os.path.join(out, ".batch-tmp")))

    def test_sigint_records_nothing_half_done(self):
        out = os.path.join(self.tmp, "out")
        driver, _ = self.start(out)
        wait_for(lambda: read_records(out), 30)  # the broken file is done
        driver.send_signal(signal.SIGINT)
        _, err = driver.communicate(timeout=120)
        self.assertEqual(driver.returncode, 130, err)
        self.assertEqual([r["path"] for r in read_records(out)], [self.empty])
        self.assertTrue(wait_for(lambda: processes_mentioning(out) == [], 5), "children outlived the driver")
        self.assert_outputs_match_records(out)
        self.assertFalse(os.path.exists(os.path.join(out, ".batch-tmp")))


if __name__ == "__main__":
    main()
