"""Writing medial axes: PLY (binary; radius per vertex, sheet and provenance
per polygon), OBJ (groups per sheet) and .ma (Q-MAT). OBJ and .ma use the
command line's writers (cli/medial_writers.cpp). Every file is written under a
temporary name and renamed when complete."""

import os

import numpy as np

from . import _native

EXPORT_FORMATS = {
    "ply": "PLY, binary: vertices with radius, polygons with sheet and provenance",
    "obj": "Wavefront OBJ: polygons grouped per sheet (radius as a comment per vertex)",
    "ma": "Q-MAT / MATFP medial mesh: v x y z r, e i j, f i j k",
}


def _format_of(path, format):
    if format:
        fmt = format.lower().lstrip(".")
    else:
        fmt = os.path.splitext(os.fspath(path))[1].lower().lstrip(".")
    if fmt not in EXPORT_FORMATS:
        raise ValueError(f"unknown export format '{fmt or path}': expected one of .ply .obj .ma")
    return fmt


def _ply_bytes(result):
    vertices = np.ascontiguousarray(result.vertices, dtype="<f8").reshape(-1, 3)
    radius = np.ascontiguousarray(result.radius, dtype="<f8")
    offsets = np.asarray(result.offsets, dtype=np.int64)
    indices = np.asarray(result.indices, dtype="<i4")
    sheet = np.asarray(result.sheet, dtype="<i4")
    provenance = np.asarray(result.provenance, dtype=np.uint8)
    sizes = np.diff(offsets)
    count_type, count_dtype = ("uchar", np.uint8) if sizes.size == 0 or sizes.max() < 256 else ("uint", np.dtype("<u4"))
    count_bytes = np.dtype(count_dtype).itemsize

    header = (
        "ply\nformat binary_little_endian 1.0\ncomment cadmedial inner medial axis\n"
        f"element vertex {vertices.shape[0]}\n"
        "property double x\nproperty double y\nproperty double z\nproperty double radius\n"
        f"element face {sizes.size}\n"
        f"property list {count_type} int vertex_indices\nproperty int sheet\nproperty uchar provenance\n"
        "end_header\n"
    ).encode("ascii")

    vertex_block = np.empty((vertices.shape[0], 4), dtype="<f8")
    vertex_block[:, :3] = vertices
    vertex_block[:, 3] = radius

    # Face records: count, indices (int32 each), sheet (int32), provenance (uint8).
    record = count_bytes + 4 * sizes + 5
    start = np.concatenate([[0], np.cumsum(record)[:-1]]).astype(np.int64)
    buffer = np.zeros(int(record.sum()), dtype=np.uint8)
    counts = sizes.astype(count_dtype).view(np.uint8).reshape(-1, count_bytes)
    buffer[(start[:, None] + np.arange(count_bytes)).reshape(-1)] = counts.reshape(-1)
    polygon_of_slot = np.repeat(np.arange(sizes.size), sizes)
    slot_in_polygon = np.arange(indices.size) - offsets[:-1][polygon_of_slot]
    slot_pos = start[polygon_of_slot] + count_bytes + 4 * slot_in_polygon
    buffer[(slot_pos[:, None] + np.arange(4)).reshape(-1)] = indices.view(np.uint8)
    tail = start + count_bytes + 4 * sizes
    buffer[(tail[:, None] + np.arange(4)).reshape(-1)] = sheet.view(np.uint8)
    buffer[tail + 4] = provenance
    return header + vertex_block.tobytes() + buffer.tobytes()


def _write_atomically(path, data):
    path = os.fspath(path)
    directory = os.path.dirname(os.path.abspath(path))
    temporary = os.path.join(directory, f".{os.path.basename(path)}.tmp-{os.getpid()}")
    try:
        with open(temporary, "wb") as f:
            f.write(data)
        os.replace(temporary, path)
    except BaseException:
        try:
            os.remove(temporary)
        except OSError:
            pass
        raise


def write_medial(result, path, format=None):
    """Writes `result` (a MedialAxisResult, or anything with vertices, radius,
    offsets, indices, sheet, provenance) to `path`; the format comes from
    `format` or the extension (.ply, .obj, .ma). Returns the path."""
    fmt = _format_of(path, format)
    if fmt == "ply":
        _write_atomically(path, _ply_bytes(result))
    else:
        _native.write_medial(
            os.fspath(path), fmt, result.vertices, result.radius, result.offsets, result.indices, result.sheet
        )
    return os.fspath(path)


def read_ply(path):
    """Reads a PLY written by write_medial back into a dict of arrays (for tests)."""
    with open(path, "rb") as f:
        data = f.read()
    end = data.index(b"end_header\n") + len(b"end_header\n")
    header = data[:end].decode("ascii").splitlines()
    nv = int(next(line.split()[2] for line in header if line.startswith("element vertex")))
    nf = int(next(line.split()[2] for line in header if line.startswith("element face")))
    wide = any(line.startswith("property list uint") for line in header)
    body = memoryview(data)[end:]
    vertex_block = np.frombuffer(body[: nv * 32], dtype="<f8").reshape(nv, 4)
    pos = nv * 32
    offsets, indices, sheet, provenance = [0], [], [], []
    for _ in range(nf):
        if wide:
            k = int(np.frombuffer(body[pos : pos + 4], dtype="<u4")[0])
            pos += 4
        else:
            k = body[pos]
            pos += 1
        indices.extend(np.frombuffer(body[pos : pos + 4 * k], dtype="<i4").tolist())
        pos += 4 * k
        sheet.append(int(np.frombuffer(body[pos : pos + 4], dtype="<i4")[0]))
        provenance.append(body[pos + 4])
        pos += 5
        offsets.append(len(indices))
    return {
        "vertices": vertex_block[:, :3].copy(),
        "radius": vertex_block[:, 3].copy(),
        "offsets": np.array(offsets),
        "indices": np.array(indices),
        "sheet": np.array(sheet),
        "provenance": np.array(provenance, dtype=np.uint8),
    }
