#!/usr/bin/python3
"""ctest peron_check: verification/peron/check.py finds the breaks of the top surface and
judges curling on the surface cracks only.

A made-up last frame of surface.csv: a 30 mm top in three blocks, broken at x0 = 10 and 20 mm.
The break at 10 mm opens 0.5 mm and both its sides stand above their blocks' means (it curls);
the one at 20 mm opens 0.3 mm and its left side stands below its block's mean. Made-up cracks
at that time: a surface crack at each break; a crack from the base whose mouth lies nearer
the 10 mm break than the surface crack does (it must not take the break); a second surface
crack 0.5 mm from the 20 mm break, listed before the one at the break (the nearer must take
it, and the other go without); and a surface crack at 25 mm, where the top is not split (a
softening joint, not yet broken). Expected: two mouths with gaps of 0.5 and 0.3 mm; each
break given to the surface crack nearest it; curling 1 of 4 surface cracks. Exits 1 on any
failure.
"""
import math
import sys
from pathlib import Path

import numpy as np

REPO = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(REPO / "verification"))
sys.path.insert(0, str(REPO / "verification" / "peron"))
import check  # noqa: E402
import ydry_case  # noqa: E402  (test_arguments, failed)

MM = 1e-3
SIZE = 1.5 * MM  # surface element: a crack takes a break within half of it


def block(segment, x0_from, x0_to, uy_ends, ux_ends):
    """The points of one block: x0 every millimetre, u_y and u_x linear between the ends."""
    x0 = np.linspace(x0_from, x0_to, int(round((x0_to - x0_from) / MM)) + 1)
    fraction = (x0 - x0_from) / (x0_to - x0_from)
    return {"x0_m": x0, "y0_m": np.full_like(x0, 12 * MM), "segment": np.full_like(x0, segment),
            "uy_m": uy_ends[0] + (uy_ends[1] - uy_ends[0]) * fraction,
            "ux_m": ux_ends[0] + (ux_ends[1] - ux_ends[0]) * fraction}


def made_up_surface():
    # Block means of u_y: 0.1, 0.1 and 0.05 mm. At 10 mm both sides (0.2, 0.2) stand above
    # them; at 20 mm the left side (0.0) stands below its block's 0.1. The sides' u_x put them
    # at 9.75 and 10.25 mm (gap 0.5 mm), and at 19.85 and 20.15 mm (gap 0.3 mm).
    blocks = [block(0, 0, 10 * MM, (0.0, 0.2 * MM), (0.0, -0.25 * MM)),
              block(1, 10 * MM, 20 * MM, (0.2 * MM, 0.0), (0.25 * MM, -0.15 * MM)),
              block(2, 20 * MM, 30 * MM, (0.1 * MM, 0.0), (0.15 * MM, 0.0))]
    surface = {key: np.concatenate([b[key] for b in blocks]) for key in blocks[0]}
    surface["time_s"] = np.full_like(surface["x0_m"], 1000.0)
    return surface


def main():
    ydry_case.test_arguments(__doc__)
    failures = []
    mouths = sorted(check.surface_mouths(made_up_surface(), 1000.0), key=lambda mouth: mouth["x"])
    gaps = [mouth["gap"] / MM for mouth in mouths]
    if len(mouths) != 2 or not np.allclose(gaps, [0.5, 0.3], rtol=0, atol=1e-12):
        failures.append(f"mouths: expected gaps 0.5 and 0.3 mm, got {gaps}")
    cracks = [{"x": 10.3 * MM, "width": 0.5 * MM, "surface": True, "first": 0.0},
              {"x": 10.05 * MM, "width": 0.1 * MM, "surface": False, "first": 0.0},
              {"x": 20.5 * MM, "width": 0.1 * MM, "surface": True, "first": 0.0},
              {"x": 20.0 * MM, "width": 0.3 * MM, "surface": True, "first": 0.0},
              {"x": 25.0 * MM, "width": 0.15 * MM, "surface": True, "first": 0.0}]
    fraction = check.curling(cracks, mouths, SIZE)
    if not math.isclose(fraction, 1 / 4, rel_tol=1e-12):
        failures.append(f"curling fraction: expected 1/4, got {fraction}")
    taken = [None if crack["mouth"] is None else round(crack["mouth"]["x"] / MM, 6) for crack in cracks]
    if taken != [10.0, None, None, 20.0, None]:
        failures.append(f"breaks given to the cracks: expected [10.0, None, None, 20.0, None] mm, got {taken}")
    if not math.isnan(check.curling([dict(cracks[1])], mouths, SIZE)):
        failures.append("curling without a surface crack: expected NaN")
    return ydry_case.failed(failures)


if __name__ == "__main__":
    sys.exit(main())
