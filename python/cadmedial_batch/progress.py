"""Progress and summary, worded as `cadmedial batch` does (cli/batch_progress.cpp):
on a terminal one line redrawn in place with failures printed above it, in a
log one plain line per file; a summary table at the end."""

import time

STATUSES = ("ok", "error", "timeout", "crash", "oom")
FAILURES_LISTED = 20


def _clock(seconds):
    s = int(seconds + 0.5)
    return "%d:%02d:%02d" % (s // 3600, s // 60 % 60, s % 60) if s >= 3600 else "%d:%02d" % (s // 60, s % 60)


class Progress:
    def __init__(self, out, redraw, to_run, skipped):
        self.out, self.redraw, self.to_run, self.skipped = out, redraw, to_run, skipped
        self.done = 0
        self.counts = dict.fromkeys(STATUSES, 0)
        self.failure_lines = []
        self.start = time.monotonic()
        self.last_draw = 0.0
        self.line_shown = False
        if skipped:
            print("resume: %d file(s) already done, %d to run" % (skipped, to_run), file=out, flush=True)

    @property
    def failures(self):
        return self.done - self.counts["ok"]

    def _clear_line(self):
        if self.line_shown:
            self.out.write("\r\033[K")
        self.line_shown = False

    def file_done(self, r):
        self.done += 1
        self.counts[r["status"]] += 1
        failed = r["status"] != "ok"
        wall = r.get("wall_seconds")
        line = "[%d/%d] %-7s %ss  %s" % (self.done, self.to_run, r["status"],
                                         "%7.1f" % wall if wall is not None else "%7s" % "?", r["output"])
        if failed:
            line += ": " + r["message"]
            self.failure_lines.append("%s  %s: %s" % (r["status"], r["output"], r["message"]))
        if self.redraw and not failed:
            return
        self._clear_line()
        print(line, file=self.out, flush=True)
        self.last_draw = 0.0

    def refresh(self, running):
        now = time.monotonic()
        if not self.redraw or now - self.last_draw < 0.5:
            return
        self.last_draw = now
        elapsed = now - self.start
        per_minute = 60.0 * self.done / elapsed if elapsed > 0 else 0.0
        eta = _clock((self.to_run - self.done) * elapsed / self.done) if self.done else "?"
        self._clear_line()
        self.out.write("[%d/%d] %d failed | %.1f files/min | ETA %s | %d running | %s elapsed"
                       % (self.done, self.to_run, self.failures, per_minute, eta, running, _clock(elapsed)))
        self.out.flush()
        self.line_shown = True

    def print_summary(self, results_path, interrupted):
        self._clear_line()
        elapsed = time.monotonic() - self.start
        w = self.out.write
        w("\nbatch %s: %d of %d file(s) in %s, %.1f files/min\n" % (
            "interrupted" if interrupted else "done", self.done, self.to_run, _clock(elapsed),
            60.0 * self.done / elapsed if elapsed > 0 else 0.0))
        w("  %-9s %8s\n" % ("status", "files"))
        for s in STATUSES:
            w("  %-9s %8d\n" % (s, self.counts[s]))
        if self.skipped:
            w("  %-9s %8d  (ok in an earlier run, --resume)\n" % ("skipped", self.skipped))
        if interrupted:
            w("  %-9s %8d  (finish with --resume)\n" % ("not done", self.to_run - self.done))
        if self.failure_lines:
            w("failures:\n")
            for line in self.failure_lines[:FAILURES_LISTED]:
                w("  %s\n" % line)
            if len(self.failure_lines) > FAILURES_LISTED:
                w("  ... and %d more\n" % (len(self.failure_lines) - FAILURES_LISTED))
        w("records: %s\n" % results_path)
        self.out.flush()
