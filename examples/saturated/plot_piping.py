#!/usr/bin/python3
"""Piping over a filter strip (in.piping): the sand early in the hold and at the end, coloured by
its excess pore pressure and by its mean effective pressure (the quick zone, where the sand
carries none, pale), and the rise of the sand over the strip against time, from dump.piping and
piping.txt.

  /usr/bin/python3 plot_piping.py [--png piping.png]
"""
import argparse

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

from dump_frames import frames

W, B, H = 0.24, 0.03, 0.1    # width, strip width, layer thickness (m), as in the input



def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--png", default="piping.png")
    args = parser.parse_args()
    rows = np.loadtxt("piping.txt", comments="#", ndmin=2)
    snaps = frames("dump.piping")
    end = rows[-1]
    print(f"piping: t = {end[0]:.3f} s, strip excess {end[1]:.0f} Pa: the sand over the strip rose "
          f"{end[2] * 1000:.2f} mm at most, {end[3] * 1000:.2f} mm on average; largest upward soil "
          f"speed {end[4]:.4f} m/s")
    for t, excess, top, mean, speed in rows[:: max(1, len(rows) // 12)]:
        print(f"   t {t:6.3f} s  excess {excess:7.1f} Pa  rise over the strip {top * 1000:6.2f} mm "
              f"(mean {mean * 1000:6.2f})  largest upward speed {speed:.4f} m/s")
    times = np.linspace(0.0, end[0], len(snaps))
    chosen = [len(snaps) // 4, len(snaps) - 1]
    fig = plt.figure(figsize=(11, 7.2))
    grid = fig.add_gridspec(3, 2, height_ratios=[1, 1, 0.9], hspace=0.5, wspace=0.25)
    for col, k in enumerate(chosen):
        step, atoms = snaps[k]
        x, y = atoms["x"], atoms["y"]
        for row, (key, label, cmap, lim) in enumerate(
                [("v_excess", "excess pore pressure (Pa)", "RdBu_r", (-2500, 2500)),
                 ("c_pw[2]", "mean effective pressure (Pa; 0: quick)", "viridis_r", (0, 800))]):
            ax = fig.add_subplot(grid[row, col])
            sc = ax.scatter(x, y, c=atoms[key], s=5, cmap=cmap, vmin=lim[0], vmax=lim[1], lw=0)
            ax.plot([0.5 * (W - B), 0.5 * (W + B)], [-0.002, -0.002], "k", lw=3)
            ax.set_xlim(0.0, W)
            ax.set_ylim(-0.005, H + 0.01)
            ax.set_aspect("equal")
            ax.set_title(f"t = {times[k]:.2f} s: {label}", fontsize=8)
            ax.tick_params(labelsize=7)
            fig.colorbar(sc, ax=ax, shrink=0.8, pad=0.01).ax.tick_params(labelsize=7)
    ax = fig.add_subplot(grid[2, :])
    ax.plot(rows[:, 0], rows[:, 2] * 1000, label="highest rise over the strip")
    ax.plot(rows[:, 0], rows[:, 3] * 1000, label="mean rise over the strip")
    ax2 = ax.twinx()
    ax2.plot(rows[:, 0], rows[:, 1], "0.6", lw=0.8, label="strip's excess pore pressure")
    ax2.set_ylabel("excess (Pa)", fontsize=8)
    ax.set_xlabel("time (s)")
    ax.set_ylabel("rise (mm)")
    ax.legend(fontsize=7, loc="upper left")
    ax2.legend(fontsize=7, loc="lower right")
    fig.savefig(args.png, dpi=120, bbox_inches="tight")
    print(f"wrote {args.png}")


if __name__ == "__main__":
    main()
