"""The files a batch works on and where each one's outputs go.

The same rules as `cadmedial batch` (cli/batch_inputs.cpp), so that the C++
batch and the Dask driver can take turns on one OUTDIR:

* a folder: every .step .stp .iges .igs .brep below it (any case, recursive,
  sorted; hidden entries and the output folder skipped); output folder = path
  relative to that folder;
* ``@FILE``, ``*.txt``, ``*.lst``: a manifest, one path per line (blank lines
  and ``#`` comments skipped, relative lines resolved against the manifest's
  folder, folder lines expanded as above); output = path relative to the
  manifest's folder;
* anything else is a model file, even if missing, so it gets its own error
  record; output = path relative to the working folder.

A path outside its base keeps its absolute path minus the leading '/'.
"""

import os

CAD_EXTENSIONS = {".step", ".stp", ".iges", ".igs", ".brep"}
MANIFEST_EXTENSIONS = {".txt", ".lst"}


class UsageError(Exception):
    """Bad inputs: nothing was run (exit code 2)."""


def is_cad_file_name(name):
    return os.path.splitext(name)[1].lower() in CAD_EXTENSIONS


def _absolute(path):
    return os.path.normpath(os.path.abspath(path))


def _output_folder(path, base):
    rel = os.path.relpath(path, base)
    if rel.split(os.sep)[0] == os.pardir:
        return path.lstrip(os.sep)
    return rel


class _Collector:
    def __init__(self, skip_folder):
        self.skip = os.path.realpath(skip_folder) if skip_folder else None
        self.inputs = []  # (path, output)
        self.seen = set()
        self.path_of_output = {}

    def add_argument(self, argument):
        if len(argument) > 1 and argument.startswith("@"):
            return self.add_manifest(argument[1:])
        if os.path.isdir(argument):
            return self.add_folder(_absolute(argument))
        if os.path.splitext(argument)[1].lower() in MANIFEST_EXTENSIONS:
            return self.add_manifest(argument)
        self.add_file(_absolute(argument), os.getcwd())

    def add_file(self, path, base):
        if path in self.seen:
            return
        self.seen.add(path)
        output = _output_folder(path, base)
        other = self.path_of_output.setdefault(output, path)
        if other != path:
            raise UsageError(f"two inputs would share the output folder '{output}': {other} and {path} "
                             "(list them from a common folder or manifest)")
        self.inputs.append((path, output))

    def add_folder(self, folder):
        files = []
        for root, dirs, names in os.walk(folder):
            # Hidden folders (.git, .batch-tmp) and the output folder are never inputs.
            dirs[:] = [d for d in dirs if not d.startswith(".")
                       and not (self.skip and os.path.realpath(os.path.join(root, d)) == self.skip)]
            for name in names:
                full = os.path.join(root, name)
                if not name.startswith(".") and is_cad_file_name(name) and os.path.isfile(full):
                    files.append(os.path.normpath(full))
        # Sorted by path components, as std::filesystem::path compares them.
        for f in sorted(files, key=lambda p: p.split(os.sep)):
            self.add_file(f, folder)

    def add_manifest(self, manifest):
        try:
            with open(manifest, encoding="utf-8", errors="surrogateescape") as f:
                lines = f.read().splitlines()
        except OSError as e:
            raise UsageError(f"cannot read manifest {manifest}: {e.strerror}") from None
        base = os.path.dirname(_absolute(manifest))
        for line in lines:
            entry = line.strip(" \t\r")
            if not entry or entry.startswith("#"):
                continue
            entry = _absolute(os.path.join(base, entry))  # absolute entries stay as they are
            if os.path.isdir(entry):
                self.add_folder(entry)
            else:
                self.add_file(entry, base)


def collect_inputs(arguments, skip_folder=None):
    """[(absolute path, output folder)] for the command-line INPUTs, in order."""
    collector = _Collector(skip_folder)
    for argument in arguments:
        collector.add_argument(argument)
    if not collector.inputs:
        raise UsageError("no input files found (looked for .step .stp .iges .igs .brep)")
    return collector.inputs
