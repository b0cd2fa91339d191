#!/usr/bin/python3
"""ctest plot_sweep_network: a plan-view sweep (cracks = "network") tabulated and drawn by
scripts/plot_sweep.py.

Two entries of verification/shear_lag/shear_lag.toml (a 200 x 5 mm strip seen in plan view) cut
by hand: value 1 by one crack across the middle (two cells of 500 mm^2), value 2 by that crack
and one along the strip (four cells of 250 mm^2, one four-branch junction). scripts/sweep.py
runs them and plot_sweep.py draws them: every figure and table must be written; each row of
NAME_table.csv must equal network.csv's last row to 1e-12 relative, with the T share of its
junctions (none at value 1); the cells must be 2 and 4; and the exponent in NAME_table.md must
be the slope of the line through the two points of network.csv, to the 3 digits it is written
with, and within 1e-3 of log(1/2) / log 2 = -1 (the strip shrinks alike in both runs, so its
cells' areas, measured as they are, halve). Exits 1 on any failure.
"""
import csv
import math
import re
import sys
import tempfile
from pathlib import Path

REPO = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(REPO / "verification"))
import ydry_case  # noqa: E402  (test_arguments, failed, read_csv)

ACROSS = "{from=[0.1,0.0],to=[0.1,0.005]}"
ALONG = "{from=[0.0,0.0025],to=[0.2,0.0025]}"
SWEEP = f"""name = "cut"
deck = "{REPO}/verification/shear_lag/shear_lag.toml"
axis = "cuts"
cracks = "network"

[[entries]]
value = 1
set = ['cracks=[{ACROSS}]']

[[entries]]
value = 2
set = ['cracks=[{ACROSS},{ALONG}]']
"""
FILES = ["table.csv", "table.md", "networks.png", "cell_area.png"]
COLUMNS = ["cells", "mean_cell_area_m2", "crack_intensity", "crack_density_per_m", "junctions_T", "junctions_Y",
           "junctions_other"]


def main():
    args = ydry_case.test_arguments(__doc__)
    failures = []
    with tempfile.TemporaryDirectory(prefix="ydry_plot_sweep_network_") as tmp:
        out, plots, sweep = Path(tmp) / "out", Path(tmp) / "plots", Path(tmp) / "cut.toml"
        sweep.write_text(SWEEP)
        failures += ydry_case.sweep_and_plot([sweep], out, plots, args.ydry)
        if not (out / "sweep.json").is_file():
            return ydry_case.failed(failures)
        failures += [f"cut_{name} not written" for name in FILES if not (plots / f"cut_{name}").is_file()]
        if (plots / "cut_table.csv").is_file():
            with open(plots / "cut_table.csv", newline="") as f:
                table = list(csv.DictReader(f))
            areas = []
            for row, cells in zip(table, [2, 4]):
                network = ydry_case.read_csv(out / row["folder"] / "network.csv")
                last = {key: float(network[key][-1]) for key in COLUMNS}
                for key in COLUMNS:
                    if abs(float(row[key]) - last[key]) > 1e-12 * max(abs(last[key]), 1e-300):
                        failures.append(f"{row['folder']} {key}: table {row[key]}, network.csv {last[key]!r}")
                junctions = last["junctions_T"] + last["junctions_Y"] + last["junctions_other"]
                share = repr(last["junctions_T"] / junctions) if junctions else ""
                if row["t_share"] != share:
                    failures.append(f"{row['folder']} t_share: table {row['t_share']!r}, want {share!r}")
                if last["cells"] != cells:
                    failures.append(f"{row['folder']}: {last['cells']:g} cells, not {cells}")
                areas.append(last["mean_cell_area_m2"])
            if len(table) != 2:
                failures.append(f"cut_table.csv has {len(table)} rows, not 2")
            elif (plots / "cut_table.md").is_file():
                slope = math.log(areas[1] / areas[0]) / math.log(2.0)
                found = re.search(r"with n = (\S+),", (plots / "cut_table.md").read_text())
                if not found or found.group(1) != f"{slope:.3g}" or abs(slope + 1.0) > 1e-3:
                    failures.append(f"cut_table.md: exponent {found.group(1) if found else None}, "
                                    f"the two points' slope {slope!r}")
    return ydry_case.failed(failures)


if __name__ == "__main__":
    sys.exit(main())
