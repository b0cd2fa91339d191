#!/usr/bin/python3
"""ctest plot_sweep: the tables of scripts/plot_sweep.py hold what the runs' files say.

Two sweep files over the shrinkage coefficient (0.2, 0.3) of tests/data/sweep_strip.toml, one
counting the surface cracks and one the penetrating ones, run by scripts/sweep.py (the same
decks: the two sweeps share their two runs), then plot_sweep.py on them. Every figure and
table must be written; each row of NAME_table.csv must equal, to 1e-12 relative, what the
run's files give when read here with the csv module: the crack count, mean and total width of
the last row (for surface cracks, series.csv's surface columns; for penetrating ones, the rows
of cracks.csv with penetrating and surface 1), their mean length (cracks.csv), the first row
time with one, and the earliest row time from which their mean width stays within 2 % of its
last value; and, where the run's final cracks all opened in its first cracked row, their mean
initiation time is that row's. The strip must have penetrating cracks and such a run (else
the test would not test them).
plot_sweep.py on a folder without sweep.json must exit 2. Exits 1 on any failure.
"""
import csv
import json
import math
import subprocess
import sys
import tempfile
from pathlib import Path

REPO = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(REPO / "verification"))
import ydry_case  # noqa: E402  (test_arguments, failed)

VALUES = [0.2, 0.3]
KINDS = ("surface", "penetrating")
FILES = ["table.csv", "table.md", "patterns.png", "width.png", "length.png"]


def sweep_file(kind):
    return f"""name = "{kind}"
deck = "{REPO}/tests/data/sweep_strip.toml"
parameter = "materials.soil.shrinkage_coefficient"
axis = "alpha"
cracks = "{kind}"
values = {VALUES}
"""


def rows(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def expected(folder, kind):
    """The table's figures of one run, from its files."""
    series = rows(folder / "series.csv")
    times = [float(row["time_s"]) for row in series]
    per_time = {t: [] for t in times}
    for row in rows(folder / "cracks.csv"):
        if row["surface"] == "1" and (kind == "surface" or row["penetrating"] == "1"):
            per_time[float(row["time_s"])].append((float(row["width_m"]), float(row["length_m"])))
    if kind == "surface":  # the crack statistics ydry writes itself
        count = [int(row["surface_crack_count"]) for row in series]
        mean = [float(row["mean_surface_crack_width_m"]) for row in series]
        total = float(series[-1]["total_surface_crack_width_m"])
    else:
        count = [len(per_time[t]) for t in times]
        mean = [sum(w for w, _ in per_time[t]) / len(per_time[t]) if per_time[t] else math.nan for t in times]
        total = sum(w for w, _ in per_time[times[-1]])
    final = per_time[times[-1]]
    stable = None
    for k in range(len(times) - 1):  # earliest row from which on all are within 2 %, not only the last
        if all(abs(m - mean[-1]) <= 0.02 * mean[-1] for m in mean[k:]):
            stable = times[k]
            break
    first = next((t for t, c in zip(times, count) if c), None)
    figures = {"crack_count": count[-1], "first_crack_s": first, "stabilisation_s": stable, "mean_width_m": mean[-1],
               "total_width_m": total,
               "mean_length_m": sum(length for _, length in final) / len(final) if final else math.nan}
    if first is not None and all(c == count[-1] for c in count[times.index(first):]):
        figures["mean_initiation_s"] = first  # all the final cracks were there at the first
    return figures


def differs(table, value):
    if value is None:
        return table != ""
    if table == "":
        return True
    number = float(table)
    if math.isnan(value):
        return not math.isnan(number)
    return abs(number - value) > 1e-12 * max(abs(value), 1e-300)


def main():
    args = ydry_case.test_arguments(__doc__)
    failures = []
    with tempfile.TemporaryDirectory(prefix="ydry_plot_sweep_") as tmp:
        out, plots = Path(tmp) / "out", Path(tmp) / "plots"
        files = []
        for kind in KINDS:
            files.append(Path(tmp) / f"{kind}.toml")
            files[-1].write_text(sweep_file(kind))
        failures += ydry_case.sweep_and_plot(files, out, plots, args.ydry)
        if not (out / "sweep.json").is_file():
            return ydry_case.failed(failures)
        failures += [f"{kind}_{name} not written" for kind in KINDS for name in FILES
                     if not (plots / f"{kind}_{name}").is_file()]
        manifest = json.loads((out / "sweep.json").read_text())["sweeps"]
        folders = [[entry["folder"] for entry in sweep["entries"]] for sweep in manifest]
        if folders[0] != folders[1]:
            failures.append(f"the two sweeps do not share their runs: {folders}")
        penetrating = initiations = 0
        for kind in KINDS:
            table = rows(plots / f"{kind}_table.csv") if (plots / f"{kind}_table.csv").is_file() else []
            for row in table:
                want = expected(out / row["folder"], kind)
                penetrating += want["crack_count"] if kind == "penetrating" else 0
                initiations += "mean_initiation_s" in want
                failures += [f"{kind} {row['folder']} {key}: table {row[key]!r}, files {value!r}"
                             for key, value in want.items() if differs(row[key], value)]
            if len(table) != len(VALUES):
                failures.append(f"{kind}_table.csv has {len(table)} rows, not {len(VALUES)}")
        if penetrating == 0:
            failures.append("no penetrating crack in the strip runs: the test data no longer tests them")
        if initiations == 0:
            failures.append("no run whose cracks all open at once: the mean initiation time went untested")

        proc = subprocess.run([sys.executable, str(REPO / "scripts" / "plot_sweep.py"), tmp], capture_output=True,
                              text=True)
        if proc.returncode != 2 or "holds no sweep.json" not in proc.stderr:
            failures.append(f"plot_sweep.py on a folder without sweep.json: exit {proc.returncode}, {proc.stderr!r}")
    return ydry_case.failed(failures)


if __name__ == "__main__":
    sys.exit(main())
