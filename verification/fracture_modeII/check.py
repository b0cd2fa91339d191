#!/usr/bin/python3
"""Verification case fracture_modeII: a column sheared along one line of joints (mode II).

Runs ydry on fracture_modeII.toml at element sizes 1 mm and 0.5 mm, checks that the peak
shear traction on the joint line equals the cohesion c and that the energy dissipated per
unit crack area equals the mode II fracture energy gf_II (also measured as the external work
through the sheared side), and that the column ends fully separated along that line. Prints
the verdict lines `fracture_modeII METRIC VALUE TOLERANCE PASS|FAIL`, writes out/results.md
and out/traction_slip.png. Exits 1 if any check fails.
"""
import sys
from pathlib import Path

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE.parent))
import fracture_case  # noqa: E402

CASE = fracture_case.FractureCase(
    name="fracture_modeII", deck=HERE / "fracture_modeII.toml", boundary="top",
    strength=1.0e4, fracture_energy=2.0,  # c (Pa) and gf_II (J/m^2) of the deck
    runs={"h1mm": (0.001, 0.001, []),      # the line: the column's width, one element
          "h0.5mm": (0.0005, 0.0005, ["mesh.element_size=0.0005", "mesh.size=[0.0005,0.001]"])},
    vertical_line=False, strength_label="cohesion c",
    motion_label="slip of the top side (mm)",
    title="Mode II: c = 10 kPa, gf$_{II}$ = 2 J/m$^2$", figure="traction_slip.png")

if __name__ == "__main__":
    sys.exit(fracture_case.run(CASE, __doc__, HERE))
