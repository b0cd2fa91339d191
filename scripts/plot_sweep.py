#!/usr/bin/python3
"""Plot the sweeps of a scripts/sweep.py folder like the paper's section 6 (Figs. 25-33) and tabulate them.

Reads OUT/sweep.json and each run's series.csv, cracks.csv, summary.json and last frame, and
writes into --out (default OUT/plots), per sweep NAME:

    NAME_patterns.png   the final crack patterns, one run above the other (Figs. 25, 28, 31)
    NAME_width.png      the mean crack width against time, one curve per value (Figs. 26, 29, 32)
    NAME_length.png     the mean crack length against time (Figs. 27, 30, 33)
    NAME_table.csv      per value: crack count, first-crack time, mean initiation time of the
    NAME_table.md       final cracks, stabilisation time, mean and total final width, mean final
                        length (CSV in s and m; Markdown in min and mm, with the definitions and
                        each quantity's trend with the value)

The cracks counted are the sweep's `cracks`: `surface` (mouth on the top surface, as seen
from above: the Peron sweeps) or `penetrating` (surface cracks that also reach the bottom of
the layer), from cracks.csv. A sweep of plan-view runs (`cracks = "network"`) is tabulated and
drawn by its crack network instead (scripts/plot_sweep_network.py: NAME_networks.png,
NAME_cell_area.png with the exponent of the mean cell area, NAME_table.csv and .md). Runs not
yet completed are shown as far as they went, and marked.

    scripts/plot_sweep.py runs/sweeps
    scripts/plot_sweep.py runs/sweeps --out figures --sweep thickness --warp 3
"""
import csv
import json
import math
import sys
from pathlib import Path

import numpy as np

import plot_run  # (save, frame_data, draw_solid, draw_cracks, MM, MINUTE: the run figures' drawing)
import plot_sweep_network  # (the plan-view sweeps: cracks = "network")
import sweep_plan  # (deck_digest: is a folder's run still its value's?)
from plot_run import MINUTE, MM, plt

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "verification"))
import run_report  # noqa: E402  (load_run, first_crack_time, stabilisation_time)
import ydry_case  # noqa: E402  (script_parser, last_frame_files)

KIND_TEXT = {"surface": "surface cracks (mouth on the top surface)",
             "penetrating": "fully penetrating cracks (from the top surface to the bottom of the layer)"}
QUANTITIES = [  # table column (SI), Markdown heading, factor to its unit
    ("crack_count", "cracks", 1.0),
    ("first_crack_s", "first crack (min)", 1.0 / MINUTE),
    ("mean_initiation_s", "mean initiation (min)", 1.0 / MINUTE),
    ("stabilisation_s", "stable from (min)", 1.0 / MINUTE),
    ("mean_width_m", "mean final width (mm)", MM),
    ("total_width_m", "total final width (mm)", MM),
    ("mean_length_m", "mean final length (mm)", MM),
]


def arguments():
    parser = ydry_case.script_parser(__doc__)
    parser.add_argument("sweep", type=Path, help="a scripts/sweep.py output folder (with sweep.json)")
    parser.add_argument("--out", type=Path, help="folder of the figures and tables (default SWEEP/plots)")
    parser.add_argument("--sweep", dest="names", action="append", metavar="NAME",
                        help="only this sweep (repeatable; default all in sweep.json)")
    parser.add_argument("--warp", type=float, default=1.0,
                        help="displacement magnification of the crack patterns (default 1: the true shape)")
    return parser.parse_args()


# ---- the cracks of one kind, per row of series.csv -----------------------------------------

def counted(cracks, kind):
    """The rows of cracks.csv (a mask) of the cracks of `kind` (surface | penetrating)."""
    keep = cracks["surface"] == 1
    return keep & (cracks["penetrating"] == 1) if kind == "penetrating" else keep


def crack_history(run, kind):
    """The cracks of `kind` at every row time of series.csv: {time_s, count, mean_width_m,
    total_width_m, mean_length_m} (means NaN at rows without one), from cracks.csv."""
    times = run["series"]["time_s"]
    cracks = run["cracks"]
    keep = counted(cracks, kind)
    row = np.searchsorted(times, cracks["time_s"][keep])
    count = np.bincount(row, minlength=len(times))
    total = np.bincount(row, weights=cracks["width_m"][keep], minlength=len(times))
    length = np.bincount(row, weights=cracks["length_m"][keep], minlength=len(times))
    with np.errstate(invalid="ignore", divide="ignore"):
        return {"time_s": times, "count": count, "total_width_m": total,
                "mean_width_m": np.where(count > 0, total / count, math.nan),
                "mean_length_m": np.where(count > 0, length / count, math.nan)}


def mean_initiation_time(run, folder, kind):
    """The mean over the cracks of `kind` open at the last row of the time each first appeared,
    s (None without any): cracks.csv's rows followed through time (run_report.crack_tracks). The
    paper's thickness study speaks of this mean, not of the first crack."""
    end = run["series"]["time_s"][-1]
    starts = [track["time"][0] for track in run_report.crack_tracks(run, folder, counted(run["cracks"], kind))
              if track["time"][-1] == end]
    return float(np.mean(starts)) if starts else None


def run_figures(run, folder, kind, history):
    """The table's figures of one run from its crack history."""
    last = {key: float(history[key][-1]) for key in ("mean_width_m", "total_width_m", "mean_length_m")}
    return {"crack_count": int(history["count"][-1]),
            "first_crack_s": run_report.first_crack_time(history, "count"),
            "mean_initiation_s": mean_initiation_time(run, folder, kind),
            "stabilisation_s": run_report.stabilisation_time(history, "mean_width_m"), **last}


def load_sweep(out, sweep):
    """Each entry of the sweep with its run (None when the folder holds no run yet) and table
    figures: of its cracks, with their history, or of a plan-view sweep's network."""
    network = sweep["cracks"] == "network"
    rows = []
    for entry in sweep["entries"]:
        folder = out / entry["folder"]
        row = {"value": entry["value"], "folder": entry["folder"], "run": None, "status": "not run", "figures": None}
        deck = folder / "deck.toml"
        if "deck_digest" in entry and deck.is_file() and \
                sweep_plan.deck_digest(deck.read_text()) != entry["deck_digest"]:
            row["status"] = "holds another deck's run: run the sweep again"
        elif (folder / "summary.json").is_file() and (folder / ("network.csv" if network else "cracks.csv")).is_file():
            run = run_report.load_run(folder, "plot_sweep")
            done = run["summary"]["completed"]
            row.update(run=run, path=folder, status="completed" if done else f"unfinished, at {run['summary']['time_s']:g} s")
            if network:
                row["figures"] = plot_sweep_network.run_figures(folder)
            else:
                row["history"] = crack_history(run, sweep["cracks"])
                row["figures"] = run_figures(run, folder, sweep["cracks"], row["history"])
        rows.append(row)
    return rows


def value_text(sweep, value):
    """A value as the figures show it: `E = 4 MPa`."""
    shown = f"{value * sweep['scale']:g}" if isinstance(value, (int, float)) else str(value)
    return f"{sweep['axis']} = {shown}{' ' + sweep['unit'] if sweep['unit'] else ''}"


def figure_title(sweep, index, text):
    figures = sweep.get("figures", [])
    return f"{text} (paper Fig. {figures[index]})" if len(figures) > index else text


# ---- figures -------------------------------------------------------------------------------

def fig_patterns(sweep, rows, path, warp):
    """The last frame of every run, deformed warp x, coloured by moisture, with the broken joints
    and a marker over the mouth of each counted crack; panels to one x scale."""
    shown = [row for row in rows if row["run"] is not None]
    data = [plot_run.frame_data(ydry_case.last_frame_files(row["path"]), warp) for row in shown]
    heights = [np.ptp(solid["x0"][:, 1]) for solid, _ in data]
    left = min(solid["x0"][:, 0].min() for solid, _ in data)
    width = max(solid["x0"][:, 0].max() for solid, _ in data) - left
    w = np.concatenate([solid["point_data"]["moisture"] for solid, _ in data])
    fig, axes = plt.subplots(len(data), 1, figsize=(12, 1.2 + sum(0.9 + 10 * h / width for h in heights)),
                             gridspec_kw={"height_ratios": [0.09 * width + h for h in heights]},
                             squeeze=False, layout="constrained")
    for ax, row, (solid, lines) in zip(axes[:, 0], shown, data):
        image = plot_run.draw_solid(ax, solid, solid["point_data"]["moisture"], cmap="YlGnBu",
                                    vmin=np.nanmin(w), vmax=np.nanmax(w))
        plot_run.draw_cracks(ax, lines)
        cracks, end = row["run"]["cracks"], row["history"]["time_s"][-1]
        at_end = (cracks["time_s"] == end) & counted(cracks, sweep["cracks"])
        top = solid["shown"][:, 1].max() * MM
        ax.plot(cracks["x_m"][at_end] * MM, np.full(np.count_nonzero(at_end), top), "rv", ms=6, clip_on=False)
        note = "" if row["status"] == "completed" else f" ({row['status']})"
        ax.set_title(f"{value_text(sweep, row['value'])}: {np.count_nonzero(at_end)} {sweep['cracks']} cracks "
                     f"(red marks), t = {end / MINUTE:.0f} min{note}", fontsize=10, loc="left")
        ax.set_xlim((left - 0.01 * width) * MM, (left + 1.01 * width) * MM)
        ax.set_ylabel("y (mm)")
    axes[-1, 0].set_xlabel("x (mm)")
    fig.suptitle(figure_title(sweep, 0, f"Final crack patterns for different {sweep['axis']}: moisture, broken "
                                        f"joints in magenta, displacements x{warp:g}"))
    fig.colorbar(image, ax=axes[:, 0].tolist(), label="moisture content w (-)", aspect=40)
    return plot_run.save(fig, path)


def fig_evolution(sweep, rows, path, key, text, index):
    """The mean width or length of the counted cracks against time, one curve per run; a dot
    marks where the width stabilises."""
    fig, ax = plt.subplots(figsize=(9, 5), layout="constrained")
    for row in rows:
        if row["run"] is None:
            continue
        history = row["history"]
        note = "" if row["status"] == "completed" else f" ({row['status']})"
        line, = ax.plot(history["time_s"] / MINUTE, history[key] * MM, label=value_text(sweep, row["value"]) + note)
        stable = row["figures"]["stabilisation_s"]
        if key == "mean_width_m" and stable is not None:
            at = np.searchsorted(history["time_s"], stable)
            ax.plot(stable / MINUTE, history[key][at] * MM, "o", color=line.get_color())
    ax.set_title(figure_title(sweep, index, f"Evolution of the average {text} for different {sweep['axis']}"))
    ax.set_xlabel("time (min)")
    ax.set_ylabel(f"mean {text} (mm), {KIND_TEXT[sweep['cracks']].split(' (')[0]}")
    if key == "mean_width_m":
        ax.plot([], [], "ko", label=f"stable from (within {100 * run_report.STABLE_FRACTION:g} % of final)")
    ax.legend(fontsize=9)
    ax.grid(alpha=0.3)
    return plot_run.save(fig, path)


# ---- the table -----------------------------------------------------------------------------

def trend(rows, key):
    """How a figure changes as the value grows: rises, falls (each "with ties" where two values
    give the same), no change, mixed, or n/a when a run is not completed or the figure missing."""
    if any(row["status"] != "completed" for row in rows) or len(rows) < 2:
        return "n/a"
    values = [v for _, v in sorted((row["value"], row["figures"][key]) for row in rows)]
    if any(v is None or not math.isfinite(v) for v in values):
        return "n/a"
    steps = np.sign(np.diff(values))
    ties = " with ties" if (steps == 0).any() else ""
    return ("no change" if (steps == 0).all() else "rises" + ties if (steps >= 0).all() else
            "falls" + ties if (steps <= 0).all() else "mixed")


def cell(row, key, factor):
    """A figure of the Markdown table in its unit; `never` for a time that never came (no
    crack), `not reached` for a width that is not stable, `-` for a run not made or a mean
    without cracks."""
    value = None if row["run"] is None else row["figures"][key]
    if row["run"] is not None and value is None:
        return "not reached" if key == "stabilisation_s" else "never"
    if value is None or not math.isfinite(value):
        return "-"
    return f"{value:d}" if key == "crack_count" else f"{value * factor:.4g}"


def write_table(sweep, rows, out, quantities, what, cell_text, notes):
    """NAME_table.csv (SI) and NAME_table.md, one row per value: `quantities` (column, heading,
    factor to its unit), `what` the title's last words, cell_text(row, key, factor) a Markdown
    cell, then the lines `notes`; returns the Markdown."""
    name = sweep["name"]
    with open(out / f"{name}_table.csv", "w", newline="") as f:
        writer = csv.writer(f)
        writer.writerow(["value", "folder", "status"] + [key for key, _, _ in quantities])
        for row in rows:
            figures = row["figures"] or {}
            writer.writerow([row["value"], row["folder"], row["status"]]
                            + ["" if figures.get(key) is None else repr(figures[key]) for key, _, _ in quantities])
    unit = f" ({sweep['unit']})" if sweep["unit"] else ""
    lines = [f"# Sweep {name}: {sweep['axis']}{unit}, {what}", "",
             f"| {sweep['axis']}{unit} | run | " + " | ".join(head for _, head, _ in quantities) + " |",
             "|---" * (len(quantities) + 2) + "|"]
    for row in rows:
        cells = [cell_text(row, key, factor) for key, _, factor in quantities]
        shown = f"{row['value'] * sweep['scale']:g}" if isinstance(row["value"], (int, float)) else row["value"]
        note = "" if row["status"] == "completed" else f" ({row['status']})"
        lines.append(f"| {shown} | {row['folder']}{note} | " + " | ".join(cells) + " |")
    text = "\n".join(lines + notes) + "\n"
    (out / f"{name}_table.md").write_text(text)
    return text


def write_tables(sweep, rows, out):
    """The crack sweeps' tables (write_table): in min and mm, with definitions and trends."""
    notes = ["", f"With larger {sweep['axis']}: " + "; ".join(f"{head.split(' (')[0]} {trend(rows, key)}"
                                                           for key, head, _ in QUANTITIES) + ".", "",
             "Definitions: the cracks counted are the rows of cracks.csv with `surface` 1"
             + (" and `penetrating` 1" if sweep["cracks"] == "penetrating" else "")
             + "; final: the last row; first crack: the first row time with one; mean initiation: the mean "
             "over the final cracks of the row time each first appeared (cracks followed by their mouth x, "
             "matched within two surface elements); stable from: the earliest "
             f"row time from which on their mean width stays within {100 * run_report.STABLE_FRACTION:g} % "
             "of its final value (not reached: only the last row is); widths are mouth openings, lengths "
             "the summed lengths of a crack's broken joints."]
    return write_table(sweep, rows, out, QUANTITIES, KIND_TEXT[sweep["cracks"]], cell, notes)


def main():
    args = arguments()
    manifest = args.sweep / "sweep.json"
    if not manifest.is_file():
        print(f"plot_sweep: {args.sweep} holds no sweep.json (scripts/sweep.py writes it)", file=sys.stderr)
        return 2
    sweeps = json.loads(manifest.read_text())["sweeps"]
    unknown = set(args.names or []) - {sweep["name"] for sweep in sweeps}
    if unknown:
        print(f"plot_sweep: no sweep {', '.join(sorted(unknown))} in {manifest}", file=sys.stderr)
        return 2
    out = args.out or args.sweep / "plots"
    out.mkdir(parents=True, exist_ok=True)
    for sweep in sweeps:
        if args.names and sweep["name"] not in args.names:
            continue
        rows = load_sweep(args.sweep, sweep)
        written = [out / f"{sweep['name']}_table.csv", out / f"{sweep['name']}_table.md"]
        if sweep["cracks"] == "network":
            print(write_table(sweep, rows, out, plot_sweep_network.QUANTITIES, "the plan-view crack network",
                              plot_sweep_network.cell, plot_sweep_network.table_notes(sweep, rows)))
            if any(row["run"] is not None for row in rows):
                written += [plot_sweep_network.fig_networks(sweep, rows, value_text, out / f"{sweep['name']}_networks.png"),
                            plot_sweep_network.fig_cell_area(sweep, rows, out / f"{sweep['name']}_cell_area.png")]
        else:
            print(write_tables(sweep, rows, out))
            if any(row["run"] is not None for row in rows):
                written += [fig_patterns(sweep, rows, out / f"{sweep['name']}_patterns.png", args.warp),
                            fig_evolution(sweep, rows, out / f"{sweep['name']}_width.png", "mean_width_m", "crack width", 1),
                            fig_evolution(sweep, rows, out / f"{sweep['name']}_length.png", "mean_length_m",
                                          "crack length", 2)]
        print(f"plot_sweep: {', '.join(path.name for path in written)} in {out}\n")
    return 0


if __name__ == "__main__":
    sys.exit(main())
