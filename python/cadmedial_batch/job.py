"""One file's job, run on a Dask worker: `cadmedial run` (and `eval`) as a
child process, with the status rules and output staging of `cadmedial batch`
(cli/batch_child.cpp, cli/batch_runner.cpp).

Standard library only: the driver ships this module to the workers by value,
so a worker needs the cadmedial executable and the shared filesystem, not
this package.
"""

import ctypes
import json
import os
import resource
import shutil
import signal
import socket
import subprocess
import time

STOP_MARKER = "STOP"  # in the staging folder: the driver was interrupted
SOLID_FILES = ("medial.ply", "medial.obj", "medial.ma", "summary.json")
_ALLOCATION_FAILURE = ("bad_alloc", "out of memory", "Out of memory", "OutOfMemory", "Cannot allocate memory")
_PR_SET_PDEATHSIG = 1


def _child_setup(max_memory_gib):
    """preexec_fn: runs in the child between fork and exec, so it only calls
    functions resolved beforehand."""
    libc = ctypes.CDLL(None, use_errno=True)
    prctl, setrlimit, kill_signal = libc.prctl, resource.setrlimit, int(signal.SIGKILL)
    limit = int(max_memory_gib * 1024 ** 3) if max_memory_gib else 0

    def setup():
        # Die with the worker: a worker killed mid-file must not leave the
        # child running on (the thread that forks it lives until it ends).
        prctl(_PR_SET_PDEATHSIG, kill_signal)
        if limit:
            setrlimit(resource.RLIMIT_AS, (limit, limit))
    return setup


def _run_step(argv, stderr_path, deadline, max_memory_gib):
    """Runs one step; returns (exit_code or None, signal or None, timed_out, peak RSS MiB)."""
    with open(stderr_path, "wb") as err:
        proc = subprocess.Popen(argv, stdin=subprocess.DEVNULL, stdout=subprocess.DEVNULL, stderr=err,
                                start_new_session=True, preexec_fn=_child_setup(max_memory_gib))
    timed_out = False
    while True:
        # wait4 rather than Popen.wait: it reports this child's own peak RSS.
        pid, status, usage = os.wait4(proc.pid, os.WNOHANG)
        if pid:
            break
        if deadline is not None and time.monotonic() >= deadline and not timed_out:
            os.killpg(proc.pid, signal.SIGKILL)  # the whole group
            timed_out = True
        time.sleep(0.05)
    proc.returncode = os.waitstatus_to_exitcode(status)  # so Popen does not wait again
    exit_code = os.WEXITSTATUS(status) if os.WIFEXITED(status) else None
    sig = os.WTERMSIG(status) if os.WIFSIGNALED(status) else None
    return exit_code, sig, timed_out, usage.ru_maxrss / 1024.0


def _read_tail(path, limit=64 * 1024):
    try:
        with open(path, "rb") as f:
            f.seek(0, os.SEEK_END)
            f.seek(max(0, f.tell() - limit))
            return f.read().decode("utf-8", "replace")
    except OSError:
        return ""


def error_line(text):
    """The child's last "error: ..." line (prefix removed), else its last
    non-empty line; at most 500 characters."""
    last_error = last_line = ""
    for line in text.split("\n"):
        line = line.rstrip("\r")
        if not line.strip(" \t"):
            continue
        if line.startswith("error: "):
            last_error = line[7:]
        last_line = line
    line = last_error or last_line
    return line[:497] + "..." if len(line) > 500 else line


def classify(exit_code, sig, timed_out, stderr_text):
    if timed_out:
        return "timeout"
    if exit_code == 0:
        return "ok"
    if any(n in stderr_text for n in _ALLOCATION_FAILURE) or sig == signal.SIGKILL:
        return "oom"  # an unexpected SIGKILL is the kernel's OOM killer
    return "crash" if sig else "error"


def describe_failure(status, sig, timeout, stderr_text):
    line = error_line(stderr_text)
    what = ""
    if status == "timeout":
        what = "timed out after %g s" % timeout
    elif sig:
        try:
            what = "killed by " + signal.Signals(sig).name
        except ValueError:
            what = "killed by signal %d" % sig
    if not what:
        return line
    return what + ": " + line if line else what


def _read_json(path):
    try:
        with open(path, encoding="utf-8") as f:
            return json.load(f)
    except (OSError, ValueError):
        return None


def _pick(j, *keys):
    for k in keys:
        if not isinstance(j, dict) or k not in j:
            return None
        j = j[k]
    return j


def solid_summaries(folder):
    """Per solid: counts, topology, stage seconds, eval headline (as the C++ batch)."""
    solids = []
    while True:
        d = os.path.join(folder, "solid_%d" % len(solids))
        summary = _read_json(os.path.join(d, "summary.json"))
        if not isinstance(summary, dict):
            return solids
        solid = {"solid": len(solids), "counts": summary.get("counts", {}),
                 "topology": summary.get("topology", {}), "seconds": summary.get("seconds", {})}
        e = _read_json(os.path.join(d, "eval.json"))
        if isinstance(e, dict):
            solid["eval"] = {
                "inside_share": _pick(e, "inside", "share"),
                "medialness_median": _pick(e, "medialness", "median"),
                "medialness_p90": _pick(e, "medialness", "p90"),
                "two_contact_share": _pick(e, "medialness", "two_contact_share"),
                "coverage_share": _pick(e, "coverage", "share"),
                "edge_attachment": _pick(e, "attachment", "edge_share"),
                "corner_attachment": _pick(e, "attachment", "corner_share"),
                "topology_matches": _pick(e, "topology", "matches"),
                "pass": _pick(e, "pass", "all"),
            }
        solids.append(solid)


def record(path, output, status, exit_code=None, sig=None, step=None, message="", wall=None, rss=None,
           solids=None, host=None):
    """A results.jsonl record, fields in the order of the C++ batch."""
    return {"path": path, "output": output, "status": status, "exit_code": exit_code, "signal": sig,
            "step": step, "message": message, "wall_seconds": wall, "peak_rss_mib": rss,
            "host": host, "finished": time.strftime("%Y-%m-%dT%H:%M:%SZ", time.gmtime()),
            "solids": solids or []}


def probe_eval(executable):
    """(available, takes -o) for `cadmedial eval` on this worker's executable."""
    try:
        p = subprocess.run([executable, "eval", "--help"], stdin=subprocess.DEVNULL, capture_output=True,
                           text=True, timeout=60)
    except OSError:
        return False, False
    # Without the subcommand, CLI11 may print the top-level help and exit 0.
    return p.returncode == 0 and "eval [OPTIONS]" in p.stdout, "--output" in p.stdout


def run_file(executable, path, output, out_dir, stage, run_args, timeout=None, max_memory_gib=None,
             eval_style=None):
    """Runs one file and publishes its outputs; returns its record, or None if
    the driver was interrupted meanwhile (nothing recorded, --resume redoes it).

    eval_style: None (no eval), "-o" (`eval MODEL -o DIR`) or "positional".
    """
    stop_marker = os.path.join(os.path.dirname(stage), STOP_MARKER)
    if os.path.exists(stop_marker):
        return None
    start = time.monotonic()
    deadline = start + timeout if timeout else None
    staged = os.path.join(stage, "out")
    os.makedirs(stage, exist_ok=True)
    steps = [("run", ["run", path, "-o", staged] + list(run_args))]
    if eval_style:
        steps.append(("eval", ["eval", path, "-o", staged] if eval_style == "-o" else ["eval", path, staged]))

    peak = 0.0
    for step, args in steps:
        stderr_path = os.path.join(stage, step + ".stderr")
        exit_code, sig, timed_out, rss = _run_step([executable] + args, stderr_path, deadline, max_memory_gib)
        peak = max(peak, rss)
        if exit_code != 0 or timed_out:
            break
    if os.path.exists(stop_marker):
        return None

    stderr_text = _read_tail(stderr_path)
    status = classify(exit_code, sig, timed_out, stderr_text)
    fields = {"exit_code": None if timed_out else exit_code, "sig": None if timed_out else sig}
    solids, message, failed_step = [], "", None
    if status != "ok":
        failed_step, message = step, describe_failure(status, sig, timeout, stderr_text)
    else:
        solids = solid_summaries(staged)
        if not solids:
            status, failed_step, message = "error", "run", "exited 0 but wrote no solid_<i>/summary.json"

    # Outputs under OUTDIR/<output>/ exist exactly when the last record is ok.
    target = os.path.join(out_dir, output)
    try:
        if os.path.lexists(target) and (os.path.islink(target) or not os.path.isdir(target)):
            # Only folders are outputs: `results.jsonl` given as an input must not take the log away.
            if status == "ok":
                raise FileExistsError(17, "exists and is not an output folder")
        elif os.path.lexists(target):
            os.rename(target, os.path.join(stage, "previous"))
        if status == "ok":
            os.makedirs(os.path.dirname(target), exist_ok=True)
            os.rename(staged, target)
    except OSError as e:
        status, failed_step, solids = "error", "publish", []
        fields["exit_code"], message = 5, "cannot move outputs to %s: %s" % (target, e.strerror)
    shutil.rmtree(stage, ignore_errors=True)
    return record(path, output, status, fields["exit_code"], fields["sig"], failed_step, message,
                  time.monotonic() - start, peak, solids, socket.gethostname())


def kill_staged_children(stage_root):
    """Run on every worker when the driver is interrupted: SIGKILLs the process
    groups of cadmedial children writing under stage_root. Returns how many."""
    killed = 0
    for pid in os.listdir("/proc"):
        if not pid.isdigit():
            continue
        try:
            with open("/proc/%s/cmdline" % pid, "rb") as f:
                argv = f.read().split(b"\0")
        except OSError:
            continue
        if any(a.startswith(os.fsencode(stage_root) + b"/") for a in argv):
            try:
                os.killpg(int(pid), signal.SIGKILL)
                killed += 1
            except OSError:
                pass
    return killed
