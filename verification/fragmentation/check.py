#!/usr/bin/python3
"""Verification case fragmentation: a strip seen in plan view breaking on a frictional base.

Runs ydry on fragmentation.toml (a 200 mm x 1 mm strip drying uniformly on a stiff base
without adhesion), finds the fragments of the last frame (its `cell` array) and checks each
fragment's length against the closed form: a fragment of length s carries at most
tau s / (2 h), tau = tan(phi_b) rho g h, so every final fragment lies between l_f and 2 l_f,
l_f = f_t / (tan(phi_b) rho g), within an element and the joints' strength factors. Prints
the verdict lines `fragmentation METRIC VALUE TOLERANCE PASS|FAIL` and writes out/results.md and
out/fragments.png. With --seeds N it also runs seeds 1..N and writes their fragments to
out/seeds.md (information, no verdicts). Exits 1 if any check fails.
"""
import json
import math
import re
import sys
from pathlib import Path

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE.parent))
import ydry_case  # noqa: E402

DECK = HERE / "fragmentation.toml"
L = 0.2                         # strip length, m
ELEMENT = 0.001                 # element size, m: a crack runs along the joints between columns
F_T, RHO, G, PHI = 85.0, 1500.0, 9.81, 30.0  # the film's f_t and density; the base's g and phi_b
L_F = F_T / (math.tan(math.radians(PHI)) * RHO * G)  # 10.0 mm


def strength_factors(outdir):
    """The smallest and largest strength factor of the joints, from the log's set-up line."""
    text = (Path(outdir) / "log.txt").read_text()
    found = re.search(r"strength factors of \d+ joints .*?: min ([0-9.eE+-]+), mean [0-9.eE+-]+, max ([0-9.eE+-]+)", text)
    return float(found.group(1)), float(found.group(2))


def fragments(outdir):
    """The reference length of each cell of the last frame, left to right, m."""
    frame = ydry_case.last_frame(outdir)
    x0 = frame["x0"][frame["cells"]][:, :, 0]
    lengths = []
    for cell in np.unique(frame["cell"]):
        mine = x0[frame["cell"] == cell]
        lengths.append((mine.min(), mine.max() - mine.min()))
    return np.array([length for _, length in sorted(lengths)])


def bounds(outdir):
    """The shortest and longest fragment the closed form allows, within an element: a crack
    forms where the stress tau d / h at distance d from a free end reaches a joint's strength
    f f_t, so d >= f_min l_f; a fragment stays whole while its middle carries less than its
    joints' strength, s < 2 f_max l_f."""
    f_min, f_max = strength_factors(outdir)
    return f_min * L_F - ELEMENT, 2.0 * f_max * L_F + ELEMENT


def main():
    parser = ydry_case.case_parser(__doc__, HERE)
    parser.add_argument("--seeds", type=int, default=0, help="also run seeds 1..N and report their fragments")
    args = ydry_case.parse_case_arguments(parser)
    args.out.mkdir(parents=True, exist_ok=True)
    verdicts = ydry_case.Verdicts("fragmentation")
    run = args.out / "run"
    wall = ydry_case.run_ydry(args.ydry, DECK, run)
    verdicts.check("ran", wall is not None, "true", wall is not None)
    if wall is None:
        return 1
    summary = json.loads((run / "summary.json").read_text())
    lengths = fragments(run)
    shortest, longest = bounds(run)
    fewest, most = math.ceil(L / longest), math.floor(L / shortest)
    print(f"# {wall:.1f} s, {summary['mechanical_steps']} relaxation steps, {len(lengths)} fragments (mm): "
          + " ".join(f"{1e3 * s:.0f}" for s in lengths))
    print(f"# allowed: {1e3 * shortest:.2f} to {1e3 * longest:.2f} mm (l_f = {1e3 * L_F:.2f} mm), "
          f"{fewest} to {most} fragments")
    verdicts.check("shortest_fragment_mm", 1e3 * lengths.min(), f">={1e3 * shortest:.2f}", lengths.min() >= shortest)
    verdicts.check("longest_fragment_mm", 1e3 * lengths.max(), f"<={1e3 * longest:.2f}", lengths.max() <= longest)
    verdicts.check("fragments", len(lengths), f"{fewest}..{most}", fewest <= len(lengths) <= most)
    verdicts.below("water_balance_error", summary["water_balance_error"], 1e-12)
    (args.out / "results.md").write_text(
        f"| fragments | shortest (mm) | longest (mm) | allowed (mm) | l_f (mm) |\n|---:|---:|---:|---|---:|\n"
        f"| {len(lengths)} | {1e3 * lengths.min():.1f} | {1e3 * lengths.max():.1f} "
        f"| {1e3 * shortest:.2f} to {1e3 * longest:.2f} | {1e3 * L_F:.2f} |\n")

    fig, ax = plt.subplots(figsize=(7, 3.6))
    ax.hist(lengths * 1e3, bins=np.arange(0, 26, 1), color="tab:blue", edgecolor="white", label="ydry, the deck's seed")
    for edge, name in ((shortest, "shortest allowed"), (longest, "longest allowed")):
        ax.axvline(edge * 1e3, color="k", ls="--", lw=1)
        ax.text(edge * 1e3, ax.get_ylim()[1] * 0.9, " " + name, fontsize=8)
    ax.set_xlabel("fragment length (mm)")
    ax.set_ylabel("fragments")
    ax.set_title(f"a strip broken on a frictional base: l_f = {1e3 * L_F:.1f} mm")
    ax.legend(loc="upper left")
    fig.tight_layout()
    fig.savefig(args.out / "fragments.png", dpi=150)
    plt.close(fig)

    if args.seeds:
        rows = []
        for seed in range(1, args.seeds + 1):
            out = args.out / f"seed{seed}"
            if ydry_case.run_ydry(args.ydry, DECK, out, [f"run.seed={seed}"]) is None:
                return 1
            s = fragments(out)
            low, high = bounds(out)
            inside = "yes" if s.min() >= low and s.max() <= high else "no"
            rows.append(f"| {seed} | {len(s)} | {1e3 * s.min():.0f} | {1e3 * s.max():.0f} "
                        f"| {1e3 * low:.2f} to {1e3 * high:.2f} | {inside} |")
            print(f"# seed {seed}: " + " ".join(f"{1e3 * x:.0f}" for x in s) + f" mm; within the bounds: {inside}")
        (args.out / "seeds.md").write_text(
            "| seed | fragments | shortest (mm) | longest (mm) | allowed (mm) | all within |\n"
            "|---:|---:|---:|---:|---|---|\n" + "\n".join(rows) + "\n")
    return verdicts.exit_code()


if __name__ == "__main__":
    sys.exit(main())
