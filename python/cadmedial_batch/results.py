"""OUTDIR/results.jsonl on the driver side: the same file and rules as
cli/batch_results.cpp, so `cadmedial batch --resume` can finish what the Dask
driver started and the other way round."""

import json
import os

from .job import SOLID_FILES


class OutputError(Exception):
    """OUTDIR or results.jsonl cannot be written (exit code 5)."""


def read_last_records(path):
    """Last parsable record per output folder; a torn last line is skipped."""
    last = {}
    try:
        with open(path, encoding="utf-8", errors="replace") as f:
            for line in f:
                try:
                    r = json.loads(line)
                except ValueError:
                    continue
                if isinstance(r, dict) and isinstance(r.get("output"), str):
                    last[r["output"]] = r
    except FileNotFoundError:
        pass
    return last


def outputs_complete(record, folder):
    """True if the record is ok and every file it vouches for exists."""
    solids = record.get("solids")
    if record.get("status") != "ok" or not isinstance(solids, list) or not solids:
        return False
    for s in solids:
        d = os.path.join(folder, "solid_%s" % s.get("solid"))
        names = SOLID_FILES + (("eval.json",) if "eval" in s else ())
        if not all(os.path.isfile(os.path.join(d, n)) for n in names):
            return False
    return True


class ResultsLog:
    """Appends one record per line, each written at once, flushed and fsynced."""

    def __init__(self, path):
        self.path = path
        try:
            self.file = open(path, "a+b")
            self.file.seek(0, os.SEEK_END)
            if self.file.tell() > 0:
                self.file.seek(-1, os.SEEK_END)
                # A killed batch can leave a line without its newline: start afresh.
                if self.file.read(1) != b"\n":
                    self._write(b"\n")
        except OSError as e:
            raise OutputError("cannot open %s: %s" % (path, e.strerror)) from None

    def _write(self, data):
        self.file.write(data)
        self.file.flush()
        os.fsync(self.file.fileno())

    def append(self, record):
        line = json.dumps(record, separators=(",", ":"), ensure_ascii=False) + "\n"
        try:
            self._write(line.encode("utf-8", "replace"))
        except OSError as e:
            raise OutputError("cannot append to %s: %s" % (self.path, e.strerror)) from None

    def close(self):
        self.file.close()
