#!/usr/bin/python3
"""Verification case interface_debonding: a soil strip bonded to a rigid base, pulled off,
sheared off, and slid on the base once debonded.

Runs ydry on interface_debonding.toml three times: the strip's top pulled up (mode I) and
pushed along (mode II, no normal stress on the interface) until the interface has debonded,
checking that the peak force is the interface's strength times the bonded length and the
dissipated energy its fracture energy times that length; and the strip pushed along the base
under its weight, checking that once debonded it slides at the pair's Coulomb ratio
tan(friction_angle). Prints the verdict lines `interface_debonding METRIC VALUE TOLERANCE
PASS|FAIL`, writes out/results.md, out/pull.png and out/shear.png. Exits 1 if any check fails.
"""
import math
import sys
from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE.parent))
import fracture_case  # noqa: E402
import ydry_case  # noqa: E402

NAME = "interface_debonding"
DECK = HERE / "interface_debonding.toml"
LENGTH = 0.004     # m, the bonded length: four 1 mm interface edges
ELEMENT = 0.001    # m
FRICTION_ANGLE = 30.0  # degrees, [interfaces.soil_base] friction_angle

PULL = fracture_case.FractureCase(
    name=NAME, deck=DECK, boundary="top", axis="y",
    strength=1.0e4, fracture_energy=1.0,  # tensile_strength (Pa) and gf_I (J/m^2) of the interface
    runs={"pull": (ELEMENT, LENGTH, [])},
    vertical_line=False, strength_label="tensile strength f$_t$",
    motion_label="pull of the strip's top (mm)",
    title="Pull-off: f$_t$ = 10 kPa, gf$_I$ = 1 J/m$^2$", figure="pull.png")

# The top pushed along, held in y, and the strip's sides held in y; the friction angle 0, so
# that the normal tractions which carry the moment of the push (compression at one end, tension
# at the other: their sum is 0) do not raise the shear strength c + sigma tan(phi) where they
# press.
SHEAR = fracture_case.FractureCase(
    name=NAME, deck=DECK, boundary="top", axis="x",
    strength=1.0e4, fracture_energy=2.0,  # cohesion (Pa) and gf_II (J/m^2) of the interface
    runs={"shear": (ELEMENT, LENGTH, [
        "run.end_time=600", "run.output_interval=60", "interfaces.soil_base.friction_angle=0",
        'mechanics.boundary=[{on="top", velocity=[1.0e-6, 0.0]}, {on="soil_left", fix=["y"]}, '
        '{on="soil_right", fix=["y"]}]'])},
    vertical_line=False, strength_label="cohesion c",
    motion_label="slip of the strip's top (mm)",
    title="Shear-off: c = 10 kPa, gf$_{II}$ = 2 J/m$^2$", figure="shear.png")

# The strip under a weight of 1e4 Pa on the interface (gravity 1e4 m/s^2 on 1 mm of soil of
# 1000 kg/m^3), pushed along by its left side, 0.9 mm in all: it debonds, then slides.
SLIDE = ["run.end_time=900", "run.output_interval=90", "run.gravity=[0.0, -1.0e4]",
         'mechanics.boundary=[{on="soil_left", velocity=[1.0e-6, 0.0]}]']

COULOMB_TOLERANCE = 1e-6   # relative, on |R_x| / R_y of the base while sliding: each contact
                           # pulls mu f_n exactly; a relaxation ends at an out-of-balance ratio of 1e-7
CAP_TOLERANCE = 1e-9       # relative: |R_x| / R_y never above tan(phi) once debonded
LENGTH_TOLERANCE = 1e-12   # relative, on debonded_length_soil_base at the end
STICK_ROWS = 20            # rows (20 um of push) after debonding before the strip slides: the
                           # friction's elastic slip takes about 7 um to reach mu f_n
SLIDING_ROWS = 100         # sliding rows, at least: 0.1 mm of sliding


def check_debonded(label, outdir, verdicts):
    """The whole interface debonded, and no crack counted: its joints are not the soil's."""
    series = ydry_case.read_csv(outdir / "series.csv")
    verdicts.below(f"debonded_length_rel_error_{label}",
                   ydry_case.relative_error(series["debonded_length_soil_base"][-1], LENGTH), LENGTH_TOLERANCE)
    verdicts.check(f"crack_count_{label}", int(series["crack_count"][-1]), 0, series["crack_count"][-1] == 0)
    kinds = ydry_case.last_cracks(outdir)["joint_kind"]
    verdicts.check(f"broken_joints_are_interface_{label}", bool(np.all(kinds == 1)), "true", np.all(kinds == 1))


def check_sliding(args, verdicts):
    """Returns the results row of the sliding run."""
    outdir = args.out / "slide"
    wall = ydry_case.run_ydry(args.ydry, DECK, outdir, SLIDE)
    if not verdicts.check("ran_slide", wall is not None, "true", wall is not None):
        return "| slide | did not run |"
    done = ydry_case.completed(outdir)
    verdicts.check("completed_slide", done, "true", done)
    check_debonded("slide", outdir, verdicts)
    series = ydry_case.read_csv(outdir / "series.csv")
    base = ydry_case.reactions(outdir, "rigid:base")  # a row per row of series.csv
    # A row's reactions are those of the equilibrium before the joints that broke there broke:
    # the rows after the first fully debonded one.
    debonded = np.flatnonzero(series["debonded_length_soil_base"] >= LENGTH * (1 - LENGTH_TOLERANCE))
    first = debonded[0] + 1 if debonded.size else len(series["time_s"])
    ratio = np.abs(base["reaction_x_N"]) / base["reaction_y_N"]
    mu = math.tan(math.radians(FRICTION_ANGLE))
    after, sliding = ratio[first:], ratio[first + STICK_ROWS:]
    verdicts.check("sliding_rows", len(sliding), f">={SLIDING_ROWS}", len(sliding) >= SLIDING_ROWS)
    cap = float(np.max(after) / mu - 1) if after.size else math.nan
    error = float(np.max(np.abs(sliding - mu)) / mu) if sliding.size else math.nan
    print(f"# slide ({wall:.1f} s): debonded at t = {series['time_s'][first - 1]:g} s; |R_x| / R_y of the base "
          f"over the {len(sliding)} rows from {STICK_ROWS} um of push later: {np.min(sliding):.9f} to "
          f"{np.max(sliding):.9f}, tan({FRICTION_ANGLE:g} deg) = {mu:.9f}; normal force "
          f"{np.mean(base['reaction_y_N'][first + STICK_ROWS:]):.3f} N")
    verdicts.below("friction_over_cap_slide", cap, CAP_TOLERANCE)
    verdicts.below("coulomb_ratio_rel_error_slide", error, COULOMB_TOLERANCE)
    return (f"| slide | Coulomb ratio {np.min(sliding):.9f} to {np.max(sliding):.9f} "
            f"(tan {FRICTION_ANGLE:g} deg = {mu:.9f}) | | | | | {wall:.1f} |")


def main():
    args = ydry_case.arguments(__doc__, HERE)
    verdicts = ydry_case.Verdicts(NAME)
    rows = []
    for case in (PULL, SHEAR):
        rows += fracture_case.check_runs(case, args, verdicts)
        for label in case.runs:
            if (args.out / label / "series.csv").exists():
                check_debonded(label, args.out / label, verdicts)
    rows.append(check_sliding(args, verdicts))
    (args.out / "results.md").write_text(fracture_case.RESULTS_HEADER + "\n".join(rows) + "\n")
    return verdicts.exit_code()


if __name__ == "__main__":
    sys.exit(main())
