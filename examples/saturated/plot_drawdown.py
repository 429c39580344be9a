#!/usr/bin/python3
"""The rapid drawdown of in.drawdown, the runs side by side: each slope at the end coloured by its
pore pressure (the settled surface drawn over it), the crest's settlement and the toe's outward
displacement against time, and the mean excess pore pressure of the slope and the pore pressure
at a point under its face.

  /usr/bin/python3 plot_drawdown.py [--runs k1e-6 k1e-3] [--png drawdown.png]

reads drawdown_<run>.txt and dump.drawdown_<run> of each run: k<k> with the k as typed on lmp's
command line (-var k 1e-6: k1e-6), k<k>_level<level> for a run with -var level_end.
"""
import argparse

import numpy as np

from dump_frames import frames

H, CREST, HW, DRAWDOWN = 0.2, 0.4, 0.23, 0.05



def history(path):
    data = np.loadtxt(path, comments="#")
    return {name: data[:, k] for k, name in enumerate(
        "time settlement toe advance p_mean excess p_probe p_min vmax".split())}


def label(run):
    words = run.split("_")
    text = f"k = {words[0][1:]} m/s"
    if len(words) > 1:
        level = float(words[1][5:])
        text += ", no drawdown" if level >= HW else f", drawn down to {level:g} m"
    return text


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--runs", nargs="+", default=["k1e-6", "k1e-3"])
    parser.add_argument("--png", default="drawdown.png")
    args = parser.parse_args()
    runs = {run: (history(f"drawdown_{run}.txt"), frames(f"dump.drawdown_{run}")) for run in args.runs}
    for run, (h, f) in runs.items():
        print(f"{label(run)}: at t = {h['time'][-1]:.3f} s crest settlement {1000 * h['settlement'][-1]:.1f} mm, "
              f"toe out {1000 * h['toe'][-1]:.1f} mm, front advanced {1000 * h['advance'][-1]:.1f} mm; "
              f"mean excess pore pressure {h['excess'][-1]:.0f} Pa (after the drawdown "
              f"{h['excess'][np.searchsorted(h['time'], DRAWDOWN - 1e-6)]:.0f} Pa), at the probe "
              f"{h['p_probe'][-1]:.0f} Pa, least {h['p_min'][-1]:.0f} Pa; largest speed {h['vmax'][-1]:.4f} m/s")

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig = plt.figure(figsize=(6 * len(runs) + 0.5, 7.5))
    grid = fig.add_gridspec(2, len(runs) + 1, width_ratios=[1] * len(runs) + [0.03],
                            height_ratios=[0.8, 1], hspace=0.25, wspace=0.12)
    plim = 2.0
    for column, (run, (h, f)) in enumerate(runs.items()):
        ax = fig.add_subplot(grid[0, column])
        last = f[-1][1]
        soil = last["type"] == 1
        walls = (last["type"] == 2) | (last["type"] == 4)
        water = last["type"] == 3
        right = last["x"][last["type"] == 4].max()
        ax.scatter(last["x"][walls], last["y"][walls], s=5, c="0.6", marker="s", lw=0)
        if water.any():
            ax.scatter(last["x"][water], last["y"][water], s=5, c="lightskyblue", marker="s", lw=0)
        art = ax.scatter(last["x"][soil], last["y"][soil], s=7, c=last["c_pw[1]"][soil] / 1000.0,
                         cmap="coolwarm", vmin=-plim, vmax=plim, marker="s", lw=0)
        # the slope as it was built, and the reservoir's level before the drawdown
        ax.plot([0.0, CREST, right], [0.0, H, H], "k--", lw=0.8, label="slope at the start")
        ax.axhline(HW, color="tab:blue", lw=0.8, ls=":", label="water level before")
        ax.set_aspect("equal")
        ax.set_xlim(last["x"].min() - 0.01, last["x"].max() + 0.01)
        ax.set_ylim(-0.04, 0.25)
        ax.set_title(f"{label(run)}: t = {h['time'][-1]:.2f} s\n"
                     f"crest settled {1000 * h['settlement'][-1]:.1f} mm, "
                     f"toe out {1000 * h['toe'][-1]:.1f} mm", fontsize=10)
        ax.set_xlabel("x (m)")
        if column == 0:
            ax.set_ylabel("y (m)")
            ax.legend(fontsize=7, loc="upper left")
    bar = fig.colorbar(art, cax=fig.add_subplot(grid[0, -1]))
    bar.set_label("pore pressure (kPa)")

    half = max(1, len(runs) // 2)
    ax = fig.add_subplot(grid[1, :half])
    for run, (h, f) in runs.items():
        line, = ax.plot(h["time"], 1000 * h["settlement"], label=f"crest settlement, {label(run)}")
        ax.plot(h["time"], 1000 * h["toe"], "--", color=line.get_color(), label=f"toe outward, {label(run)}")
    ax.axvspan(0, DRAWDOWN, color="lightskyblue", alpha=0.3, lw=0, label="drawdown")
    ax.set_xlabel("time from the drawdown's start (s)")
    ax.set_ylabel("displacement (mm)")
    ax.legend(fontsize=7)
    ax.grid(alpha=0.3)
    ax = fig.add_subplot(grid[1, half:])
    for run, (h, f) in runs.items():
        line, = ax.plot(h["time"], h["excess"], label=f"mean excess, {label(run)}")
        ax.plot(h["time"], h["p_probe"], "--", color=line.get_color(),
                label=f"pore pressure at (0.2, 0.05), {label(run)}")
    ax.axvspan(0, DRAWDOWN, color="lightskyblue", alpha=0.3, lw=0)
    ax.axhline(0, color="k", lw=0.5)
    ax.set_xlabel("time from the drawdown's start (s)")
    ax.set_ylabel("Pa")
    ax.set_title("excess: the pore pressure beyond rho_w g (level_end - y), the drained state", fontsize=9)
    ax.legend(fontsize=7)
    ax.grid(alpha=0.3)
    fig.savefig(args.png, dpi=110, bbox_inches="tight")
    print(f"wrote {args.png}")


if __name__ == "__main__":
    main()
