#!/usr/bin/python3
"""Mandel's problem: the run's pore pressure and settlement against the closed-form solution.

Reads mandel.txt (written by in.mandel) and prints, at a few dimensionless times T = c t / a^2,
the excess pore pressure at the centre and at x = a/2 and the plate's settlement, each with
Mandel's solution (Mandel 1953; in the form of Abousleiman et al. 1996 for a compressible pore
fluid and incompressible grains) for the same load history; writes mandel.png.

Usage: /usr/bin/python3 compare_mandel.py [mandel.txt] [--no-plot]
"""
import math
import sys

import numpy as np

G_STD = 9.80665    # gamma_w = rho_w g: conductivities are measured under standard gravity


def constants(run):
    """Shear modulus, Skempton's B, undrained Poisson ratio and consolidation coefficient of a
    run's parameters (the header line of mandel.txt)."""
    K, nu, n, K_w = run['K'], run['nu'], run['n'], run['K_w']
    shear = 3 * K * (1 - 2 * nu) / (2 * (1 + nu))
    skempton = K_w / (K_w + n * K)                 # Biot's alpha = 1 (grains incompressible)
    nu_u = (3 * nu + skempton * (1 - 2 * nu)) / (3 - skempton * (1 - 2 * nu))
    mobility = run['k'] / (run['rho_w'] * G_STD)   # k / gamma_w (m^2 / (Pa s))
    m_biot = K_w / n
    c = mobility * m_biot * (K + 4 * shear / 3) / (K + m_biot + 4 * shear / 3)
    return shear, skempton, nu_u, c


def roots(nu, nu_u, count=400):
    """The roots of tan(alpha) = (1 - nu) / (nu_u - nu) alpha, one in each (n pi, n pi + pi/2)."""
    slope = (1 - nu) / (nu_u - nu)
    out = []
    for n in range(count):
        lo, hi = max(n * math.pi, 1e-9), n * math.pi + math.pi / 2 - 1e-12
        f = lambda x: math.sin(x) - slope * x * math.cos(x)
        flo = f(lo)
        for _ in range(100):
            mid = 0.5 * (lo + hi)
            if flo * f(mid) <= 0:
                hi = mid
            else:
                lo, flo = mid, f(mid)
        out.append(0.5 * (lo + hi))
    return np.array(out)


class Mandel:
    def __init__(self, run):
        self.run = run
        self.nu, self.a, self.b, self.q = run['nu'], run['a'], run['b'], run['q']
        self.shear, self.skempton, self.nu_u, self.c = constants(run)
        self.alpha = roots(self.nu, self.nu_u)
        s, co = np.sin(self.alpha), np.cos(self.alpha)
        self.weight_p = s / (self.alpha - s * co)
        self.weight_u = s * co / (self.alpha - s * co)
        self.p0 = self.q * self.skempton * (1 + self.nu_u) / 3      # undrained pore pressure

    def unit(self, x, t):
        """Pore pressure and settlement for a unit step of the load at t = 0 (0 before)."""
        t = np.maximum(np.asarray(t, dtype=float), 0.0)
        a = self.a
        decay = np.exp(-np.outer(t, self.alpha ** 2) * self.c / a ** 2)
        p = 2 * self.p0 / self.q * decay @ (self.weight_p * (np.cos(self.alpha * x / a) - np.cos(self.alpha)))
        u = self.b / self.shear * ((1 - self.nu) / 2 - (1 - self.nu_u) * decay @ self.weight_u)
        return p, u

    def ramped(self, x, t, ramp):
        """The same for the example's load, q (1 - cos(pi t / ramp)) / 2 up to t = ramp (Duhamel)."""
        taus = np.linspace(0.0, ramp, 801)
        dq = self.q * 0.5 * math.pi / ramp * np.sin(math.pi * taus / ramp)     # dq/dtau
        wts = np.full(taus.size, taus[1] - taus[0]); wts[[0, -1]] *= 0.5
        p = np.zeros(len(t)); u = np.zeros(len(t))
        for tau, w, rate in zip(taus, wts, dq):
            live = np.asarray(t) > tau
            if not live.any():
                continue
            pu, uu = self.unit(x, np.asarray(t)[live] - tau)
            p[live] += w * rate * pu
            u[live] += w * rate * uu
        return p, u


def main():
    args = [a for a in sys.argv[1:] if not a.startswith("--")]
    path = args[0] if args else "mandel.txt"
    run = {}
    for line in open(path):
        if line.startswith("# k "):
            words = line[2:].split()
            run = dict(zip(words[0::2], map(float, words[1::2])))
    data = np.loadtxt(path)
    k, d, ramp, A = run["k"], run["d"], run["ramp"], run["a"]
    model = Mandel(run)
    t = data[:, 0]
    # the strips average the two particle columns either side of x = 0 and of x = a/2
    p_c = 0.5 * sum(model.ramped(x, t, ramp)[0] for x in (0.5 * d, 0.5 * d))
    p_h = 0.5 * sum(model.ramped(x, t, ramp)[0] for x in (0.5 * A - 0.5 * d, 0.5 * A + 0.5 * d))
    u = model.ramped(0.0, t, ramp)[1]
    T = model.c * t / A ** 2
    print(f"Mandel: k {k} m/s, d {d} m: B {model.skempton:.4f}, nu_u {model.nu_u:.4f}, "
          f"c {model.c:.4e} m^2/s, a^2/c {A * A / model.c:.3f} s, p0 {model.p0:.1f} Pa")
    print("   T      t(s)   p_centre/p0 (Mandel)   p_half/p0 (Mandel)   settlement mm (Mandel)")
    for target in (0.005, 0.01, 0.02, 0.05, 0.1, 0.2, 0.3, 0.5, 0.75, 1.0):
        if target > T[-1] * 1.0001:
            break
        i = int(np.argmin(abs(T - target)))
        print(f"{T[i]:6.3f} {t[i]:7.4f}   {data[i, 2] / model.p0:6.3f} ({p_c[i] / model.p0:6.3f})"
              f"        {data[i, 3] / model.p0:6.3f} ({p_h[i] / model.p0:6.3f})"
              f"       {1e3 * data[i, 1]:7.4f} ({1e3 * u[i]:7.4f})")
    after = T > 2 * model.c * ramp / A ** 2
    if not after.any():
        print("(the run ends before twice the ramp: no peak to compare)")
    else:
        report_peak(data, p_c, T, after, model)
    if "--no-plot" in sys.argv:
        return
    plot(data, p_c, p_h, u, T, model, d)


def report_peak(data, p_c, T, after, model):
    peak, peak_m = data[after, 2].max() / model.p0, p_c[after].max() / model.p0
    print(f"peak at the centre (the Mandel-Cryer rise): {peak:.3f} p0 at T = {T[after][data[after, 2].argmax()]:.3f}"
          f" (Mandel {peak_m:.3f} p0 at T = {T[after][p_c[after].argmax()]:.3f})")


def plot(data, p_c, p_h, u, T, model, d):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(10, 4))
    ax1.plot(T, data[:, 2] / model.p0, "C0", lw=1, label="SPH, centre")
    ax1.plot(T, p_c / model.p0, "k--", lw=1, label="Mandel, centre")
    ax1.plot(T, data[:, 3] / model.p0, "C1", lw=1, label="SPH, x = a/2")
    ax1.plot(T, p_h / model.p0, "k:", lw=1, label="Mandel, x = a/2")
    ax1.set_xlabel("T = c t / a²"); ax1.set_ylabel("excess pore pressure / p0"); ax1.legend()
    ax2.plot(T, 1e3 * data[:, 1], "C0", lw=1, label="SPH")
    ax2.plot(T, 1e3 * u, "k--", lw=1, label="Mandel")
    ax2.set_xlabel("T = c t / a²"); ax2.set_ylabel("settlement of the plate (mm)"); ax2.legend()
    fig.suptitle(f"Mandel's problem, d = {d} m")
    fig.tight_layout(); fig.savefig("mandel.png", dpi=110)
    print("wrote mandel.png")


if __name__ == "__main__":
    main()
