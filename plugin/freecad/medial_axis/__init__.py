"""FreeCAD addon "Medial Axis" (namespace package freecad.medial_axis).

FreeCAD imports this package at start-up (freecadcmd and GUI); the GUI part
is in init_gui.py. The computation and the document objects are in the
plain package `cadmedial`, which sits next to `freecad/` in the addon folder.
"""

import os

__version__ = "0.1.0"

PACKAGE_DIR = os.path.dirname(os.path.realpath(__file__))
ICON_DIR = os.path.join(PACKAGE_DIR, "resources", "icons")


def icon(name):
    return os.path.join(ICON_DIR, name)
