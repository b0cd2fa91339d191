"""The plan-view sweeps of scripts/plot_sweep.py (a sweep file's `cracks = "network"`): the crack
network of each run's last row of network.csv, side by side over the swept value.

Writes into the plots folder, per sweep NAME:

    NAME_networks.png   each run's last frame, each cell (fragment) in its own colour
    NAME_cell_area.png  the mean cell area against the value on log-log axes, with the exponent
                        n of the least-squares line log A = n log v + c through the completed
                        runs (cell size proportional to the layer's thickness gives n = 2)
    NAME_table.csv      per value (plot_sweep.write_table): cells, mean cell area, crack
    NAME_table.md       intensity factor, crack length per unit area, T, Y and other
                        junctions, the T junctions' share; and n
"""
import math

import numpy as np

import plot_network  # (draw_cells)
import plot_run  # (save, plt)
import ydry_case  # (read_csv, last_frame)

QUANTITIES = [  # table column (SI, as network.csv names it), Markdown heading, factor to its unit
    ("cells", "cells", 1.0),
    ("mean_cell_area_m2", "mean cell area (mm^2)", 1e6),
    ("crack_intensity", "crack intensity factor (%)", 100.0),
    ("crack_density_per_m", "crack length per area (1/m)", 1.0),
    ("junctions_T", "T junctions", 1.0),
    ("junctions_Y", "Y junctions", 1.0),
    ("junctions_other", "other junctions", 1.0),
    ("t_share", "T share (%)", 100.0),
]
COUNTS = {"cells", "junctions_T", "junctions_Y", "junctions_other"}


def run_figures(folder):
    """The table's figures of one plan-view run: network.csv's last row, and the T junctions'
    share of all junctions (None without any)."""
    network = ydry_case.read_csv(folder / "network.csv")
    last = {key: np.atleast_1d(column)[-1] for key, column in network.items()}
    figures = {key: (int(last[key]) if key in COUNTS else float(last[key])) for key, _, _ in QUANTITIES[:-1]}
    junctions = figures["junctions_T"] + figures["junctions_Y"] + figures["junctions_other"]
    figures["t_share"] = figures["junctions_T"] / junctions if junctions else None
    return figures


def area_exponent(rows):
    """(n, c) of the least-squares line log(mean cell area) = n log(value) + c through the
    completed runs with cells; None where fewer than two values have one."""
    points = [(math.log(row["value"]), math.log(row["figures"]["mean_cell_area_m2"])) for row in rows
              if row["status"] == "completed" and row["figures"]["mean_cell_area_m2"] > 0.0]
    if len({v for v, _ in points}) < 2:
        return None
    v, a = np.array(points).T
    n, c = np.polyfit(v, a, 1)
    return float(n), float(c)


def fig_networks(sweep, rows, value_text, path):
    shown = [row for row in rows if row["figures"] is not None]
    fig, axes = plot_run.plt.subplots(1, len(shown), figsize=(5 * len(shown), 5.2), squeeze=False,
                                      layout="constrained")
    for ax, row in zip(axes[0], shown):
        cells = plot_network.draw_cells(ax, ydry_case.last_frame(row["path"]))
        note = "" if row["status"] == "completed" else f" ({row['status']})"
        ax.set_title(f"{value_text(sweep, row['value'])}: {cells} cells{note}", fontsize=10)
    fig.suptitle(f"The crack networks for different {sweep['axis']}: each cell in its own colour")
    return plot_run.save(fig, path)


def fig_cell_area(sweep, rows, path):
    fig, ax = plot_run.plt.subplots(figsize=(7, 5.5), layout="constrained")
    done = [row for row in rows if row["figures"] is not None and row["figures"]["mean_cell_area_m2"] > 0.0]
    scale = sweep["scale"]
    for row in done:
        marker = "o" if row["status"] == "completed" else "x"
        ax.loglog(row["value"] * scale, row["figures"]["mean_cell_area_m2"] * 1e6, marker, color="C0")
    fit = area_exponent(rows)
    if fit is not None:
        values = np.array([row["value"] for row in done])
        v = np.geomspace(values.min(), values.max(), 50)
        ax.loglog(v * scale, np.exp(fit[1]) * v ** fit[0] * 1e6, "C0-", label=f"least squares: n = {fit[0]:.2f}")
        middle = math.sqrt(values.min() * values.max())
        reference = np.exp(fit[0] * math.log(middle) + fit[1]) * (v / middle) ** 2
        ax.loglog(v * scale, reference * 1e6, "0.5", ls="--", label="n = 2 (cell size proportional)")
        ax.legend()
    unit = f" ({sweep['unit']})" if sweep["unit"] else ""
    ax.set_xlabel(f"{sweep['axis']}{unit}")
    ax.set_ylabel("mean cell area (mm$^2$)")
    ax.set_title(f"Mean cell area against {sweep['axis']}: A ~ {sweep['axis']}$^n$ (x: run not completed)")
    ax.grid(alpha=0.3, which="both")
    return plot_run.save(fig, path)


def cell(row, key, factor):
    value = None if row["figures"] is None else row["figures"][key]
    if value is None:
        return "-"
    return f"{value:d}" if key in COUNTS else f"{value * factor:.4g}"


def table_notes(sweep, rows):
    """The lines under the table (plot_sweep.write_table): the exponent and the definitions."""
    fit = area_exponent(rows)
    return ["", ("Mean cell area against " + sweep["axis"] + ": A ~ " + sweep["axis"] + "^n with n = "
                 + (f"{fit[0]:.3g}" if fit else "- (fewer than two completed runs with cells)")
                 + ", the least-squares line through the completed runs on log-log axes."), "",
            "Definitions: each figure is network.csv's last row (doc/outputs.md); the T share is T "
            "junctions over all junctions."]
