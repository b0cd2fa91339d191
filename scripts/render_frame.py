#!/usr/bin/python3
"""Render one frame of a ydry run to a PNG with VTK, offscreen.

Top panel: the whole deformed solid coloured by the point moisture, with the broken joints
(the cracks part of the .pvd) drawn as magenta lines. Each triangle owns its three corners and
the moisture nodes split where a joint breaks, so the colour can jump across a crack. Bottom
panel: a zoom on the widest crack (the connected cracks around the broken joint of the largest
opening), with the element edges and a scale bar; its box is outlined in the top panel.

    scripts/render_frame.py runs/drying_layer                       # last frame
    scripts/render_frame.py runs/drying_layer --time 60000 --warp 20 --out t60000.png

Debian's VTK renders through X: with no DISPLAY the script renders on a private Xvfb display
(scripts/virtual_display.py, package xvfb).
"""
import contextlib
import os
import sys
from pathlib import Path

import numpy as np
import vtkmodules.vtkRenderingFreeType  # noqa: F401  (text rendering)
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401  (the render window)
from vtkmodules.util.numpy_support import numpy_to_vtk, vtk_to_numpy
from vtkmodules.vtkCommonCore import vtkPoints
from vtkmodules.vtkCommonDataModel import vtkCellArray, vtkDataObject, vtkPolyData
from vtkmodules.vtkFiltersCore import vtkCleanPolyData, vtkPolyDataConnectivityFilter
from vtkmodules.vtkFiltersGeneral import vtkWarpVector
from vtkmodules.vtkFiltersGeometry import vtkGeometryFilter
from vtkmodules.vtkIOImage import vtkPNGWriter
from vtkmodules.vtkRenderingAnnotation import vtkScalarBarActor
from vtkmodules.vtkRenderingCore import (vtkActor, vtkColorTransferFunction, vtkDataSetMapper,
                                         vtkPolyDataMapper, vtkRenderer, vtkRenderWindow,
                                         vtkTextActor, vtkWindowToImageFilter)

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "verification"))
import virtual_display  # noqa: E402  (beside this script)
import ydry_case  # noqa: E402  (script_parser, frames, read_grid, corners, crack_displacement)

CRACK_COLOR = (1.0, 0.0, 1.0)
# Moisture: dry brown through pale sand to wet dark blue.
MOISTURE_COLORS = ((0.0, (0.45, 0.22, 0.05)), (0.35, (0.93, 0.80, 0.55)),
                   (0.7, (0.35, 0.60, 0.80)), (1.0, (0.03, 0.15, 0.40)))
TOP, ZOOM = (0.0, 0.66, 1.0, 0.90), (0.0, 0.0, 0.84, 0.62)  # viewports (x0, y0, x1, y1)


def arguments():
    parser = ydry_case.script_parser(__doc__)
    parser.add_argument("run", type=Path, help="run folder (ydry -o) or its .pvd")
    parser.add_argument("--time", type=float, help="time in s; the nearest frame (default: the last)")
    parser.add_argument("--warp", type=float, default=1.0,
                        help="displacement magnification (default 1: the true deformed shape)")
    parser.add_argument("--size", default="1600x1000", help="image size WxH in pixels (default 1600x1000)")
    parser.add_argument("--out", type=Path, help="PNG to write (default: NAME_tTIME.png in the run folder)")
    return parser.parse_args()


@contextlib.contextmanager
def display_for_rendering():
    """An X render window needs a display: without one, a private Xvfb for as long as this lasts."""
    if os.environ.get("DISPLAY") or vtkRenderWindow().GetClassName() != "vtkXOpenGLRenderWindow":
        yield
        return
    try:
        with virtual_display.virtual_display() as display:
            os.environ["DISPLAY"] = display
            try:
                yield
            finally:
                del os.environ["DISPLAY"]  # the server stops here
    except virtual_display.DisplayError as error:
        sys.exit(f"render_frame: no DISPLAY, and {error}")


def warped(grid, warp):
    """grid moved by (warp - 1) times its point displacement (its points are the deformed ones)."""
    if warp == 1.0:
        return grid
    filt = vtkWarpVector()
    filt.SetInputData(grid)
    filt.SetInputArrayToProcess(0, 0, 0, vtkDataObject.FIELD_ASSOCIATION_POINTS, "displacement")
    filt.SetScaleFactor(warp - 1.0)
    filt.Update()
    return filt.GetOutput()


def widest_crack(cracks, merge):
    """Bounds (x0, x1, y0, y1) of the connected crack lines around the widest broken joint,
    line ends within `merge` counted as one; that joint's opening and its end points."""
    opening = vtk_to_numpy(cracks.GetCellData().GetArray("opening"))
    widest = int(np.argmax(opening))
    ends = np.array([cracks.GetPoint(cracks.GetCell(widest).GetPointId(k)) for k in (0, 1)])
    centre = ends.mean(axis=0)
    filters = (vtkGeometryFilter(), vtkCleanPolyData(), vtkPolyDataConnectivityFilter())
    filters[0].SetInputData(cracks)
    filters[1].ToleranceIsAbsoluteOn()
    filters[1].SetAbsoluteTolerance(merge)
    filters[2].SetExtractionModeToClosestPointRegion()
    filters[2].SetClosestPoint(*centre)
    for upstream, downstream in zip(filters, filters[1:]):
        downstream.SetInputConnection(upstream.GetOutputPort())
    filters[2].Update()
    return filters[2].GetOutput().GetBounds()[:4], opening[widest], ends


def polyline_actor(xy, color, width, z=1e-5):
    points = vtkPoints()
    for x, y in xy:
        points.InsertNextPoint(x, y, z)
    lines = vtkCellArray()
    lines.InsertNextCell(len(xy), list(range(len(xy))))
    poly = vtkPolyData()
    poly.SetPoints(points)
    poly.SetLines(lines)
    mapper = vtkPolyDataMapper()
    mapper.SetInputData(poly)
    actor = vtkActor()
    actor.SetMapper(mapper)
    actor.GetProperty().SetColor(color)
    actor.GetProperty().SetLineWidth(width)
    return actor


def text_actor(text, x, y, size, bold=False):
    """Text at (x, y) in the normalised coordinates of its renderer's viewport."""
    actor = vtkTextActor()
    actor.SetInput(text)
    actor.GetPositionCoordinate().SetCoordinateSystemToNormalizedViewport()
    actor.SetPosition(x, y)
    prop = actor.GetTextProperty()
    prop.SetFontSize(size)
    prop.SetColor(0.0, 0.0, 0.0)
    prop.SetBold(bold)
    return actor


def aspect(window, viewport):
    """Width over height of a viewport (x0, y0, x1, y1) of the window, in pixels."""
    width, height = window.GetSize()
    return (viewport[2] - viewport[0]) * width / ((viewport[3] - viewport[1]) * height)


def panel(window, viewport, bulk, cracks, colors, edges, line_width, box):
    """A renderer over `viewport` showing bulk and cracks, its camera fitting box (x0, x1, y0, y1)."""
    renderer = vtkRenderer()
    renderer.SetViewport(viewport)
    renderer.SetBackground(1.0, 1.0, 1.0)
    mapper = vtkDataSetMapper()
    mapper.SetInputData(bulk)
    mapper.SetScalarModeToUsePointFieldData()
    mapper.SelectColorArray("moisture")
    mapper.SetLookupTable(colors)
    mapper.UseLookupTableScalarRangeOn()
    mapper.InterpolateScalarsBeforeMappingOn()
    actor = vtkActor()
    actor.SetMapper(mapper)
    actor.GetProperty().SetEdgeVisibility(edges)
    actor.GetProperty().SetEdgeColor(0.35, 0.35, 0.35)
    renderer.AddActor(actor)
    crack_mapper = vtkDataSetMapper()
    crack_mapper.SetInputData(cracks)
    crack_mapper.ScalarVisibilityOff()
    crack_actor = vtkActor()
    crack_actor.SetMapper(crack_mapper)
    crack_actor.SetPosition(0.0, 0.0, 1e-5)  # in front of the solid
    crack_actor.GetProperty().SetColor(CRACK_COLOR)
    crack_actor.GetProperty().SetLineWidth(line_width)
    renderer.AddActor(crack_actor)
    # Parallel projection; the box fills the viewport's width or its height.
    camera = renderer.GetActiveCamera()
    camera.ParallelProjectionOn()
    cx, cy = 0.5 * (box[0] + box[1]), 0.5 * (box[2] + box[3])
    camera.SetFocalPoint(cx, cy, 0.0)
    camera.SetPosition(cx, cy, 1.0)
    camera.SetViewUp(0.0, 1.0, 0.0)
    camera.SetParallelScale(max(0.5 * (box[3] - box[2]), 0.5 * (box[1] - box[0]) / aspect(window, viewport)))
    renderer.ResetCameraClippingRange()
    window.AddRenderer(renderer)
    return renderer


def moisture_colors(w):
    """MOISTURE_COLORS spread over the range of w."""
    colors = vtkColorTransferFunction()
    colors.SetColorSpaceToLab()
    low, high = np.nanmin(w), np.nanmax(w)
    for f, rgb in MOISTURE_COLORS:
        colors.AddRGBPoint(low + f * (high - low), *rgb)
    colors.SetNanColor(0.7, 0.7, 0.7)
    return colors


def add_overlay(window, title, colors):
    """A renderer over the whole window with the title and the colour bar; the panels, added
    after it, draw over it."""
    overlay = vtkRenderer()
    overlay.SetBackground(1.0, 1.0, 1.0)
    overlay.AddActor(text_actor(title, 0.5, 0.94, 26, bold=True))
    overlay.GetActors2D().GetLastActor2D().GetTextProperty().SetJustificationToCentered()
    bar = vtkScalarBarActor()
    bar.SetLookupTable(colors)
    bar.SetTitle("moisture w (-)\n")
    bar.SetNumberOfLabels(6)
    bar.SetLabelFormat("%.3f")
    bar.UnconstrainedFontSizeOn()
    bar.GetPositionCoordinate().SetCoordinateSystemToNormalizedViewport()
    bar.SetPosition(0.87, 0.05)
    bar.SetWidth(0.1)
    bar.SetHeight(0.5)
    for prop, size in ((bar.GetTitleTextProperty(), 20), (bar.GetLabelTextProperty(), 18)):
        prop.SetFontSize(size)
        prop.SetColor(0.0, 0.0, 0.0)
        prop.ItalicOff()
        prop.ShadowOff()
    overlay.AddActor2D(bar)
    window.AddRenderer(overlay)


def add_zoom(window, top, bulk, cracks, colors, warp):
    """The zoom panel on the widest crack, its box outlined in the top panel."""
    x = vtk_to_numpy(bulk.GetPoints().GetData())[:, :2]
    shortest_edge = np.min(np.linalg.norm(x[1::3] - x[0::3], axis=1))
    (c0, c1, c2, c3), opening, ends = widest_crack(cracks, 0.25 * shortest_edge)
    w = vtk_to_numpy(bulk.GetPointData().GetArray("moisture"))
    jump = max(np.ptp(w[ids]) for ids in ydry_case.corners(bulk, ends, warp))
    y0, y1 = bulk.GetBounds()[2:4]
    half_height = 0.6 * max(c3 - c2, 0.2 * (y1 - y0))
    half_width = half_height * aspect(window, ZOOM)
    box = (0.5 * (c0 + c1) - half_width, 0.5 * (c0 + c1) + half_width,
           0.5 * (c2 + c3) - half_height, 0.5 * (c2 + c3) + half_height)
    zoom = panel(window, ZOOM, bulk, cracks, colors, True, 3.0, box)
    b0, b1 = max(box[2], y0), min(box[3], y1)  # the outline within the solid's height
    top.AddActor(polyline_actor([(box[0], b0), (box[1], b0), (box[1], b1), (box[0], b1), (box[0], b0)],
                                (0.0, 0.0, 0.0), 1.5))
    zoom.AddActor(text_actor(f"zoom on the widest crack at x = {1e3 * 0.5 * (c0 + c1):.1f} mm: "
                             f"largest opening {1e3 * opening:.3f} mm, moisture jump across it "
                             f"{jump:.2g}; element edges in grey", 0.01, 0.95, 18))
    # Scale bar: 1, 2 or 5 x 10^n m, at most a sixth of the box width.
    decade = 10.0 ** np.floor(np.log10((box[1] - box[0]) / 6.0))
    length = max(m * decade for m in (1, 2, 5) if m * decade <= (box[1] - box[0]) / 6.0)
    bx, by = box[0] + 0.03 * (box[1] - box[0]), box[2] + 0.05 * (box[3] - box[2])
    zoom.AddActor(polyline_actor([(bx, by), (bx + length, by)], (0.0, 0.0, 0.0), 4.0))
    zoom.AddActor(text_actor(f"{1e3 * length:g} mm", 0.03, 0.07, 16))


def write_png(window, path):
    image = vtkWindowToImageFilter()
    image.SetInput(window)
    image.Update()
    writer = vtkPNGWriter()
    writer.SetFileName(str(path))
    writer.SetCompressionLevel(9)
    writer.SetInputConnection(image.GetOutputPort())
    writer.Write()


def render(args):
    """Render the frame args ask for to its PNG; return the PNG's path and the frame's time."""
    pvd = args.run if args.run.suffix == ".pvd" else next(args.run.glob("*.pvd"))
    frames = ydry_case.frames(pvd)
    time = max(frames) if args.time is None else min(frames, key=lambda t: abs(t - args.time))
    bulk = ydry_case.read_grid(frames[time][0])
    cracks = ydry_case.read_grid(frames[time][1])
    if args.warp != 1.0 and cracks.GetNumberOfPoints():
        cracks.GetPointData().AddArray(numpy_to_vtk(ydry_case.crack_displacement(bulk, cracks), deep=True))
        cracks.GetPointData().GetArray(0).SetName("displacement")
    bulk, cracks = warped(bulk, args.warp), warped(cracks, args.warp)
    colors = moisture_colors(vtk_to_numpy(bulk.GetPointData().GetArray("moisture")))

    window = vtkRenderWindow()
    window.SetOffScreenRendering(1)
    window.SetSize(*(int(v) for v in args.size.lower().split("x")))
    window.SetDPI(round(72 * window.GetSize()[0] / 1600))  # the text sizes are for 1600 px wide
    add_overlay(window, f"{pvd.stem}: t = {time / 3600.0:.2f} h ({time:g} s), "
                        f"displacements x{args.warp:g}", colors)
    x0, x1, y0, y1 = bulk.GetBounds()[:4]
    top = panel(window, TOP, bulk, cracks, colors, False, 3.0,
                (x0 - 0.01 * (x1 - x0), x1 + 0.01 * (x1 - x0), y0, y1))
    top.AddActor(text_actor(f"whole solid, {1e3 * (x1 - x0):.1f} mm x {1e3 * (y1 - y0):.1f} mm"
                            f"; broken joints (magenta): {cracks.GetNumberOfCells()}", 0.01, 0.86, 18))
    if cracks.GetNumberOfCells():
        add_zoom(window, top, bulk, cracks, colors, args.warp)
    window.Render()
    out = args.out or pvd.parent / f"{pvd.stem}_t{time:g}.png"
    write_png(window, out)
    return out, time


def main():
    args = arguments()
    with display_for_rendering():
        out, time = render(args)
    print(f"render_frame: {out} (t = {time:g} s)")


if __name__ == "__main__":
    main()
