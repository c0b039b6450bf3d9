#!/usr/bin/python3
"""Reads a deploydyn ParaView time series with VTK itself (the vtkmodules of Debian's python3-paraview), an
independent reader for tests/output/vtk_writer_test.cpp, and prints what it read as JSON:

  {"vtk_version": "9.1.0",
   "frames": [{"file": ..., "timestep": t from the .pvd, "time_value": the frame's TimeValue,
               "points": [[x, y, z], ...], "cells": [[i, j], ...], "cell_types": [3, ...],
               "point_vectors": active vectors' name, "cell_scalars": active scalars' name,
               "point_data": {name: {"type": "double", "tuples": [[...], ...]}, ...,
                              name: {"type": "string", "values": [...]} for String arrays},
               "cell_data": {...}}, ...]}

Usage: read_vtu.py COLLECTION.pvd. The collection is parsed with VTK's XML parser and every
frame it names with vtkXMLUnstructuredGridReader; any error or warning VTK reports, or a
collection that is not a VTKFile of type Collection, ends the script with exit code 1.
"""

import json
import os
import sys

from vtkmodules.vtkCommonCore import vtkVersion
from vtkmodules.vtkIOXML import vtkXMLUnstructuredGridReader
from vtkmodules.vtkIOXMLParser import vtkXMLDataParser


def fail(message):
    print(f"read_vtu.py: {message}", file=sys.stderr)
    sys.exit(1)


def fail_on_messages(vtk_object, what):
    def report(_caller, event):
        fail(f"VTK reported an {event} while reading {what}")

    vtk_object.AddObserver("ErrorEvent", report)
    vtk_object.AddObserver("WarningEvent", report)


def collection_entries(pvd):
    parser = vtkXMLDataParser()
    parser.SetFileName(pvd)
    fail_on_messages(parser, pvd)
    if not parser.Parse():
        fail(f"{pvd}: not well-formed XML")
    root = parser.GetRootElement()
    if root.GetName() != "VTKFile" or root.GetAttribute("type") != "Collection":
        fail(f"{pvd}: root is <{root.GetName()} type={root.GetAttribute('type')}>, not a VTKFile Collection")
    if root.GetNumberOfNestedElements() != 1 or root.GetNestedElement(0).GetName() != "Collection":
        fail(f"{pvd}: a VTKFile Collection holds exactly one <Collection>")
    collection = root.GetNestedElement(0)
    entries = []
    for i in range(collection.GetNumberOfNestedElements()):
        entry = collection.GetNestedElement(i)
        if entry.GetName() != "DataSet":
            fail(f"{pvd}: <{entry.GetName()}> in <Collection>; only <DataSet> is allowed")
        entries.append((entry.GetAttribute("file"), float(entry.GetAttribute("timestep"))))
    return entries


def arrays(data):
    out = {}
    for i in range(data.GetNumberOfArrays()):
        array = data.GetAbstractArray(i)
        if array.IsA("vtkStringArray"):  # names: {"type": "string", "values": [...]}
            values = [array.GetValue(k) for k in range(array.GetNumberOfValues())]
            out[array.GetName()] = {"type": "string", "values": values}
            continue
        tuples = [list(array.GetTuple(k)) for k in range(array.GetNumberOfTuples())]
        out[array.GetName()] = {"type": array.GetDataTypeAsString(), "tuples": tuples}
    return out


def read_frame(path):
    reader = vtkXMLUnstructuredGridReader()
    fail_on_messages(reader, path)
    reader.SetFileName(path)
    reader.Update()
    grid = reader.GetOutput()
    cells = []
    for c in range(grid.GetNumberOfCells()):
        ids = grid.GetCell(c).GetPointIds()
        cells.append([ids.GetId(k) for k in range(ids.GetNumberOfIds())])
    time_value = grid.GetFieldData().GetArray("TimeValue")
    vectors = grid.GetPointData().GetVectors()
    scalars = grid.GetCellData().GetScalars()
    return {
        "time_value": time_value.GetValue(0) if time_value is not None else None,
        "points": [list(grid.GetPoint(p)) for p in range(grid.GetNumberOfPoints())],
        "cells": cells,
        "cell_types": [grid.GetCellType(c) for c in range(grid.GetNumberOfCells())],
        "point_vectors": vectors.GetName() if vectors is not None else None,
        "cell_scalars": scalars.GetName() if scalars is not None else None,
        "point_data": arrays(grid.GetPointData()),
        "cell_data": arrays(grid.GetCellData()),
    }


def main():
    if len(sys.argv) != 2:
        fail("usage: read_vtu.py COLLECTION.pvd")
    pvd = sys.argv[1]
    frames = []
    for name, timestep in collection_entries(pvd):
        frame = read_frame(os.path.join(os.path.dirname(pvd), name))
        frame.update({"file": name, "timestep": timestep})
        frames.append(frame)
    # json writes each float in its shortest exact form: nothing is lost on the way.
    json.dump({"vtk_version": vtkVersion.GetVTKVersion(), "frames": frames}, sys.stdout)


if __name__ == "__main__":
    main()
