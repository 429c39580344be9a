#!/usr/bin/python3
"""The consolidation example (in.consolidation) against Terzaghi's one-dimensional solution.

Reads consolidation.txt (time, settlement, excess pore pressure at the floor) and the example's
parameters, prints the degree of consolidation U = (s - s_0) / (s_inf - s_0) against Terzaghi's
U(T_v) at T_v = 0.05, 0.2 and 0.5 (and more), and the excess pore pressure at the floor against
his series, and writes consolidation.png.

The theory (doc/theory.rst 7): a soil of oedometric modulus M = K + 4G/3 with pore water of
bulk modulus K_w and porosity n, loaded by q, takes at once the pore pressure B q with
B = (K_w/n) / (K_w/n + M) and the settlement s_0 = (1 - B) q H / M; the excess pore pressure
then diffuses with c_v = (k / gamma_w) / (1/M + n/K_w) to a drained top, to s_inf = q H / M.

  /usr/bin/python3 compare_consolidation.py [--file consolidation.txt] [--k 1e-4] [--png F]
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


def terzaghi_base_excess(tv, u0, terms=200):
    """The excess pore pressure at the impermeable base (z = H from the drained top)."""
    total = 0.0
    for m in range(terms):
        big_m = math.pi * (2 * m + 1) / 2
        total += 2.0 / big_m * math.sin(big_m) * math.exp(-big_m**2 * tv)
    return u0 * total


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--file", default="consolidation.txt")
    parser.add_argument("--k", type=float, default=1.0e-4, help="hydraulic conductivity (m/s)")
    parser.add_argument("--png", default="consolidation.png")
    args = parser.parse_args()

    # the example's parameters
    height, load, bulk, poisson = 0.1, 1.0e4, 1.5e6, 0.3
    porosity, water_density, water_modulus = 0.4, 1000.0, 2.0e7
    shear = 3 * bulk * (1 - 2 * poisson) / (2 * (1 + poisson))
    modulus = bulk + 4 * shear / 3
    storage = porosity / water_modulus
    skempton = (1 / storage) / (1 / storage + modulus)
    mobility = args.k / (water_density * G_N)
    cv = mobility / (1 / modulus + storage)
    s0 = (1 - skempton) * load * height / modulus
    s_inf = load * height / modulus

    rows = []
    with open(args.file) as f:
        for line in f:
            if line.startswith("#") or not line.strip():
                continue
            t, s, u = (float(x) for x in line.split())
            rows.append((t, s, u))
    print(f"B = {skempton:.4f}, c_v = {cv:.5g} m^2/s, s_0 = {s0:.4e} m, s_inf = {s_inf:.4e} m, "
          f"T_v = 1 at t = {height**2 / cv:.4f} s")
    print(f"{'T_v':>6} {'t (s)':>8} {'U SPH':>7} {'U Terzaghi':>10} {'diff':>7} "
          f"{'u_base/Bq SPH':>13} {'Terzaghi':>9}")
    results = []
    for tv in (0.02, 0.05, 0.1, 0.2, 0.3, 0.5, 0.8, 1.0):
        t = tv * height**2 / cv
        if t > rows[-1][0]:
            break
        # interpolated between the records on either side
        after = next(k for k, r in enumerate(rows) if r[0] >= t)
        (t0, s_a, u_a), (t1, s_b, u_b) = rows[max(after - 1, 0)], rows[after]
        w = (t - t0) / (t1 - t0) if t1 > t0 else 0.0
        s = s_a + w * (s_b - s_a)
        u = u_a + w * (u_b - u_a)
        degree = (s - s0) / (s_inf - s0)
        exact = terzaghi_degree(tv)
        base = terzaghi_base_excess(tv, 1.0)
        results.append((tv, degree, exact))
        print(f"{tv:6.2f} {t:8.4f} {degree:7.3f} {exact:10.3f} {degree - exact:+7.3f} "
              f"{u / (skempton * load):13.3f} {base:9.3f}")

    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        return
    fig, (left, right) = plt.subplots(1, 2, figsize=(10, 4))
    rows = [r for r in rows if r[0] > 0.0]
    tvs = [r[0] * cv / height**2 for r in rows]
    left.plot(tvs, [(r[1] - s0) / (s_inf - s0) for r in rows], label="SPH")
    grid = [0.001 * 1.02**k for k in range(400) if 0.001 * 1.02**k <= max(tvs)]
    left.plot(grid, [terzaghi_degree(tv) for tv in grid], "k--", label="Terzaghi")
    left.set_xscale("log")
    left.set_xlabel("T_v = c_v t / H^2")
    left.set_ylabel("degree of consolidation U")
    left.legend()
    right.plot(tvs, [r[2] / (skempton * load) for r in rows], label="SPH")
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
