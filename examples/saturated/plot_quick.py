#!/usr/bin/python3
"""The onset of heave in in.quick -var onset 1: the layer's mean vertical speed against time at
0.9 and 1.1 times the critical gradient, from quick_onset.<d>.txt (one file per spacing d), and
its acceleration at 1.1 i_c against the force balance's.

  /usr/bin/python3 plot_quick.py [--png quick_onset.png] [--fit 0.04]

At 1.1 i_c the layer's base sees more water pressure than the layer and the water above it weigh:
the two accelerate together at a = (i - i_c) gamma_w H / (rho_sat H + rho_w D). The fit is a
straight line through the soil's mean speed over the last --fit seconds of the 1.1 hold (after
the pore pressure has followed the floor's step; c_v t / H^2 = 0.8 in 0.05 s).
"""
import argparse
import glob

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np


def read(path):
    """The header's parameters (its "name value [unit]" items: d, H, D, rho_sat, rho_w, g) and
    the rows (time, i, soil's and water's mean speed)."""
    header = open(path).readline().lstrip("# ").strip()
    params = {}
    for item in header.split(", "):
        words = item.split()
        if len(words) >= 2:
            try:
                params[words[0]] = float(words[1])
            except ValueError:
                pass
    rows = np.loadtxt(path, comments="#", ndmin=2)
    return params, rows


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--png", default="quick_onset.png")
    parser.add_argument("--fit", type=float, default=0.04,
                        help="fit the acceleration over the last this many seconds (default 0.04)")
    args = parser.parse_args()
    paths = sorted(glob.glob("quick_onset.*.txt"), key=lambda p: -float(p[12:-4]))
    if not paths:
        raise SystemExit("no quick_onset.<d>.txt: run mpirun -np 2 lmp -in in.quick -var onset 1")
    fig, ax = plt.subplots(figsize=(7.5, 4.5))
    for path in paths:
        p, rows = read(path)
        t, i, v_soil = rows[:, 0], rows[:, 1], rows[:, 2]
        i_c = (p["rho_sat"] - p["rho_w"]) / p["rho_w"]
        lifted = i > 1.0
        t0 = t[lifted][0]
        i_high = i[lifted][0]
        balance = (i_high - i_c) * p["rho_w"] * p["g"] * p["H"] / (p["rho_sat"] * p["H"] + p["rho_w"] * p["D"])
        at_rest = np.abs(v_soil[~lifted][len(v_soil[~lifted]) // 2:]).max()
        window = lifted & (t >= t[-1] - args.fit)
        slope, intercept = np.polyfit(t[window], v_soil[window], 1)
        print(f"d = {p['d'] * 1000:.0f} mm: at i = {i[0]:.2f} the layer's mean speed stays below "
              f"{at_rest:.1e} m/s over the hold's second half; at i = {i_high:.2f} it accelerates at "
              f"{slope:.3f} m/s^2 (t = {t[-1] - args.fit - t0:.3f} to {t[-1] - t0:.3f} s after the step), "
              f"the force balance's {balance:.3f} m/s^2: {slope / balance:.2f} of it")
        line, = ax.plot(t, v_soil * 1000, label=f"d = {p['d'] * 1000:.0f} mm: a = {slope:.3f} m/s² "
                        f"({slope / balance:.2f} of the force balance's)")
        mid = t[window].mean()
        ax.plot(t[window], (slope * mid + intercept + balance * (t[window] - mid)) * 1000, "--",
                color=line.get_color(), lw=1.0)
    ax.axvline(t0, color="0.6", lw=0.8)
    ax.text(t0, ax.get_ylim()[1] * 0.95, f"  i = {i_high:.1f} i_c", fontsize=8, va="top")
    ax.text(t[0], ax.get_ylim()[1] * 0.95, f"  i = {i[0]:.1f} i_c", fontsize=8, va="top")
    ax.set_xlabel("time (s)")
    ax.set_ylabel("mean vertical speed of the layer (mm/s)")
    ax.set_title("Upward seepage: the layer lifts above the critical gradient\n"
                 "(dashed: the force balance's acceleration through the fitted window)", fontsize=9)
    ax.legend(fontsize=8, loc="upper left", bbox_to_anchor=(0.0, 0.88))
    fig.tight_layout()
    fig.savefig(args.png, dpi=130)
    print(f"wrote {args.png}")


if __name__ == "__main__":
    main()
