"""Shared helpers for the verification check scripts and the scripts that read runs.

The demo deck and the overrides that make it crack early (for short runs: paraview and
tests/test_plot_run.py). Run ydry on a deck into an output folder, read its CSV files into
dicts of numpy arrays, list the frames of its .pvd and read them (any frame, or the last one,
as arrays), find the displacement of the crack lines, and print the suite verdict lines
`CASE METRIC VALUE TOLERANCE PASS|FAIL` while remembering whether any failed. Used by
shrinkage, fracture_modeI, fracture_modeII, crack_moisture, the contact cases (strip1d keeps
its own copy), peron and paraview, and by scripts/render_frame.py, scripts/plot_run.py and
run_report.py.
"""
import argparse
import json
import subprocess
import sys
import time
import xml.etree.ElementTree as ET
from pathlib import Path

import numpy as np
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkCommonDataModel import vtkStaticPointLocator
from vtkmodules.vtkIOXML import vtkXMLUnstructuredGridReader

REPO = Path(__file__).resolve().parents[1]
DEMO_DECK = REPO / "inputs" / "demo" / "drying_layer.toml"
# --set overrides that make the demo's soil crack early, for short test runs: a 4 mm mesh
# (300 triangles), shrinkage coefficient 0.4 and gf_I 0.02 J/m^2 (cracks from the first 2000 s).
DEMO_EARLY_CRACKING = ["mesh.element_size=0.004", "materials.soil.shrinkage_coefficient=0.4",
                       "materials.soil.gf_I=0.02"]


# --set overrides a check script was given, added to every run it makes (run_ydry): the same
# case checked with other solver controls, e.g. --set solver.relaxation=newton.
EXTRA_OVERRIDES = []


def case_parser(doc, here):
    """An argument parser for a check script: --ydry, --out (default: build/ydry and the
    case's out/) and --set (overrides added to every run); a case adds its own arguments."""
    parser = argparse.ArgumentParser(description=doc.splitlines()[0])
    parser.add_argument("--ydry", type=Path, default=REPO / "build" / "ydry")
    parser.add_argument("--out", type=Path, default=here / "out")
    parser.add_argument("--set", action="append", default=[], metavar="KEY=VALUE",
                        help="a deck override added to every run of the case (repeatable)")
    return parser


def parse_case_arguments(parser):
    """Parse a case's arguments; its --set overrides go to every run_ydry."""
    args = parser.parse_args()
    EXTRA_OVERRIDES[:] = args.set
    return args


def arguments(doc, here):
    """Parse --ydry, --out and --set (case_parser); create --out."""
    args = parse_case_arguments(case_parser(doc, here))
    args.out.mkdir(parents=True, exist_ok=True)
    return args


def script_parser(doc):
    """An argument parser for a script whose docstring is `doc`: its first line describes the
    script, the rest (examples) ends the --help text as written."""
    return argparse.ArgumentParser(description=doc.splitlines()[0],
                                   formatter_class=argparse.RawDescriptionHelpFormatter,
                                   epilog="\n".join(doc.splitlines()[2:]))


def test_arguments(doc):
    """The arguments of a script test run by ctest (tests/test_*.py): --ydry (default
    build/ydry)."""
    parser = argparse.ArgumentParser(description=doc.splitlines()[0])
    parser.add_argument("--ydry", type=Path, default=REPO / "build" / "ydry")
    return parser.parse_args()


def failed(failures):
    """Prints `FAIL: ...` for each failure of a script test; its exit code."""
    for failure in failures:
        print(f"FAIL: {failure}")
    return 1 if failures else 0


def sweep_and_plot(sweep_files, out, plots, ydry):
    """A script test's sweeps: scripts/sweep.py on the files into `out` (2 runs at a time, 1
    thread each), then scripts/plot_sweep.py on `out` into `plots`, their output printed.
    Returns the failures: [] where both exit 0."""
    commands = [["sweep.py", *map(str, sweep_files), "--out", str(out), "--jobs", "2", "--threads", "1", "--ydry",
                 str(ydry)], ["plot_sweep.py", str(out), "--out", str(plots)]]
    for script, *arguments in commands:
        proc = subprocess.run([sys.executable, str(REPO / "scripts" / script), *arguments], capture_output=True,
                              text=True)
        print(proc.stdout + proc.stderr)
        if proc.returncode != 0:
            return [f"{script} exited {proc.returncode}"]
    return []


def run_ydry(ydry, deck, outdir, overrides=()):
    """Run `ydry DECK -o OUTDIR --force --quiet --set o ...`; return the wall time in seconds,
    or None if ydry failed."""
    cmd = [str(ydry), str(deck), "-o", str(outdir), "--force", "--quiet"]
    for override in list(overrides) + EXTRA_OVERRIDES:
        cmd += ["--set", override]
    start = time.perf_counter()
    proc = subprocess.run(cmd, capture_output=True, text=True)
    if proc.returncode != 0:
        print(f"ydry failed ({proc.returncode}): {' '.join(cmd)}\n{proc.stdout}{proc.stderr}")
        return None
    return time.perf_counter() - start


def completed(outdir):
    """True if summary.json says the run reached its end time."""
    return bool(json.loads((Path(outdir) / "summary.json").read_text())["completed"])


def read_csv(path):
    """{column: numpy array}; numeric columns as float, the others as str."""
    table = np.genfromtxt(path, delimiter=",", names=True, dtype=None, encoding="utf-8")
    table = np.atleast_1d(table)
    return {name: table[name] for name in table.dtype.names}


def reactions(outdir, boundary):
    """The rows of reactions.csv for one boundary, as {column: array}."""
    table = read_csv(Path(outdir) / "reactions.csv")
    rows = table["boundary"] == boundary
    return {name: column[rows] for name, column in table.items() if name != "boundary"}


def frames(pvd):
    """The frames of a run's .pvd in time order: {time in s: {part: path of its .vtu}}
    (part 0: the solid, part 1: the cracks)."""
    pvd = Path(pvd)
    found = {}
    for ds in ET.parse(pvd).getroot().iter("DataSet"):
        found.setdefault(float(ds.get("timestep")), {})[int(ds.get("part"))] = pvd.parent / ds.get("file")
    return dict(sorted(found.items()))


def read_grid(path):
    """One .vtu file as a vtkUnstructuredGrid."""
    reader = vtkXMLUnstructuredGridReader()
    reader.SetFileName(str(path))
    reader.Update()
    return reader.GetOutput()


def last_frame_files(outdir):
    """{part: path} of the last frame of the run's .pvd (part 0: the solid, part 1: the cracks)."""
    pvd = next(Path(outdir).glob("*.pvd"))
    return list(frames(pvd).values())[-1]


def _arrays(data):
    return {data.GetArrayName(i): vtk_to_numpy(data.GetArray(i)) for i in range(data.GetNumberOfArrays())}


def solid_arrays(grid):
    """One frame's solid (part 0, a grid from read_grid) as a dict: the current point
    coordinates x (n x 2), the reference ones x0 and the displacement u (n x 2), triangle
    connectivity (m x 3), triangle reference areas (m), the point arrays under "point_data"
    (e.g. moisture, n), and every cell array (e.g. stress, m x 3)."""
    x = vtk_to_numpy(grid.GetPoints().GetData())[:, :2]
    u = vtk_to_numpy(grid.GetPointData().GetArray("displacement"))[:, :2]
    cells = vtk_to_numpy(grid.GetCells().GetConnectivityArray()).reshape(-1, 3)
    x0 = x - u
    a, b, c = x0[cells[:, 0]], x0[cells[:, 1]], x0[cells[:, 2]]
    area = 0.5 * np.abs((b[:, 0] - a[:, 0]) * (c[:, 1] - a[:, 1]) - (b[:, 1] - a[:, 1]) * (c[:, 0] - a[:, 0]))
    return {"x": x, "x0": x0, "u": u, "cells": cells, "area": area,
            "point_data": _arrays(grid.GetPointData()), **_arrays(grid.GetCellData())}


def crack_arrays(grid):
    """One frame's broken joints (part 1, a grid from read_grid) as a dict: their end points
    in the current configuration, ends (m x 2 x 2), the ids of those points in the grid,
    cells (m x 2), and every cell array (opening, slip). A frame without any has m = 0."""
    if grid.GetNumberOfCells() == 0:
        return {"ends": np.zeros((0, 2, 2)), "cells": np.zeros((0, 2), dtype=int),
                **_arrays(grid.GetCellData())}
    points = vtk_to_numpy(grid.GetPoints().GetData())[:, :2]
    cells = vtk_to_numpy(grid.GetCells().GetConnectivityArray()).reshape(-1, 2)
    return {"ends": points[cells], "cells": cells, **_arrays(grid.GetCellData())}


def last_frame(outdir):
    """The solid in the last frame (solid_arrays)."""
    return solid_arrays(read_grid(last_frame_files(outdir)[0]))


def last_cracks(outdir):
    """The broken joints in the last frame (crack_arrays)."""
    return crack_arrays(read_grid(last_frame_files(outdir)[1]))


def corners(bulk, at, warp=1.0):
    """For each point in `at` (n x 3): the ids of the points of the solid's grid `bulk` at the
    reference vertex of the nearest point (the corners of every triangle meeting there, on
    both faces of a crack). The solid's points are its reference ones plus warp times the
    displacement."""
    x = vtk_to_numpy(bulk.GetPoints().GetData())
    u = vtk_to_numpy(bulk.GetPointData().GetArray("displacement"))
    _, vertex, count = np.unique(np.round((x - warp * u) * 1e9), axis=0, return_inverse=True,
                                 return_counts=True)
    groups = np.split(np.argsort(vertex, kind="stable"), np.cumsum(count)[:-1])
    locator = vtkStaticPointLocator()
    locator.SetDataSet(bulk)
    locator.BuildLocator()
    return [groups[vertex[locator.FindClosestPoint(point)]] for point in at]


def crack_displacement(bulk, cracks):
    """The displacement at the ends of the crack lines (grid `cracks`): the mean over the
    corners of the solid's grid `bulk` at their vertices (n x 3)."""
    u = vtk_to_numpy(bulk.GetPointData().GetArray("displacement"))
    ends = vtk_to_numpy(cracks.GetPoints().GetData())
    return np.array([u[ids].mean(axis=0) for ids in corners(bulk, ends)])


def relative_error(value, exact):
    return abs(value - exact) / abs(exact)


class Verdicts:
    """Prints `CASE METRIC VALUE TOLERANCE PASS|FAIL` lines and remembers any failure."""

    def __init__(self, case):
        self.case = case
        self.ok = True

    def check(self, metric, value, tolerance, passed):
        shown = f"{value:.4g}" if isinstance(value, float) else str(value).lower()
        print(f"{self.case} {metric} {shown} {tolerance} {'PASS' if passed else 'FAIL'}")
        self.ok &= bool(passed)
        return passed

    def below(self, metric, value, tolerance):
        """PASS if value <= tolerance (a NaN fails)."""
        return self.check(metric, value, tolerance, value <= tolerance)

    def exit_code(self):
        return 0 if self.ok else 1
