#!/usr/bin/python3
"""Verification case contact_rest: a block resting on a rigid base under gravity.

Runs ydry on contact_rest.toml (a 0.1 x 0.05 m elastic block on a rigid base, touching it
only through contact) and checks that the rigid base's reaction equals the block's weight
within 0.5 % and that the block sinks into the base by less than 1 % of the element size.
Prints `contact_rest METRIC VALUE TOLERANCE PASS|FAIL` and exits 1 if a check fails.
"""
import sys
from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE.parent))
import ydry_case  # noqa: E402

DECK = HERE / "contact_rest.toml"
DENSITY, WIDTH, HEIGHT, THICKNESS, G = 2000.0, 0.1, 0.05, 1.0, 9.81
BASE_TOP, ELEMENT_SIZE = 0.05, 0.0125   # m (block_on_base.geo)
REACTION_TOLERANCE = 0.005              # relative to the weight
PENETRATION_TOLERANCE = 0.01            # relative to the element size


def main():
    args = ydry_case.arguments(__doc__, HERE)
    verdicts = ydry_case.Verdicts("contact_rest")
    outdir = args.out / "run"
    if ydry_case.run_ydry(args.ydry, DECK, outdir) is None or not ydry_case.completed(outdir):
        verdicts.check("completed", False, "true", False)
        return verdicts.exit_code()
    weight = DENSITY * WIDTH * HEIGHT * THICKNESS * G
    base = ydry_case.reactions(outdir, "rigid:base")
    verdicts.below("reaction_y_error", ydry_case.relative_error(base["reaction_y_N"][-1], weight),
                   REACTION_TOLERANCE)
    verdicts.below("reaction_x_over_weight", abs(base["reaction_x_N"][-1]) / weight, REACTION_TOLERANCE)

    frame = ydry_case.last_frame(outdir)
    bottom = np.isclose(frame["x0"][:, 1], BASE_TOP) & (frame["u"][:, 1] != 0.0)  # the block's
    sunk = BASE_TOP - (frame["x0"][bottom, 1] + frame["u"][bottom, 1])
    print(f"info: weight {weight:.4f} N, base reaction {base['reaction_y_N'][-1]:.4f} N, "
          f"deepest block corner {sunk.max():.3e} m below the base top ({bottom.sum()} corners)")
    verdicts.below("penetration_over_element_size", float(sunk.max()) / ELEMENT_SIZE, PENETRATION_TOLERANCE)
    return verdicts.exit_code()


if __name__ == "__main__":
    sys.exit(main())
