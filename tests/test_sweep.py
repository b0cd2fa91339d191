#!/usr/bin/python3
"""ctest sweep: scripts/sweep.py skips completed runs, stops its ydry processes on SIGINT (each
writing a checkpoint), resumes the interrupted ones from their checkpoints, and writes a SLURM
script whose task body runs, or restarts, one run.

A sweep file over run.end_time = 1000, 2000, 20000 and 32000 s of tests/data/sweep_strip.toml
(seconds of CPU each), two runs at a time:
1. SIGINT while the last two runs are under way: sweep.py exits 130, no ydry process of the
   sweep is left, the first two runs are completed, the last two are not and hold a checkpoint;
2. the body of OUT/sweep.slurm, run with bash and SLURM_ARRAY_TASK_ID=3: run 3 goes on from
   its checkpoint (its log.txt says so) to its end, and no other run changes;
3. the same sweep.py command again: runs 0, 1 and 3 are skipped (their summary.json untouched),
   run 2 goes on from its checkpoint to its end;
4. run 1's folder removed, the SLURM task body for index 1: it makes run 1 again from the start
   (end time 2000 s) and touches no other run;
5. another sweep file into the same folder, end times 1000 and 3000 s: the 1000 s value shares
   the completed run strip_1000 (untouched; sweep.json points the value at it), the 3000 s one
   runs; and a third whose values all have completed runs says there is nothing to run. Then
   strip_1000 is made the run of another deck (its deck.toml's end time changed): plot_sweep.py
   must not take it for the second sweep's 1000 s value any more.
And the shipped sweeps, inputs/sweeps/*.toml, planned without running (--slurm-only: every
deck and override checked by ydry): 16 runs for their 18 values (E = 4 MPa of young.toml and
young_cohesive_length.toml and alpha = 0.08 are one deck). Exits 1 on any failure.
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

END_TIMES = [1000, 2000, 20000, 32000]
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


def stamp(runs):
    return [(run / "summary.json").stat().st_mtime_ns for run in runs]


def finished(run, end_time, restarted):
    """Failures unless the run completed at end_time, restarted from a checkpoint or not."""
    facts = summary(run)
    failures = [] if facts.get("completed") is True and facts.get("time_s") == end_time else \
        [f"{run.name} ended at {facts.get('time_s')} s, completed {facts.get('completed')}"]
    if ("restart from" in (run / "log.txt").read_text()) != restarted:
        failures.append(f"{run.name}: {'no' if restarted else 'a'} restart in its log.txt")
    return failures


def slurm_task(out, runs, index):
    """Runs the SLURM script's body for one index without SLURM; failures unless that run
    completes (restarted when it held a checkpoint) and no other run changes."""
    others = [run for k, run in enumerate(runs) if k != index and (run / "summary.json").is_file()]
    stamps = stamp(others)
    restart = runs[index].is_dir() and bool(list((runs[index] / "checkpoints").glob("*.chk")))
    env = {key: value for key, value in os.environ.items() if not key.startswith("SLURM_")}
    proc = subprocess.run(["bash", str(out / "sweep.slurm")], cwd=REPO, capture_output=True, text=True,
                          env=dict(env, SLURM_ARRAY_TASK_ID=str(index)))
    print(proc.stdout + proc.stderr)
    failures = [] if proc.returncode == 0 else [f"the SLURM task body for {index} exited {proc.returncode}"]
    failures += finished(runs[index], END_TIMES[index], restart)
    return failures + ([f"the SLURM task for {index} touched another run"] if stamp(others) != stamps else [])


def main():
    args = ydry_case.test_arguments(__doc__)
    failures = []
    with tempfile.TemporaryDirectory(prefix="ydry_sweep_") as tmp:
        sweep_file, out = Path(tmp) / "strip.toml", Path(tmp) / "out"
        sweep_file.write_text(SWEEP_FILE)
        runs = [out / f"strip_{t}" for t in END_TIMES]
        command = [sys.executable, str(REPO / "scripts" / "sweep.py"), str(sweep_file), "--out", str(out),
                   "--jobs", "2", "--threads", "1", "--ydry", str(args.ydry), "--progress-every", "1"]

        # 1. Interrupted during the last two runs.
        proc = subprocess.Popen(command, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
        if not wait_for(lambda: last_row_time(runs[2]) > 0 and last_row_time(runs[3]) > 0, 120):
            failures.append("the last two runs never wrote a row together")
        proc.send_signal(signal.SIGINT)
        output = proc.communicate(timeout=300)[0]
        print(output)
        if proc.returncode != 130:
            failures.append(f"interrupted sweep.py exited {proc.returncode}, not 130")
        if not wait_for(lambda: not ydry_processes(tmp), 5):
            failures.append(f"ydry processes left after the interrupt: {ydry_processes(tmp)}")
        done = [summary(run).get("completed") is True for run in runs]
        if done != [True, True, False, False]:
            failures.append(f"after the interrupt, completed runs {done}, expected [True, True, False, False]")
        if not all(list((run / "checkpoints").glob("*.chk")) for run in runs[2:]):
            failures.append("an interrupted run holds no checkpoint")

        # 2. The SLURM task body for index 3: a restart.
        if f"#SBATCH --array=0-{len(END_TIMES) - 1}" not in (out / "sweep.slurm").read_text():
            failures.append("sweep.slurm has no array line for the 4 runs")
        failures += slurm_task(out, runs, 3)

        # 3. Resumed: completed runs skipped, the interrupted one restarted.
        stamps = stamp(runs[:2] + runs[3:])
        proc = subprocess.run(command, capture_output=True, text=True)
        print(proc.stdout + proc.stderr)
        if proc.returncode != 0:
            failures.append(f"resumed sweep.py exited {proc.returncode}")
        if proc.stdout.count("skipped (completed)") != 3 or "strip_20000: unfinished: restart from" not in proc.stdout:
            failures.append("the resumed sweep did not announce 3 skipped runs and a restart of the unfinished one")
        if stamp(runs[:2] + runs[3:]) != stamps:
            failures.append("a completed run was written again on resuming")
        failures += finished(runs[2], END_TIMES[2], restarted=True)

        # 4. The SLURM task body for index 1, from the start.
        shutil.rmtree(runs[1])
        failures += slurm_task(out, runs, 1)

        # 5. Another sweep into the same folder: a value whose deck has a completed run shares it.
        again = Path(tmp) / "again.toml"
        again.write_text(SWEEP_FILE.replace('name = "strip"', 'name = "again"')
                         .replace(f"values = {END_TIMES}", "values = [1000, 3000]"))
        stamps = stamp(runs)
        proc = subprocess.run([*command[:2], str(again), *command[3:]], capture_output=True, text=True)
        print(proc.stdout + proc.stderr)
        manifest = {sweep["name"]: sweep for sweep in json.loads((out / "sweep.json").read_text())["sweeps"]}
        folders = [entry["folder"] for entry in manifest.get("again", {}).get("entries", [])]
        if proc.returncode != 0 or "again_1000: the deck of strip_1000, shares its run" not in proc.stdout:
            failures.append(f"the second sweep (exit {proc.returncode}) did not share strip_1000")
        if stamp(runs) != stamps:
            failures.append("the second sweep wrote into the first sweep's runs")
        if folders != ["strip_1000", "again_3000"]:
            failures.append(f"sweep.json's folders of the second sweep are {folders}")
        failures += finished(out / "again_3000", 3000, restarted=False)
        third = Path(tmp) / "third.toml"
        third.write_text(SWEEP_FILE.replace('name = "strip"', 'name = "third"')
                         .replace(f"values = {END_TIMES}", "values = [2000, 3000]"))
        proc = subprocess.run([*command[:2], str(third), *command[3:]], capture_output=True, text=True)
        print(proc.stdout + proc.stderr)
        if proc.returncode != 0 or "nothing to run" not in proc.stdout:
            failures.append(f"a sweep whose runs are all completed exited {proc.returncode} without "
                            "saying there is nothing to run")
        deck = runs[0] / "deck.toml"
        deck.write_text(deck.read_text().replace("end_time = 1000", "end_time = 1500", 1))
        proc = subprocess.run([sys.executable, str(REPO / "scripts" / "plot_sweep.py"), str(out), "--sweep", "again",
                               "--out", str(Path(tmp) / "plots")], capture_output=True, text=True)
        print(proc.stdout + proc.stderr)
        table = Path(tmp) / "plots" / "again_table.md"
        if not table.is_file() or "holds another deck's run" not in table.read_text():
            failures.append("plot_sweep.py took strip_1000, now another deck's run, for the second sweep's value")

        # The shipped sweeps.
        shipped = sorted((REPO / "inputs" / "sweeps").glob("*.toml"))
        shipped = [path for path in shipped if "deck" in tomllib.loads(path.read_text())]
        proc = subprocess.run([sys.executable, str(REPO / "scripts" / "sweep.py"), *map(str, shipped), "--out",
                               str(Path(tmp) / "shipped"), "--ydry", str(args.ydry), "--slurm-only"],
                              capture_output=True, text=True)
        print(proc.stdout + proc.stderr)
        if proc.returncode != 0 or "16 runs for 18 values" not in proc.stdout:
            failures.append(f"the shipped sweeps {[path.name for path in shipped]} do not plan as 16 runs for 18 values")
    return ydry_case.failed(failures)


if __name__ == "__main__":
    sys.exit(main())
