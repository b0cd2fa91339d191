#!/usr/bin/python3
"""ctest robustness: verification/peron/robustness.py judges each variant against the run of
the shipped deck with the robustness bars (surface crack count +-1, mean width within 10 %).

scripts/sweep.py --slurm-only lays out the seed and relaxation studies (sweep.json); every
folder gets its deck as `ydry check` resolves it (the reference the shipped deck, the variants
it with their overrides: a seed differs only in keys the shipped deck leaves to their
defaults, so the reference must be told apart by the whole resolved deck), and made-up
summaries on both sides of each bar (reference: 7 cracks, 1.0 mm): 8 cracks at +9.99 % pass
both; 5 cracks at -15 % fail both; an unfinished run inside the bars fails only `completed`; a
run not started fails `completed`. Every verdict line must be the expected one and the exit
code 1; without a completed reference run the script must exit 2. Exits 1 on any failure.
"""
import json
import subprocess
import sys
import tempfile
from pathlib import Path

REPO = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(REPO / "verification"))
import ydry_case  # noqa: E402  (test_arguments, failed)

STUDIES = [REPO / "verification" / "peron" / "robustness" / name for name in ("seed.toml", "relaxation.toml")]
WIDTH = 1.0e-3
# folder: (overrides, (completed, surface cracks, mean width) of the made-up run or None: not
# started)
HETEROGENEITY = "materials.soil.strength_heterogeneity=0.05"
VARIANTS = {"seed_1": (["run.seed=1", HETEROGENEITY], (True, 8, 1.0999 * WIDTH)),
            "seed_2": (["run.seed=2", HETEROGENEITY], (True, 5, 0.85 * WIDTH)),
            "seed_3": (["run.seed=3", HETEROGENEITY], (False, 7, WIDTH)),
            "relaxation_tolerance_1e-06": (["solver.relaxation_tolerance=1e-06"], None)}
EXPECTED = {
    "seed_1_completed true true PASS", "seed_1_surface_crack_count_change 1 +-1 PASS",
    "seed_1_mean_surface_width_rel_change 0.0999 0.1 PASS",
    "seed_2_completed true true PASS", "seed_2_surface_crack_count_change -2 +-1 FAIL",
    "seed_2_mean_surface_width_rel_change 0.15 0.1 FAIL",
    "seed_3_completed false true FAIL", "seed_3_surface_crack_count_change 0 +-1 PASS",
    "seed_3_mean_surface_width_rel_change 0 0.1 PASS",
    "relaxation_tolerance_1e-06_completed false true FAIL",
}


def summary(completed, count, width):
    return {"completed": completed, "time_s": 460000 if completed else 200000, "surface_crack_count": count,
            "mean_surface_crack_width_m": width, "total_surface_crack_width_m": count * width,
            "right_end_displacement_m": -4.7e-4}


def resolved(ydry, overrides):
    """The shipped Peron deck with the overrides as `ydry check` prints it (a run's deck.toml)."""
    cmd = [str(ydry), "check", str(REPO / "inputs" / "peron" / "peron.toml")]
    return subprocess.run(cmd + [a for o in overrides for a in ("--set", o)], check=True, capture_output=True,
                          text=True).stdout


def robustness(out, ydry):
    proc = subprocess.run([sys.executable, str(REPO / "verification" / "peron" / "robustness.py"), str(out),
                           "--ydry", str(ydry)], capture_output=True, text=True)
    verdicts = {line.split(" ", 1)[1] for line in proc.stdout.splitlines() if line.startswith("peron_robustness ")}
    return proc, verdicts


def main():
    args = ydry_case.test_arguments(__doc__)
    failures = []
    with tempfile.TemporaryDirectory() as tmp:
        out = Path(tmp)
        subprocess.run([sys.executable, str(REPO / "scripts" / "sweep.py"), *map(str, STUDIES), "--out", str(out),
                        "--ydry", str(args.ydry), "--slurm-only"], check=True, capture_output=True)
        reference = out / "relaxation_tolerance_1e-05"
        reference.mkdir()
        (reference / "deck.toml").write_text(resolved(args.ydry, []))
        (reference / "summary.json").write_text(json.dumps(summary(False, 7, WIDTH)))
        proc, _ = robustness(out, args.ydry)
        if proc.returncode != 2:
            failures.append(f"an unfinished reference run: exit {proc.returncode}, not 2")
        (reference / "summary.json").write_text(json.dumps(summary(True, 7, WIDTH)))
        for folder, (overrides, figures) in VARIANTS.items():
            (out / folder).mkdir()
            (out / folder / "deck.toml").write_text(resolved(args.ydry, overrides))
            if figures is not None:
                (out / folder / "summary.json").write_text(json.dumps(summary(*figures)))
        proc, verdicts = robustness(out, args.ydry)
        print(proc.stdout, end="")
        if proc.returncode != 1:
            failures.append(f"exit {proc.returncode}, not 1: {proc.stderr}")
        failures += [f"missing verdict: {line}" for line in sorted(EXPECTED - verdicts)]
        failures += [f"unexpected verdict: {line}" for line in sorted(verdicts - EXPECTED)]
    return ydry_case.failed(failures)


if __name__ == "__main__":
    sys.exit(main())
