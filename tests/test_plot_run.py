#!/usr/bin/python3
"""ctest plot_run: scripts/plot_run.py on a short run of the demo deck.

Runs ydry on inputs/demo/drying_layer.toml cut short to 20000 s on a 4 mm mesh, its soil made
to crack early (shrinkage coefficient 0.4, gf_I 0.02 J/m^2: about ten cracks in 10 s of CPU),
then plot_run.py on it: every figure and report.md must be written, and the report's crack
count must be summary.json's. plot_run.py on a folder that is not a ydry run must exit
non-zero and say so. Exits 1 on any failure.
"""
import json
import re
import subprocess
import sys
import tempfile
from pathlib import Path

REPO = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(REPO / "verification"))
import ydry_case  # noqa: E402

OVERRIDES = ["run.end_time=20000", *ydry_case.DEMO_EARLY_CRACKING]
FIGURES = ["fig18_moisture.png", "fig19_crack_pattern.png", "fig20_vertical_displacement.png",
           "fig21_horizontal_displacement.png", "fig22_surface_displacement.png",
           "fig23_crack_width.png", "fig24_crack_length.png"]


def plot_run(*args):
    return subprocess.run([sys.executable, str(REPO / "scripts" / "plot_run.py"), *map(str, args)],
                          capture_output=True, text=True)


def main():
    args = ydry_case.test_arguments(__doc__)
    failures = []
    with tempfile.TemporaryDirectory(prefix="ydry_plot_run_") as tmp:
        run, out = Path(tmp) / "run", Path(tmp) / "plots"
        if ydry_case.run_ydry(args.ydry, ydry_case.DEMO_DECK, run, OVERRIDES) is None:
            return 1
        proc = plot_run(run, "--out", out)
        print(proc.stdout + proc.stderr)
        if proc.returncode != 0:
            failures.append(f"plot_run.py exited {proc.returncode}")
        failures += [f"{name} not written" for name in FIGURES + ["report.md"] if not (out / name).is_file()]
        if (out / "report.md").is_file():
            found = re.search(r"^\| crack count: open on the top surface / all \| (\d+) / (\d+) \|$",
                              (out / "report.md").read_text(), re.M)
            summary = json.loads((run / "summary.json").read_text())
            expected = (summary["surface_crack_count"], summary["crack_count"])
            if not found or (int(found.group(1)), int(found.group(2))) != expected:
                failures.append(f"report crack counts {found and found.groups()}, summary.json {expected}")

        empty = Path(tmp) / "not_a_run"
        empty.mkdir()
        proc = plot_run(empty)
        if proc.returncode == 0 or "is not a ydry run folder" not in proc.stderr:
            failures.append(f"plot_run.py on a folder that is not a run: exit {proc.returncode}, "
                            f"{proc.stderr!r}")
    return ydry_case.failed(failures)


if __name__ == "__main__":
    sys.exit(main())
