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

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE.parent))
import fracture_case  # noqa: E402

CASE = fracture_case.FractureCase(
    name="fracture_modeI", deck=HERE / "fracture_modeI.toml", boundary="right",
    strength=1.0e4, fracture_energy=1.0,  # f_t (Pa) and gf_I (J/m^2) of the deck
    runs={"h1mm": (0.001, 0.004, []),      # the line: the bar's height, four rows
          "h0.5mm": (0.0005, 0.002, ["mesh.element_size=0.0005", "mesh.size=[0.001,0.002]"])},
    vertical_line=True, strength_label="tensile strength f$_t$",
    motion_label="pull of the right side (mm)",
    title="Mode I: f$_t$ = 10 kPa, gf$_I$ = 1 J/m$^2$", figure="traction_opening.png")

if __name__ == "__main__":
    sys.exit(fracture_case.run(CASE, __doc__, HERE))
