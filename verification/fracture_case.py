"""The fracture verification cases (fracture_modeI, fracture_modeII, interface_debonding): a
body whose one line of joints is opened or sheared by a driven side; the peak traction must
equal the strength and the energy dissipated per unit crack area the fracture energy, in
every run."""
from dataclasses import dataclass
from pathlib import Path

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

import ydry_case


@dataclass
class FractureCase:
    name: str
    deck: Path
    boundary: str            # the driven side
    strength: float          # Pa: f_t (mode I) or c (mode II)
    fracture_energy: float   # J/m^2
    runs: dict               # label: (element size h, joint line length, --set overrides)
    vertical_line: bool      # the joint line is vertical (mode I) or horizontal (mode II)
    strength_label: str
    motion_label: str
    title: str
    figure: str
    thickness: float = 1.0   # m
    axis: str = "x"          # the component of the driven side's motion and reaction


STRENGTH_TOLERANCE = 0.02
ENERGY_TOLERANCE = 0.02
WORK_TOLERANCE = 0.02
RESIDUAL_TOLERANCE = 1e-6  # final reaction / peak reaction


def measure(case, outdir, length):
    side = ydry_case.reactions(outdir, case.boundary)
    series = ydry_case.read_csv(outdir / "series.csv")
    cracks = ydry_case.last_cracks(outdir)
    area = length * case.thickness
    dx, dy = np.abs(np.diff(cracks["ends"], axis=1))[:, 0].T
    reaction, motion = side[f"reaction_{case.axis}_N"], side[f"mean_u{case.axis}_m"]
    load = np.abs(reaction)  # the support drives its side along +axis
    peak = np.max(load)
    return {
        "motion": motion, "traction": load / area,
        "peak": peak / area,
        "energy": series["fracture_energy_J"][-1] / area,
        "work": side["work_J"][-1] / area,
        "work_trapezoid": np.trapz(reaction, motion) / area,
        "residual": np.hypot(side["reaction_x_N"][-1], side["reaction_y_N"][-1]) / peak,
        "broken": int(series["broken_joints"][-1]),
        # The joint line is the only vertical (mode I) or horizontal (mode II) one.
        "broken_on_line": int(np.sum(dx < 1e-3 * dy) if case.vertical_line else np.sum(dy < 1e-3 * dx)),
    }


def plot(case, results, path):
    fig, ax = plt.subplots(figsize=(7, 4.5))
    for (label, r), style in zip(results.items(), ("-", "--")):
        ax.plot(r["motion"] * 1e3, r["traction"] / 1e3, style,
                label=f"ydry, {label}: peak {r['peak'] / 1e3:.3f} kPa, G = {r['energy']:.4f} J/m$^2$")
    ax.axhline(case.strength / 1e3, color="k", lw=0.8, ls=":", label=case.strength_label)
    ax.set_xlabel(case.motion_label)
    ax.set_ylabel("traction on the joint line (kPa)")
    ax.set_title(case.title)
    ax.set_xlim(left=0)
    ax.grid(alpha=0.3)
    ax.legend()
    fig.tight_layout()
    fig.savefig(path, dpi=150)
    plt.close(fig)


RESULTS_HEADER = ("| run | peak traction (Pa) | fracture energy (J/m^2) | external work (J/m^2) | "
                  "trapezoid of reactions (J/m^2) | broken on the line | wall (s) |\n"
                  "|---|---:|---:|---:|---:|---:|---:|\n")


def check_runs(case, args, verdicts):
    """Runs each run of the case into args.out/<run>, prints its verdicts and draws its figure;
    returns its rows of the results table (RESULTS_HEADER)."""
    results, rows = {}, []
    for label, (h, length, overrides) in case.runs.items():
        wall = ydry_case.run_ydry(args.ydry, case.deck, args.out / label, overrides)
        if not verdicts.check(f"ran_{label}", wall is not None, "true", wall is not None):
            continue
        done = ydry_case.completed(args.out / label)
        verdicts.check(f"completed_{label}", done, "true", done)
        r = results[label] = measure(case, args.out / label, length)
        joints_on_line = round(length / h)
        print(f"# {label} ({wall:.1f} s): peak traction {r['peak']:.2f} Pa, fracture energy "
              f"{r['energy']:.5f} J/m^2, external work {r['work']:.5f} J/m^2 "
              f"(trapezoid of the logged reactions: {r['work_trapezoid']:.5f} J/m^2)")
        verdicts.below(f"peak_traction_rel_error_{label}", ydry_case.relative_error(r["peak"], case.strength),
                       STRENGTH_TOLERANCE)
        verdicts.below(f"fracture_energy_rel_error_{label}", ydry_case.relative_error(r["energy"], case.fracture_energy),
                       ENERGY_TOLERANCE)
        verdicts.below(f"external_work_rel_error_{label}", ydry_case.relative_error(r["work"], case.fracture_energy),
                       WORK_TOLERANCE)
        verdicts.below(f"final_reaction_over_peak_{label}", r["residual"], RESIDUAL_TOLERANCE)
        verdicts.check(f"broken_joints_{label}", r["broken"], joints_on_line, r["broken"] == joints_on_line)
        verdicts.check(f"broken_joints_on_line_{label}", r["broken_on_line"], joints_on_line,
                       r["broken_on_line"] == joints_on_line)
        rows.append(f"| {label} | {r['peak']:.1f} | {r['energy']:.5f} | {r['work']:.5f} | "
                    f"{r['work_trapezoid']:.5f} | {r['broken_on_line']} / {joints_on_line} | {wall:.1f} |")

    if results:
        plot(case, results, args.out / case.figure)
    return rows


def run(case, doc, here):
    """Runs the case at each of its element sizes and checks it; returns the exit code."""
    args = ydry_case.arguments(doc, here)
    verdicts = ydry_case.Verdicts(case.name)
    rows = check_runs(case, args, verdicts)
    (args.out / "results.md").write_text(RESULTS_HEADER + "\n".join(rows) + "\n")
    return verdicts.exit_code()


