#!/usr/bin/python3
"""The submerged column collapse of in.submerged_collapse: the soil coloured by its excess pore
pressure at half time and at the end of each run, and the runout and the excess pore pressure
under the column against time, from dump.collapse.<tag> and collapse.<tag>.txt.

  /usr/bin/python3 plot_submerged_collapse.py [--tags psi0 psi5] [--png submerged_collapse.png]
"""
import argparse

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

from dump_frames import frames

L0, H0, D = 0.05, 0.04, 0.05    # column length and height, water depth (m), as in the input
SPACING = 0.0025                # the particle spacing d of the input (m)
PLOTTED = 0.105                 # the part of the 0.16 m tank that is drawn (m)



def deposit_front(atoms):
    """The front of the soil's body: the largest x (plus half a spacing) of the soil particles
    with at least two soil neighbours within 1.5 spacings, so that a grain that went ahead on its
    own (the largest x, the input's runout) does not count."""
    soil = atoms["type"] == 1
    x, y = atoms["x"][soil], atoms["y"][soil]
    close = np.hypot(x[:, None] - x[None, :], y[:, None] - y[None, :]) < 1.5 * SPACING
    body = close.sum(axis=1) - 1 >= 2
    return x[body].max() + 0.5 * SPACING


def series(path):
    """The run's label (psi and k, from the first line) and its rows: time, runout, excess
    under the column, least and largest excess, largest speeds of soil and water."""
    first = open(path).readline().lstrip("# ").strip()
    label = "psi = " + first.split()[1] + " deg, k = " + first.split("k ")[1].split()[0] + " m/s"
    # (the last row is written again at the end of the run if it fell on an output step)
    rows = np.loadtxt(path, comments="#", ndmin=2)
    keep = np.concatenate([np.diff(rows[:, 0]) > 0, [True]])
    return label, rows[keep]


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--tags", nargs="+", default=["psi0", "psi5"],
                        help="the runs' tags (-var tag, default psi<psi>; default psi0 psi5)")
    parser.add_argument("--png", default="submerged_collapse.png")
    parser.add_argument("--range", type=float, default=200.0,
                        help="colour range of the excess pore pressure, +- Pa (default 200)")
    args = parser.parse_args()

    runs = []
    for tag in args.tags:
        label, data = series(f"collapse.{tag}.txt")
        snaps = frames(f"dump.collapse.{tag}")
        runs.append((label, data, snaps))
        end = data[-1]
        print(f"{label}: runout {end[1]:.4f} m at t = {end[0]:.3f} s ((L - L0)/L0 = "
              f"{(end[1] - L0) / L0:.3f}), excess pore pressure under the column {end[2]:.1f} Pa, "
              f"soil's largest speed {end[5]:.4f} m/s")
        for t, runout, under, *_ in data[:: max(1, len(data) // 10)]:
            print(f"   t {t:6.3f} s  runout {runout:.4f} m  excess under the column {under:8.1f} Pa")
        last_step = max(snaps[-1][0], 1)
        print("   front of the body (m) at t (s): " + ", ".join(
            f"{deposit_front(atoms):.4f} at {end[0] * step / last_step:.3f}" for step, atoms in snaps))

    fig = plt.figure(figsize=(11, 3.0 * len(runs) + 3.4))
    grid = fig.add_gridspec(len(runs) + 1, 2, height_ratios=[1.0] * len(runs) + [1.25],
                            hspace=0.45, wspace=0.28)
    scatter, snapshots = None, []
    # the time step is fixed and the last frame is the run's end: the frames' times follow
    for row, (label, data, snaps) in enumerate(runs):
        last_step = max(snaps[-1][0], 1)
        chosen = [snaps[len(snaps) // 2], snaps[-1]]
        for col, (step, atoms) in enumerate(chosen):
            ax = fig.add_subplot(grid[row, col])
            snapshots.append(ax)
            time = data[-1, 0] * step / last_step
            water = atoms["type"] == 3
            soil = atoms["type"] == 1
            walls = ~(water | soil)
            ax.scatter(atoms["x"][water], atoms["y"][water], s=3, c="#b9d7ee", lw=0)
            ax.scatter(atoms["x"][walls], atoms["y"][walls], s=3, c="0.55", lw=0)
            scatter = ax.scatter(atoms["x"][soil], atoms["y"][soil], s=9, lw=0.25,
                                 edgecolors="0.3",
                                 c=atoms["v_excess"][soil], cmap="RdBu_r",
                                 vmin=-args.range, vmax=args.range)
            ax.plot([0, L0, L0], [H0, H0, 0], "k--", lw=0.8)
            ax.set_xlim(-0.008, PLOTTED)
            ax.set_ylim(-0.008, D + 0.006)
            ax.set_aspect("equal")
            runout = atoms["x"][soil].max() + 0.5 * SPACING
            ax.set_title(f"{label}, t = {time:.3f} s\nrunout {runout:.4f} m (largest x), "
                         f"front {deposit_front(atoms):.4f} m", fontsize=8)
            ax.tick_params(labelsize=7)
    bar = fig.colorbar(scatter, ax=snapshots, shrink=0.8, pad=0.02)
    bar.set_label("excess pore pressure (Pa)")

    ax = fig.add_subplot(grid[-1, 0])
    for label, data, snaps in runs:
        line, = ax.plot(data[:, 0], (data[:, 1] - L0) * 100, label=label + ": largest x")
        last_step = max(snaps[-1][0], 1)
        ax.plot([data[-1, 0] * step / last_step for step, _ in snaps],
                [(deposit_front(atoms) - L0) * 100 for _, atoms in snaps], "o--", ms=4,
                color=line.get_color(), lw=0.8, label=label + ": front of the body")
    ax.set_xlabel("time (s)")
    ax.set_ylabel("runout L - L0 (cm)")
    ax.legend(fontsize=7, loc="center right")
    ax.grid(alpha=0.3)
    ax = fig.add_subplot(grid[-1, 1])
    for label, data, _ in runs:
        ax.plot(data[:, 0], data[:, 2], label=label)
    ax.axhline(0.0, color="k", lw=0.6)
    ax.set_xlabel("time (s)")
    ax.set_ylabel("excess pore pressure\nunder the column (Pa)")
    ax.legend(fontsize=8)
    ax.grid(alpha=0.3)
    fig.suptitle("Saturated column collapsing under water: dilatant (psi > 0) against "
                 "non-dilatant (psi = 0)", fontsize=10)
    fig.savefig(args.png, dpi=110, bbox_inches="tight")
    print(f"wrote {args.png}")


if __name__ == "__main__":
    main()
