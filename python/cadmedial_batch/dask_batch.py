"""`cadmedial batch` on a Dask distributed cluster.

    python3 -m cadmedial_batch.dask_batch INPUT... -o OUTDIR (--scheduler ADDR | --local N) [options]

Each file runs `cadmedial run` (and `eval`) as a subprocess on a worker, with
the status rules, staging and results.jsonl records of the C++ batch; only the
driver writes results.jsonl. OUTDIR and the inputs must be on a filesystem
every worker sees at the same paths. See README.md next to this file.
"""

import argparse
import fcntl
import os
import shutil
import signal
import sys
import time
import uuid

from . import job
from .inputs import UsageError, collect_inputs
from .progress import Progress
from .results import OutputError, ResultsLog, outputs_complete, read_last_records

EXIT_OK, EXIT_SOME_FAILED, EXIT_USAGE, EXIT_OUTPUT_FAILED = 0, 1, 2, 5
GRACE_SECONDS = 10  # after an interrupt, how long to wait for files that already finished


class Stopped(Exception):
    def __init__(self, signum):
        super().__init__(signum)
        self.signum = signum


def _default_executable():
    """$CADMEDIAL, else the repo's build, else `cadmedial` on PATH."""
    repo = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
    for candidate in (os.environ.get("CADMEDIAL"), os.path.join(repo, "build", "cli", "cadmedial"),
                      shutil.which("cadmedial")):
        if candidate and os.access(candidate, os.X_OK):
            return os.path.abspath(candidate)
    return None


def parse_args(argv):
    p = argparse.ArgumentParser(prog="python3 -m cadmedial_batch.dask_batch",
                                description="cadmedial batch on a Dask cluster; one record per file in "
                                            "OUTDIR/results.jsonl")
    p.add_argument("inputs", nargs="+", help="model files, folders (recursive) or manifests (*.txt, *.lst, @FILE)")
    p.add_argument("-o", "--output", required=True, help="output folder (on the shared filesystem)")
    where = p.add_mutually_exclusive_group(required=True)
    where.add_argument("--scheduler", metavar="ADDR", help="address of a running dask scheduler (tcp://host:8786)")
    where.add_argument("--local", type=int, metavar="N", help="start a LocalCluster of N worker processes")
    p.add_argument("--threads-per-worker", type=int, default=1, help="files at once per local worker (default 1)")
    p.add_argument("--cadmedial", default=_default_executable(),
                   help="cadmedial executable, same path on every worker (default: $CADMEDIAL, build/cli/cadmedial, "
                        "PATH)")
    p.add_argument("--timeout", type=float, help="seconds per file before it is killed (default: none)")
    p.add_argument("--max-memory", type=float, metavar="GIB", help="address-space limit per file in GiB")
    p.add_argument("--resume", action="store_true", help="skip files whose last record is ok and whose outputs exist")
    p.add_argument("--eval", action="store_true", help="also run `cadmedial eval` on each file's outputs")
    p.add_argument("--window", type=int, help="files submitted ahead of the workers (default: 4 x worker threads)")
    for name in ("--spacing", "--theta", "--rho"):
        p.add_argument(name, type=float, help="as for cadmedial run")
    p.add_argument("--no-oracle", action="store_true", help="as for cadmedial run")
    p.add_argument("--uniform-spacing", action="store_true", help="as for cadmedial run (one spacing per face)")
    args = p.parse_args(argv)
    for name in ("local", "threads_per_worker", "timeout", "max_memory", "window", "spacing", "rho"):
        value = getattr(args, name)
        if value is not None and value <= 0:
            p.error("--%s must be positive" % name.replace("_", "-"))
    if args.theta is not None and not 0 <= args.theta <= 89:
        p.error("--theta must be in [0, 89]")
    if not args.cadmedial:
        p.error("no cadmedial executable found; pass --cadmedial PATH")
    return args


def run_arguments(args):
    out = []
    for name in ("spacing", "theta", "rho"):
        if getattr(args, name) is not None:
            out += ["--" + name, repr(getattr(args, name))]
    return out + (["--no-oracle"] if args.no_oracle else []) + (["--uniform-spacing"] if args.uniform_spacing else [])


def connect(args):
    """A Client on the given scheduler, or on a LocalCluster of worker processes."""
    import dask
    from distributed import Client, LocalCluster
    if args.scheduler:
        return Client(args.scheduler), None
    # A worker that dies fails its file at once (a crash record) rather than the
    # scheduler handing the same file to the next worker to kill.
    dask.config.set({"distributed.scheduler.allowed-failures": 0})
    # Ctrl-C on a terminal reaches the whole process group, local workers
    # included; they must not die of it (the driver decides what to stop).
    # Worker processes inherit an ignored SIGINT (and then Python and asyncio
    # leave it alone); restarted workers get it from _IgnoreInterrupt.
    previous = signal.signal(signal.SIGINT, signal.SIG_IGN)
    try:
        cluster = LocalCluster(n_workers=args.local, threads_per_worker=args.threads_per_worker, processes=True,
                               host="127.0.0.1", dashboard_address=None, memory_limit=0)
        client = Client(cluster)
        client.register_worker_plugin(_IgnoreInterrupt(), name="cadmedial-ignore-sigint")
        return client, cluster
    finally:
        signal.signal(signal.SIGINT, previous)


class _IgnoreInterrupt:
    """Worker plugin of local clusters: see connect()."""

    def setup(self, worker):
        signal.signal(signal.SIGINT, signal.SIG_IGN)


def _lost_record(path, output, error):
    """The record of a file whose worker died or lost contact mid-file."""
    from distributed import KilledWorker
    from distributed.comm.core import CommClosedError
    name = type(error).__name__
    if isinstance(error, KilledWorker):
        worker = getattr(getattr(error, "last_worker", None), "address", "?")
        return job.record(path, output, "crash", step="worker",
                          message="worker %s died while running the file (KilledWorker)" % worker)
    if isinstance(error, CommClosedError):
        return job.record(path, output, "crash", step="worker",
                          message="lost contact with the worker running the file (%s: %s)" % (name, error))
    return job.record(path, output, "error", step="worker", message="%s: %s" % (name, error))


class Driver:
    def __init__(self, args, client, todo, log, progress):
        self.args, self.client, self.log, self.progress = args, client, log, progress
        self.todo = iter(enumerate(todo))
        self.out_dir = os.path.abspath(args.output)
        self.stage_root = os.path.join(self.out_dir, ".batch-tmp")
        self.run_args = run_arguments(args)
        self.eval_style = None
        self.token = uuid.uuid4().hex[:8]
        self.pending = {}  # future -> (path, output)

    def check_eval(self):
        if not self.args.eval:
            return
        available, output_flag = self.client.submit(job.probe_eval, self.args.cadmedial, pure=False).result()
        if not available:
            raise UsageError("--eval needs the `cadmedial eval` subcommand, which %s does not have"
                             % self.args.cadmedial)
        self.eval_style = "-o" if output_flag else "positional"

    def submit_next(self, queue):
        item = next(self.todo, None)
        if item is None:
            return
        index, (path, output) = item
        future = self.client.submit(
            job.run_file, self.args.cadmedial, path, output, self.out_dir,
            os.path.join(self.stage_root, str(index)), self.run_args, self.args.timeout, self.args.max_memory,
            self.eval_style, key="cadmedial-%s-%d" % (self.token, index), retries=0)
        self.pending[future] = (path, output)
        queue.add(future)

    def collect(self, future):
        path, output = self.pending.pop(future)
        try:
            return future.result()
        except Exception as error:  # noqa: BLE001 - every failure becomes a record
            return _lost_record(path, output, error)

    def record(self, r):
        self.log.append(r)
        self.progress.file_done(r)

    def run(self):
        from distributed import as_completed
        queue = as_completed()
        window = self.args.window or 4 * max(1, sum(self.client.nthreads().values()))
        for _ in range(window):
            self.submit_next(queue)
        for future in queue:
            r = self.collect(future)
            if r is not None:
                self.record(r)
            self.submit_next(queue)
            self.progress.refresh(len(self.pending))

    def stop(self):
        """Interrupted: stop submitting, kill the children on every worker, and
        record only files that had finished; --resume redoes the rest."""
        from distributed import wait
        open(os.path.join(self.stage_root, job.STOP_MARKER), "w").close()  # tasks starting now return at once
        futures = list(self.pending)
        deadline = time.monotonic() + GRACE_SECONDS
        while True:
            # Again each round: a task may have started its child just before the marker appeared.
            try:
                self.client.run(job.kill_staged_children, self.stage_root, on_error="ignore")
                wait(futures, timeout=1)
                break
            except Exception:  # noqa: BLE001 - timeout, or a worker gone while shutting down
                if time.monotonic() > deadline:
                    break
        for f in futures:
            r = self.collect(f) if f.status == "finished" else None
            if r is not None and r["status"] == "ok":
                self.record(r)
            f.cancel()


def run_batch(args):
    out_dir = os.path.abspath(args.output)
    inputs = collect_inputs(args.inputs, out_dir)
    try:
        os.makedirs(out_dir, exist_ok=True)
        lock = open(os.path.join(out_dir, ".batch.lock"), "a")
    except OSError as e:
        raise OutputError("cannot create %s: %s" % (out_dir, e.strerror)) from None
    try:
        fcntl.flock(lock, fcntl.LOCK_EX | fcntl.LOCK_NB)  # the same lock as `cadmedial batch`
    except BlockingIOError:
        raise UsageError("another batch is writing to %s" % out_dir) from None
    stage_root = os.path.join(out_dir, ".batch-tmp")
    shutil.rmtree(stage_root, ignore_errors=True)  # left by a killed batch; nothing in it was published
    os.makedirs(stage_root)

    results_path = os.path.join(out_dir, "results.jsonl")
    todo = inputs
    if args.resume:
        last = read_last_records(results_path)
        todo = [(p, o) for p, o in inputs
                if not (o in last and last[o].get("path") == p and outputs_complete(last[o], os.path.join(out_dir, o)))]
    log = ResultsLog(results_path)
    progress = Progress(sys.stderr, sys.stderr.isatty(), len(todo), len(inputs) - len(todo))

    import cloudpickle
    cloudpickle.register_pickle_by_value(job)  # workers need the executable, not this package
    client, cluster = connect(args)
    driver = Driver(args, client, todo, log, progress)
    stopped = 0
    try:
        driver.check_eval()
        try:
            driver.run()
        except (KeyboardInterrupt, Stopped) as e:
            stopped = e.signum if isinstance(e, Stopped) else signal.SIGINT
            driver.stop()
    finally:
        client.close()
        if cluster is not None:
            cluster.close()
        shutil.rmtree(stage_root, ignore_errors=True)
        log.close()
    progress.print_summary(results_path, stopped != 0)
    if stopped:
        return 128 + stopped
    return EXIT_SOME_FAILED if progress.failures else EXIT_OK


def main(argv=None):
    args = parse_args(argv)

    def on_term(signum, frame):
        raise Stopped(signum)
    signal.signal(signal.SIGTERM, on_term)
    try:
        return run_batch(args)
    except UsageError as e:
        print("error: %s" % e, file=sys.stderr)
        return EXIT_USAGE
    except OutputError as e:
        print("error: %s" % e, file=sys.stderr)
        return EXIT_OUTPUT_FAILED


if __name__ == "__main__":
    sys.exit(main())
