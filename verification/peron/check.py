#!/usr/bin/python3
"""Verification case peron: the paper's section 5 simulation of Peron et al. (2009).

Runs ydry on inputs/peron/peron.toml (a 295 x 12 mm silt layer drying on a notched rigid base
for 460,000 s; 8-9 minutes on 2 cores) on every core, or with --run DIR checks a run of that deck
made before, and compares its final figures with the experiment and the paper: the crack
count and mean width of the cracks open on the top surface (7 +- 1; 0.836 mm +- 10 %), the horizontal displacement of the
right end of the top surface (|u_x| 0.67 mm +- 15 %), a mean width stable over the last 20 %
of the run, and blocks that curl up at the cracks (README.md defines each). Prints
`peron METRIC VALUE TOLERANCE PASS|FAIL` and exits 1 if a check fails, 2 if DIR is not a
ydry run with cracks and a top surface.
"""
import json
import math
import os
import sys
import tomllib
from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE.parent))
sys.path.insert(0, str(HERE.parents[1] / "scripts"))
import run_report  # noqa: E402
import sweep_plan  # noqa: E402  (resolved_deck, deck_key: how scripts/sweep.py tells decks apart)
import ydry_case  # noqa: E402

DECK = ydry_case.REPO / "inputs" / "peron" / "peron.toml"
CRACKS, CRACKS_TOLERANCE = 7, 1         # experiment (Peron et al. 2009) and paper Fig. 19
MEAN_WIDTH = 0.836e-3                   # m, experiment (paper: 0.841 mm)
WIDTH_TOLERANCE = 0.10                  # relative
RIGHT_END_UX = 6.7e-4                   # m, magnitude (paper 6.73e-4, UDEC 6.64e-4)
RIGHT_END_TOLERANCE = 0.15              # relative
STABLE_WINDOW = 0.2                     # the last fifth of the run's time
CURLING_FRACTION = 0.7                  # of the cracks whose mouth is on the top surface
MM = 1e3


def number(value):
    """A summary.json number; null (NaN in the run) as NaN."""
    return math.nan if value is None else float(value)


def run_deck(ydry, outdir):
    """Runs the deck into outdir on every core (ydry's default once OMP_NUM_THREADS is unset);
    prints the wall time. False if ydry failed."""
    os.environ.pop("OMP_NUM_THREADS", None)
    print(f"# running ydry on {DECK.relative_to(ydry_case.REPO)} into {outdir} on every core "
          "(8-9 minutes on 2 cores)", flush=True)
    wall = ydry_case.run_ydry(ydry, DECK, outdir)
    if wall is not None:
        print(f"# ydry wall time {wall:.0f} s ({wall / 60:.1f} min)")
    return wall is not None


def flat(table, prefix=""):
    """{dotted key: value} of a TOML table's leaves (an array of tables is one value)."""
    leaves = {}
    for key, value in table.items():
        if isinstance(value, dict):
            leaves.update(flat(value, f"{prefix}{key}."))
        else:
            leaves[f"{prefix}{key}"] = value
    return leaves


def deck_differences(outdir, ydry):
    """Every value of the run's deck.toml that differs from the shipped deck as `ydry check`
    resolves it (defaults included; the mesh compared by its contents, numbers by value), as
    `key = run value (deck value)` strings; None if the run has no deck.toml or ydry cannot
    resolve the deck."""
    path = outdir / "deck.toml"
    try:
        shipped_text = sweep_plan.resolved_deck(ydry, str(DECK), [])
    except (OSError, sweep_plan.SweepError):
        return None
    if not path.is_file():
        return None
    used, shipped = (flat(json.loads(sweep_plan.deck_key(text))) for text in (path.read_text(), shipped_text))
    return [f"{key} = {json.dumps(used.get(key, '(missing)'))} (deck {json.dumps(shipped.get(key, '(missing)'))})"
            for key in sorted(set(used) | set(shipped)) if used.get(key) != shipped.get(key)]


def final_cracks(run, t, size):
    """The cracks counted at time t (cracks.csv), ordered by x, each {x, width, surface, first}:
    the current x of the mouth, its width and whether it is on the top surface at t, and the
    first time its track (crack tracking of run_report, matching within two surface elements)
    was seen."""
    found = []
    for track in run_report.track_cracks(run["cracks"], 2.0 * size):
        at = np.flatnonzero(track["time"] == t)
        if len(at):
            found.append({"x": float(track["x"][at[0]]), "width": float(track["width"][at[0]]),
                          "surface": bool(track["surface"][at[0]]), "first": float(track["time"][0])})
    return sorted(found, key=lambda crack: crack["x"])


def end_blocks(cracks, left, right):
    """The words that name the end blocks, the top between each end and its nearest surface
    crack: the ends' movements follow their lengths, so a small change of the run that moves
    the last crack moves the right end with it."""
    top = [crack["x"] for crack in cracks if crack["surface"]]
    if not top:
        return ""
    return (f"; the end blocks: {left * MM:g} to {top[0] * MM:.1f} mm ({(top[0] - left) * MM:.1f} mm long) and "
            f"{top[-1] * MM:.1f} to {right * MM:g} mm ({(right - top[-1]) * MM:.1f} mm long)")


def surface_mouths(surface, t):
    """The crack mouths on the top surface at time t (surface.csv): one per surface vertex that
    has several points (the sides of a crack, on different segments), each {x: the current x of
    the vertex (mean of its sides), gap: how far its right side (the side on the block further
    right) has moved from its left side, u_x right - u_x left (negative where they overlap),
    margins: the u_y of each side minus the mean u_y of its block}. A block is a segment (an unbroken stretch of the surface); its mean u_y is the mean
    along its length, the trapezoidal integral of u_y over x0 divided by the segment's span."""
    at = surface["time_s"] == t
    x0, y0, ux, uy, segment = (surface[k][at] for k in ("x0_m", "y0_m", "ux_m", "uy_m", "segment"))
    block_mean, block_x0 = {}, {}
    for block in np.unique(segment):
        rows = segment == block
        span = np.ptp(x0[rows])
        block_mean[block] = np.trapz(uy[rows], x0[rows]) / span if span > 0 else float(uy[rows][0])
        block_x0[block] = float(np.mean(x0[rows]))
    _, vertex, count = np.unique(np.c_[x0, y0], axis=0, return_inverse=True, return_counts=True)
    vertex = vertex.ravel()
    mouths = []
    for v in np.flatnonzero(count > 1):
        sides = np.flatnonzero(vertex == v)
        left, right = sorted(sides, key=lambda p: block_x0[segment[p]])[::len(sides) - 1]
        mouths.append({"x": float(np.mean(x0[sides] + ux[sides])), "gap": float(ux[right] - ux[left]),
                       "margins": [float(uy[p] - block_mean[segment[p]]) for p in sides]})
    return mouths


def curling(cracks, mouths, size):
    """Gives each surface crack (mouth on the top surface in cracks.csv) its break of the top:
    the mouth of surface.csv nearest to it within half a surface element, each mouth to one
    crack, nearest pairs first (None: the crack meets the top at a joint that is softening but
    not yet broken, so the top is not split there). Returns the fraction of the surface cracks
    with a break whose sides both stand above the mean u_y of their blocks (NaN if none)."""
    for crack in cracks:
        crack["mouth"] = None
    surface = [crack for crack in cracks if crack["surface"]]
    pairs = sorted((abs(mouth["x"] - crack["x"]), c, m) for c, crack in enumerate(surface)
                   for m, mouth in enumerate(mouths))
    taken = set()
    for distance, c, m in pairs:
        if distance <= 0.5 * size and surface[c]["mouth"] is None and m not in taken:
            taken.add(m)
            surface[c]["mouth"] = mouths[m]
    curled = sum(crack["mouth"] is not None and all(margin > 0 for margin in crack["mouth"]["margins"])
                 for crack in surface)
    return curled / len(surface) if surface else math.nan


def print_cracks(cracks):
    print("# crack   x (mm)  width (mm)  first seen (s)  top mouth: u_y above its blocks' means (um)")
    for k, crack in enumerate(cracks, start=1):
        mouth = crack["mouth"]
        sides = ("no (mouth below the top)" if not crack["surface"] else
                 "no break of the top (its joint there softens, unbroken)" if mouth is None else
                 " / ".join(f"{margin * 1e6:+.1f}" for margin in mouth["margins"]))
        print(f"# {k:5d} {crack['x'] * MM:8.2f} {crack['width'] * MM:11.4f} {crack['first']:15g}  {sides}")


def check_run(run, outdir, verdicts, ydry):
    s, series, surface = run["summary"], run["series"], run["surface"]
    deck = tomllib.loads(DECK.read_text())
    print(f"# run {outdir}: ydry {s['version']}, {s['threads']} threads, wall {s['wall_s']:.0f} s, "
          f"{s['elements']} elements, {s['moisture_steps']} coupling steps")
    differences = deck_differences(outdir, ydry)
    deck_name = DECK.relative_to(ydry_case.REPO)
    print(f"# the run's deck.toml could not be compared with {deck_name} (no deck.toml, or {ydry} check failed)"
          if differences is None else
          f"# the run's deck.toml is {deck_name} as ydry resolves it, every value alike" if not differences else
          f"# the run's deck.toml differs from {deck_name}: " + "; ".join(differences))
    done = bool(s["completed"])
    if not done:
        print(f"# {outdir} is not a completed run: summary.json says completed = false at "
              f"t = {s['time_s']:g} s (still running, stopped or interrupted); the figures below "
              "are those at that time")
    verdicts.check("completed", done, "true", done)
    deck_end = deck["run"]["end_time"]
    verdicts.check("end_time_s", f"{s['time_s']:g}", f"{deck_end:g}", s["time_s"] == deck_end)

    # The experiment counts and measures the cracks from above (the paper's seven are surface
    # cracks; the crack it sees rising from the base is not among them).
    count = s["surface_crack_count"]
    print(f"# cracks: {count} open on the top surface, {s['crack_count']} in all (the others rise from "
          f"the base), mean width of all {number(s['mean_crack_width_m']) * MM:.4f} mm")
    if "closed_crack_count" in s:  # runs of ydry before this field have not
        print(f"# closed cracks (mouth no wider than run.crack_width_threshold, counted in neither): "
              f"{s['closed_crack_count']}")
    verdicts.check("surface_crack_count", count, f"{CRACKS}+-{CRACKS_TOLERANCE}",
                   abs(count - CRACKS) <= CRACKS_TOLERANCE)

    width = number(s["mean_surface_crack_width_m"])
    print(f"# mean final surface crack width {width * MM:.4f} mm (experiment {MEAN_WIDTH * MM:.3f} mm, "
          f"paper 0.841 mm), total {number(s['total_surface_crack_width_m']) * MM:.4f} mm (paper 5.89 mm)")
    verdicts.below("mean_surface_crack_width_rel_error", ydry_case.relative_error(width, MEAN_WIDTH),
                   WIDTH_TOLERANCE)

    ux, source = run_report.right_end(run)
    t_last = float(surface["time_s"][-1])
    last = surface["time_s"] == t_last
    print(f"# right end of the top surface, (x0, y0) = ({surface['x0_m'][last][-1] * MM:g}, "
          f"{surface['y0_m'][last][-1] * MM:g}) mm: u_x {ux * MM:+.4f} mm at t = {t_last:g} s from {source} "
          f"(summary.json right_end_displacement_m {number(s['right_end_displacement_m']) * MM:+.4f} mm at "
          f"t = {s['time_s']:g} s); paper {RIGHT_END_UX * MM:.2f} mm in magnitude")
    verdicts.below("right_end_ux_rel_error", ydry_case.relative_error(abs(ux), RIGHT_END_UX), RIGHT_END_TOLERANCE)
    x0_last = surface["x0_m"][last]
    ux_last = surface["ux_m"][last]
    size = run_report.element_size(surface)
    cracks = final_cracks(run, t_last, size)
    print(f"# for comparison, the left end (x0 = {x0_last[0] * MM:g} mm): u_x {ux_last[0] * MM:+.4f} mm; "
          "an end block shrinks towards its middle, so each end moves with the length of its block"
          + end_blocks(cracks, x0_last[0], x0_last[-1]))

    time = series["time_s"]
    window = time >= (1.0 - STABLE_WINDOW) * time[-1]
    change = float(np.max(run_report.width_deviation(series)[window]))
    first, stable = run_report.first_crack_time(series), run_report.stabilisation_time(series)
    print(f"# first crack: {'none' if first is None else f'{first:g} s'}; mean surface crack width within "
          f"{100 * run_report.STABLE_FRACTION:g} % of its final value from "
          f"{'(not reached)' if stable is None else f'{stable:g} s'} on; the last "
          f"{100 * STABLE_WINDOW:g} % of the run is t >= {time[window][0]:g} s "
          f"({np.count_nonzero(window)} rows of series.csv)")
    verdicts.below("mean_surface_width_change_last_20pct", change, run_report.STABLE_FRACTION)

    mouths = surface_mouths(surface, t_last)
    gaps = sum(mouth["gap"] for mouth in mouths)
    print(f"# the top surface breaks at {len(mouths)} vertices; their horizontal gaps add up to {gaps * MM:.3f} mm, "
          f"and with the two ends' movements to {(gaps + ux_last[0] - ux_last[-1]) * MM:.3f} mm: how much the top "
          "has shrunk, whichever cracks are counted")
    fraction = curling(cracks, mouths, size)
    print(f"# cracks counted at the last frame, t = {t_last:g} s (surface element {size * MM:.2f} mm):")
    print_cracks(cracks)
    top = [crack["width"] for crack in cracks if crack["surface"]]
    print(f"# {len(top)} of the {len(cracks)} cracks have their mouth on the top surface"
          + (f", mean width {np.mean(top) * MM:.4f} mm" if top else "")
          + f"; {sum(crack['mouth'] is not None for crack in cracks)} of them break it")
    verdicts.check("curling_fraction", fraction, f">={CURLING_FRACTION:g}", fraction >= CURLING_FRACTION)


def main():
    parser = ydry_case.case_parser(__doc__, HERE)
    parser.add_argument("--run", type=Path,
                        help="check this run of the deck (a ydry -o folder) instead of running it")
    args = ydry_case.parse_case_arguments(parser)
    verdicts = ydry_case.Verdicts("peron")
    outdir = args.run
    if outdir is None:
        args.out.mkdir(parents=True, exist_ok=True)
        outdir = args.out / "run"
        ran = run_deck(args.ydry, outdir)
        if not verdicts.check("ran", ran, "true", ran):
            return verdicts.exit_code()
    run = run_report.load_run(outdir, "peron")
    if run["cracks"] is None or run["surface"] is None or not len(run["surface"]["time_s"]):
        print(f"peron: {outdir} has no cracks.csv or no surface.csv rows: not a run of the Peron "
              "deck (mechanics on, a boundary named top)", file=sys.stderr)
        return 2
    check_run(run, outdir, verdicts, args.ydry)
    return verdicts.exit_code()


if __name__ == "__main__":
    sys.exit(main())
