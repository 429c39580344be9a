#!/usr/bin/python3
"""The submerged column of in.hydrostatic against hydrostatics: pore pressure and vertical
effective stress along the height, row by row, from the last frame of dump.hydrostatic.

  /usr/bin/python3 plot_hydrostatic.py [--dump dump.hydrostatic] [--png hydrostatic.png]
"""
import argparse

import numpy as np

H, D, RHO_SAT, RHO_W, G = 0.1, 0.02, 2000.0, 1000.0, 9.81


def last_frame(path):
    frame = open(path).read().split("ITEM: TIMESTEP")[-1].strip().split("\n")
    start = next(k for k, line in enumerate(frame) if line.startswith("ITEM: ATOMS"))
    names = frame[start].split()[2:]
    values = np.array([[float(x) for x in line.split()] for line in frame[start + 1:]])
    return {name: values[:, k] for k, name in enumerate(names)}


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--dump", default="dump.hydrostatic")
    parser.add_argument("--png", default="hydrostatic.png")
    args = parser.parse_args()
    atoms = last_frame(args.dump)
    rows = []
    for kind in (1, 3):    # soil, free water
        mine = atoms["type"] == kind
        for y in np.unique(np.round(atoms["y"][mine], 4)):
            row = mine & (np.abs(atoms["y"] - y) < 5e-4)
            rows.append((kind, y, atoms["c_all[1]"][row].mean(), atoms["c_all[2]"][row].mean()))
    print(f"{'kind':>5} {'y (m)':>7} {'p (Pa)':>9} {'rho_w g depth':>13} {'syy (Pa)':>9} {'buoyant':>9}")
    for kind, y, p, syy in rows:
        print(f"{'soil' if kind == 1 else 'water':>5} {y:7.4f} {p:9.1f} {RHO_W * G * (H + D - y):13.1f} "
              f"{syy:9.1f} {-(RHO_SAT - RHO_W) * G * max(H - y, 0.0) if kind == 1 else 0.0:9.1f}")
    speed = np.hypot(atoms["vx"], atoms["vy"]).max()
    print(f"largest speed {speed:.3e} m/s")
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        return
    fig, ax = plt.subplots(figsize=(5, 5))
    soil = [r for r in rows if r[0] == 1]
    water = [r for r in rows if r[0] == 3]
    heights = np.linspace(0, H + D, 50)
    ax.plot(RHO_W * G * (H + D - heights), heights, "k--", label="rho_w g depth")
    ax.plot([-(RHO_SAT - RHO_W) * G * max(H - y, 0) for y in heights], heights, "k:",
            label="-(rho_sat - rho_w) g depth")
    ax.plot([r[2] for r in soil], [r[1] for r in soil], "o", ms=3, label="pore pressure (soil)")
    ax.plot([r[2] for r in water], [r[1] for r in water], "s", ms=3, label="pressure (free water)")
    ax.plot([r[3] for r in soil], [r[1] for r in soil], "^", ms=3, label="effective sigma_yy (soil)")
    ax.axhline(H, color="grey", lw=0.5)
    ax.set_xlabel("Pa")
    ax.set_ylabel("y (m)")
    ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(args.png, dpi=120)
    print(f"wrote {args.png}")


if __name__ == "__main__":
    main()
