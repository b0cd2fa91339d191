#!/usr/bin/python3
"""Verification case contact_incline: a block on an inclined plane with Coulomb friction.

Runs ydry on incline.toml (dynamic, friction angle phi = 20 degrees) for plane angles theta =
15 and 25 degrees. Below phi the block must stay: its mean displacement stays under 1 % of
the element size. Above phi it must slide with a = g (sin theta - cos theta tan phi): the
acceleration fitted to the block's mean displacement over time must be within 2 %, and the
work done on the contact must equal the friction work mu m g cos(theta) x distance within 2 %.
Prints `contact_incline METRIC VALUE TOLERANCE PASS|FAIL`, writes out/incline.png, exits 1
if a check fails.
"""
import math
import sys
from pathlib import Path

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np
from vtkmodules.util.numpy_support import vtk_to_numpy

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE.parent))
import ydry_case  # noqa: E402

DECK = HERE / "incline.toml"
G, PHI = 9.81, math.radians(20.0)
MASS = 2000.0 * 0.1 * 0.05           # kg per m of thickness
ELEMENT_SIZE = 0.0125                # m
ANGLES = (15.0, 25.0)                # degrees
ACCELERATION_TOLERANCE = 0.02        # relative
WORK_TOLERANCE = 0.02                # relative
STICK_TOLERANCE = 0.01               # displacement / element size


def block_motion(outdir):
    """Times and the mean x-displacement of the block's corners (the base's never move)."""
    times, ux = [], []
    for time, parts in ydry_case.frames(next(Path(outdir).glob("*.pvd"))).items():
        grid = ydry_case.read_grid(parts[0])
        u = vtk_to_numpy(grid.GetPointData().GetArray("displacement"))
        x0 = vtk_to_numpy(grid.GetPoints().GetData())[:, 1] - u[:, 1]
        block = x0 > 0.05 - 1e-9
        block &= np.repeat(np.add.reduceat(block, np.arange(0, len(block), 3)) == 3, 3)  # whole triangles
        times.append(time)
        ux.append(u[block, 0].mean())
    return np.array(times), np.array(ux)


def main():
    args = ydry_case.arguments(__doc__, HERE)
    verdicts = ydry_case.Verdicts("contact_incline")
    fig, ax = plt.subplots(figsize=(6, 4))
    for degrees in ANGLES:
        theta = math.radians(degrees)
        outdir = args.out / f"theta_{degrees:g}"
        gravity = f"run.gravity=[{G * math.sin(theta)!r}, {-G * math.cos(theta)!r}]"
        wall = ydry_case.run_ydry(args.ydry, DECK, outdir, [gravity])
        if wall is None or not ydry_case.completed(outdir):
            verdicts.check(f"theta_{degrees:g}_completed", False, "true", False)
            continue
        t, ux = block_motion(outdir)
        exact = G * (math.sin(theta) - math.cos(theta) * math.tan(PHI))
        series = ydry_case.read_csv(outdir / "series.csv")
        print(f"info: theta {degrees:g} deg: wall {wall:.1f} s, final displacement {ux[-1]:.4e} m, "
              f"{int(series['mechanical_steps'][-1])} steps")
        ax.plot(t, ux * 1e3, "o", label=f"ydry, theta = {degrees:g} deg")
        if exact <= 0.0:
            verdicts.below(f"theta_{degrees:g}_stick_displacement_over_h", float(np.abs(ux).max()) / ELEMENT_SIZE,
                           STICK_TOLERANCE)
            continue
        fitted = 2.0 * np.polyfit(t, ux, 2)[0]
        ax.plot(t, 0.5 * exact * t**2 * 1e3, "-", label=f"g (sin - cos tan phi) t^2 / 2, {degrees:g} deg")
        print(f"info: theta {degrees:g} deg: fitted acceleration {fitted:.5f} m/s^2, exact {exact:.5f}")
        verdicts.below(f"theta_{degrees:g}_acceleration_error", ydry_case.relative_error(fitted, exact),
                       ACCELERATION_TOLERANCE)
        friction_work = math.tan(PHI) * MASS * G * math.cos(theta) * ux[-1]
        verdicts.below(f"theta_{degrees:g}_contact_work_error",
                       ydry_case.relative_error(series["contact_work_J"][-1], friction_work), WORK_TOLERANCE)
    ax.set_xlabel("time (s)")
    ax.set_ylabel("mean x-displacement of the block (mm)")
    ax.set_title("Block on an incline, friction angle 20 deg")
    ax.legend()
    fig.tight_layout()
    fig.savefig(args.out / "incline.png", dpi=120)
    return verdicts.exit_code()


if __name__ == "__main__":
    sys.exit(main())
