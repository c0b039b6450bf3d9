"""Run by pvpython (ParaView's Python) from test_paraview.py: opens a run's vtk/deploydyn.pvd
and history.xdmf, and for each prints, as one JSON line, the number of time steps, the points,
cells and cell arrays at time T, and the axial force of every cell there; then renders the
xdmf's last time step into PNG.

    pvpython paraview_check.py RUN_FOLDER T PNG
"""
import json
import sys

from paraview import servermanager
from paraview.simple import OpenDataFile, CreateRenderView, Show, ResetCamera, SaveScreenshot, ColorBy
from vtk.numpy_interface import dataset_adapter as dsa

folder, time, png = sys.argv[1], float(sys.argv[2]), sys.argv[3]
result = {}
for name in ("vtk/deploydyn.pvd", "history.xdmf"):
    reader = OpenDataFile(f"{folder}/{name}")
    reader.UpdatePipelineInformation()
    reader.UpdatePipeline(time)
    data = dsa.WrapDataObject(servermanager.Fetch(reader))
    result[name] = {
        "reader": reader.GetXMLName(),
        "times": list(reader.TimestepValues),
        "points": data.GetNumberOfPoints(),
        "cells": data.GetNumberOfCells(),
        "cell_arrays": list(data.CellData.keys()),
        "axial_force_N": [float(v) for v in data.CellData["axial_force_N"]],
        "displacement_m": [[float(c) for c in v] for v in data.PointData["displacement_m"]],
    }
print(json.dumps(result))
view = CreateRenderView()
view.ViewSize = [640, 480]
if hasattr(view, "UseColorPaletteForBackground"):
    view.UseColorPaletteForBackground = 0
view.Background = [1, 1, 1]
view.CameraPosition = [1, 2, 3]
view.CameraViewUp = [0, 1, 0]
view.OrientationAxesVisibility = 0
display = Show(reader, view)
display.LineWidth = 4
ColorBy(display, ("CELLS", "axial_force_N"))
view.ViewTime = result["history.xdmf"]["times"][-1]
ResetCamera(view)
SaveScreenshot(png, view)
