#!/usr/bin/python3
"""Compares the speed of two ydry builds on the same stretch of a run, both at once.

    bench/paired_restarts.py --run DIR --checkpoint NAME [--rows N] [--pairs P] [--steps-only] YDRY_A YDRY_B

On a machine whose speed swings between one run and the next (this 2-core one: by a third
within the hour, bench/RESULTS.md), runs of A and B one after the other cannot tell apart a
difference of 10 %. Here A and B restart from the same checkpoint of DIR at the same moment,
one thread each, pinned to cores 0 and 1 (taskset), so that both see the same machine; then
again with the cores swapped (P pairs in all). Each is timed until it has written N more rows
of series.csv, and then stopped. Prints the seconds of each and their ratio B / A per pair, and
fails (exit 1) if the two builds' rows differ: a speed-up that changes the bits is not the
same run, and its time says nothing without a run of its own. With --steps-only (a change
that moves the last bits, whose results a run of its own checks) the rows need only show the
same mechanical steps: the two did the same number of pseudo-steps.

Each restart runs in a copy of DIR under a temporary folder (the checkpoints but NAME left out);
DIR is not touched.
"""
import argparse
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time


def copy_run(run, checkpoint, into):
    """A copy of the run folder with only the checkpoint to restart from, without series.csv
    (the restart writes it again, whole, at its first new row)."""
    shutil.copytree(run, into, ignore=shutil.ignore_patterns("*.chk", "series.csv"))
    shutil.copy2(os.path.join(run, "checkpoints", checkpoint), os.path.join(into, "checkpoints", checkpoint))


def checkpoint_time(ydry, path):
    """The time of the checkpoint, s, as `ydry check --restart` reports it."""
    report = subprocess.run([os.path.abspath(ydry), "check", "--restart", path], capture_output=True, text=True)
    found = re.search(r" at t = (\S+) s of ", report.stderr)
    if report.returncode != 0 or not found:
        sys.exit(f"{ydry} check --restart {path}: {report.stderr.strip()}")
    return float(found.group(1))


def series_rows(folder):
    try:
        with open(os.path.join(folder, "series.csv")) as f:
            return f.read().splitlines()[1:]
    except FileNotFoundError:
        return None


def time_pair(binaries, cores, folders, checkpoint, target_rows):
    """Starts each binary on its core; returns the seconds each took until its series.csv had
    target_rows rows."""
    env = dict(os.environ, OMP_NUM_THREADS="1")
    start = time.monotonic()
    processes = [
        subprocess.Popen(["taskset", "-c", str(core), os.path.abspath(binary), "--restart",
                          os.path.join(folder, "checkpoints", checkpoint), "--threads", "1", "-q"],
                         env=env, stdout=subprocess.DEVNULL, stderr=open(os.path.join(folder, "stderr.txt"), "w"))
        for binary, core, folder in zip(binaries, cores, folders)]
    seconds = [None, None]
    while None in seconds:
        for k, (process, folder) in enumerate(zip(processes, folders)):
            if seconds[k] is not None:
                continue
            written = series_rows(folder)
            if written and len(written) >= target_rows:
                seconds[k] = time.monotonic() - start
                process.kill()  # its checkpoint on SIGTERM would wait for the relaxation under way
            elif process.poll() is not None:
                with open(os.path.join(folder, "stderr.txt")) as f:
                    sys.exit(f"{binaries[k]} stopped before {target_rows} rows of series.csv: {f.read().strip()}")
        time.sleep(0.2)
    for process in processes:
        process.wait()
    return seconds


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--run", required=True, help="a run folder with checkpoints (ydry --checkpoint-every-steps)")
    parser.add_argument("--checkpoint", required=True, help="the checkpoint to restart from, e.g. peron_014000.chk")
    parser.add_argument("--rows", type=int, default=4, help="rows of series.csv to time (default 4)")
    parser.add_argument("--pairs", type=int, default=2, help="pairs of runs, the cores swapped each time (default 2)")
    parser.add_argument("--steps-only", action="store_true",
                        help="compare only the rows' mechanical_steps, not every digit (a change of bits)")
    parser.add_argument("ydry", nargs=2, help="the two builds, A and B")
    args = parser.parse_args()
    if not os.path.isfile(os.path.join(args.run, "checkpoints", args.checkpoint)):
        sys.exit(f"no checkpoint {args.checkpoint} in {args.run}/checkpoints")
    if os.cpu_count() < 2:
        sys.exit("needs two cores")
    # The rows the checkpoint holds: those of the run's series.csv up to its time.
    at = checkpoint_time(args.ydry[0], os.path.join(args.run, "checkpoints", args.checkpoint))
    target_rows = sum(float(row.split(",")[0]) <= at for row in series_rows(args.run)) + args.rows
    with tempfile.TemporaryDirectory() as scratch:
        rows_of = {}
        for pair in range(args.pairs):
            cores = (0, 1) if pair % 2 == 0 else (1, 0)
            folders = []
            for k in range(2):
                folder = os.path.join(scratch, f"pair{pair}_{k}")
                copy_run(args.run, args.checkpoint, folder)
                folders.append(folder)
            seconds = time_pair(args.ydry, cores, folders, args.checkpoint, target_rows)
            print(f"pair {pair + 1}: A on core {cores[0]} {seconds[0]:.1f} s, B on core {cores[1]} {seconds[1]:.1f} s, "
                  f"B / A = {seconds[1] / seconds[0]:.3f}", flush=True)
            for k in range(2):
                rows_of.setdefault(k, []).append(series_rows(folders[k]))
            shutil.rmtree(folders[0]), shutil.rmtree(folders[1])
    # The rows both builds wrote in every pair must be the same, to the last digit (or in
    # their steps).
    written = [rows for runs in rows_of.values() for rows in runs]
    common = min(len(rows) for rows in written)
    if args.steps_only:
        with open(os.path.join(args.run, "series.csv")) as f:
            column = f.readline().strip().split(",").index("mechanical_steps")
        written = [[row.split(",")[column] for row in rows] for rows in written]
    if any(rows[:common] != written[0][:common] for rows in written):
        print(f"the builds' series.csv rows differ{' in their steps' if args.steps_only else ''}: not the same run",
              file=sys.stderr)
        sys.exit(1)
    print(f"series.csv: the {common} rows are the same{' in their steps' if args.steps_only else ''} in every run")


if __name__ == "__main__":
    main()
