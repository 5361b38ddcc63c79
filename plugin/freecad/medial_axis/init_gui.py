"""The "Medial Axis" workbench (loaded by FreeCAD's GUI at start-up)."""

import FreeCADGui as Gui

from . import icon


class MedialAxisWorkbench(Gui.Workbench):
    MenuText = "Medial Axis"
    ToolTip = "Inner medial axes of CAD solids (CAD_MEDIAL) as parametric medial sheets"
    Icon = icon("MedialAxisWorkbench.svg")

    def GetClassName(self):
        return "Gui::PythonWorkbench"

    def Initialize(self):
        from . import commands

        commands.register()
        self.appendToolbar("Medial Axis", commands.TOOLBAR)
        self.appendMenu("&Medial Axis", commands.MENU)

    def Activated(self):
        return None

    def Deactivated(self):
        return None

    def ContextMenu(self, recipient):
        from . import commands

        if recipient == "Tree":
            self.appendContextMenu("Medial Axis", commands.CONTEXT_MENU)


Gui.addWorkbench(MedialAxisWorkbench())
