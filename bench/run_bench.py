#!/usr/bin/python3
"""make bench: runs the throughput benchmarks and appends their figures to bench/RESULTS.md.

Prints the machine (cores, CPU model, load average), the compiler, the commit, the memory
bandwidth (bench_memory: the STREAM triad at 1 thread and at all threads, the ceiling of a step
on a mesh larger than the cache), then the lines of bench_moisture (moisture node-steps per
second) and bench_mechanics (element-steps per second of the 200k-triangle cracking rectangle
and of the Peron mesh, at 1 thread and at all threads, with their wall time by stage) and
bench_factorisation (the implicit solver's factorisation of the Peron deck at the stiff
penalties with each ordering, AMD and METIS), and appends all of it to RESULTS.md as a dated section with the command that made it. The Peron
end-to-end figures (wall time, steps) come from a full run's summary.json: one made before
(--peron-run DIR), or one this script makes first (--peron: 7-9 minutes on 2 cores).

examples:
  bench/run_bench.py                           # what `make bench` runs
  bench/run_bench.py --peron-run runs/peron    # plus the figures of an earlier full Peron run
  bench/run_bench.py --peron                   # plus a full Peron run now, into runs/peron_bench
"""
import datetime
import json
import os
import platform
import shlex
import subprocess
import sys
from pathlib import Path

REPO = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(REPO / "verification"))
import ydry_case  # noqa: E402


def first_line(command):
    return subprocess.run(command, capture_output=True, text=True, check=True).stdout.splitlines()[0]


def machine_lines(build):
    """The facts a figure needs beside it: where, with what, from which commit."""
    cpu = next((line.split(":", 1)[1].strip() for line in Path("/proc/cpuinfo").read_text().splitlines()
                if line.startswith("model name")), platform.processor() or "unknown")
    cache = (build / "CMakeCache.txt").read_text().splitlines()
    compiler = next(line.split("=", 1)[1] for line in cache if line.startswith("CMAKE_CXX_COMPILER:"))
    build_type = next(line.split("=", 1)[1] for line in cache if line.startswith("CMAKE_BUILD_TYPE:"))
    commit = first_line(["git", "-C", str(REPO), "rev-parse", "--short=12", "HEAD"])
    # -dirty for uncommitted changes, but not for the figures an earlier run appended here.
    changes = subprocess.run(["git", "-C", str(REPO), "status", "--porcelain", "--untracked-files=no"],
                             capture_output=True, text=True, check=True).stdout.splitlines()
    if any(not line.endswith(" bench/RESULTS.md") for line in changes):
        commit += "-dirty"
    load = " ".join(f"{x:.2f}" for x in os.getloadavg())
    openmp = ", ".join(f"{name}={os.environ.get(name, 'unset')}" for name in ("OMP_NUM_THREADS", "OMP_WAIT_POLICY"))
    return [f"machine: {len(os.sched_getaffinity(0))} cores (nproc), {cpu}",
            f"compiler: {first_line([compiler, '--version'])}, {build_type} build",
            f"commit: {commit}",
            f"load average at the start (1, 5, 15 min): {load}; {openmp}"]


def run_bench(program, *args):
    """Runs a benchmark program, echoing its lines; returns them. Exits on a failure."""
    proc = subprocess.Popen([str(program), *args], stdout=subprocess.PIPE, text=True)
    lines = []
    for line in proc.stdout:
        print(line, end="", flush=True)
        lines.append(line.rstrip("\n"))
    if proc.wait() != 0:
        sys.exit(f"run_bench.py: {program.name} failed (exit {proc.returncode})")
    return lines


def peron_lines(run):
    """The end-to-end figures of a full Peron run, from its summary.json."""
    summary = json.loads((run / "summary.json").read_text())
    if summary["name"] != "peron":
        sys.exit(f"run_bench.py: {run} is a run of '{summary['name']}', not of inputs/peron/peron.toml")
    if not summary["completed"]:
        sys.exit(f"run_bench.py: {run} did not reach its end time (summary.json: completed false)")
    return [f"peron end to end ({run}, ydry {summary['version']}): {summary['wall_s']:.0f} s wall on "
            f"{summary['threads']} threads, {summary['mechanical_steps']:.0f} mechanical steps, "
            f"{summary['moisture_steps']} coupling steps, {summary['elements']} triangles, "
            f"{summary['crack_count']:.0f} cracks"]


def main():
    parser = ydry_case.script_parser(__doc__)
    parser.add_argument("--build", type=Path, default=REPO / "build", help="the CMake build folder (build)")
    parser.add_argument("--results", type=Path, default=REPO / "bench" / "RESULTS.md",
                        help="the file the dated section is appended to (bench/RESULTS.md)")
    peron = parser.add_mutually_exclusive_group()
    peron.add_argument("--peron-run", type=Path, metavar="DIR", help="a completed run of inputs/peron/peron.toml")
    peron.add_argument("--peron", action="store_true", help="run inputs/peron/peron.toml in full first")
    args = parser.parse_args()
    command = "bench/run_bench.py " + " ".join(shlex.quote(a) for a in sys.argv[1:])
    stamp = datetime.datetime.now().astimezone().strftime("%Y-%m-%d %H:%M %Z")  # the start

    lines = machine_lines(args.build)
    print("\n".join(lines), flush=True)
    peron_run = args.peron_run
    if args.peron:
        peron_run = REPO / "runs" / "peron_bench"
        print(f"running inputs/peron/peron.toml into {peron_run} (8-9 minutes on 2 cores)", flush=True)
        if ydry_case.run_ydry(args.build / "ydry", REPO / "inputs/peron/peron.toml", peron_run) is None:
            sys.exit("run_bench.py: the Peron run failed")
    lines += run_bench(args.build / "bench" / "bench_memory")
    lines += run_bench(args.build / "bench" / "bench_moisture")
    lines += run_bench(args.build / "bench" / "bench_mechanics")
    lines += run_bench(args.build / "bench" / "bench_factorisation", str(REPO / "inputs/peron/peron.toml"),
                       "--set", "solver.joint_penalty=100", "--set", "contact.penalty=4e7")
    if peron_run:
        lines += peron_lines(peron_run)
        print(lines[-1])

    with args.results.open("a") as results:
        results.write(f"\n## {stamp}\n\n`{command.strip()}`\n\n```\n" + "\n".join(lines) + "\n```\n")
    print(f"appended to {args.results}")


if __name__ == "__main__":
    main()
