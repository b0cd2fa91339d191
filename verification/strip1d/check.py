#!/usr/bin/python3
"""Verification case strip1d: 1D moisture inflow into a dry strip (paper section 4.1).

Runs ydry on the deck strip1d.toml for three element sizes and three triangle patterns,
compares the moisture at the nodes with the closed-form semi-infinite solution (Eq. 20),
prints an error table and the suite verdict lines `strip1d METRIC VALUE TOLERANCE PASS|FAIL`,
writes out/error_table.md and the figures fig08, fig11 and fig13. Exits 1 if any check fails.
"""
import argparse
import json
import math
import subprocess
import sys
import xml.etree.ElementTree as ET
from pathlib import Path

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkIOXML import vtkXMLUnstructuredGridReader

HERE = Path(__file__).resolve().parent
REPO = HERE.parents[1]
DECK = HERE / "strip1d.toml"

K = 1.0e-6       # moisture conductivity, kg/(m s)
RHO0 = 1333.0    # dry density, kg/m^3
Q = 1.0e-5       # inflow on the left, kg/(m^2 s)
KAPPA = K / RHO0  # diffusivity, m^2/s
LENGTH = 0.1     # m

SIZES = (0.005, 0.002, 0.001)        # element sizes, m
PATTERNS = ("right", "left", "cross")
TIMES = (1e5, 2e5, 4e5, 8e5)         # s
FINAL_TIME = 8e5
L2_TOLERANCE = 0.005
BALANCE_TOLERANCE = 1e-12


def analytic_moisture(x, t):
    """Eq. 20: moisture w(x, t) in a semi-infinite dry bar fed with flux Q at x = 0."""
    root = math.sqrt(KAPPA * t)

    def w(xi):
        return 2 * Q / K * (root / math.sqrt(math.pi) * math.exp(-xi**2 / (4 * root**2))
                            - xi / 2 * math.erfc(xi / (2 * root)))
    return np.array([w(xi) for xi in np.atleast_1d(x)])


def mesh_label(size, pattern):
    return f"h{round(size * 1000)}mm_{pattern}"


def time_label(t):
    return f"{round(t / 1000)}ks"


def run_ydry(ydry, size, pattern, outdir):
    """Run one ydry simulation; return True if it exited 0."""
    cmd = [str(ydry), str(DECK), "-o", str(outdir), "--force", "--quiet",
           "--set", f"mesh.element_size={size}", "--set", f'mesh.pattern="{pattern}"']
    proc = subprocess.run(cmd, capture_output=True, text=True)
    if proc.returncode != 0:
        print(f"ydry failed ({proc.returncode}): {' '.join(cmd)}\n{proc.stdout}{proc.stderr}")
    return proc.returncode == 0


def frame_files(outdir):
    """Map output time -> bulk .vtu path (part 0; part 1 is the cracks), from the .pvd."""
    root = ET.parse(outdir / "strip1d.pvd").getroot()
    return {float(ds.get("timestep")): outdir / ds.get("file") for ds in root.iter("DataSet")
            if ds.get("part", "0") == "0"}


def unique_moisture(vtu):
    """Coordinates x and moisture w at the unique nodes of the exploded mesh, sorted by x."""
    reader = vtkXMLUnstructuredGridReader()
    reader.SetFileName(str(vtu))
    reader.Update()
    grid = reader.GetOutput()
    points = vtk_to_numpy(grid.GetPoints().GetData())[:, :2]
    moisture = vtk_to_numpy(grid.GetPointData().GetArray("moisture"))
    _, first = np.unique(np.round(points, 9), axis=0, return_index=True)
    x, w = points[first, 0], moisture[first]
    order = np.argsort(x)
    return x[order], w[order]


def relative_l2_error(x, w, t):
    exact = analytic_moisture(x, t)
    return math.sqrt(np.sum((w - exact) ** 2) / np.sum(exact ** 2))


def profiles_at(outdir, times):
    """{t: (x, w)} for the requested output times of one run."""
    frames = frame_files(outdir)
    result = {}
    for t in times:
        match = [f for ft, f in frames.items() if math.isclose(ft, t, rel_tol=1e-9)]
        result[t] = unique_moisture(match[0])
    return result


def verdict(metric, value, tolerance, passed):
    print(f"strip1d {metric} {value} {tolerance} {'PASS' if passed else 'FAIL'}")
    return passed


def write_error_table(errors, path):
    lines = ["| mesh | " + " | ".join(f"t = {t / 1000:g} ks" for t in TIMES) + " |",
             "|---|" + "---:|" * len(TIMES)]
    for (size, pattern), per_time in errors.items():
        cells = " | ".join(f"{100 * per_time[t]:.3f} %" for t in TIMES)
        lines.append(f"| h = {size * 1000:g} mm, {pattern} | {cells} |")
    path.write_text("Relative L2 error of w against Eq. 20\n\n" + "\n".join(lines) + "\n")


def plot_against_analytic(curves, title, path):
    """curves: list of (label, x, w, t). Top: w(x) over Eq. 20; bottom: deviation from Eq. 20."""
    x_fine = np.linspace(0.0, LENGTH, 400)
    fig, (top, bottom) = plt.subplots(2, 1, figsize=(7, 6.5), sharex=True,
                                      gridspec_kw={"height_ratios": [2, 1]})
    for t in sorted({t for *_, t in curves}):
        top.plot(x_fine * 100, analytic_moisture(x_fine, t), "k-", lw=1,
                 label=None if top.lines else "analytic (Eq. 20)")
    for i, (label, x, w, t) in enumerate(curves):
        style = dict(marker="os^D"[i % 4], ms=7 - 1.5 * i, mfc="none", ls="none", label=label)
        top.plot(x * 100, w, **style)
        bottom.plot(x * 100, (w - analytic_moisture(x, t)) * 1e3, **style)
    top.set_ylabel("moisture content w (-)")
    top.set_title(title)
    top.set_ylim(bottom=0)
    top.legend()
    bottom.axhline(0.0, color="k", lw=1)
    bottom.set_xlabel("distance from the wetted side x (cm)")
    bottom.set_ylabel("w - w$_{Eq. 20}$ (10$^{-3}$)")
    bottom.set_xlim(0, LENGTH * 100)
    for ax in (top, bottom):
        ax.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(path, dpi=150)
    plt.close(fig)


def make_figures(profiles, out):
    base = profiles[(0.005, "right")]
    plot_against_analytic([(f"ydry, t = {t / 1000:g} ks", *base[t], t) for t in TIMES],
                          "Fig. 8: moisture profiles, h = 5 mm, right pattern",
                          out / "fig08_strip_profiles.png")
    plot_against_analytic([(f"ydry, h = {s * 1000:g} mm", *profiles[(s, "right")][FINAL_TIME], FINAL_TIME)
                           for s in SIZES],
                          "Fig. 11: element size, right pattern, t = 800 ks",
                          out / "fig11_element_size.png")
    plot_against_analytic([(f"ydry, {p} pattern", *profiles[(0.005, p)][FINAL_TIME], FINAL_TIME)
                           for p in PATTERNS],
                          "Fig. 13: element pattern, h = 5 mm, t = 800 ks",
                          out / "fig13_element_shape.png")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--ydry", type=Path, default=REPO / "build" / "ydry")
    parser.add_argument("--out", type=Path, default=HERE / "out")
    args = parser.parse_args()
    args.out.mkdir(parents=True, exist_ok=True)

    meshes = [(s, p) for s in SIZES for p in PATTERNS]
    completed, balance, profiles, errors = {}, {}, {}, {}
    for size, pattern in meshes:
        outdir = args.out / mesh_label(size, pattern)
        if not run_ydry(args.ydry, size, pattern, outdir):
            completed[(size, pattern)], balance[(size, pattern)] = False, math.nan
            continue
        summary = json.loads((outdir / "summary.json").read_text())
        completed[(size, pattern)] = bool(summary["completed"])
        balance[(size, pattern)] = summary["water_balance_error"]
        profiles[(size, pattern)] = profiles_at(outdir, TIMES)
        errors[(size, pattern)] = {t: relative_l2_error(*profiles[(size, pattern)][t], t) for t in TIMES}

    print(f"{'mesh':<16}{'t (s)':>10}{'nodes':>8}{'rel. L2 error':>16}")
    for mesh, per_time in errors.items():
        for t in TIMES:
            print(f"{mesh_label(*mesh):<16}{t:>10.0f}{len(profiles[mesh][t][0]):>8}{per_time[t]:>16.5f}")
    write_error_table(errors, args.out / "error_table.md")
    if len(errors) == len(meshes):
        make_figures(profiles, args.out)

    ok = True
    for mesh in meshes:
        error = errors.get(mesh, {}).get(FINAL_TIME, math.nan)
        ok &= verdict(f"l2_error_{time_label(FINAL_TIME)}_{mesh_label(*mesh)}", f"{error:.4g}",
                      L2_TOLERANCE, error <= L2_TOLERANCE)
    for mesh in meshes:
        ok &= verdict(f"water_balance_{mesh_label(*mesh)}", f"{balance[mesh]:.3g}",
                      BALANCE_TOLERANCE, abs(balance[mesh]) < BALANCE_TOLERANCE)
    for mesh in meshes:
        ok &= verdict(f"completed_{mesh_label(*mesh)}", str(completed[mesh]).lower(), "true",
                      completed[mesh])
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
