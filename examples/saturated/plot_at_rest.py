#!/usr/bin/python3
"""A saturated layer at rest under free water (in.hydrostatic, e.g. -var D 0.3 -var duration 10):
the kinetic energy against time from its log, and the pore pressure and vertical effective stress
of every row of the final dump against gamma_w z and the buoyant weight.

  /usr/bin/python3 plot_at_rest.py [--log log.lammps] [--dump dump.hydrostatic] [--H 0.1] [--D 0.3]
                                   [--compare LOG LABEL] [--png at_rest.png]

--compare adds another run's kinetic energy (a log of the same input), e.g. one made before a
change. Prints, for the rows deeper than two spacings below the soil's surface, the largest
deviations in per cent; writes the figure.
"""
import argparse

import numpy as np

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

G, RHO_W, RHO_SAT = 9.81, 1000.0, 2000.0


def thermo(path):
    """time and kinetic energy columns of the last thermo table holding both"""
    lines = open(path).read().splitlines()
    time, energy, columns = [], [], None
    for line in lines:
        words = line.split()
        if words and words[0] == "Step":
            columns = words
            time, energy = [], []
            continue
        if columns and words and words[0].isdigit() and len(words) == len(columns):
            try:
                values = [float(w) for w in words]
            except ValueError:
                continue
            kinetic = "c_kinetic" if "c_kinetic" in columns else None
            if kinetic is None:
                # (an older log: the soil's and the water's kinetic energies)
                if "c_kes" in columns:
                    values_k = values[columns.index("c_kes")] + values[columns.index("c_kew")]
                else:
                    continue
            else:
                values_k = values[columns.index(kinetic)]
            time.append(values[columns.index("Time")])
            energy.append(values_k)
        elif columns and not (words and words[0].isdigit()):
            if time:
                columns = None
    return np.array(time), np.array(energy)


def rows(path, height, depth):
    lines = open(path).read().splitlines()
    start = [k for k, line in enumerate(lines) if line.startswith("ITEM: ATOMS")][-1]
    names = lines[start].split()[2:]
    data = np.array([[float(w) for w in line.split()] for line in lines[start + 1:] if line.strip()])
    col = {n: k for k, n in enumerate(names)}
    soil = data[data[:, col["type"]] == 1]
    y = soil[:, col["y"]]
    levels = np.unique(np.round(y, 6))
    out = []
    for level in levels:
        pick = np.abs(y - level) < 1e-6
        out.append((level, soil[pick, col["c_all[1]"]].mean(), soil[pick, col["c_all[2]"]].mean()))
    out = np.array(out)
    spacing = np.min(np.diff(levels)) if len(levels) > 1 else 0.0
    return out, spacing


def main():
    p = argparse.ArgumentParser()
    p.add_argument("--log", default="log.lammps")
    p.add_argument("--dump", default="dump.hydrostatic")
    p.add_argument("--H", type=float, default=0.1)
    p.add_argument("--D", type=float, default=0.3)
    p.add_argument("--compare", nargs=2, metavar=("LOG", "LABEL"))
    p.add_argument("--png", default="at_rest.png")
    a = p.parse_args()

    fig, (ax_k, ax_p, ax_s) = plt.subplots(1, 3, figsize=(13, 4.2))
    t, k = thermo(a.log)
    ax_k.semilogy(t, np.maximum(k, 1e-20), label="this run")
    if a.compare:
        tc, kc = thermo(a.compare[0])
        ax_k.semilogy(tc, np.maximum(kc, 1e-20), label=a.compare[1])
    ax_k.set_xlabel("time (s)")
    ax_k.set_ylabel("kinetic energy (J per m of depth)")
    ax_k.legend()
    ax_k.set_title(f"layer {a.H} m under {a.D} m of water")

    r, spacing = rows(a.dump, a.H, a.D)
    y, pore, sigma = r[:, 0], r[:, 1], r[:, 2]
    p_theory = RHO_W * G * (a.H + a.D - y)
    s_theory = -(RHO_SAT - RHO_W) * G * (a.H - y)
    deep = y < a.H - 2 * spacing
    dp = 100 * np.max(np.abs(pore[deep] / p_theory[deep] - 1))
    ds = 100 * np.max(np.abs(sigma[deep] / s_theory[deep] - 1))
    print(f"at rest: rows deeper than two spacings ({deep.sum()}): pore pressure within {dp:.2f}% "
          f"of gamma_w z, vertical effective stress within {ds:.2f}% of the buoyant weight")
    print(f"at rest: kinetic energy {k[len(k) // 2]:.3e} J/m at t = {t[len(t) // 2]:.2f} s, "
          f"{k[-1]:.3e} at {t[-1]:.2f} s")
    ax_p.plot(100 * (pore / p_theory - 1), y, "o-", ms=3)
    ax_p.axvspan(-1, 1, color="0.9")
    ax_p.set_xlabel("pore pressure / gamma_w z - 1 (%)")
    ax_p.set_ylabel("y (m)")
    ax_s.plot(100 * (sigma / s_theory - 1), y, "o-", ms=3)
    ax_s.axvspan(-2, 2, color="0.9")
    ax_s.axhline(a.H - 2 * spacing, color="0.6", ls=":")
    ax_s.set_xlabel("sigma'_yy / buoyant weight - 1 (%)")
    for ax in (ax_p, ax_s):
        ax.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(a.png, dpi=110)
    print(f"wrote {a.png}")


if __name__ == "__main__":
    main()
