#!/usr/bin/python3
"""ctest plot_run: scripts/plot_run.py and scripts/render_frame.py on a short run of the demo deck.

Runs ydry on inputs/demo/drying_layer.toml cut short to 20000 s on a 4 mm mesh, its soil made
to crack early (shrinkage coefficient 0.4, gf_I 0.02 J/m^2: about ten cracks in 10 s of CPU),
then plot_run.py on it: every figure and report.md must be written, and the report's crack
count must be summary.json's. plot_run.py on a folder that is not a ydry run must exit
non-zero and say so. render_frame.py, run without a DISPLAY (so on a private Xvfb, package
xvfb), must write a PNG of the size asked for with a colour map's range of colours and the
magenta of the cracks. Exits 1 on any failure.
"""
import json
import os
import re
import subprocess
import sys
import tempfile
from pathlib import Path

REPO = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(REPO / "verification"))
import ydry_case  # noqa: E402

import matplotlib.image  # noqa: E402
import numpy as np  # noqa: E402

OVERRIDES = ["run.end_time=20000", *ydry_case.DEMO_EARLY_CRACKING]
FIGURES = ["fig18_moisture.png", "fig19_crack_pattern.png", "fig20_vertical_displacement.png",
           "fig21_horizontal_displacement.png", "fig22_surface_displacement.png",
           "fig23_crack_width.png", "fig24_crack_length.png"]


def plot_run(*args):
    return subprocess.run([sys.executable, str(REPO / "scripts" / "plot_run.py"), *map(str, args)],
                          capture_output=True, text=True)


RENDER_SIZE = (800, 500)  # pixels, width x height
MIN_COLOURS = 100         # a colour map's gradient, not a blank or flat picture


def render_problems(run, png):
    """What is wrong with render_frame.py's picture of the run's last frame ([] if nothing)."""
    env = {k: v for k, v in os.environ.items() if k != "DISPLAY"}
    proc = subprocess.run([sys.executable, str(REPO / "scripts" / "render_frame.py"), str(run), "--out", str(png),
                           "--size", "x".join(map(str, RENDER_SIZE))], capture_output=True, text=True, env=env)
    print(proc.stdout + proc.stderr)
    if proc.returncode != 0 or not png.is_file():
        return [f"render_frame.py exited {proc.returncode}, PNG written: {png.is_file()}"]
    rgb = np.round(matplotlib.image.imread(png)[..., :3] * 255).astype(int)
    pixels = rgb.reshape(-1, 3)
    colours = len(np.unique(pixels, axis=0))
    magenta = int(np.sum((pixels[:, 0] > 200) & (pixels[:, 1] < 60) & (pixels[:, 2] > 200)))
    print(f"info: render_frame: {rgb.shape[1]}x{rgb.shape[0]}, {colours} colours, {magenta} magenta pixels")
    problems = []
    if (rgb.shape[1], rgb.shape[0]) != RENDER_SIZE:
        problems.append(f"render_frame PNG is {rgb.shape[1]}x{rgb.shape[0]}, asked for {RENDER_SIZE}")
    if colours < MIN_COLOURS:
        problems.append(f"render_frame PNG has {colours} colours, fewer than {MIN_COLOURS}")
    if magenta == 0:
        problems.append("render_frame PNG shows no crack (magenta) pixel")
    return problems


def main():
    args = ydry_case.test_arguments(__doc__)
    failures = []
    with tempfile.TemporaryDirectory(prefix="ydry_plot_run_") as tmp:
        run, out = Path(tmp) / "run", Path(tmp) / "plots"
        if ydry_case.run_ydry(args.ydry, ydry_case.DEMO_DECK, run, OVERRIDES) is None:
            return 1
        proc = plot_run(run, "--out", out)
        print(proc.stdout + proc.stderr)
        if proc.returncode != 0:
            failures.append(f"plot_run.py exited {proc.returncode}")
        failures += [f"{name} not written" for name in FIGURES + ["report.md"] if not (out / name).is_file()]
        if (out / "report.md").is_file():
            found = re.search(r"^\| crack count: open on the top surface / all \| (\d+) / (\d+) \|$",
                              (out / "report.md").read_text(), re.M)
            summary = json.loads((run / "summary.json").read_text())
            expected = (summary["surface_crack_count"], summary["crack_count"])
            if not found or (int(found.group(1)), int(found.group(2))) != expected:
                failures.append(f"report crack counts {found and found.groups()}, summary.json {expected}")

        failures += render_problems(run, Path(tmp) / "frame.png")

        empty = Path(tmp) / "not_a_run"
        empty.mkdir()
        proc = plot_run(empty)
        if proc.returncode == 0 or "is not a ydry run folder" not in proc.stderr:
            failures.append(f"plot_run.py on a folder that is not a run: exit {proc.returncode}, "
                            f"{proc.stderr!r}")
    return ydry_case.failed(failures)


if __name__ == "__main__":
    sys.exit(main())
