#!/usr/bin/python3
"""Run every verification case and summarise its verdicts.

Discovers verification/*/check.py, runs each with --ydry, streams its output and collects the
verdict lines `CASE METRIC VALUE TOLERANCE PASS|FAIL`. A script that exits non-zero without a
FAIL verdict to explain it is reported as a FAIL line of its own. Prints `N passed, M failed`
and exits 1 if anything failed.
"""
import argparse
import re
import subprocess
import sys
from pathlib import Path

HERE = Path(__file__).resolve().parent
VERDICT = re.compile(r"^(\S+) (\S+) (\S+) (\S+) (PASS|FAIL)$")


def run_check(script, ydry):
    """Run one check script, echoing its output; return (exit code, verdict lines)."""
    proc = subprocess.Popen([sys.executable, "-u", str(script), "--ydry", str(ydry)],
                            stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    verdicts = []
    for line in proc.stdout:
        print(line, end="", flush=True)
        if VERDICT.match(line.rstrip("\n")):
            verdicts.append(line.rstrip("\n"))
    return proc.wait(), verdicts


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--ydry", type=Path, default=HERE.parent / "build" / "ydry")
    args = parser.parse_args()

    verdicts = []
    for script in sorted(HERE.glob("*/check.py")):
        case = script.parent.name
        print(f"=== {case}", flush=True)
        code, lines = run_check(script, args.ydry.resolve())
        if code != 0 and not any(line.endswith(" FAIL") for line in lines):
            lines.append(f"{case} exit_code {code} 0 FAIL")
            print(lines[-1])
        verdicts += lines

    failed = [line for line in verdicts if line.endswith(" FAIL")]
    if failed:
        print("\nFailed checks:\n" + "\n".join(failed))
    print(f"\n{len(verdicts) - len(failed)} passed, {len(failed)} failed")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
