#!/usr/bin/python3
"""Plot the crack network of a plan-view ydry run (run.view = "plan"; doc/outputs.md
"network.csv, cells.csv and junctions.csv").

Reads the run's network.csv, cells.csv, junctions.csv and its last frame, and writes into
--out (default RUN/plots):

    network_cells.png       the layer at the last frame, each cell (fragment) in its own colour
    network_statistics.png  the cell areas' and the junction angles' histograms at the last
                            frame, and the crack intensity factor and the cell count against time

    scripts/plot_network.py runs/planview
    scripts/plot_network.py runs/planview --out figures

Exits 2 on a folder that is not a plan-view ydry run with its solid.
"""
import sys
from pathlib import Path

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from matplotlib.tri import Triangulation  # noqa: E402

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "verification"))
import ydry_case  # noqa: E402  (run folders: tables, frames)

MM2 = 1e6  # the figures show mm^2


def arguments():
    parser = ydry_case.script_parser(__doc__)
    parser.add_argument("run", type=Path, help="a plan-view ydry output folder (ydry -o)")
    parser.add_argument("--out", type=Path, help="folder for the PNGs (default RUN/plots)")
    return parser.parse_args()


def load(run):
    """The run's tables, the rows of its last frame, and that frame's solid; exits 2 where the
    folder holds no plan-view run."""
    needed = [run / name for name in ("network.csv", "cells.csv", "junctions.csv", "summary.json")]
    missing = [path.name for path in needed if not path.is_file()]
    if missing:
        print(f"plot_network: {run} is not a plan-view ydry run with its solid (no {', '.join(missing)})",
              file=sys.stderr)
        sys.exit(2)
    network = ydry_case.read_csv(run / "network.csv")
    cells = ydry_case.read_csv(run / "cells.csv")
    has_junctions = len((run / "junctions.csv").read_text().splitlines()) > 1  # more than the header
    junctions = ydry_case.read_csv(run / "junctions.csv") if has_junctions else None
    frame = ydry_case.last_frame(run)
    last = cells["time_s"].max()
    at_last = {name: column[cells["time_s"] == last] for name, column in cells.items()}
    angles, kinds = [], []
    if junctions is not None:
        rows = np.atleast_1d(junctions["time_s"]) == last
        kinds = list(np.atleast_1d(junctions["kind"])[rows])
        for text in np.atleast_1d(junctions["angles_deg"])[rows]:
            angles.extend(float(a) for a in str(text).split())
    return network, at_last, last, kinds, angles, frame


def draw_cells(ax, frame):
    """The frame's solid on ax in mm, each cell in its own colour; returns the number of cells."""
    x = frame["x"]
    cell = frame["cell"].astype(int)
    shuffled = np.random.default_rng(1).permutation(cell.max() + 1)  # neighbours in different colours
    ax.tripcolor(Triangulation(x[:, 0] * 1e3, x[:, 1] * 1e3, frame["cells"]), facecolors=shuffled[cell] % 20,
                 cmap="tab20", vmin=0, vmax=19, edgecolors="none")
    ax.set_aspect("equal")
    ax.set_xlabel("x (mm)")
    ax.set_ylabel("y (mm)")
    return cell.max() + 1


def fig_cells(frame, last, path):
    fig, ax = plt.subplots(figsize=(7, 6.5))
    ax.set_title(f"{draw_cells(ax, frame)} cells at t = {last:g} s")
    fig.tight_layout()
    fig.savefig(path, dpi=150)
    plt.close(fig)


def fig_statistics(network, cells, kinds, angles, path):
    fig, ((areas, junction), (intensity, count)) = plt.subplots(2, 2, figsize=(11, 8))
    area = cells["area_m2"] * MM2
    areas.hist(area, bins=max(5, min(40, len(area) // 3)), color="C0")
    areas.set_xlabel("cell area (mm$^2$)")
    areas.set_ylabel("cells")
    areas.set_title(f"cell areas: {len(area)} cells, mean {area.mean():.3g} mm$^2$")
    if angles:
        junction.hist(angles, bins=np.arange(0, 361, 10), color="C1")
        for reference in (90, 120, 180):
            junction.axvline(reference, color="0.5", lw=0.8, ls="--")
    else:
        junction.text(0.5, 0.5, "no junctions", transform=junction.transAxes, ha="center", color="0.4")
    t, y = kinds.count("T"), kinds.count("Y")
    junction.set_xlabel("angle between neighbouring branches (degrees)")
    junction.set_ylabel("angles")
    junction.set_title(f"junctions: {t} T, {y} Y, {len(kinds) - t - y} other")
    hours = network["time_s"] / 3600.0
    intensity.plot(hours, network["crack_intensity"] * 100, "C3-")
    intensity.set_xlabel("time (h)")
    intensity.set_ylabel("crack intensity factor (%)")
    intensity.set_title("crack area over the layer's area")
    count.plot(hours, network["cells"], "C2-")
    count.set_xlabel("time (h)")
    count.set_ylabel("cells")
    count.set_title("cells against time")
    for ax in (areas, junction, intensity, count):
        ax.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(path, dpi=150)
    plt.close(fig)


def main():
    args = arguments()
    network, cells, last, kinds, angles, frame = load(args.run)
    out = args.out or args.run / "plots"
    out.mkdir(parents=True, exist_ok=True)
    fig_cells(frame, last, out / "network_cells.png")
    fig_statistics(network, cells, kinds, angles, out / "network_statistics.png")
    print(f"plot_network: network_cells.png and network_statistics.png in {out}")


if __name__ == "__main__":
    main()
