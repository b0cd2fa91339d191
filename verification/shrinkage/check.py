#!/usr/bin/python3
"""Verification case shrinkage: a block shrinking between two supports (paper section 4.3).

Runs ydry on shrinkage.toml in plane stress and plane strain, compares the vertical stress
(from the top support's reaction and from the element stresses) and the horizontal shortening
with the closed form, reruns plane stress with a larger relaxation step cap, a tighter
relaxation tolerance and the damping in place of Newton to show the answer does not depend
on them, prints an info line per run
(wall time, relaxation steps, final residual ratio) and the verdict lines
`shrinkage METRIC VALUE TOLERANCE PASS|FAIL`, writes out/results.md and
out/shrinkage_fields.png. Exits 1 if any check fails.
"""
import json
import sys
from pathlib import Path

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE.parent))
import ydry_case  # noqa: E402

DECK = HERE / "shrinkage.toml"
L, W, THICKNESS = 0.1, 0.05, 1.0  # block length (x), height (y), m
E, NU, ALPHA, DW = 1.0e6, 0.2, 0.1, 0.2
EXACT = {  # plane: (sigma_y in Pa, shortening dLx in m)
    "stress": (E * ALPHA * DW, L * (NU * ALPHA * DW + ALPHA * DW)),
    "strain": (E * ALPHA * DW / (1 - NU), L * ALPHA * DW * (1 + NU) / (1 - NU)),
}
RUNS = {  # label: --set overrides
    "stress": ['run.plane="stress"'],
    "strain": ['run.plane="strain"'],
    "stress_max_steps_400k": ['run.plane="stress"', "solver.relaxation_max_steps=400000"],
    "stress_tolerance_5e-8": ['run.plane="stress"', "solver.relaxation_tolerance=5e-8"],
    "stress_damping": ['run.plane="stress"', 'solver.relaxation="viscous"'],
}
ERROR_TOLERANCE = 0.005       # relative, on sigma_y (both measures) and dLx
INDEPENDENCE_TOLERANCE = 0.001  # relative change against the default plane stress run


def measure(outdir):
    """sigma_y from the top reaction and from the element stresses, dLx, and the top and
    bottom reaction_y (for the sign check), all at the last output."""
    top, bottom = ydry_case.reactions(outdir, "top"), ydry_case.reactions(outdir, "bottom")
    frame = ydry_case.last_frame(outdir)
    x0, ux = frame["x0"][:, 0], frame["u"][:, 0]
    return {
        "sigma_reaction": abs(top["reaction_y_N"][-1]) / (L * THICKNESS),
        "sigma_mean": np.average(frame["stress"][:, 1], weights=frame["area"]),
        "dLx": ux[np.isclose(x0, 0.0, atol=1e-9)].mean() - ux[np.isclose(x0, L, atol=1e-9)].mean(),
        "top_ry": top["reaction_y_N"][-1], "bottom_ry": bottom["reaction_y_N"][-1],
        "frame": frame,
    }


def plot(results, path):
    fig, (left, right) = plt.subplots(1, 2, figsize=(11, 4.2))
    for plane, marker in (("stress", "o"), ("strain", "s")):
        frame = results[plane]["frame"]
        y0 = frame["x0"][:, 1]
        mid = np.isclose(y0, y0[np.argmin(abs(y0 - W / 2))], atol=1e-9)  # the node row nearest W/2
        x, ux = frame["x0"][mid, 0], frame["u"][mid, 0]
        slope = -EXACT[plane][1] / L
        offset = np.mean(ux - slope * (x - L / 2))  # the block is free in x: fit its rigid shift
        xs = np.linspace(0, L, 2)
        left.plot(xs * 100, (slope * (xs - L / 2) + offset) * 1e3, "k-", lw=1)
        left.plot(x * 100, ux * 1e3, marker, mfc="none", ms=5, ls="none", label=f"ydry, plane {plane}")
        syy = frame["stress"][:, 1]
        deviation = (syy / EXACT[plane][0] - 1) * 100
        right.hist(deviation, bins=40, alpha=0.6, label=f"plane {plane}, mean {deviation.mean():+.3f} %")
    left.plot([], [], "k-", lw=1, label="closed form")
    left.set_xlabel("x (cm), node row nearest mid-height")
    left.set_ylabel("horizontal displacement u$_x$ (mm)")
    left.set_title("u$_x$ along the block")
    right.set_xlabel("element $\\sigma_{yy}$ / closed form - 1 (%); the bar is $\\pm$0.5 %")
    right.set_ylabel("number of elements")
    right.set_title("vertical stress of the elements")
    for ax in (left, right):
        ax.grid(alpha=0.3)
        ax.legend()
    fig.tight_layout()
    fig.savefig(path, dpi=150)
    plt.close(fig)


def main():
    args = ydry_case.arguments(__doc__, HERE)
    verdicts = ydry_case.Verdicts("shrinkage")
    results = {}
    for label, overrides in RUNS.items():
        wall = ydry_case.run_ydry(args.ydry, DECK, args.out / label, overrides)
        verdicts.check(f"ran_{label}", wall is not None, "true", wall is not None)
        if wall is not None:
            done = ydry_case.completed(args.out / label)
            verdicts.check(f"completed_{label}", done, "true", done)
            results[label] = measure(args.out / label)
            summary = json.loads((args.out / label / "summary.json").read_text())
            print(f"# {label}: {wall:.1f} s, {summary['mechanical_steps']} relaxation steps, "
                  f"final residual ratio {summary['relaxation_residual']:.3g}")
    if len(results) < len(RUNS):
        return 1

    rows = []
    for plane in ("stress", "strain"):
        r, (sigma, dlx) = results[plane], EXACT[plane]
        errors = {key: ydry_case.relative_error(r[key], exact)
                  for key, exact in (("sigma_reaction", sigma), ("sigma_mean", sigma), ("dLx", dlx))}
        print(f"# plane {plane}: sigma_y {r['sigma_reaction']:.2f} Pa (reaction), "
              f"{r['sigma_mean']:.2f} Pa (elements), exact {sigma:.0f} Pa; "
              f"dLx {r['dLx']:.6e} m, exact {dlx:.4e} m")
        sign_ok = r["top_ry"] > 0 and r["bottom_ry"] < 0 and r["sigma_mean"] > 0
        verdicts.check(f"reaction_sign_plane_{plane}", sign_ok, "true", sign_ok)
        verdicts.below(f"sigma_y_reaction_rel_error_plane_{plane}", errors["sigma_reaction"], ERROR_TOLERANCE)
        verdicts.below(f"sigma_y_elements_rel_error_plane_{plane}", errors["sigma_mean"], ERROR_TOLERANCE)
        verdicts.below(f"dLx_rel_error_plane_{plane}", errors["dLx"], ERROR_TOLERANCE)
        rows.append(f"| plane {plane} | {r['sigma_reaction']:.1f} ({100 * errors['sigma_reaction']:.3f} %) "
                    f"| {r['sigma_mean']:.1f} ({100 * errors['sigma_mean']:.3f} %) "
                    f"| {r['dLx'] * 1e3:.5f} ({100 * errors['dLx']:.3f} %) |")

    base = results["stress"]
    for label in ("stress_max_steps_400k", "stress_tolerance_5e-8", "stress_damping"):
        for key in ("sigma_reaction", "dLx"):
            change = ydry_case.relative_error(results[label][key], base[key])
            metric = f"{'sigma_y' if key == 'sigma_reaction' else 'dLx'}_change_{label}"
            verdicts.below(metric, change, INDEPENDENCE_TOLERANCE)

    (args.out / "results.md").write_text(
        "| run | sigma_y from reaction (Pa) | mean element sigma_yy (Pa) | dLx (mm) |\n"
        "|---|---:|---:|---:|\n" + "\n".join(rows) + "\n")
    plot(results, args.out / "shrinkage_fields.png")
    return verdicts.exit_code()


if __name__ == "__main__":
    sys.exit(main())
