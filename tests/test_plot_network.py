#!/usr/bin/python3
"""ctest plot_network: scripts/plot_network.py on a plan-view run cut by hand.

Runs ydry on verification/shear_lag/shear_lag.toml with two pre-existing cracks across the strip's
middle both ways (four cells, one four-branch junction at right angles), then plot_network.py
on it: both figures must be written, and its count of cells and junction angles must be the
run's. plot_network.py on a vertical-section run must exit 2 and say why. Exits 1 on any failure.
"""
import subprocess
import sys
import tempfile
from pathlib import Path

REPO = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(REPO / "verification"))
import ydry_case  # noqa: E402  (test_arguments, failed, run_ydry)

CRACKS = "cracks=[{from=[0.1,0.0],to=[0.1,0.005]},{from=[0.0,0.0025],to=[0.2,0.0025]}]"


def plot_network(*args):
    return subprocess.run([sys.executable, str(REPO / "scripts" / "plot_network.py"), *map(str, args)],
                          capture_output=True, text=True)


def main():
    args = ydry_case.test_arguments(__doc__)
    failures = []
    with tempfile.TemporaryDirectory() as tmp:
        run = Path(tmp) / "plan"
        if ydry_case.run_ydry(args.ydry, REPO / "verification" / "shear_lag" / "shear_lag.toml", run, [CRACKS]) is None:
            return ydry_case.failed(["ydry did not run the plan-view deck"])
        done = plot_network(run)
        if done.returncode != 0:
            failures.append(f"plot_network.py exited {done.returncode}: {done.stderr}")
        for name in ("network_cells.png", "network_statistics.png"):
            if not (run / "plots" / name).is_file():
                failures.append(f"no {name}")
        network = ydry_case.read_csv(run / "network.csv")
        if list(network["cells"]) != [4, 4] or list(network["junctions_other"]) != [1, 1]:
            failures.append(f"network.csv: cells {list(network['cells'])}, junctions {list(network['junctions_other'])}")
        section = Path(tmp) / "section"
        if ydry_case.run_ydry(args.ydry, REPO / "verification" / "shrinkage" / "shrinkage.toml", section) is None:
            return ydry_case.failed(failures + ["ydry did not run the vertical section"])
        refused = plot_network(section)
        if refused.returncode != 2 or "not a plan-view ydry run" not in refused.stderr:
            failures.append(f"a vertical section: exit {refused.returncode}, {refused.stderr!r}")
    return ydry_case.failed(failures)


if __name__ == "__main__":
    sys.exit(main())
