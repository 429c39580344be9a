"""Analysis of the runs' results shared by the studies: in 2D dumps the free surface, the runout
and the failure line; in time series the late movement that tells a failing run from one at rest.

Free surface: the surface of the continuum that the particles represent.

The SPH volume fraction (Shepard sum) at a point,

    phi(x) = sum_j V_j W(|x - x_j|, h_j),     V_j = m_j / rho_j,

is about 1 inside the material and falls to about 0.5 at its edge (half of the kernel support
is empty there). The free surface is taken as its 0.5 level: at each position x, the highest
y with phi(x, y) >= 0.5. On a lattice this is the top row of particles plus about half a
spacing (the top edge of the particles' cells), like the "highest centre + d/2" of a column;
but a single particle, or a scatter of particles that have left the body, has phi < 0.5 (an
isolated particle reaches 0.32 at its centre with h = 1.2 d) and is not counted as material,
while a continuous layer one particle thick is (its phi is 0.57 at its centre line).

"""
import math

import numpy as np

LEVEL = 0.5


def failure_line(x0, y0, moved, spacing, height):
    """The upper boundary of the soil that did not move, by initial position: per column of
    width `spacing` the top of its unmoved particles (+ spacing/2), and the angle in degrees of
    a straight-line fit over the columns where it lies between 5% and 95% of `height`."""
    xs, ys = [], []
    for xc in np.arange(x0.min(), x0.max() + 0.5 * spacing, spacing):
        col = np.abs(x0 - xc) < 0.5 * spacing
        if not col.any():
            continue
        still = col & ~moved
        xs.append(xc)
        ys.append(y0[still].max() + 0.5 * spacing if still.any() else 0.0)
    xs, ys = np.array(xs), np.array(ys)
    fit = (ys > 0.05 * height) & (ys < 0.95 * height)
    angle = float('nan')
    if fit.sum() >= 2:
        angle = math.degrees(math.atan(-np.polyfit(xs[fit], ys[fit], 1)[0]))
    return xs, ys, angle


def kernel_2d(r, h):
    """Cubic spline W(r, h) in 2D (doc/theory.rst section 1)."""
    q = r / h
    w = np.where(q < 1.0, 1.0 - 1.5 * q * q + 0.75 * q ** 3,
                 np.where(q < 2.0, 0.25 * (2.0 - q) ** 3, 0.0))
    return w * 10.0 / (7.0 * math.pi * h * h)


SURFACE_BLOCK = 64    # points of a column evaluated at a time (surface_height)


def surface_height(x, y, volume, h, at, resolution=None):
    """Height of the phi = 0.5 level above each position of `at` (0 where phi < 0.5 everywhere).

    x, y, volume, h: per-particle arrays (h may be a scalar); resolution: vertical step of the
    search (default h_min / 20), refined by linear interpolation between the bracketing points.
    """
    h = np.broadcast_to(np.asarray(h, dtype=float), x.shape)
    volume = np.broadcast_to(np.asarray(volume, dtype=float), x.shape)
    reach = 2.0 * h.max()
    step = resolution or h.min() / 20.0
    heights = np.zeros(len(at))
    for k, xa in enumerate(at):
        near = np.abs(x - xa) < reach
        if not near.any():
            continue
        xn, yn, vn, hn = x[near], y[near], volume[near], h[near]
        ys = np.arange(max(0.0, yn.min() - reach), yn.max() + reach + step, step)
        # phi on the column from the top down, a block of points at a time with the particles
        # within reach of the block, until a block holds the topmost point inside (the level
        # lies near the top: most columns need one or two blocks, not the whole height)
        phi = np.zeros(len(ys))
        top = -1
        end = len(ys)
        while end > 0 and top < 0:
            begin = max(0, end - SURFACE_BLOCK)
            block = ys[begin:end]
            close = (yn > block[0] - reach) & (yn < block[-1] + reach)
            r = np.hypot(xa - xn[close][None, :], block[:, None] - yn[close][None, :])
            phi[begin:end] = (vn[close][None, :] * kernel_2d(r, hn[close][None, :])).sum(axis=1)
            inside = np.nonzero(phi[begin:end] >= LEVEL)[0]
            if len(inside):
                top = begin + inside[-1]
            end = begin
        if top < 0:
            continue
        if top + 1 < len(ys):
            # linear interpolation of the crossing between ys[top] and ys[top + 1]
            f0, f1 = phi[top], phi[top + 1]
            heights[k] = ys[top] + step * (f0 - LEVEL) / (f0 - f1)
        else:
            heights[k] = ys[top]
    return heights


def runout(x, y, volume, h, threshold, spacing):
    """Furthest position (on a grid of step spacing/2) where the surface is higher than threshold."""
    grid = np.arange(0.0, x.max() + 2.0 * spacing, 0.5 * spacing)
    top = surface_height(x, y, volume, h, grid)
    high = grid[top > threshold]
    return float(high.max()) if len(high) else 0.0, grid, top


def particle_top(x, y, at, spacing):
    """Top of the particles within one spacing of each position (0 where there are none)."""
    heights = np.zeros(len(at))
    for k, xa in enumerate(at):
        near = np.abs(x - xa) <= spacing
        heights[k] = y[near].max() + 0.5 * spacing if near.any() else 0.0
    return heights


def runout_particle_top(x, y, spacing, threshold=0.002):
    """Furthest x (particle edge) whose column still stands higher than the threshold."""
    edges = np.arange(0.0, x.max() + 2 * spacing, spacing)
    top = particle_top(x, y, edges, 0.5 * spacing)
    high = edges[top > threshold]
    return float(high.max() + 0.5 * spacing) if len(high) else 0.0


def late_movement(time_values, moved, late=0.3):
    """How far the monitored displacement grows over the last `late` share of the run."""
    window = time_values >= (1.0 - late) * time_values[-1]
    return float(moved[window][-1] - moved[window][0])
