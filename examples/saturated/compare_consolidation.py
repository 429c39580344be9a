#!/usr/bin/python3
"""The consolidation example (in.consolidation) against Terzaghi's one-dimensional solution.

Reads consolidation.txt (the run's parameters in its first line, then time, settlement, excess
pore pressure at the floor), prints the degree of consolidation U = (s - s_0) / (s_inf - s_0) against Terzaghi's
U(T_v) at T_v = 0.05, 0.2 and 0.5 (and more), and the excess pore pressure at the floor against
his series, and writes consolidation.png. Terzaghi's U is that of the example's load, which rises
linearly over its first 5 ms (T_v = 0.012): the mean of his U for an instant load over the ramp.

The theory (doc/theory.rst 7): a soil of oedometric modulus M = K + 4G/3 with pore water of
bulk modulus K_w and porosity n, loaded by q, takes at once the pore pressure B q with
B = (K_w/n) / (K_w/n + M) and the settlement s_0 = (1 - B) q H / M; the excess pore pressure
then diffuses with c_v = (k / gamma_w) / (1/M + n/K_w) to a drained top, to s_inf = q H / M.

  /usr/bin/python3 compare_consolidation.py [--file consolidation.txt] [--png F]
"""
import argparse
import math

G_N = 9.80665  # standard gravity: hydraulic conductivities are measured under it


def terzaghi_degree(tv, terms=200):
    """U(T_v) = 1 - sum 2/M^2 exp(-M^2 T_v), M = pi (2m + 1) / 2."""
    total = 0.0
    for m in range(terms):
        big_m = math.pi * (2 * m + 1) / 2
        total += 2.0 / big_m**2 * math.exp(-big_m**2 * tv)
    return 1.0 - total


def terzaghi_degree_ramped(tv, tv_ramp, steps=200):
    """U(T_v) under a load that rises linearly over T_v = tv_ramp (the example's), by
    superposition: the mean of U(T_v - s) over the ramp (s from 0 to tv_ramp, U = 0 before the
    load); U(T_v) itself for tv_ramp = 0."""
    if tv_ramp <= 0.0:
        return terzaghi_degree(tv)
    total = 0.0
    for k in range(steps):       # the midpoint rule over the ramp
        t = tv - (k + 0.5) / steps * tv_ramp
        total += terzaghi_degree(t) if t > 0.0 else 0.0
    return total / steps


def terzaghi_base_excess(tv, u0, terms=200):
    """The excess pore pressure at the impermeable base (z = H from the drained top)."""
    total = 0.0
    for m in range(terms):
        big_m = math.pi * (2 * m + 1) / 2
        total += 2.0 / big_m * math.sin(big_m) * math.exp(-big_m**2 * tv)
    return u0 * total


def read(path):
    """The run's parameters (the first line of consolidation.txt: '# name value ...') and its
    records (time, settlement, excess pore pressure at the floor)."""
    run, rows = {}, []
    with open(path) as f:
        for line in f:
            if line.startswith("# k "):
                words = line[2:].split()
                run = dict(zip(words[0::2], map(float, words[1::2])))
            elif line.strip() and not line.startswith("#"):
                rows.append(tuple(float(x) for x in line.split()))
    if not run:
        raise SystemExit(f"{path}: no parameter line ('# k ...'): written by an older in.consolidation")
    return run, rows


def theory(run):
    """Skempton's B, c_v, and the settlements at once (s_0) and in the end (s_inf) of a run's
    parameters."""
    shear = 3 * run["K"] * (1 - 2 * run["nu"]) / (2 * (1 + run["nu"]))
    modulus = run["K"] + 4 * shear / 3
    storage = run["n"] / run["K_w"]
    skempton = (1 / storage) / (1 / storage + modulus)
    mobility = run["k"] / (run["rho_w"] * G_N)
    cv = mobility / (1 / modulus + storage)
    s0 = (1 - skempton) * run["q"] * run["H"] / modulus
    s_inf = run["q"] * run["H"] / modulus
    return {"B": skempton, "c_v": cv, "s_0": s0, "s_inf": s_inf}


def degrees(path, tvs):
    """For each T_v of `tvs` that the run reached: the degree of consolidation U and the excess
    pore pressure at the floor over B q, each interpolated between the records either side,
    beside Terzaghi's."""
    run, rows = read(path)
    th = theory(run)
    table = []
    for tv in tvs:
        t = tv * run["H"] ** 2 / th["c_v"]
        if t > rows[-1][0]:
            break
        after = next(k for k, r in enumerate(rows) if r[0] >= t)
        (t0, s_a, u_a), (t1, s_b, u_b) = rows[max(after - 1, 0)], rows[after]
        w = (t - t0) / (t1 - t0) if t1 > t0 else 0.0
        s = s_a + w * (s_b - s_a)
        u = u_a + w * (u_b - u_a)
        tv_ramp = run.get("ramp", 0.0) * th["c_v"] / run["H"] ** 2
        table.append({"T_v": tv, "t": t, "U": (s - th["s_0"]) / (th["s_inf"] - th["s_0"]),
                      "U_terzaghi": terzaghi_degree_ramped(tv, tv_ramp), "base": u / (th["B"] * run["q"]),
                      "base_terzaghi": terzaghi_base_excess(tv, 1.0)})
    return table


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--file", default="consolidation.txt")
    parser.add_argument("--png", default="consolidation.png")
    args = parser.parse_args()

    run, rows = read(args.file)
    th = theory(run)
    height = run["H"]
    print(f"B = {th['B']:.4f}, c_v = {th['c_v']:.5g} m^2/s, s_0 = {th['s_0']:.4e} m, "
          f"s_inf = {th['s_inf']:.4e} m, T_v = 1 at t = {height**2 / th['c_v']:.4f} s")
    print(f"{'T_v':>6} {'t (s)':>8} {'U SPH':>7} {'U Terzaghi':>10} {'diff':>7} "
          f"{'u_base/Bq SPH':>13} {'Terzaghi':>9}")
    for r in degrees(args.file, (0.02, 0.05, 0.1, 0.2, 0.3, 0.5, 0.8, 1.0)):
        print(f"{r['T_v']:6.2f} {r['t']:8.4f} {r['U']:7.3f} {r['U_terzaghi']:10.3f} "
              f"{r['U'] - r['U_terzaghi']:+7.3f} {r['base']:13.3f} {r['base_terzaghi']:9.3f}")

    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        return
    fig, (left, right) = plt.subplots(1, 2, figsize=(10, 4))
    rows = [r for r in rows if r[0] > 0.0]
    cv, s0, s_inf, base = th["c_v"], th["s_0"], th["s_inf"], th["B"] * run["q"]
    tv_ramp = run.get("ramp", 0.0) * cv / height**2
    tvs = [r[0] * cv / height**2 for r in rows]
    left.plot(tvs, [(r[1] - s0) / (s_inf - s0) for r in rows], label="SPH")
    grid = [0.001 * 1.02**k for k in range(400) if 0.001 * 1.02**k <= max(tvs)]
    left.plot(grid, [terzaghi_degree_ramped(tv, tv_ramp) for tv in grid], "k--", label="Terzaghi")
    left.set_xscale("log")
    left.set_xlabel("T_v = c_v t / H^2")
    left.set_ylabel("degree of consolidation U")
    left.legend()
    right.plot(tvs, [r[2] / base for r in rows], label="SPH")
    right.plot(grid, [terzaghi_base_excess(tv, 1.0) for tv in grid], "k--", label="Terzaghi")
    right.set_xscale("log")
    right.set_xlabel("T_v")
    right.set_ylabel("excess pore pressure at the floor / (B q)")
    right.legend()
    fig.tight_layout()
    fig.savefig(args.png, dpi=120)
    print(f"wrote {args.png}")


if __name__ == "__main__":
    main()
