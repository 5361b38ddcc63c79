"""cadmedial: inner medial axes of CAD solids (CAD_MEDIAL) from Python and FreeCAD.

Headless use (freecadcmd, or plain python3 after plugin/install.sh)::

    import cadmedial
    for axis in cadmedial.compute("models/flange.step", spacing=2.0):
        print(axis.sheet_count, axis.summary["topology"])
        axis.write("flange_medial.ply")
        report = cadmedial.evaluate("models/flange.step", axis)   # exact-geometry metrics
        print("\n".join(cadmedial.evaluation_lines(report)))

    # inside FreeCAD: a Part shape or a document object works as well
    results = cadmedial.compute(doc.Box.Shape)
    medial = cadmedial.add_to_document(doc, doc.Box)   # parametric objects

    # pair-mesh (B-rep solids): tetrahedra between the inner Voronoi diagram and the boundary
    (axis,) = cadmedial.compute("models/box.step", pair_mesh=True)
    pm = axis.pair_mesh                                  # PairMesh: nodes, tets, types, ...
    print(pm.validity["inverted"], pm.validity["enclosed_volume"], pm.validity["exact_volume"])
    points, triangles = cadmedial.iso_surface(pm, 0.5)
    pm.write("box_pairmesh.vtu")

    # point clouds and meshes (MEDIAL, seed 000): arrays, files, Points/Mesh objects
    axis = cadmedial.compute_points("scan.xyz")[0]       # whole axis
    axis = cadmedial.compute("part.stl")[0]              # closed mesh: inner axis

``compute`` and ``sample`` need no FreeCAD; ``add_to_document`` and the
objects in ``cadmedial.document`` do.
"""

from .api import (
    Cancelled,
    InputError,
    PAIR_ELEMENT_TYPES,
    MedialAxisResult,
    PairMesh,
    SampleResult,
    compute,
    compute_points,
    estimate_samples,
    evaluate,
    evaluation_lines,
    inspect,
    solids_brep,
    iso_surface,
    point_source,
    sample,
    to_source,
)
from .export import EXPORT_FORMATS, write_medial

__all__ = [
    "Cancelled",
    "EXPORT_FORMATS",
    "InputError",
    "MedialAxisResult",
    "PAIR_ELEMENT_TYPES",
    "PairMesh",
    "SampleResult",
    "add_pair_mesh",
    "add_to_document",
    "compute",
    "compute_points",
    "estimate_samples",
    "evaluate",
    "evaluation_lines",
    "inspect",
    "solids_brep",
    "iso_surface",
    "point_source",
    "sample",
    "sync_sheets",
    "to_source",
    "write_medial",
]

__version__ = "0.1.0"


def add_to_document(doc, source, spacing=0.0, theta=None, rho=8.0, **options):
    """Parametric MedialAxis objects for every solid of `source` (a document
    object with a Shape); returns the list of created objects. See
    cadmedial.document.add_to_document."""
    from . import document

    return document.add_to_document(doc, source, spacing=spacing, theta=theta, rho=rho, **options)


def add_pair_mesh(doc, source, spacing=None, theta=None, rho=None, **options):
    """Parametric PairMesh objects (FEM meshes) for the solids of `source` (a
    solid object or a MedialAxis object); returns them. See
    cadmedial.pair_document.add_pair_mesh."""
    from . import pair_document

    return pair_document.add_pair_mesh(doc, source, spacing=spacing, theta=theta, rho=rho, **options)


def sync_sheets(medial_obj):
    """Creates / removes the per-sheet child objects of a MedialAxis object so
    they match its last result (done automatically after each recompute)."""
    from . import document

    return document.sync_sheets(medial_obj)
