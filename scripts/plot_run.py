#!/usr/bin/python3
"""Plot a ydry run like the paper's section 5 (Figs. 18-24) and write a short report.

Reads the run's series.csv, cracks.csv, surface.csv, summary.json and .pvd frames, and
writes into --out (default RUN/plots):

    fig18_moisture.png                 mean moisture, water lost and water balance vs time
    fig19_crack_pattern.png            deformed solid coloured by moisture, cracks, 4-6 times
    fig20_vertical_displacement.png    the final u_y field
    fig21_horizontal_displacement.png  the final u_x field
    fig22_surface_displacement.png     u_y (and u_x) of the top surface along x, several times
    fig23_crack_width.png              the width of each crack vs time, the mean width
    fig24_crack_length.png             the length of each crack vs time
    report.md                          crack count and widths, right-end displacement, the
                                       times of the first crack and of stabilisation

    scripts/plot_run.py runs/drying_layer
    scripts/plot_run.py runs/drying_layer --out figures --frames 6 --warp 20

A moisture-only run has no cracks.csv or surface.csv: the figures that need them are left
out and the report says so. Exits 2 on a folder that is not a ydry run.
"""
import math
import sys
from pathlib import Path

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from matplotlib.collections import LineCollection  # noqa: E402
from matplotlib.colors import TwoSlopeNorm  # noqa: E402
from matplotlib.tri import Triangulation  # noqa: E402

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "verification"))
import run_report  # noqa: E402  (the report: crack tracks, stabilisation, right-end displacement)
import ydry_case  # noqa: E402  (run folders: tables, frames, crack displacement)

MM, MINUTE = 1e3, 60.0   # the figures show mm and minutes, as the paper does


def arguments():
    parser = ydry_case.script_parser(__doc__)
    parser.add_argument("run", type=Path, help="a ydry output folder (ydry -o)")
    parser.add_argument("--out", type=Path, help="folder for the PNGs and report.md (default RUN/plots)")
    parser.add_argument("--frames", type=int, default=5, choices=range(4, 7),
                        help="times shown in Fig. 19 (4 to 6, default 5)")
    parser.add_argument("--warp", type=float, default=10.0,
                        help="displacement magnification of the deformed shapes (default 10)")
    return parser.parse_args()


def save(fig, path):
    fig.savefig(path, dpi=150)
    plt.close(fig)
    return path


def no_data(ax, text):
    ax.text(0.5, 0.5, text, transform=ax.transAxes, ha="center", va="center", color="0.4")


def on_grid(times, track, key):
    """A track's values on the row times, NaN where the crack was narrower than the threshold."""
    values = np.full(len(times), np.nan)
    values[np.searchsorted(times, track["time"])] = track[key]
    return values


# ---- the report ------------------------------------------------------------------------

def report(run, folder, figures, skipped):
    s, series = run["summary"], run["series"]
    count = "n/a" if s["crack_count"] is None else s["crack_count"]
    surface_count = "n/a" if s["surface_crack_count"] is None else s["surface_crack_count"]
    first, stable = run_report.first_crack_time(series), run_report.stabilisation_time(series)
    ux, ux_from = run_report.right_end(run)
    fmt_time = lambda t: "never" if t is None else f"{t:g} s ({t / MINUTE:.0f} min)"  # noqa: E731
    fmt_mm = lambda v: "n/a" if v is None or not math.isfinite(v) else f"{v * MM:.4g} mm"  # noqa: E731
    first_text = "n/a (no solid)" if run["cracks"] is None else fmt_time(first)
    end = float(series["time_s"][-1])
    stable_text = ("n/a (no crack)" if first is None else "not reached" if stable is None else
                   f"{fmt_time(stable)}; held for the last {(end - stable) / MINUTE:.0f} min of the run "
                   f"({np.count_nonzero(series['time_s'] >= stable)} rows)")
    status = "completed" if s["completed"] else f"NOT completed (stopped at t = {s['time_s']:g} s)"
    lines = [f"# ydry run {s['name']}: {folder}", "",
             f"{status}; {s['elements']} elements, {s['moisture_steps']} coupling steps, "
             f"wall {s['wall_s']:.0f} s, version {s['version']}", "",
             "| quantity | value |", "|---|---|",
             f"| end time | {fmt_time(s['time_s'])} |",
             f"| final mean moisture | {s['mean_moisture']:.4f} |",
             f"| crack count: open on the top surface / all | {surface_count} / {count} |",
             f"| mean final crack width: surface cracks / all | {fmt_mm(s['mean_surface_crack_width_m'])} / "
             f"{fmt_mm(s['mean_crack_width_m'])} |",
             f"| total final crack width: surface cracks / all | {fmt_mm(s['total_surface_crack_width_m'])} / "
             f"{fmt_mm(s['total_crack_width_m'])} |",
             f"| horizontal displacement of the right end of the surface | {fmt_mm(ux)} |",
             f"| time of the first crack | {first_text} |",
             f"| time of stabilisation | {stable_text} |",
             "", "Definitions:",
             "- crack count and widths: the last row of series.csv (summary.json); a crack counts "
             "when its mouth opening exceeds run.crack_width_threshold; a surface crack has its mouth "
             "on the top surface (the outer boundary facing up: seen from above), the others open "
             "on the ends, rise from an interface with another material or are internal.",
             f"- right-end displacement: {ux_from}.",
             "- first crack: the first row of series.csv with crack_count >= 1 (resolution: the "
             "series interval).",
             f"- stabilisation: the earliest row time t_s of series.csv such that for every row "
             f"t >= t_s, |mean surface crack width(t) - its final value| <= "
             f"{100 * run_report.STABLE_FRACTION:g} % of "
             "the final value; not reached when no surface crack is open at the end or only the last "
             "row is within (still changing).",
             "", "Figures: " + ", ".join(p.name for p in figures)]
    if skipped:
        lines.append("Left out: " + "; ".join(skipped))
    return "\n".join(lines) + "\n"


# ---- figures ---------------------------------------------------------------------------

def fig_moisture(run, path):
    """Fig. 18: the mean moisture, the water lost and the water balance error against time."""
    series = run["series"]
    minutes = series["time_s"] / MINUTE
    fig, axes = plt.subplots(3, 1, figsize=(8, 8), sharex=True, layout="constrained")
    axes[0].plot(minutes, series["mean_moisture"], "b-")
    axes[0].set_ylabel("mean moisture content w (-)")
    axes[0].set_title("Evolution of the soil moisture content (paper Fig. 18)")
    axes[1].plot(minutes, series["water_lost_kg"] * 1e3, "g-")
    axes[1].set_ylabel("water lost (g)")
    error = series["water_balance_error"]
    axes[2].semilogy(minutes[error > 0], error[error > 0], "k.-")  # exact zeros have no place on it
    axes[2].set_ylabel("water balance error (-)")
    axes[2].set_xlabel("time (min)")
    for ax in axes:
        ax.grid(alpha=0.3)
    return save(fig, path)


def frame_data(files, warp):
    """A frame's solid and cracks with their points moved by warp x the displacement."""
    bulk, cracks = ydry_case.read_grid(files[0]), ydry_case.read_grid(files[1])
    solid = ydry_case.solid_arrays(bulk)
    solid["shown"] = solid["x0"] + warp * solid["u"]
    lines = ydry_case.crack_arrays(cracks)
    if len(lines["ends"]):
        u = ydry_case.crack_displacement(bulk, cracks)[:, :2]
        lines["ends"] = lines["ends"] + (warp - 1.0) * u[lines["cells"]]
    return solid, lines


def draw_solid(ax, solid, values, **style):
    """The (warped) solid shaded by per-corner values: colours jump across broken joints."""
    tri = Triangulation(solid["shown"][:, 0] * MM, solid["shown"][:, 1] * MM, solid["cells"])
    image = ax.tripcolor(tri, values, shading="gouraud", **style)
    ax.set_aspect("equal")
    return image


def draw_cracks(ax, lines):
    if len(lines["ends"]):
        ax.add_collection(LineCollection(lines["ends"] * MM, colors="magenta", linewidths=1.2))


def spread(start, stop, count):
    """Up to `count` indices in [start, stop) spread evenly, the first and the last included."""
    return np.unique(np.round(np.linspace(start, stop - 1, count)).astype(int))


def chosen_frames(run, count):
    """`count` frame times evenly spread from the first frame with a broken joint (or the first
    after t = 0) to the last."""
    times = list(run["frames"])
    cracked = [t for t in times if ydry_case.read_grid(run["frames"][t][1]).GetNumberOfCells()]
    start = times.index(cracked[0]) if cracked else min(1, len(times) - 1)
    return [times[i] for i in spread(start, len(times), count)]


def fig_pattern(run, path, count, warp):
    """Fig. 19a: the deformed solid coloured by moisture with the cracks, at several times."""
    times = chosen_frames(run, count)
    data = [frame_data(run["frames"][t], warp) for t in times]
    w = np.concatenate([solid["point_data"]["moisture"] for solid, _ in data])
    lo, hi = np.nanmin(w), np.nanmax(w)
    x0 = data[0][0]["x0"]
    aspect = np.ptp(x0[:, 1]) / np.ptp(x0[:, 0])
    fig, axes = plt.subplots(len(times), 1, figsize=(12, 0.8 + len(times) * (0.5 + 10 * aspect)),
                             squeeze=False, layout="constrained")
    for ax, t, (solid, lines) in zip(axes[:, 0], times, data):
        image = draw_solid(ax, solid, solid["point_data"]["moisture"], cmap="YlGnBu", vmin=lo, vmax=hi)
        draw_cracks(ax, lines)
        ax.set_title(f"t = {t / MINUTE:.0f} min, broken joints: {len(lines['ends'])}", fontsize=10,
                     loc="left")
        ax.set_ylabel("y (mm)")
    axes[-1, 0].set_xlabel("x (mm)")
    fig.suptitle(f"Crack initiation and propagation (paper Fig. 19a): moisture, broken joints in magenta, "
                 f"displacements x{warp:g}")
    fig.colorbar(image, ax=axes[:, 0].tolist(), label="moisture content w (-)", aspect=40)
    return save(fig, path)


def fig_field(run, path, component, warp):
    """Figs. 20-21: the final displacement component (0: x, 1: y) on the deformed solid."""
    solid, lines = frame_data(list(run["frames"].values())[-1], warp)
    u = solid["u"][:, component] * MM
    limit = max(np.abs(u).max(), 1e-12)
    x0 = solid["x0"]
    fig, ax = plt.subplots(figsize=(12, 1.5 + 10 * np.ptp(x0[:, 1]) / np.ptp(x0[:, 0])), layout="constrained")
    image = draw_solid(ax, solid, u, cmap="RdBu_r", norm=TwoSlopeNorm(0.0, -limit, limit))
    draw_cracks(ax, lines)
    name, figure = (("horizontal", 21), ("vertical", 20))[component]
    ax.set_title(f"Final {name} displacement, t = {max(run['frames']) / MINUTE:.0f} min "
                 f"(paper Fig. {figure}); displacements x{warp:g}")
    ax.set_xlabel("x (mm)")
    ax.set_ylabel("y (mm)")
    fig.colorbar(image, ax=ax, label=f"u$_{'xy'[component]}$ (mm)", aspect=10, shrink=0.8)
    return save(fig, path)


def fig_surface(run, path):
    """Fig. 22: u_y (and u_x) of the top surface along x at up to 8 frame times; each unbroken
    segment is its own line, so the curves jump at the cracks."""
    surface = run["surface"]
    all_times = np.unique(surface["time_s"])
    times = all_times[spread(0, len(all_times), 8)]
    colors = plt.cm.viridis(np.linspace(0, 0.9, len(times)))
    fig, axes = plt.subplots(2, 1, figsize=(10, 7), sharex=True, layout="constrained")
    for t, color in zip(times, colors):
        at = surface["time_s"] == t
        for k, segment in enumerate(np.unique(surface["segment"][at])):
            rows = at & (surface["segment"] == segment)
            label = f"{t / MINUTE:.0f} min" if k == 0 else None
            axes[0].plot(surface["x0_m"][rows] * MM, surface["uy_m"][rows] * MM, color=color, label=label)
            axes[1].plot(surface["x0_m"][rows] * MM, surface["ux_m"][rows] * MM, color=color)
    axes[0].set_title("Displacement of the soil surface at different times (paper Fig. 22)")
    axes[0].set_ylabel("vertical displacement u$_y$ (mm)")
    axes[1].set_ylabel("horizontal displacement u$_x$ (mm)")
    axes[1].set_xlabel("initial position along the surface x$_0$ (mm)")
    axes[0].legend(fontsize=8, title="time", loc="upper left", bbox_to_anchor=(1.01, 1.0))
    for ax in axes:
        ax.grid(alpha=0.3)
    return save(fig, path)


def fig_tracks(run, tracks, path, key, figure):
    """Figs. 23-24: the width or length of each crack against time, cracks numbered by x."""
    series = run["series"]
    times = series["time_s"]
    panels = 2 if key == "width" else 1
    fig, axes = plt.subplots(panels, 1, figsize=(9, 3.8 * panels + 0.5), sharex=True, squeeze=False,
                             layout="constrained")
    ax = axes[0, 0]
    for number, track in enumerate(tracks, start=1):  # markers tell apart cracks whose curves coincide
        ax.plot(times / MINUTE, on_grid(times, track, key) * MM, marker="os^vD<>ph*"[(number - 1) % 10], ms=4,
                mfc="none", label=f"crack {number} (x = {track['x'][-1] * MM:.1f} mm)")
    if tracks:
        ax.legend(fontsize=8, ncol=2)
    else:
        no_data(ax, "no crack wider than run.crack_width_threshold")
    ax.set_title(f"Evolution of the crack {key} (paper Fig. {figure})")
    ax.set_xlim(0.0, times[-1] / MINUTE)
    ax.set_ylabel(f"crack {'mouth opening' if key == 'width' else 'length'} (mm)")
    if panels == 2:
        mean = axes[1, 0]
        mean.plot(times / MINUTE, series["mean_surface_crack_width_m"] * MM, "k-", label="mean width, surface cracks")
        mean.plot(times / MINUTE, series["mean_crack_width_m"] * MM, "k:", label="mean width, all cracks")
        stable = run_report.stabilisation_time(series)
        if stable is not None:
            final, band = series["mean_surface_crack_width_m"][-1] * MM, run_report.STABLE_FRACTION
            mean.axhspan(final * (1 - band), final * (1 + band), color="0.85",
                         label=f"final mean width $\\pm${100 * band:g} %")
            mean.axvline(stable / MINUTE, color="r", ls="--",
                         label=f"stabilised at {stable / MINUTE:.0f} min")
        count = mean.twinx()
        count.step(times / MINUTE, series["surface_crack_count"], "b-", where="post", alpha=0.6)
        count.step(times / MINUTE, series["crack_count"], "b:", where="post")
        count.set_ylabel("crack count: surface (solid), all (dotted)", color="b")
        mean.set_ylabel("mean crack width (mm)")
        mean.legend(fontsize=8, loc="upper left")
    for row in axes[:, 0]:
        row.grid(alpha=0.3)
    axes[-1, 0].set_xlabel("time (min)")
    return save(fig, path)


def main():
    args = arguments()
    run = run_report.load_run(args.run, "plot_run")
    out = args.out or args.run / "plots"
    out.mkdir(parents=True, exist_ok=True)
    figures, skipped = [fig_moisture(run, out / "fig18_moisture.png")], []
    if run["cracks"] is None:
        skipped.append("Figs. 19-24 (no cracks.csv: a moisture-only run has no solid)")
    else:
        figures.append(fig_pattern(run, out / "fig19_crack_pattern.png", args.frames, args.warp))
        figures.append(fig_field(run, out / "fig20_vertical_displacement.png", 1, args.warp))
        figures.append(fig_field(run, out / "fig21_horizontal_displacement.png", 0, args.warp))
        if run["surface"] is None:
            skipped.append("Fig. 22 (no surface.csv in the run: see its log.txt)")
        else:
            figures.append(fig_surface(run, out / "fig22_surface_displacement.png"))
        tracks = run_report.crack_tracks(run, args.run)
        figures.append(fig_tracks(run, tracks, out / "fig23_crack_width.png", "width", 23))
        figures.append(fig_tracks(run, tracks, out / "fig24_crack_length.png", "length", 24))
    text = report(run, args.run, figures, skipped)
    (out / "report.md").write_text(text)
    print(text, end="")
    print(f"plot_run: {len(figures)} figures and report.md in {out}")


if __name__ == "__main__":
    main()
