#!/usr/bin/python3
"""ctest sweep: scripts/sweep.py skips completed runs, resumes an interrupted one, stops its
ydry processes on SIGINT, and writes a SLURM script whose task body runs one run.

A sweep file over run.end_time = 1000, 2000 and 20000 s of tests/data/sweep_strip.toml (a few
seconds of CPU each), one run at a time:
1. SIGINT while the 20000 s run is under way: sweep.py exits 130, no ydry process of the sweep
   is left, the first two runs are completed and the third is not;
2. the same command again: the first two are skipped (their summary.json untouched), the third
   runs again and completes;
3. run 1's folder removed, the body of OUT/sweep.slurm run with bash and SLURM_ARRAY_TASK_ID=1:
   it makes run 1 again (end time 2000 s) and touches no other run.
And the shipped sweeps, inputs/sweeps/*.toml, planned without running (--slurm-only: every
deck and override checked by ydry): 8 runs for their 9 values (E = 4 MPa and alpha = 0.08 are
one). Exits 1 on any failure.
"""
import json
import os
import shutil
import signal
import subprocess
import sys
import tempfile
import time
import tomllib
from pathlib import Path

REPO = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(REPO / "verification"))
import ydry_case  # noqa: E402  (test_arguments, failed)

END_TIMES = [1000, 2000, 20000]
SWEEP_FILE = f"""name = "strip"
deck = "{REPO}/tests/data/sweep_strip.toml"
parameter = "run.end_time"
axis = "end time"
values = {END_TIMES}
"""


def summary(folder):
    path = folder / "summary.json"
    return json.loads(path.read_text()) if path.is_file() else {}


def ydry_processes(marker):
    """Ids of the processes whose command line names `marker` (the test's temporary folder)."""
    found = []
    for proc in Path("/proc").iterdir():
        try:
            if proc.name.isdigit() and marker in (proc / "cmdline").read_bytes().decode(errors="replace"):
                found.append(int(proc.name))
        except OSError:  # gone meanwhile
            pass
    return [pid for pid in found if pid != os.getpid()]


def wait_for(condition, timeout_s):
    deadline = time.monotonic() + timeout_s
    while time.monotonic() < deadline:
        if condition():
            return True
        time.sleep(0.05)
    return False


def last_row_time(folder):
    try:
        return float((folder / "series.csv").read_text().strip().splitlines()[-1].split(",")[0])
    except (OSError, ValueError, IndexError):
        return 0.0


def main():
    args = ydry_case.test_arguments(__doc__)
    failures = []
    with tempfile.TemporaryDirectory(prefix="ydry_sweep_") as tmp:
        sweep_file, out = Path(tmp) / "strip.toml", Path(tmp) / "out"
        sweep_file.write_text(SWEEP_FILE)
        runs = [out / f"strip_{t}" for t in END_TIMES]
        command = [sys.executable, str(REPO / "scripts" / "sweep.py"), str(sweep_file), "--out", str(out),
                   "--jobs", "1", "--threads", "1", "--ydry", str(args.ydry), "--progress-every", "1"]

        # 1. Interrupted during the last run.
        proc = subprocess.Popen(command, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
        if not wait_for(lambda: last_row_time(runs[2]) > 0, 120):
            failures.append("the 20000 s run never wrote a row")
        proc.send_signal(signal.SIGINT)
        output = proc.communicate(timeout=60)[0]
        print(output)
        if proc.returncode != 130:
            failures.append(f"interrupted sweep.py exited {proc.returncode}, not 130")
        if not wait_for(lambda: not ydry_processes(tmp), 5):
            failures.append(f"ydry processes left after the interrupt: {ydry_processes(tmp)}")
        done = [summary(run).get("completed") is True for run in runs]
        if done != [True, True, False]:
            failures.append(f"after the interrupt, completed runs {done}, expected [True, True, False]")

        # 2. Resumed: completed runs skipped, the interrupted one run again to its end.
        stamps = [(run / "summary.json").stat().st_mtime_ns for run in runs[:2]]
        proc = subprocess.run(command, capture_output=True, text=True)
        print(proc.stdout + proc.stderr)
        if proc.returncode != 0:
            failures.append(f"resumed sweep.py exited {proc.returncode}")
        if proc.stdout.count("skipped (completed)") != 2 or "strip_20000: unfinished: run again" not in proc.stdout:
            failures.append("the resumed sweep did not announce 2 skipped runs and the unfinished one")
        if [(run / "summary.json").stat().st_mtime_ns for run in runs[:2]] != stamps:
            failures.append("a completed run was written again on resuming")
        last = summary(runs[2])
        if last.get("completed") is not True or last.get("time_s") != END_TIMES[2]:
            failures.append(f"the resumed run ended at {last.get('time_s')} s, completed {last.get('completed')}")

        # 3. The SLURM task body for index 1, without SLURM.
        slurm = (out / "sweep.slurm").read_text()
        if f"#SBATCH --array=0-{len(END_TIMES) - 1}" not in slurm:
            failures.append("sweep.slurm has no array line for the 3 runs")
        shutil.rmtree(runs[1])
        stamps = [(run / "summary.json").stat().st_mtime_ns for run in (runs[0], runs[2])]
        env = {key: value for key, value in os.environ.items() if not key.startswith("SLURM_")}
        proc = subprocess.run(["bash", str(out / "sweep.slurm")], cwd=REPO, capture_output=True, text=True,
                              env=dict(env, SLURM_ARRAY_TASK_ID="1"))
        print(proc.stdout + proc.stderr)
        if proc.returncode != 0:
            failures.append(f"the SLURM task body exited {proc.returncode}")
        task = summary(runs[1])
        if task.get("completed") is not True or task.get("time_s") != END_TIMES[1]:
            failures.append(f"the SLURM task's run ended at {task.get('time_s')} s, completed {task.get('completed')}")
        if [(run / "summary.json").stat().st_mtime_ns for run in (runs[0], runs[2])] != stamps:
            failures.append("the SLURM task for index 1 touched another run")
        # The shipped sweeps.
        shipped = sorted((REPO / "inputs" / "sweeps").glob("*.toml"))
        shipped = [path for path in shipped if "deck" in tomllib.loads(path.read_text())]
        proc = subprocess.run([sys.executable, str(REPO / "scripts" / "sweep.py"), *map(str, shipped), "--out",
                               str(Path(tmp) / "shipped"), "--ydry", str(args.ydry), "--slurm-only"],
                              capture_output=True, text=True)
        print(proc.stdout + proc.stderr)
        if proc.returncode != 0 or "8 runs for 9 values" not in proc.stdout:
            failures.append(f"the shipped sweeps {[path.name for path in shipped]} do not plan as 8 runs for 9 values")
    return ydry_case.failed(failures)


if __name__ == "__main__":
    sys.exit(main())
