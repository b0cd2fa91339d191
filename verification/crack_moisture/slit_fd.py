"""An independent reference for crack_moisture: the steady moisture field of the slit block by
finite differences, with numpy only.

Steady state: div(k grad w) = 0 on the L x H block, w = 1 on the left side, w = 0 on the
right, no flux through the top, the bottom and both faces of the slit x = XS, y > YT (the
crack). k and the dry density drop out. Cell-centred 5-point Laplacian on square cells of
side h: the slit lies on cell faces, whose conductance is set to zero; a Dirichlet side sits
half a cell from the first centres (conductance 2). Ordered column by column the matrix is
block tridiagonal (one ny x ny block per column), solved directly by block elimination.
"""
import numpy as np

L, H = 0.1, 0.05      # m: block
XS, YT = 0.05, 0.025  # m: the slit runs along x = XS from the top down to y = YT
W_LEFT, W_RIGHT = 1.0, 0.0


def _slit_rows(h):
    """Rows whose cell centres lie beside the slit, and the index of the first column right of it."""
    ny = round(H / h)
    return (np.arange(ny) + 0.5) * h > YT, round(XS / h)


def solve_steady(h):
    """w at the cell centres ((i + 1/2) h, (j + 1/2) h), as an nx x ny array."""
    nx, ny = round(L / h), round(H / h)
    slit, first_right = _slit_rows(h)
    across = np.ones((nx - 1, ny))         # conductance between columns i and i + 1, per row
    across[first_right - 1, slit] = 0.0    # the slit: no flux
    vertical = 2 * np.eye(ny) - np.eye(ny, k=1) - np.eye(ny, k=-1)
    vertical[0, 0] = vertical[-1, -1] = 1  # no flux through the top and the bottom
    inverse, rhs = [], []                  # block elimination, forward sweep
    for i in range(nx):
        left = across[i - 1] if i > 0 else np.full(ny, 2.0)
        right = across[i] if i < nx - 1 else np.full(ny, 2.0)
        block = vertical + np.diag(left + right)
        g = np.full(ny, 2.0 * W_LEFT) if i == 0 else np.zeros(ny)
        if i == nx - 1:
            g = g + 2.0 * W_RIGHT
        if i > 0:
            block -= left[:, None] * inverse[-1] * left[None, :]
            g = g + left * (inverse[-1] @ rhs[-1])
        inverse.append(np.linalg.inv(block))
        rhs.append(g)
    w = np.zeros((nx, ny))                 # back substitution
    w[-1] = inverse[-1] @ rhs[-1]
    for i in range(nx - 2, -1, -1):
        w[i] = inverse[i] @ (rhs[i] + across[i] * w[i + 1])
    return w


def left_inflow_per_k(w):
    """Water in through the left side per unit k and out-of-plane thickness: sum over the
    rows of (W_LEFT - w) / (h / 2) x h."""
    return float(np.sum(2.0 * (W_LEFT - w[0])))


def interpolate(w, h, points, left_of_slit):
    """Bilinear interpolation of the cell-centre field at `points` (n x 2, m). Ghost cells
    outside carry the boundary conditions (Dirichlet: reflected about the side value; no
    flux: mirrored), and a point on the left of the slit (`left_of_slit`, booleans) sees the
    cells across the slit as mirrors of its own side, so no value leaks across the crack."""
    nx, ny = w.shape
    slit, first_right = _slit_rows(h)
    padded = np.empty((nx + 2, ny + 2))
    padded[1:-1, 1:-1] = w
    padded[0, 1:-1] = 2 * W_LEFT - w[0]
    padded[-1, 1:-1] = 2 * W_RIGHT - w[-1]
    padded[:, 0], padded[:, -1] = padded[:, 1], padded[:, -2]
    rows = np.r_[False, slit, slit[-1]]
    values = np.empty(len(points))
    for side in (True, False):
        ghosts = padded.copy()
        if side:   # the column right of the slit mirrors the one left of it
            ghosts[first_right + 1, rows] = ghosts[first_right, rows]
        else:
            ghosts[first_right, rows] = ghosts[first_right + 1, rows]
        chosen = left_of_slit == side
        fx, fy = points[chosen, 0] / h + 0.5, points[chosen, 1] / h + 0.5  # padded index space
        i = np.clip(np.floor(fx).astype(int), 0, nx)
        j = np.clip(np.floor(fy).astype(int), 0, ny)
        a, b = fx - i, fy - j
        values[chosen] = (ghosts[i, j] * (1 - a) * (1 - b) + ghosts[i + 1, j] * a * (1 - b)
                          + ghosts[i, j + 1] * (1 - a) * b + ghosts[i + 1, j + 1] * a * b)
    return values
