#!/usr/bin/python3
"""The submerged layer of in.hydrostatic against hydrostatics: pore pressure and vertical
effective stress row by row, from the last frame of dump.hydrostatic, and with --log the kinetic
energy of the run against time.

  /usr/bin/python3 plot_hydrostatic.py [--dump dump.hydrostatic] [--D 0.02] [--H 0.1]
                                       [--log log.lammps] [--compare LOG LABEL] [--png hydrostatic.png]

--D is the water's depth the run had (-var D), --compare adds another run's kinetic energy (a log
of the same input, e.g. one made before a change). Prints every row, the largest deviations of the
soil's rows deeper than two spacings below its surface (the targets: pore pressure within 1% of
gamma_w z, effective stress within 2% of the buoyant weight), and the largest speed.
"""
import argparse

import numpy as np

RHO_SAT, RHO_W, G = 2000.0, 1000.0, 9.81


def last_frame(path):
    frame = open(path).read().split("ITEM: TIMESTEP")[-1].strip().split("\n")
    start = next(k for k, line in enumerate(frame) if line.startswith("ITEM: ATOMS"))
    names = frame[start].split()[2:]
    values = np.array([[float(x) for x in line.split()] for line in frame[start + 1:]])
    return {name: values[:, k] for k, name in enumerate(names)}


def kinetic_energy(path):
    """time and kinetic energy (c_kinetic, or an older log's c_kes + c_kew) of its thermo tables"""
    time, energy, columns = [], [], None
    for line in open(path):
        words = line.split()
        if words and words[0] == "Step":
            columns = words
            continue
        if not columns or not words or not words[0].isdigit() or len(words) != len(columns):
            continue
        try:
            row = dict(zip(columns, map(float, words)))
        except ValueError:
            continue
        if "c_kinetic" in row:
            energy.append(row["c_kinetic"])
        elif "c_kes" in row:
            energy.append(row["c_kes"] + row["c_kew"])
        else:
            continue
        time.append(row["Time"])
    return np.array(time), np.array(energy)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--dump", default="dump.hydrostatic")
    parser.add_argument("--H", type=float, default=0.1)
    parser.add_argument("--D", type=float, default=0.02)
    parser.add_argument("--log", default=None)
    parser.add_argument("--compare", nargs=2, metavar=("LOG", "LABEL"))
    parser.add_argument("--png", default="hydrostatic.png")
    args = parser.parse_args()
    height, depth = args.H, args.D
    atoms = last_frame(args.dump)
    rows = []
    for kind in (1, 3):    # soil, free water
        mine = atoms["type"] == kind
        for y in np.unique(np.round(atoms["y"][mine], 4)):
            row = mine & (np.abs(atoms["y"] - y) < 5e-4)
            rows.append((kind, y, atoms["c_all[1]"][row].mean(), atoms["c_all[2]"][row].mean()))
    print(f"{'kind':>5} {'y (m)':>7} {'p (Pa)':>9} {'rho_w g depth':>13} {'syy (Pa)':>9} {'buoyant':>9}")
    for kind, y, p, syy in rows:
        print(f"{'soil' if kind == 1 else 'water':>5} {y:7.4f} {p:9.1f} {RHO_W * G * (height + depth - y):13.1f} "
              f"{syy:9.1f} {-(RHO_SAT - RHO_W) * G * max(height - y, 0.0) if kind == 1 else 0.0:9.1f}")
    soil = np.array([r[1:] for r in rows if r[0] == 1])
    water = np.array([r[1:] for r in rows if r[0] == 3])
    spacing = np.min(np.diff(soil[:, 0]))
    pore_theory = RHO_W * G * (height + depth - soil[:, 0])
    buoyant = -(RHO_SAT - RHO_W) * G * (height - soil[:, 0])
    pore_error = 100 * (soil[:, 1] / pore_theory - 1)
    stress_error = 100 * (soil[:, 2] / buoyant - 1)
    deep = soil[:, 0] < height - 2 * spacing
    print(f"rows deeper than two spacings ({deep.sum()}): pore pressure within "
          f"{np.abs(pore_error[deep]).max():.2f}% of gamma_w z, effective stress within "
          f"{np.abs(stress_error[deep]).max():.2f}% of the buoyant weight")
    speed = np.hypot(atoms["vx"], atoms["vy"]).max()
    print(f"largest speed {speed:.3e} m/s")
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        return
    panels = 3 if args.log else 2
    fig, axes = plt.subplots(1, panels, figsize=(4.6 * panels, 4.6))
    ax = axes[0]
    heights = np.linspace(0, height + depth, 50)
    ax.plot(RHO_W * G * (height + depth - heights), heights, "k--", label="rho_w g depth")
    ax.plot([-(RHO_SAT - RHO_W) * G * max(height - y, 0) for y in heights], heights, "k:",
            label="-(rho_sat - rho_w) g depth")
    ax.plot(soil[:, 1], soil[:, 0], "o", ms=3, label="pore pressure (soil)")
    if len(water):
        ax.plot(water[:, 1], water[:, 0], "s", ms=3, label="pressure (free water)")
    ax.plot(soil[:, 2], soil[:, 0], "^", ms=3, label="effective sigma_yy (soil)")
    ax.axhline(height, color="grey", lw=0.5)
    ax.set_xlabel("Pa")
    ax.set_ylabel("y (m)")
    ax.legend(fontsize=7)
    ax = axes[1]
    ax.axvspan(-1, 1, color="0.92")
    ax.plot(pore_error, soil[:, 0], "o-", ms=3, label="pore pressure / gamma_w z - 1")
    ax.plot(stress_error, soil[:, 0], "^-", ms=3, label="sigma'_yy / buoyant weight - 1")
    ax.axhline(height - 2 * spacing, color="grey", ls=":", lw=0.8)
    ax.set_xlim(-5, 5)
    ax.set_xlabel("%")
    ax.legend(fontsize=7)
    if args.log:
        ax = axes[2]
        t, k = kinetic_energy(args.log)
        ax.semilogy(t, np.maximum(k, 1e-20), label="this run")
        if args.compare:
            tc, kc = kinetic_energy(args.compare[0])
            ax.semilogy(tc, np.maximum(kc, 1e-20), label=args.compare[1])
        ax.set_xlabel("time (s)")
        ax.set_ylabel("kinetic energy (J per m of depth)")
        ax.legend(fontsize=7)
    fig.suptitle(f"a layer {height} m thick under {depth} m of water")
    fig.tight_layout()
    fig.savefig(args.png, dpi=120)
    print(f"wrote {args.png}")


if __name__ == "__main__":
    main()
