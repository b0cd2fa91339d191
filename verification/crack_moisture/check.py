#!/usr/bin/python3
"""Verification case crack_moisture: moisture migration past a crack (paper section 4.2, Fig. 14).

Runs ydry on crack_moisture.toml (a 0.1 m x 0.05 m block, w = 1 on the left, w = 0 on the
right, a crack from the middle of the top down to half the height) and once without the crack
(--set cracks=[]). Checks that without the crack the steady field is linear in x; that with it
w jumps across the crack at 500 ks; that the field at 4 Ms matches a finite-difference solution
of the slit block (slit_fd.py, 10 x finer); and that at the end (6 Ms) the water in through the
left side equals the water out through the right. Prints the verdict lines
`crack_moisture METRIC VALUE TOLERANCE PASS|FAIL`, writes out/fig14_crack_moisture.png.
Exits 1 if any check fails.
"""
import json
import sys
from pathlib import Path

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
import matplotlib.tri as mtri
import numpy as np
from vtkmodules.util.numpy_support import vtk_to_numpy

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE.parent))
import ydry_case  # noqa: E402
import slit_fd  # noqa: E402

DECK = HERE / "crack_moisture.toml"
K_TIMES_THICKNESS = 5.0e-6 * 1.0       # moisture conductivity x thickness, kg/(m s) x m
FIG14_TIMES = (1e5, 2e5, 5e5, 1.2e6, 4e6)  # s
JUMP_TIME, COMPARE_TIME = 5e5, 4e6       # s
MID_CRACK = (0.05, 0.0375)               # m: half-way down the crack
FD_CELL = 0.00025                        # m: the reference grid, 10 x finer than the mesh
LINEAR_TOLERANCE = 0.005                 # max |w - (1 - x/L)|, of the imposed difference 1
L2_TOLERANCE = 0.01                      # relative L2 against the finite differences
STEADY_TOLERANCE = 1e-4                  # relative L2 change from 4 Ms to the end
FLOW_TOLERANCE = 1e-6                    # |in + out| / in at the end
BALANCE_TOLERANCE = 1e-12


def moisture_frames(outdir):
    """{time in s: (points n x 2, w n)} for every frame; the run has no mechanics, so the
    points are the reference positions, three per triangle (corner a of triangle t is 3t + a)."""
    frames = {}
    for t, parts in ydry_case.frames(next(Path(outdir).glob("*.pvd"))).items():
        grid = ydry_case.read_grid(parts[0])
        frames[t] = (vtk_to_numpy(grid.GetPoints().GetData())[:, :2].copy(),
                     vtk_to_numpy(grid.GetPointData().GetArray("moisture")).copy())
    return frames


def frame_at(frames, t):
    return frames[min(frames, key=lambda ft: abs(ft - t))]


def left_of_crack(points):
    """True for the corners of triangles whose centroid lies left of the crack line."""
    return np.repeat(points[:, 0].reshape(-1, 3).mean(axis=1) < slit_fd.XS, 3)


def unique_nodes(points, w):
    """One row per moisture node: the corners of a node share their position and their w,
    the two sides of the crack differ in w."""
    return np.unique(np.c_[np.round(points, 9), w], axis=0, return_index=True)[1]


def relative_l2(values, reference):
    return float(np.sqrt(np.sum((values - reference) ** 2) / np.sum(reference ** 2)))


def side_flows(points, w):
    """kg/s in through the left side and in through the right side: at steady state the water
    a fixed node takes in is what its triangles pass on, sum of (K w) over its corners, with
    the linear triangle's conductance K_ab = k t A grad N_a . grad N_b (Eqs. 2-4)."""
    x, y, wt = points[:, 0].reshape(-1, 3), points[:, 1].reshape(-1, 3), w.reshape(-1, 3)
    gx = np.stack([y[:, (a + 1) % 3] - y[:, (a + 2) % 3] for a in range(3)], axis=1)  # 2A grad N
    gy = np.stack([x[:, (a + 2) % 3] - x[:, (a + 1) % 3] for a in range(3)], axis=1)
    twice_area = (x[:, 1] - x[:, 0]) * (y[:, 2] - y[:, 0]) - (x[:, 2] - x[:, 0]) * (y[:, 1] - y[:, 0])
    K = K_TIMES_THICKNESS / (2 * twice_area)[:, None, None] * (
        gx[:, :, None] * gx[:, None, :] + gy[:, :, None] * gy[:, None, :])
    passed_on = np.einsum("tab,tb->ta", K, wt).ravel()
    left, right = (np.isclose(points[:, 0], side_x, rtol=0, atol=1e-9) for side_x in (0.0, slit_fd.L))
    return float(passed_on[left].sum()), float(passed_on[right].sum())


def plot_fig14(frames, path):
    fig, axes = plt.subplots(len(FIG14_TIMES), 1, figsize=(6.5, 10), sharex=True, constrained_layout=True)
    levels = np.linspace(0, 1, 21)
    for ax, t in zip(axes, FIG14_TIMES):
        points, w = frame_at(frames, t)
        triangulation = mtri.Triangulation(points[:, 0] * 100, points[:, 1] * 100,
                                           np.arange(len(points)).reshape(-1, 3))
        filled = ax.tricontourf(triangulation, w, levels=levels, cmap="viridis")
        ax.plot([slit_fd.XS * 100] * 2, [slit_fd.YT * 100, slit_fd.H * 100], "w-", lw=2)
        ax.set_title(f"t = {t:,.0f} s")
        ax.set_aspect("equal")
        ax.set_ylabel("y (cm)")
    axes[-1].set_xlabel("x (cm)")
    fig.colorbar(filled, ax=axes, label="moisture content w", shrink=0.5)
    fig.suptitle("Fig. 14: moisture past a crack (white), w = 1 left, w = 0 right")
    fig.savefig(path, dpi=150)
    plt.close(fig)


def run(args, verdicts, label, overrides=()):
    """Runs the deck into out/LABEL; returns its frames, or None if it failed."""
    out = args.out
    wall = ydry_case.run_ydry(args.ydry, DECK, out / label, overrides)
    verdicts.check(f"ran_{label}", wall is not None, "true", wall is not None)
    if wall is None:
        return None
    done = ydry_case.completed(out / label)
    verdicts.check(f"completed_{label}", done, "true", done)
    balance = json.loads((out / label / "summary.json").read_text())["water_balance_error"]
    verdicts.below(f"water_balance_{label}", balance, BALANCE_TOLERANCE)
    print(f"# {label}: {wall:.1f} s")
    return moisture_frames(out / label)


def main():
    args = ydry_case.arguments(__doc__, HERE)
    verdicts = ydry_case.Verdicts("crack_moisture")
    intact = run(args, verdicts, "intact", ["cracks=[]", "run.output_interval=6e6"])
    cracked = run(args, verdicts, "cracked")
    if intact is None or cracked is None:
        return 1

    # (0) Without the crack the steady field is w = 1 - x / L.
    points, w = frame_at(intact, max(intact))
    verdicts.below("linear_max_deviation_intact", float(np.max(np.abs(w - (1 - points[:, 0] / slit_fd.L)))),
                   LINEAR_TOLERANCE)

    # (a) The crack holds the water back: w jumps across it, half-way down, at 500 ks.
    points, w = frame_at(cracked, JUMP_TIME)
    at_mid = np.all(np.isclose(points, MID_CRACK, rtol=0, atol=1e-9), axis=1)
    left = left_of_crack(points)
    jump = float(w[at_mid & left].mean() - w[at_mid & ~left].mean())
    print(f"# w at ({MID_CRACK[0]}, {MID_CRACK[1]}) m, t = {JUMP_TIME:.0f} s: left {w[at_mid & left].mean():.4f}, "
          f"right {w[at_mid & ~left].mean():.4f}")
    verdicts.check("jump_across_crack_500ks", jump, ">0", jump > 0)

    # (b) At 4 Ms the field is steady and matches the finite differences of the slit block.
    points, w = frame_at(cracked, COMPARE_TIME)
    end_points, end_w = frame_at(cracked, max(cracked))
    verdicts.below("steady_change_4Ms_to_end", relative_l2(w, end_w), STEADY_TOLERANCE)
    reference = slit_fd.solve_steady(FD_CELL)
    coarse = slit_fd.solve_steady(2 * FD_CELL)
    nodes = unique_nodes(points, w)
    left = left_of_crack(points)
    fd = slit_fd.interpolate(reference, FD_CELL, points, left)[nodes]
    fd_coarse = slit_fd.interpolate(coarse, 2 * FD_CELL, points, left)[nodes]
    print(f"# {len(nodes)} moisture nodes; finite differences on {reference.shape[0]} x {reference.shape[1]} cells "
          f"change by {relative_l2(fd_coarse, fd):.2e} (relative L2) from {reference.shape[0] // 2} x "
          f"{reference.shape[1] // 2}; largest |w - w_FD| {np.max(np.abs(w[nodes] - fd)):.4f}")
    verdicts.below("l2_vs_finite_differences_4Ms", relative_l2(w[nodes], fd), L2_TOLERANCE)

    # (c) At the end the water in through the left side leaves through the right.
    inflow, outflow = side_flows(end_points, end_w)
    fd_inflow = slit_fd.left_inflow_per_k(reference) * K_TIMES_THICKNESS
    print(f"# t = {max(cracked):.0f} s: in through the left {inflow:.6e} kg/s, through the right {outflow:.6e} "
          f"kg/s; finite differences {fd_inflow:.6e} kg/s")
    verdicts.below("flow_imbalance_end", abs(inflow + outflow) / inflow, FLOW_TOLERANCE)

    plot_fig14(cracked, args.out / "fig14_crack_moisture.png")
    return verdicts.exit_code()


if __name__ == "__main__":
    sys.exit(main())
