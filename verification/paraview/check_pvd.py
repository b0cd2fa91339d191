"""ParaView's view of a ydry run: what a pvpython client finds in the .pvd, and a picture.

Run it with ParaView's Python, under a virtual display (Debian's pvpython and pvbatch crash
without one, even with --force-offscreen-rendering):

    scripts/virtual_display.py pvpython check_pvd.py RUN/NAME.pvd --json found.json --png last.png --size 1600x400

Opens the .pvd with ParaView's PVDReader, steps through every time value it offers and writes,
as JSON, what ParaView delivers at each: the data's own time, and for each part (0: the solid,
1: the cracks) its numbers of points and cells, its cell types, and for each point and cell
array its components, tuples and whether every value is finite. It judges nothing:
verification/paraview/check.py compares this with the run. Then it renders the last frame to
the PNG: the solid coloured by the point moisture, the crack line cells as thick black lines.
"""
import argparse
import json

import numpy as np
from paraview import servermanager
from paraview.simple import (ColorBy, CreateView, ExtractCellsByType, GetColorTransferFunction,
                             GetScalarBar, PVDReader, SaveScreenshot, Show)
from vtkmodules.util.numpy_support import vtk_to_numpy

CRACK_LINE_WIDTH = 4.0  # pixels


def leaves(block):
    """The datasets under a composite dataset, depth first (the .pvd parts in order)."""
    if not block.IsA("vtkMultiBlockDataSet"):
        return [block]
    return [leaf for b in range(block.GetNumberOfBlocks()) if block.GetBlock(b) is not None
            for leaf in leaves(block.GetBlock(b))]


def arrays(data):
    """{name: {components, tuples, finite}} of a vtkPointData or vtkCellData."""
    found = {}
    for i in range(data.GetNumberOfArrays()):
        a = data.GetArray(i)
        values = vtk_to_numpy(a) if a.GetNumberOfTuples() else np.zeros(0)
        found[a.GetName()] = {"components": a.GetNumberOfComponents(), "tuples": a.GetNumberOfTuples(),
                              "finite": bool(np.all(np.isfinite(values)))}
    return found


def part(grid):
    """One part of a frame: its numbers of points and cells, its cell types and its arrays."""
    types = sorted({grid.GetCellType(c) for c in range(grid.GetNumberOfCells())})
    return {"points": grid.GetNumberOfPoints(), "cells": grid.GetNumberOfCells(), "cell_types": types,
            "point_arrays": arrays(grid.GetPointData()), "cell_arrays": arrays(grid.GetCellData())}


def frames(reader):
    """What ParaView delivers at each of the reader's time values."""
    seen = []
    for time in reader.TimestepValues:
        reader.UpdatePipeline(time)
        data = servermanager.Fetch(reader)
        seen.append({"time": time, "data_time": data.GetInformation().Get(data.DATA_TIME_STEP()),
                     "parts": [part(grid) for grid in leaves(data)]})
    return seen


def render_last_frame(reader, png, size):
    """The solid (triangles) coloured by point moisture (dry red, wet blue), the cracks (lines)
    as thick black lines, the layer filling the width of the picture."""
    time = reader.TimestepValues[-1]
    view = CreateView("RenderView")
    view.ViewSize = size
    view.ViewTime = time
    view.OrientationAxesVisibility = 0
    view.UseColorPaletteForBackground = 0
    view.Background = [1.0, 1.0, 1.0]

    solid = ExtractCellsByType(Input=reader, CellTypes=["Triangle"])
    solid_display = Show(solid, view)
    ColorBy(solid_display, ("POINTS", "moisture"))
    solid_display.RescaleTransferFunctionToDataRange(False, True)
    moisture = GetColorTransferFunction("moisture")
    moisture.InvertTransferFunction()
    bar = GetScalarBar(moisture, view)
    bar.Title, bar.ComponentTitle = f"moisture w at t = {time:g} s", ""
    bar.TitleColor = bar.LabelColor = [0.0, 0.0, 0.0]
    bar.Orientation, bar.WindowLocation = "Horizontal", "Any Location"
    bar.Position, bar.ScalarBarLength = [0.3, 0.12], 0.4
    bar.RangeLabelFormat = "%.3f"
    solid_display.SetScalarBarVisibility(view, True)

    cracks = ExtractCellsByType(Input=reader, CellTypes=["Line"])
    crack_display = Show(cracks, view)
    crack_display.ColorArrayName = ["POINTS", ""]  # a solid colour
    crack_display.AmbientColor = crack_display.DiffuseColor = [0.0, 0.0, 0.0]
    crack_display.LineWidth = CRACK_LINE_WIDTH

    # Looking down z at the layer's centre; the width (with a margin) spans the picture, and
    # the lower part of it is left to the scalar bar.
    solid.UpdatePipeline(time)
    x0, x1, y0, y1, _, _ = solid.GetDataInformation().GetBounds()
    centre = [0.5 * (x0 + x1), 0.5 * (y0 + y1) - 0.1 * (x1 - x0) * size[1] / size[0], 0.0]
    view.CameraFocalPoint = centre
    view.CameraPosition = [centre[0], centre[1], 1.0]
    view.CameraViewUp = [0.0, 1.0, 0.0]
    view.CameraParallelProjection = 1
    view.CameraParallelScale = 0.55 * (x1 - x0) * size[1] / size[0]
    SaveScreenshot(str(png), view, ImageResolution=size)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("pvd")
    parser.add_argument("--json", required=True, help="where to write what ParaView found")
    parser.add_argument("--png", required=True, help="where to render the last frame")
    parser.add_argument("--size", required=True, help="the PNG's size in pixels, WxH")
    args = parser.parse_args()
    reader = PVDReader(FileName=args.pvd)
    found = {"paraview_version": servermanager.vtkSMProxyManager.GetParaViewSourceVersion(),
             "timestep_values": list(reader.TimestepValues), "frames": frames(reader)}
    render_last_frame(reader, args.png, [int(n) for n in args.size.split("x")])
    with open(args.json, "w") as out:
        json.dump(found, out, indent=1)


if __name__ == "__main__":
    main()
