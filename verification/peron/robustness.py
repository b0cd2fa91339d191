#!/usr/bin/python3
"""Robustness of the Peron figures: does each variant keep the shipped deck's crack
count within +-1 and its mean final width within 10 %?

Reads a folder that `make robustness` (scripts/sweep.py on verification/peron/robustness/*.toml)
filled: OUT/sweep.json names the runs. The reference is the run whose deck.toml is the shipped
deck inputs/peron/peron.toml as `ydry check` resolves it, every value alike (defaults included;
the mesh compared by its contents), the run the relaxation, penalty and mesh studies share;
every other run is a variant: three seeds of a 5 % strength heterogeneity, the relaxation
tolerance ten times tighter, the penalties ten times stiffer, the element size halved. Each
variant's surface_crack_count and mean_surface_crack_width_m (summary.json, the figures the experiment
measures) are compared with the reference's, and printed beside the experiment's (7 cracks,
0.836 mm), with the sum of the top surface's gaps (the shrinkage the cracks take up, whichever
cracks count). A variant not yet completed is shown at the time it reached and fails `completed`.
Prints `peron_robustness METRIC VALUE TOLERANCE PASS|FAIL` (METRIC names the variant) and exits
1 if a check fails, 2 if OUT has no sweep.json or no completed reference run.

    verification/peron/robustness.py runs/robustness [--ydry build/ydry]
"""
import json
import math
import sys
from pathlib import Path

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE.parent))
sys.path.insert(0, str(HERE))
sys.path.insert(0, str(HERE.parents[1] / "scripts"))
import check  # noqa: E402  (DECK, number, CRACKS, MEAN_WIDTH, MM)
import sweep_plan  # noqa: E402  (resolved_deck, deck_key: how scripts/sweep.py tells decks apart)
import ydry_case  # noqa: E402

COUNT_TOLERANCE = 1     # cracks, against the reference run
WIDTH_TOLERANCE = 0.10  # relative, against the reference run


def runs_of(out):
    """{folder name: [(study, value text)]} of the runs sweep.json lists, in its order."""
    runs = {}
    for sweep in json.loads((out / "sweep.json").read_text())["sweeps"]:
        for entry in sweep["entries"]:
            value = entry["value"]
            label = f"{value * sweep.get('scale', 1.0):g} {sweep.get('unit', '')}".strip()
            runs.setdefault(entry["folder"], []).append(f"{sweep['axis']} = {label}")
    return runs


def figures(folder, shipped_key):
    """(summary.json, whether its deck.toml is the shipped deck) of a run folder, or None if the
    run has not written its summary yet."""
    if not (folder / "summary.json").is_file():
        return None
    deck = folder / "deck.toml"
    is_shipped = deck.is_file() and sweep_plan.deck_key(deck.read_text()) == shipped_key
    return json.loads((folder / "summary.json").read_text()), is_shipped


def top_gaps(folder):
    """The horizontal gaps of the top surface at its breaks, summed, at the last frame of the
    run's surface.csv (check.py prints the same), in m; NaN without surface.csv rows. Unlike
    the count and mean width of the cracks, it does not depend on which cracks count."""
    path = folder / "surface.csv"
    surface = ydry_case.read_csv(path) if path.is_file() else None
    if surface is None or not len(surface["time_s"]):
        return math.nan
    return sum(mouth["gap"] for mouth in check.surface_mouths(surface, surface["time_s"][-1]))


def main():
    parser = ydry_case.script_parser(__doc__)
    parser.add_argument("out", type=Path, help="the folder of the robustness runs (sweep.json)")
    parser.add_argument("--ydry", type=Path, default=ydry_case.REPO / "build" / "ydry",
                        help="resolves the shipped deck (ydry check)")
    args = parser.parse_args()
    if not (args.out / "sweep.json").is_file():
        print(f"robustness: {args.out} has no sweep.json (run `make robustness` first)", file=sys.stderr)
        return 2
    shipped_key = sweep_plan.deck_key(sweep_plan.resolved_deck(args.ydry, str(check.DECK), []))
    runs = {name: (what, figures(args.out / name, shipped_key)) for name, what in runs_of(args.out).items()}
    reference = [name for name, (_, found) in runs.items() if found is not None and found[1]]
    if not reference or not runs[reference[0]][1][0]["completed"]:
        print(f"robustness: {args.out} has no completed run of the shipped deck to compare with", file=sys.stderr)
        return 2
    base = runs[reference[0]][1][0]
    base_width = check.number(base["mean_surface_crack_width_m"])
    print(f"# reference {reference[0]} ({', '.join(runs[reference[0]][0])}): {base['surface_crack_count']} surface "
          f"cracks, mean width {base_width * check.MM:.4f} mm (experiment {check.CRACKS}, "
          f"{check.MEAN_WIDTH * check.MM:.3f} mm), top gaps {top_gaps(args.out / reference[0]) * check.MM:.3f} mm")
    print("# run                       what                         t (s)   cracks  mean width (mm)  "
          "vs reference   total (mm)  right end u_x (mm)  top gaps (mm)")
    verdicts = ydry_case.Verdicts("peron_robustness")
    for name, (what, found) in runs.items():
        if name == reference[0]:
            continue
        if found is None:
            verdicts.check(f"{name}_completed", "false", "true", False)
            print(f"# {name}: not started")
            continue
        s = found[0]
        width = check.number(s["mean_surface_crack_width_m"])
        change = (width - base_width) / base_width
        print(f"# {name:25s} {', '.join(what):28s} {s['time_s']:7g} {s['surface_crack_count']:7d} "
              f"{width * check.MM:16.4f} {100 * change:+11.1f} % {check.number(s['total_surface_crack_width_m']) * check.MM:12.3f} "
              f"{check.number(s['right_end_displacement_m']) * check.MM:+19.4f} "
              f"{top_gaps(args.out / name) * check.MM:14.3f}")
        verdicts.check(f"{name}_completed", bool(s["completed"]), "true", bool(s["completed"]))
        count_change = s["surface_crack_count"] - base["surface_crack_count"]
        verdicts.check(f"{name}_surface_crack_count_change", count_change, f"+-{COUNT_TOLERANCE}",
                       abs(count_change) <= COUNT_TOLERANCE)
        verdicts.below(f"{name}_mean_surface_width_rel_change", abs(change) if math.isfinite(change) else math.nan,
                       WIDTH_TOLERANCE)
    return verdicts.exit_code()


if __name__ == "__main__":
    sys.exit(main())
