#!/usr/bin/python3
"""ctest interruption: SIGINT, SIGTERM and kill -9 on a running ydry.

The cracking notched layer (tests/test_support.h's deck, run to 6000 s with a row every 250 s
and a frame every 500 s: 216 coupling steps, 5 broken joints) runs once uninterrupted. Then:

- SIGINT, and SIGTERM, part way: ydry exits 130 with a checkpoint, every file in its folder is
  complete, and `ydry --restart` from the checkpoint ends in the uninterrupted run's files.
- kill -9 six times at random moments (seeded), each time continued from the newest
  checkpoint (written every 0.2 s of wall time) or started afresh if there is none: after
  every kill, every file in the folder reads back completely (CSV rows whole, JSON, TOML, the
  .pvd's frames present and readable, every .vtu whole, every checkpoint valid by
  `ydry check --restart`), files under a temporary name (.tmp) aside; and the run that
  finally completes ends in the uninterrupted run's files.

"The uninterrupted run's files": every file of it is there with the same bytes, but log.txt
(each process logs its own lines and wall times) and summary.json's wall_s and its split by stage; anything else is a
checkpoint. Exits 1 on any failure.
"""
import argparse
import json
import random
import re
import signal
import subprocess
import sys
import tempfile
import time
import tomllib
import xml.etree.ElementTree as ET
from pathlib import Path

REPO = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(REPO / "verification"))
import ydry_case  # noqa: E402  (frames, read_grid)

DECK = REPO / "inputs/peron/peron.toml"
OVERRIDES = [f'mesh.file="{REPO}/tests/data/notched_layer.msh"', "run.end_time=6000", "run.output_interval=500",
             "run.series_interval=250", "solver.mechanics_interval=250", "materials.soil.shrinkage_coefficient=0.4",
             "materials.soil.gf_I=0.02", "solver.relaxation_tolerance=1e-4", "solver.relaxation_max_steps=3000"]
KILLS = 6


def command(ydry, outdir, *extra):
    args = [str(ydry), str(DECK), "-o", str(outdir), "--quiet", *extra]
    for override in OVERRIDES:
        args += ["--set", override]
    return args


def restart_command(ydry, checkpoint, *extra):
    return [str(ydry), "--restart", str(checkpoint), "--quiet", *extra]


def checkpoints(outdir):
    """The run's checkpoints, oldest first (NAME_NNNNNN.chk, NNNNNN the coupling step)."""
    return sorted((Path(outdir) / "checkpoints").glob("*.chk"), key=lambda p: int(p.stem.rsplit("_", 1)[1]))


def whole_vtu(path):
    """Problems of a .vtu: not ending as VTK's writer ends it, or reading back fewer points or
    cells than its header gives."""
    data = path.read_bytes()
    if not data.endswith(b"</VTKFile>\n"):
        return [f"{path}: does not end with </VTKFile>"]
    header = data[:data.index(b"<AppendedData")].decode()
    points, cells = map(int, re.search(r'NumberOfPoints="(\d+)" *NumberOfCells="(\d+)"', header).groups())
    grid = ydry_case.read_grid(path)
    if (grid.GetNumberOfPoints(), grid.GetNumberOfCells()) != (points, cells):
        return [f"{path}: read {grid.GetNumberOfPoints()} points, {grid.GetNumberOfCells()} cells of "
                f"{points}, {cells}"]
    return []


def whole_csv(path):
    lines = path.read_text().split("\n")
    if lines[-1] != "":
        return [f"{path}: the last line is not whole"]
    columns = len(lines[0].split(","))
    return [f"{path}:{k + 1}: {len(line.split(','))} fields of {columns}"
            for k, line in enumerate(lines[1:-1], 1) if len(line.split(",")) != columns]


def complete_files(ydry, outdir):
    """Problems with the files in a run folder: each must read back whole (see the docstring)."""
    problems = []
    outdir = Path(outdir)
    for path in sorted(p for p in outdir.rglob("*") if p.is_file() and p.suffix != ".tmp"):
        try:
            if path.suffix == ".csv":
                problems += whole_csv(path)
            elif path.suffix == ".json":
                json.loads(path.read_text())
            elif path.suffix == ".toml":
                tomllib.loads(path.read_text())
            elif path.suffix == ".vtu":
                problems += whole_vtu(path)
            elif path.suffix == ".pvd":
                problems += [f"{path}: lists {f}, which is not there"
                             for frame in ydry_case.frames(path).values() for f in frame.values() if not f.is_file()]
            elif path.suffix == ".chk":
                proc = subprocess.run([str(ydry), "check", "--restart", str(path)], capture_output=True, text=True)
                if proc.returncode != 0:
                    problems.append(f"{path}: ydry check --restart exits {proc.returncode}: {proc.stderr.strip()}")
            elif path.name == "log.txt" and not path.read_text().endswith("\n"):
                problems.append(f"{path}: the last line is not whole")
        except (ValueError, ET.ParseError, tomllib.TOMLDecodeError) as error:
            problems.append(f"{path}: {error}")
    return problems


def same_outputs(reference, outdir):
    """Problems with outdir's files against the uninterrupted run's (see the docstring)."""
    problems = []
    reference, outdir = Path(reference), Path(outdir)
    ours = {p.relative_to(reference) for p in reference.rglob("*") if p.is_file()}
    theirs = {p.relative_to(outdir) for p in outdir.rglob("*") if p.is_file()}
    problems += [f"{outdir / f}: missing" for f in sorted(ours - theirs)]
    problems += [f"{outdir / f}: not the uninterrupted run's" for f in sorted(theirs - ours)
                 if f.parent != Path("checkpoints") or f.suffix != ".chk"]
    wall = re.compile(rb'"wall(_[a-z]+)?_s": [^,\n]+')
    for f in sorted(ours & theirs):
        if f.name == "log.txt":
            continue
        a, b = (reference / f).read_bytes(), (outdir / f).read_bytes()
        if f.name == "summary.json":
            a, b = wall.sub(b"", a), wall.sub(b"", b)
        if a != b:
            problems.append(f"{outdir / f}: differs from the uninterrupted run's")
    return problems


def run_to_end(args):
    proc = subprocess.run(args, capture_output=True, text=True)
    return [] if proc.returncode == 0 else [f"{' '.join(args)} exits {proc.returncode}: {proc.stderr}"]


def rows(outdir):
    try:
        return (Path(outdir) / "series.csv").read_text().count("\n") - 1
    except FileNotFoundError:
        return 0


def interrupted(ydry, outdir, reference, sig):
    """SIGINT or SIGTERM once a third of the rows are written: exit 130, a checkpoint, whole
    files, and a restart that ends as the uninterrupted run did."""
    proc = subprocess.Popen(command(ydry, outdir), stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    while rows(outdir) < 8 and proc.poll() is None:
        time.sleep(0.01)
    proc.send_signal(sig)
    _, stderr = proc.communicate()
    name = signal.Signals(sig).name
    if proc.returncode != 130:
        return [f"{name}: exit {proc.returncode}, not 130: {stderr}"]
    problems = complete_files(ydry, outdir)
    saved = checkpoints(outdir)
    if len(saved) != 1 or f"continue with: ydry --restart {saved[0]}" not in stderr:
        return problems + [f"{name}: checkpoints {saved}; ydry said: {stderr}"]
    print(f"{name} after {rows(outdir)} rows: exit 130, {saved[0].name}")
    return problems + run_to_end(restart_command(ydry, saved[0])) + same_outputs(reference, outdir)


def killed(ydry, outdir, reference, wall_s):
    """kill -9 at random moments, each time going on from the newest checkpoint."""
    problems = []
    chance = random.Random(9)
    for kill in range(KILLS):
        saved = checkpoints(outdir)
        args = (restart_command(ydry, saved[-1], "--checkpoint-every", "0.2") if saved
                else command(ydry, outdir, "--checkpoint-every", "0.2"))
        proc = subprocess.Popen(args, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        time.sleep(chance.uniform(0.02, 0.5 * wall_s))
        proc.kill()
        proc.wait()
        found = complete_files(ydry, outdir)
        print(f"kill -9 {kill + 1} ({'from ' + saved[-1].name if saved else 'afresh'}): exit {proc.returncode}, "
              f"{rows(outdir)} rows, {len(checkpoints(outdir))} checkpoints, {len(found)} problems")
        problems += found
    saved = checkpoints(outdir)
    problems += run_to_end(restart_command(ydry, saved[-1]) if saved else command(ydry, outdir))
    return problems + same_outputs(reference, outdir)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--ydry", type=Path, default=REPO / "build" / "ydry")
    args = parser.parse_args()
    with tempfile.TemporaryDirectory(prefix="ydry_interruption_") as tmp:
        reference = Path(tmp) / "uninterrupted"
        start = time.perf_counter()
        problems = run_to_end(command(args.ydry, reference))
        wall_s = time.perf_counter() - start
        problems += complete_files(args.ydry, reference)
        for sig in (signal.SIGINT, signal.SIGTERM):
            problems += interrupted(args.ydry, Path(tmp) / signal.Signals(sig).name, reference, sig)
        problems += killed(args.ydry, Path(tmp) / "killed", reference, wall_s)
    for problem in problems:
        print("FAIL:", problem)
    print("interruption:", "FAIL" if problems else "PASS")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
