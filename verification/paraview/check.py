#!/usr/bin/python3
"""Verification case paraview: ParaView opens a run's .pvd as its users will.

Runs ydry on the demo deck made to crack early and cut short (frames at 0, 4000 and 8000 s, and
at the end time, 10000 s, off that grid), then check_pvd.py with pvpython on a private Xvfb display
(scripts/virtual_display.py), and
checks what ParaView's PVDReader delivered: the time values it offers are the ones the .pvd
lists and those run.output_interval implies; at each, the data carries that time, the solid
part (0) has 3 points per triangle and summary.json's triangles with the point arrays moisture,
displacement, velocity and the cell arrays material, moisture, stress, and the crack part (1)
one line cell per broken joint of series.csv at that time with opening, slip, moisture_face1,
moisture_face2 and strength_factor, every value finite. The PNG of the last frame (the solid
coloured by moisture, the cracks in black) must have the size asked for, a colour map's range
of colours and black crack lines across the layer. Needs pvpython and Xvfb
(scripts/install-deps.sh --with-paraview). Prints `paraview METRIC VALUE TOLERANCE PASS|FAIL`
and exits 1 if a check fails.
"""
import json
import os
import shutil
import signal
import subprocess
import sys
import time
import tomllib
from pathlib import Path

import matplotlib.image
import numpy as np

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE.parent))
sys.path.insert(0, str(HERE.parents[1] / "scripts"))
import virtual_display  # noqa: E402
import ydry_case  # noqa: E402

OVERRIDES = ["run.end_time=10000", "run.output_interval=4000", "run.series_interval=2000",
             *ydry_case.DEMO_EARLY_CRACKING]
POINT_ARRAYS = {0: {"moisture": 1, "displacement": 3, "velocity": 3}, 1: {}}  # part: {name: components}
CELL_ARRAYS = {0: {"material": 1, "moisture": 1, "stress": 3},
               1: {"opening": 1, "slip": 1, "moisture_face1": 1, "moisture_face2": 1, "strength_factor": 1}}
VTK_TRIANGLE, VTK_LINE = 5, 3
TIME_TOLERANCE_S = 1e-9          # the times are written with 17 digits: they come back exact
IMAGE_SIZE = "1600x400"          # pixels, WxH: the layer is 10 times as wide as it is high
MIN_COLOURS = 100                # a colour map's gradient, not a blank or flat picture
MIN_COLOURED_FRACTION = 0.10     # of the picture: the layer in colour (about 0.3 of it)
LAYER_ROWS = 0.6                 # the top 60 % of the picture: the layer, above the scalar bar
CLIENT_TIMEOUT_S = 120


def expected_frame_times(deck):
    """The frame times ydry writes (run.cpp): rows at every series_interval and at end_time; a
    frame at the first row at or after each multiple of output_interval, and at end_time."""
    run = deck["run"]
    end, interval, rows = run["end_time"], run["output_interval"], run["series_interval"]
    times, next_frame, row = [], 0, 0
    while not times or times[-1] < end:
        t = min(end, row * rows)
        if t >= next_frame * interval * (1.0 - 1e-12) or t >= end:
            times.append(float(t))
            next_frame = int(np.floor(t / interval * (1.0 + 1e-12))) + 1
        row += 1
    return times


def time_error(times, reference):
    """The largest difference between two lists of times, s (infinite when their lengths differ)."""
    if len(times) != len(reference):
        return float("inf")
    return max((abs(a - b) for a, b in zip(times, reference)), default=0.0)


def part_problems(part, index, expected_points, expected_cells, cell_type):
    """What is wrong with one part of one frame as ParaView delivered it ([] if nothing)."""
    problems = []
    if (part["points"], part["cells"]) != (expected_points, expected_cells):
        problems.append(f"{part['points']} points, {part['cells']} cells, expected {expected_points}, "
                        f"{expected_cells}")
    if part["cell_types"] != ([cell_type] if expected_cells else []):
        problems.append(f"cell types {part['cell_types']}, expected [{cell_type}]")
    for where, expected, count in (("point_arrays", POINT_ARRAYS[index], part["points"]),
                                   ("cell_arrays", CELL_ARRAYS[index], part["cells"])):
        for name, components in expected.items():
            a = part[where].get(name)
            if a is None:
                problems.append(f"no {where[:-1].replace('_', ' ')} {name}")
            elif (a["components"], a["tuples"], a["finite"]) != (components, count, True):
                problems.append(f"{name}: {a['components']} components, {a['tuples']} tuples, "
                                f"finite {a['finite']}; expected {components}, {count}, True")
    return problems


def frame_problems(frame, triangles, broken_joints):
    """What is wrong with one frame ([] if nothing): its parts' sizes, types and arrays."""
    if len(frame["parts"]) != 2:
        return [f"{len(frame['parts'])} parts, expected 2"]
    solid, cracks = frame["parts"]
    return ([f"solid: {p}" for p in part_problems(solid, 0, 3 * triangles, triangles, VTK_TRIANGLE)] +
            [f"cracks: {p}" for p in part_problems(cracks, 1, 2 * broken_joints, broken_joints, VTK_LINE)])


def check_picture(verdicts, png):
    """The PNG is the size asked for, holds a colour map's range of colours, and black (crack)
    pixels where the layer is."""
    if not verdicts.check("png_written", png.is_file(), "true", png.is_file()):
        return
    rgb = np.round(matplotlib.image.imread(png)[..., :3] * 255).astype(int)
    size = f"{rgb.shape[1]}x{rgb.shape[0]}"
    verdicts.check("png_size", size, IMAGE_SIZE, size == IMAGE_SIZE)
    pixels = rgb.reshape(-1, 3)
    colours = len(np.unique(pixels, axis=0))
    verdicts.check("png_colours", colours, f">={MIN_COLOURS}", colours >= MIN_COLOURS)
    black, white = np.all(pixels < 40, axis=1), np.all(pixels > 245, axis=1)
    coloured = float(np.mean(~black & ~white))
    verdicts.check("png_coloured_fraction", coloured, f">={MIN_COLOURED_FRACTION}",
                   coloured >= MIN_COLOURED_FRACTION)
    layer = rgb[: int(LAYER_ROWS * rgb.shape[0])]
    crack_columns = int(np.any(np.all(layer < 40, axis=2), axis=0).sum())
    print(f"info: {png}: {colours} colours, {coloured:.3f} coloured, black in {crack_columns} columns "
          f"of the layer")
    verdicts.check("png_crack_columns", crack_columns, ">0", crack_columns > 0)


def run_client(command):
    """Run the ParaView client on a display of its own, in a process group of its own so that a
    timeout ends it and all it started; return its exit code ("timeout" if it ran out of time)
    and its output ("no display" and Xvfb's output when Xvfb does not start)."""
    try:
        return run_on_display(command)
    except virtual_display.DisplayError as error:
        return "no display", str(error)


def run_on_display(command):
    with virtual_display.virtual_display() as display:
        proc = subprocess.Popen(command, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
                                start_new_session=True, env={**os.environ, "DISPLAY": display})
        try:
            output = proc.communicate(timeout=CLIENT_TIMEOUT_S)[0]
            return proc.returncode, output
        except subprocess.TimeoutExpired:
            os.killpg(proc.pid, signal.SIGKILL)
            return "timeout", proc.communicate()[0]


def main():
    parser = ydry_case.case_parser(__doc__, HERE)
    parser.add_argument("--pvpython", default="pvpython", help="ParaView's Python (default: from PATH)")
    args = ydry_case.parse_case_arguments(parser)
    args.out.mkdir(parents=True, exist_ok=True)
    verdicts = ydry_case.Verdicts("paraview")
    client = [shutil.which("Xvfb"), shutil.which(args.pvpython)]
    if not verdicts.check("client_found", all(client), "true", all(client)):
        print(f"info: Xvfb {client[0]}, pvpython {client[1]}: "
              "install them with scripts/install-deps.sh --with-paraview")
        return verdicts.exit_code()

    run = args.out / "run"
    ran = ydry_case.run_ydry(args.ydry, ydry_case.DEMO_DECK, run, OVERRIDES) is not None
    if not ran or not ydry_case.completed(run):
        verdicts.check("completed", False, "true", False)
        return verdicts.exit_code()
    pvd, found, png = run / "drying_layer.pvd", args.out / "paraview.json", args.out / "last_frame.png"
    found.unlink(missing_ok=True)
    png.unlink(missing_ok=True)
    command = [client[1], str(HERE / "check_pvd.py"), str(pvd), "--json", str(found), "--png", str(png),
               "--size", IMAGE_SIZE]
    start = time.perf_counter()
    code, output = run_client(command)
    wall = time.perf_counter() - start
    if not verdicts.check("client_exit_code", code, 0, code == 0 and found.is_file()):
        print(output)
        return verdicts.exit_code()
    seen = json.loads(found.read_text())
    print(f"info: {seen['paraview_version']}, {len(seen['frames'])} frames read and the last rendered "
          f"in {wall:.1f} s")

    listed = list(ydry_case.frames(pvd))
    implied = expected_frame_times(tomllib.loads((run / "deck.toml").read_text()))
    print(f"info: frame times (s): ParaView {seen['timestep_values']}, .pvd {listed}, implied {implied}")
    verdicts.below("pvd_vs_interval_time_error_s", time_error(listed, implied), TIME_TOLERANCE_S)
    offered = seen["timestep_values"]
    verdicts.below("reader_vs_pvd_time_error_s", time_error(offered, listed), TIME_TOLERANCE_S)
    verdicts.below("data_vs_reader_time_error_s", time_error([f["data_time"] for f in seen["frames"]], offered),
                   TIME_TOLERANCE_S)

    triangles = json.loads((run / "summary.json").read_text())["elements"]
    series = ydry_case.read_csv(run / "series.csv")
    broken = dict(zip(series["time_s"], series["broken_joints"]))
    good = 0
    for frame in seen["frames"]:
        problems = (frame_problems(frame, triangles, int(broken[frame["time"]])) if frame["time"] in broken
                    else ["no row of series.csv at this time"])
        for problem in problems:
            print(f"info: t = {frame['time']:g} s: {problem}")
        good += not problems
    verdicts.check("frames_with_all_arrays_and_cells", good, len(seen["frames"]),
                   good == len(seen["frames"]) == len(implied))
    last = seen["frames"][-1]["parts"] if seen["frames"] else []
    last_cracks = last[1]["cells"] if len(last) == 2 else 0
    verdicts.check("last_frame_crack_cells", last_cracks, ">0", last_cracks > 0)
    check_picture(verdicts, png)
    return verdicts.exit_code()


if __name__ == "__main__":
    sys.exit(main())
