"""The figures of a run's report, shared by scripts/plot_run.py and verification/peron/check.py.

Loads a run folder's tables (load_run), follows each crack through cracks.csv (track_cracks),
and derives the report's figures: the time of the first crack, the mean width's deviation
from its final value and the time it stabilises, and the horizontal displacement of the right
end of the top surface.
"""
import json
import math
import sys

import numpy as np

import ydry_case

STABLE_FRACTION = 0.02   # stabilisation: the mean width stays within 2 % of its final value


def load_run(folder, program):
    """The run's tables and facts: summary, series, frames, and cracks and surface (None when
    the run has no such file). Exits 2 naming what is missing, with `program:` before the
    message, if `folder` is not a ydry run."""
    missing = [name for name in ("summary.json", "series.csv") if not (folder / name).is_file()]
    pvds = sorted(folder.glob("*.pvd")) if folder.is_dir() else []
    if not folder.is_dir() or missing or not pvds:
        missing += [] if pvds else ["*.pvd"]
        what = "missing " + ", ".join(missing) if folder.is_dir() else "no such folder"
        print(f"{program}: {folder} is not a ydry run folder ({what})", file=sys.stderr)
        sys.exit(2)
    run = {"summary": json.loads((folder / "summary.json").read_text()),
           "series": ydry_case.read_csv(folder / "series.csv"),
           "frames": ydry_case.frames(pvds[0])}
    for name in ("cracks", "surface"):
        path = folder / f"{name}.csv"
        run[name] = ydry_case.read_csv(path) if path.is_file() else None
    return run


# ---- the crack tracks: cracks.csv numbers cracks by x at each time, not for life ----------

def track_cracks(cracks, match_m):
    """Follows each crack through the rows of cracks.csv: a crack continues the track whose
    last mouth x is nearest, within match_m, pairs taken nearest first; any other starts a new
    track. Returns the tracks ordered by their last x, each {time, x, width, length} arrays and,
    where cracks.csv has the column, surface (1 while its mouth is on the top surface)."""
    x = cracks["x_m"]
    tracks = []  # the rows of cracks.csv of each track
    for t in np.unique(cracks["time_s"]):
        rows = np.flatnonzero(cracks["time_s"] == t)
        pairs = sorted((abs(x[r] - x[track[-1]]), k, r) for k, track in enumerate(tracks) for r in rows)
        taken_tracks, taken_rows = set(), set()
        for distance, k, r in pairs:
            if distance <= match_m and k not in taken_tracks and r not in taken_rows:
                taken_tracks.add(k)
                taken_rows.add(r)
                tracks[k].append(r)
        tracks += [[r] for r in rows if r not in taken_rows]
    columns = {"time": "time_s", "x": "x_m", "width": "width_m", "length": "length_m", "surface": "surface"}
    return [{key: cracks[column][rows] for key, column in columns.items() if column in cracks}
            for rows in sorted(tracks, key=lambda rows: x[rows[-1]])]


def crack_tracks(run, folder, rows=None):
    """track_cracks of the run's cracks.csv, or of its `rows` (a mask) when given, matching
    within two element sizes of the top surface; without surface.csv, within a hundredth of
    the solid's length (its last frame in `folder`)."""
    size = element_size(run["surface"])
    if not math.isfinite(size):
        size = 0.005 * np.ptp(ydry_case.last_frame(folder)["x0"][:, 0])
    cracks = run["cracks"] if rows is None else {key: column[rows] for key, column in run["cracks"].items()}
    return track_cracks(cracks, 2.0 * size)


def element_size(surface):
    """The median spacing of the surface points at the first frame, m (NaN without them)."""
    if surface is None or not len(surface["time_s"]):
        return math.nan
    x0 = np.unique(surface["x0_m"][surface["time_s"] == surface["time_s"][0]])
    return float(np.median(np.diff(x0))) if len(x0) > 1 else math.nan


# ---- the report's figures ------------------------------------------------------------

def first_crack_time(series, count="crack_count"):
    """The first row time with a crack wider than the width threshold, s (None if never);
    `count` names the column that counts them (scripts/plot_sweep.py counts one kind)."""
    rows = np.flatnonzero(series[count] > 0)
    return float(series["time_s"][rows[0]]) if len(rows) else None


def width_deviation(series, column="mean_surface_crack_width_m"):
    """|mean surface crack width - its value at the last row| / that value, at every row of
    series.csv (the cracks open on the top surface: those an observer sees widen); NaN at rows
    without one, and at every row when the last has none. `column` names the mean width."""
    width = series[column]
    final = width[-1] if width[-1] > 0 else math.nan
    return np.abs(width - final) / final


def stabilisation_time(series, column="mean_surface_crack_width_m"):
    """The earliest row time from which on the mean surface crack width (`column`) stays
    within STABLE_FRACTION of its value at the last row, s; None without surface cracks at the
    end or when only the last row is within (still changing)."""
    deviation = width_deviation(series, column)
    if math.isnan(deviation[-1]):
        return None
    outside = np.flatnonzero(~(deviation <= STABLE_FRACTION))
    first_within = outside[-1] + 1 if len(outside) else 0
    return None if first_within >= len(deviation) - 1 else float(series["time_s"][first_within])


def right_end(run):
    """(u_x of the right end of the top surface at the last frame, m; where it comes from)."""
    surface = run["surface"]
    if surface is not None and len(surface["time_s"]):
        last = surface["time_s"] == surface["time_s"][-1]
        return float(surface["ux_m"][last][-1]), "surface.csv: the point of largest x0 at the last frame"
    return run["summary"]["right_end_displacement_m"], "summary.json right_end_displacement_m"
