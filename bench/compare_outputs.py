#!/usr/bin/python3
"""Compare every output file of two folders of ydry runs, byte for byte.

  bench/compare_outputs.py OLD NEW

OLD and NEW hold the same runs (e.g. `verification/CASE/check.py --out OLD/CASE` of two
builds, and the Peron deck run into OLD/peron). Every file of OLD must be in NEW with the same
bytes, except what states the execution rather than the results: log.txt, checkpoints (they
hold the ydry version), results.md and *.verdicts of the check scripts (wall times);
summary.json is compared without version, threads and wall times, deck.toml without the
lines naming the deck's and the mesh's paths. Prints the files that differ or are missing;
exits 1 if any.
"""
import json
import re
import sys
from pathlib import Path

UNCOMPARED = {"log.txt", "results.md"}
UNCOMPARED_SUFFIXES = {".chk", ".verdicts", ".out", ".png"}


def summary(path):
    values = json.loads(path.read_text())
    return {k: v for k, v in values.items()
            if k not in ("version", "threads") and not re.fullmatch(r"wall(_[a-z]+)?_s", k)}


def deck(path):
    lines = path.read_text().splitlines()[1:]  # the first names the deck's path
    return [line for line in lines if not line.startswith("file = ")]


def same(a, b):
    if a.name == "summary.json":
        return summary(a) == summary(b)
    if a.name == "deck.toml":
        return deck(a) == deck(b)
    return a.read_bytes() == b.read_bytes()


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    old, new = Path(sys.argv[1]), Path(sys.argv[2])
    compared = skipped = 0
    differ = []
    for a in sorted(p for p in old.rglob("*") if p.is_file()):
        rel = a.relative_to(old)
        if a.name in UNCOMPARED or a.suffix in UNCOMPARED_SUFFIXES:
            skipped += 1
            continue
        b = new / rel
        if not b.is_file():
            differ.append(f"missing {rel}")
        elif not same(a, b):
            differ.append(f"differs {rel}")
        compared += 1
    print("\n".join(differ))
    print(f"{compared - len(differ)} of {compared} files the same; {skipped} not compared "
          "(logs, checkpoints, wall times)")
    return 1 if differ else 0


if __name__ == "__main__":
    sys.exit(main())
