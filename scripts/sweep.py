#!/usr/bin/python3
"""Run parameter sweeps of ydry, several runs at a time and resumably; write their SLURM job array.

Each entry of a sweep is one run, `ydry DECK -o OUT/NAME_VALUE --force --quiet --set ...`, in its
own folder. Runs whose summary.json says `completed` (and whose deck.toml is the deck this
sweep would run now) are skipped, an unfinished one goes on from its newest checkpoint
(`ydry --restart`), so the same command resumes a sweep after an interruption; entries that
resolve to the same deck share one run, as does an entry whose deck another folder of OUT has
completed (an earlier sweep into the same OUT ran it). Ctrl-C (or SIGTERM) makes every running ydry end its
coupling step and write a checkpoint (Ctrl-C again: at once), waits for them and exits 130.
Writes OUT/sweep.json (the sweeps and their run folders, read by scripts/plot_sweep.py) and
OUT/sweep.slurm (the same runs as a SLURM job array: one array task per run).

    scripts/sweep.py inputs/sweeps/young.toml --out runs/sweeps --jobs 2
    scripts/sweep.py inputs/sweeps/*.toml --out runs/sweeps --jobs 2     # the paper's three sweeps
    scripts/sweep.py --deck inputs/demo/drying_layer.toml --parameter materials.soil.young \\
        --values 1e6 4e6 16e6 --out runs/young --jobs 3 --set run.end_time=20000
    scripts/sweep.py inputs/sweeps/*.toml --out runs/sweeps --slurm-only  # write sweep.slurm only
    sbatch runs/sweeps/sweep.slurm                 # on a cluster, from the repository root

A sweep file (inputs/sweeps/README.md):

    name = "young"                        # names the runs: OUT/young_1e+06, ...
    deck = "../peron/peron.toml"          # the base deck, relative to this file
    parameter = "materials.soil.young"    # the deck value each entry sets to its value (optional)
    axis = "E"                            # tables and plots: the value times scale, in unit
    unit = "MPa"
    scale = 1e-6
    cracks = "surface"                    # what plot_sweep.py counts: surface | penetrating cracks, or
                                          # network (plan-view runs: cells, junctions)
    figures = [25, 26, 27]                # the paper's patterns, width and length figures
    set = []                              # overrides of every run of the sweep
    values = [1.0e6, 4.0e6, 16.0e6]       # or, where a value needs overrides of its own:
    # [[entries]]
    # value = 0.004
    # set = ['mesh.file="layer_h4.msh"', "run.end_time=150000"]

Threads: each run gets OMP_NUM_THREADS = --threads, or the cores divided by --jobs (at least
one). Exit 0 when every run has completed, 1 when some failed, 2 on bad input, 130 when
interrupted.
"""
import json
import os
import shlex
import signal
import subprocess
import sys
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "verification"))
import ydry_case  # noqa: E402  (script_parser)
from sweep_plan import (REPO, SweepError, command_line_sweep, load_sweep_file,  # noqa: E402
                        plan_runs, resume_arguments, run_arguments, run_state, shown)

STOP_WAIT_S = 300.0  # after SIGTERM, how long a ydry may take to end its coupling step before SIGKILL


def arguments():
    parser = ydry_case.script_parser(__doc__)
    parser.add_argument("files", nargs="*", type=Path, help="sweep files (TOML)")
    parser.add_argument("--deck", type=Path, help="without a sweep file: the base deck")
    parser.add_argument("--parameter", help="with --deck: the deck value to vary, e.g. materials.soil.young")
    parser.add_argument("--values", nargs="+", help="with --deck: its values (TOML values)")
    parser.add_argument("--name", help="with --deck: names the runs (default: the parameter's last key)")
    parser.add_argument("--out", type=Path, required=True, help="folder of the runs, sweep.json and sweep.slurm")
    parser.add_argument("--set", action="append", default=[], metavar="KEY=VALUE",
                        help="an override of every run, after the sweep's own (repeatable)")
    parser.add_argument("--jobs", type=int, default=1, help="runs at a time (default 1)")
    parser.add_argument("--threads", type=int, help="OpenMP threads of each run (default: cores // jobs)")
    parser.add_argument("--ydry", type=Path, default=REPO / "build" / "ydry")
    parser.add_argument("--progress-every", type=float, default=30.0, metavar="SECONDS",
                        help="seconds between progress lines (default 30)")
    parser.add_argument("--checkpoint-every", type=float, default=1800.0, metavar="SECONDS",
                        help="wall seconds between the checkpoints of a run (default 1800; 0: only at its end "
                             "and when stopped)")
    parser.add_argument("--slurm-only", action="store_true", help="write sweep.json and sweep.slurm, run nothing")
    parser.add_argument("--slurm-cpus", type=int, help="cpus-per-task of sweep.slurm (default: the threads of a run)")
    parser.add_argument("--slurm-time", default="12:00:00", help="time limit of an array task (default 12:00:00)")
    args = parser.parse_args()
    if bool(args.files) == bool(args.deck) or bool(args.deck) != bool(args.parameter and args.values):
        parser.error("give sweep files, or --deck with --parameter and --values")
    if args.jobs < 1 or (args.threads is not None and args.threads < 1):
        parser.error("--jobs and --threads must be at least 1")
    return args


# ---- the files of a sweep --------------------------------------------------------------

def write_manifest(out, sweeps):
    """OUT/sweep.json: the sweeps (with their run folders, relative to OUT), merged with those
    of earlier commands into the same OUT (a sweep of the same name is replaced)."""
    path = out / "sweep.json"
    earlier = json.loads(path.read_text())["sweeps"] if path.is_file() else []
    names = {sweep["name"] for sweep in sweeps}
    kept = [sweep for sweep in earlier if sweep["name"] not in names]
    path.write_text(json.dumps({"sweeps": kept + sweeps}, indent=1) + "\n")
    return path


def write_slurm(out, runs, ydry, checkpoint_every, cpus, time_limit):
    """OUT/sweep.slurm: a SLURM job array, one task per run, each the local runner's ydry command
    (paths relative to the repository root: submit from it); a completed run is skipped, an
    unfinished one restarts from its newest checkpoint (resume_arguments)."""
    cases = "\n".join(f"  {k}) out={shlex.quote(shown(run['path']))}\n"
                      f"     args=({shlex.join(run_arguments(run, checkpoint_every))}) ;;" for k, run in enumerate(runs))
    text = f"""#!/bin/bash
# ydry sweep of {len(runs)} runs into {shown(out)}, written by scripts/sweep.py: one array task per
# run. Submit from the repository root (the paths are relative to it), after building ydry:
#   sbatch {shown(out)}/sweep.slurm
# A task whose run completed (summary.json) does nothing; one whose run was stopped goes on
# from its newest checkpoint (ydry refuses it if the deck changed since: remove the folder).
# Test one task without SLURM:
#   SLURM_ARRAY_TASK_ID=0 bash {shown(out)}/sweep.slurm
#SBATCH --job-name=ydry-sweep
#SBATCH --array=0-{len(runs) - 1}
#SBATCH --cpus-per-task={cpus}
#SBATCH --time={time_limit}
#SBATCH --output={shown(out)}/slurm-%A_%a.out
set -euo pipefail
cd "${{SLURM_SUBMIT_DIR:-.}}"
export OMP_NUM_THREADS="${{SLURM_CPUS_PER_TASK:-{cpus}}}"
case "${{SLURM_ARRAY_TASK_ID:?the array task index, 0-{len(runs) - 1}}}" in
{cases}
  *) echo "sweep.slurm: no run ${{SLURM_ARRAY_TASK_ID}} (0-{len(runs) - 1})" >&2; exit 2 ;;
esac
if grep -qs '"completed": true' "$out/summary.json"; then
  echo "$out: completed earlier, skipped"
  exit 0
fi
resume=(--force)  # the newest checkpoint, of the most coupling steps (NAME_NNNNNN.chk), if any
steps=-1
for checkpoint in "$out"/checkpoints/*.chk; do
  [ -e "$checkpoint" ] || continue
  n="${{checkpoint##*_}}"
  n="${{n%.chk}}"
  if [ "$((10#$n))" -gt "$steps" ]; then steps="$((10#$n))"; resume=(--restart "$checkpoint"); fi
done
exec {shlex.quote(shown(ydry))} "${{resume[@]}}" "${{args[@]}}"
"""
    path = out / "sweep.slurm"
    path.write_text(text)
    path.chmod(0o755)
    return path


# ---- running -----------------------------------------------------------------------------

def simulated_time(folder):
    """The time of the last row of the run's series.csv, s (0 before its first row)."""
    try:
        with open(folder / "series.csv", "rb") as f:
            f.seek(max(0, f.seek(0, os.SEEK_END) - 4096))
            return float(f.read().decode().strip().splitlines()[-1].split(",")[0])
    except (OSError, ValueError, IndexError):
        return 0.0


def clock(seconds):
    return time.strftime("%H:%M:%S", time.gmtime(seconds))


def progress_line(done, running, left, start):
    shown_runs = "; ".join(f"{run['folder']} {simulated_time(run['path']):,.0f}/{run['end_time']:,.0f} s"
                           for run in running)
    return (f"sweep {clock(time.monotonic() - start)}: {len(done)} done, {len(running)} running"
            f"{' (' + shown_runs + ')' if running else ''}, {len(left)} left")


def stop(running):
    """SIGTERM to every running ydry: each ends its coupling step, writes a checkpoint and exits.
    A second Ctrl-C (or SIGTERM) passes a second SIGTERM on, which ends them at once, their files
    whole; any still there after STOP_WAIT_S is killed. Returns when all have ended."""
    for run in running:
        run["process"].terminate()
    print(f"sweep: waiting for {len(running)} ydry to write a checkpoint (Ctrl-C again: stop at once)", flush=True)
    deadline = time.monotonic() + STOP_WAIT_S
    while any(run["process"].poll() is None for run in running):
        try:
            time.sleep(0.1)
            if time.monotonic() > deadline:
                for run in running:
                    run["process"].kill()
        except KeyboardInterrupt:
            for run in running:
                if run["process"].poll() is None:
                    run["process"].terminate()


def finished(run, logs):
    """One line on a run that has just ended; failed runs also show the end of their stderr."""
    rc = run["process"].returncode
    wall = time.monotonic() - run["started"]
    if rc == 0:
        return f"done    {run['folder']} in {wall:.0f} s"
    tail = (logs / f"{run['folder']}.txt").read_text().strip().splitlines()[-5:]
    return f"FAILED  {run['folder']} (ydry exit {rc}) after {wall:.0f} s:\n  " + "\n  ".join(tail)


def run_all(todo, out, jobs, threads, every):
    """Runs the commands of todo, `jobs` at a time, printing progress; returns the runs that
    failed. Ctrl-C or SIGTERM stops the running ones and raises KeyboardInterrupt."""
    logs = out / "logs"
    logs.mkdir(exist_ok=True)
    env = dict(os.environ, OMP_NUM_THREADS=str(threads))
    left, running, done, failed = list(todo), [], [], []
    start = last_line = time.monotonic()
    try:
        while left or running:
            while left and len(running) < jobs:
                run = left.pop(0)
                with open(logs / f"{run['folder']}.txt", "a") as log:
                    run["process"] = subprocess.Popen(run["command"], cwd=REPO, env=env, stdin=subprocess.DEVNULL,
                                                      stdout=log, stderr=subprocess.STDOUT, start_new_session=True)
                run["started"] = time.monotonic()
                running.append(run)
                print(f"start   {run['folder']}", flush=True)
            time.sleep(0.2)
            for run in [r for r in running if r["process"].poll() is not None]:
                running.remove(run)
                (done if run["process"].returncode == 0 else failed).append(run)
                print(finished(run, logs), flush=True)
            if time.monotonic() - last_line >= every:
                print(progress_line(done, running, left, start), flush=True)
                last_line = time.monotonic()
    except KeyboardInterrupt:
        print(f"sweep: interrupted; stopping {len(running)} running ydry", flush=True)
        stop(running)
        raise
    return failed


def plan_note(run, state):
    """What the sweep does with a run, as the plan it prints says."""
    command = run.get("command", [])
    if state == "unfinished":
        return (f"unfinished: restart from {Path(command[command.index('--restart') + 1]).name}"
                if "--restart" in command else "unfinished, no checkpoint: run again from the start")
    return {"completed": "skipped (completed)", "new": "to run",
            "changed": "holds another deck's run: run again from the start"}[state]


def print_plan(runs, states, shared):
    """One line per run (what the sweep does with it), then one per entry that shares a run."""
    for run in runs:
        print(f"  {run['folder']}: {plan_note(run, states[run['folder']])}")
    for entry, run in shared:
        print(f"  {entry}: the deck of {run}, shares its run")


def interrupt(signum, frame):
    raise KeyboardInterrupt


def main():
    args = arguments()
    out = args.out.resolve()
    try:
        sweeps = [load_sweep_file(path) for path in args.files] if args.files else [command_line_sweep(args)]
        runs, shared = plan_runs(sweeps, out, args.ydry.resolve(), args.set)
    except SweepError as error:
        print(f"sweep: error: {error}", file=sys.stderr)
        return 2
    out.mkdir(parents=True, exist_ok=True)
    threads = args.threads or max(1, len(os.sched_getaffinity(0)) // args.jobs)
    write_manifest(out, sweeps)
    if not runs:
        print(f"sweep: every value's deck has a completed run in {shown(out)}: nothing to run")
        print_plan([], {}, shared)
        return 0
    slurm = write_slurm(out, runs, args.ydry.resolve(), args.checkpoint_every, args.slurm_cpus or threads,
                        args.slurm_time)
    states = {run["folder"]: run_state(run) for run in runs}
    todo = [run for run in runs if states[run["folder"]] != "completed"]
    for run in todo:
        run["command"] = [shown(args.ydry.resolve()), *resume_arguments(run, states[run["folder"]]),
                          *run_arguments(run, args.checkpoint_every)]
    entries = sum(len(sweep["entries"]) for sweep in sweeps)
    print(f"sweep: {len(runs)} runs for {entries} values into {shown(out)} ({slurm.name} written); "
          f"{len(runs) - len(todo)} completed earlier, {len(todo)} to run, {args.jobs} at a time, "
          f"{threads} thread(s) each")
    print_plan(runs, states, shared)
    if args.slurm_only:
        return 0
    for signum in (signal.SIGINT, signal.SIGTERM):  # SIGINT too where a shell started sweep.py ignoring it
        signal.signal(signum, interrupt)
    try:
        failed = run_all(todo, out, args.jobs, threads, args.progress_every)
    except KeyboardInterrupt:
        print("sweep: stopped; run the same command again to resume")
        return 130
    print(f"sweep: {len(runs) - len(failed)} of {len(runs)} runs completed"
          + (f"; failed: {', '.join(run['folder'] for run in failed)} (logs in {shown(out / 'logs')})" if failed else ""))
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
