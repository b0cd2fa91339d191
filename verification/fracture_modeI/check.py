#!/usr/bin/python3
"""Verification case fracture_modeI: a bar pulled apart across one line of joints (mode I).

Runs ydry on fracture_modeI.toml at element sizes 1 mm and 0.5 mm, checks that the peak
traction on the joint line equals the tensile strength f_t and that the energy dissipated per
unit crack area equals the mode I fracture energy gf_I (also measured as the external work
through the pulled side), and that the bar ends fully separated along that line. Prints the
verdict lines `fracture_modeI METRIC VALUE TOLERANCE PASS|FAIL`, writes out/results.md and
out/traction_opening.png. Exits 1 if any check fails.
"""
import sys
from pathlib import Path

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE.parent))
import ydry_case  # noqa: E402

DECK = HERE / "fracture_modeI.toml"
F_T, GF_I, THICKNESS = 1.0e4, 1.0, 1.0  # Pa, J/m^2, m
RUNS = {  # label: (element size h, bar height H = joint line length, --set overrides)
    "h1mm": (0.001, 0.004, []),
    "h0.5mm": (0.0005, 0.002, ["mesh.element_size=0.0005", "mesh.size=[0.001,0.002]"]),
}
STRENGTH_TOLERANCE = 0.02
ENERGY_TOLERANCE = 0.02
WORK_TOLERANCE = 0.02
RESIDUAL_TOLERANCE = 1e-6  # final reaction / peak reaction


def measure(outdir, height):
    right = ydry_case.reactions(outdir, "right")
    series = ydry_case.read_csv(outdir / "series.csv")
    cracks = ydry_case.last_cracks(outdir)
    area = height * THICKNESS
    dx, dy = np.abs(np.diff(cracks["ends"], axis=1))[:, 0].T
    peak = np.max(right["reaction_x_N"])
    return {
        "pull": right["mean_ux_m"], "traction": right["reaction_x_N"] / area,
        "peak": peak / area,
        "energy": series["fracture_energy_J"][-1] / area,
        "work": right["work_J"][-1] / area,
        "work_trapezoid": np.trapz(right["reaction_x_N"], right["mean_ux_m"]) / area,
        "residual": np.hypot(right["reaction_x_N"][-1], right["reaction_y_N"][-1]) / peak,
        "broken": int(series["broken_joints"][-1]),
        "broken_on_line": int(np.sum(dx < 1e-3 * dy)),  # vertical: only the middle line is
    }


def plot(results, path):
    fig, ax = plt.subplots(figsize=(7, 4.5))
    for (label, r), style in zip(results.items(), ("-", "--")):
        ax.plot(r["pull"] * 1e3, r["traction"] / 1e3, style,
                label=f"ydry, {label}: peak {r['peak'] / 1e3:.3f} kPa, G = {r['energy']:.4f} J/m$^2$")
    ax.axhline(F_T / 1e3, color="k", lw=0.8, ls=":", label="tensile strength f$_t$")
    ax.set_xlabel("pull of the right side (mm)")
    ax.set_ylabel("traction on the joint line (kPa)")
    ax.set_title(f"Mode I: f$_t$ = {F_T / 1e3:g} kPa, gf$_I$ = {GF_I:g} J/m$^2$")
    ax.set_xlim(left=0)
    ax.grid(alpha=0.3)
    ax.legend()
    fig.tight_layout()
    fig.savefig(path, dpi=150)
    plt.close(fig)


def main():
    args = ydry_case.arguments(__doc__, HERE)
    verdicts = ydry_case.Verdicts("fracture_modeI")
    results, rows = {}, []
    for label, (h, height, overrides) in RUNS.items():
        wall = ydry_case.run_ydry(args.ydry, DECK, args.out / label, overrides)
        if not verdicts.check(f"ran_{label}", wall is not None, "true", wall is not None):
            continue
        done = ydry_case.completed(args.out / label)
        verdicts.check(f"completed_{label}", done, "true", done)
        r = results[label] = measure(args.out / label, height)
        rows_of_elements = round(height / h)
        print(f"# {label} ({wall:.1f} s): peak traction {r['peak']:.2f} Pa, fracture energy "
              f"{r['energy']:.5f} J/m^2, external work {r['work']:.5f} J/m^2 "
              f"(trapezoid of the logged reactions: {r['work_trapezoid']:.5f} J/m^2)")
        verdicts.below(f"peak_traction_rel_error_{label}", ydry_case.relative_error(r["peak"], F_T),
                       STRENGTH_TOLERANCE)
        verdicts.below(f"fracture_energy_rel_error_{label}", ydry_case.relative_error(r["energy"], GF_I),
                       ENERGY_TOLERANCE)
        verdicts.below(f"external_work_rel_error_{label}", ydry_case.relative_error(r["work"], GF_I),
                       WORK_TOLERANCE)
        verdicts.below(f"final_reaction_over_peak_{label}", r["residual"], RESIDUAL_TOLERANCE)
        verdicts.check(f"broken_joints_{label}", r["broken"], rows_of_elements, r["broken"] == rows_of_elements)
        verdicts.check(f"broken_joints_on_line_{label}", r["broken_on_line"], rows_of_elements,
                       r["broken_on_line"] == rows_of_elements)
        rows.append(f"| {label} | {r['peak']:.1f} | {r['energy']:.5f} | {r['work']:.5f} | "
                    f"{r['work_trapezoid']:.5f} | {r['broken_on_line']} / {rows_of_elements} | {wall:.1f} |")

    (args.out / "results.md").write_text(
        "| run | peak traction (Pa) | fracture energy (J/m^2) | external work (J/m^2) | "
        "trapezoid of reactions (J/m^2) | broken on the line | wall (s) |\n"
        "|---|---:|---:|---:|---:|---:|---:|\n" + "\n".join(rows) + "\n")
    if results:
        plot(results, args.out / "traction_opening.png")
    return verdicts.exit_code()


if __name__ == "__main__":
    sys.exit(main())
