"""Load-settlement curve of examples/footing against the bearing capacity of a rough strip footing.

Reads footing.dat (fix ave/time: step, time, applied pressure q, settlement, the soil's pressure
on the footing), prints a JSON summary and writes a plot:
  - the pressures at settlements of 5% and 10% of the footing width B (with a load that grows at
    a steady rate, the settlement runs away at the bearing capacity: 10% of B is the usual
    criterion of failure in load tests);
  - their ratio to q_u = 0.5 gamma B N_gamma with N_gamma of a rough footing by the method of
    characteristics (Martin 2005; associated flow), the reference, and beside it the textbook
    formulas (Meyerhof, Hansen, Vesic), whose spread shows how uncertain N_gamma is.

  python3 -m sph_soil footing --dat examples/footing/footing.dat [--dat other.dat --label ...]
      [--phi 30] [--gamma 18148.5] [--width 0.2] [--plot footing.png] [--json footing.json]
"""
import math
import os

import numpy as np

from .. import report
from ..dumps import read_ave_time

COMMAND = 'footing'
# N_gamma of a rough strip footing, method of characteristics (Martin 2005), by phi in degrees
MARTIN_ROUGH = {20: 2.84, 25: 6.49, 30: 14.75, 35: 34.48, 40: 85.57}
GAMMA, WIDTH = 1850 * 9.81, 0.2     # examples/footing: unit weight (N/m^3), B (m)


def textbook_n_gamma(phi_deg):
    phi = math.radians(phi_deg)
    nq = math.exp(math.pi * math.tan(phi)) * math.tan(math.pi / 4 + phi / 2) ** 2
    return {'Meyerhof': (nq - 1) * math.tan(1.4 * phi),
            'Hansen': 1.5 * (nq - 1) * math.tan(phi),
            'Vesic': 2 * (nq + 1) * math.tan(phi)}


def read(path):
    data = read_ave_time(path)
    return {'time': data[:, 1], 'q': data[:, 2], 'settlement': data[:, 3], 'reaction': data[:, 4]}


def pressure_at(curve, settlement):
    s, q = curve['settlement'], curve['q']
    above = np.nonzero(s >= settlement)[0]
    if len(above) == 0:
        return None
    k = above[0]
    if k == 0:
        return float(q[0])
    return float(np.interp(settlement, [s[k - 1], s[k]], [q[k - 1], q[k]]))


def footing(dats, labels=None, phi=30.0, gamma=GAMMA, width=WIDTH, plot=None, json_path=None):
    labels = labels or [p for p in dats]
    n_gamma = MARTIN_ROUGH.get(int(round(phi)))
    scale = 0.5 * gamma * width
    q_u = scale * n_gamma if n_gamma else None
    summary = {'phi': phi, 'B': width, 'gamma': gamma, 'N_gamma_Martin_rough': n_gamma,
               'q_u_Martin': q_u,
               'q_u_textbook': {k: scale * v for k, v in textbook_n_gamma(phi).items()},
               'runs': []}
    curves = []
    for path, label in zip(dats, labels):
        curve = read(path)
        curves.append((label, curve))
        run = {'label': label, 'file': path}
        for fraction in (0.05, 0.1):
            q = pressure_at(curve, fraction * width)
            run['q_at_%g_B' % fraction] = q
            run['q_at_%g_B_over_q_u' % fraction] = q / q_u if (q is not None and q_u) else None
        summary['runs'].append(run)
    report.write_json(summary, json_path, indent=2, end='')
    if plot:
        plt = report.pyplot()
        fig, ax = plt.subplots(figsize=(7, 4.5))
        for label, curve in curves:
            ax.plot(curve['settlement'] / width, curve['q'] / 1000, label='%s: applied' % label)
            ax.plot(curve['settlement'] / width, curve['reaction'] / 1000, ':',
                    label='%s: soil on footing' % label)
        if q_u:
            ax.axhline(q_u / 1000, color='k', lw=1,
                       label=r'$0.5\gamma B N_\gamma$, $N_\gamma$ = %.2f (Martin 2005, rough)' % n_gamma)
        for name, q in summary['q_u_textbook'].items():
            ax.axhline(q / 1000, color='gray', lw=0.6, ls='--')
            ax.text(0.49, q / 1000, name, fontsize=7, va='bottom', ha='right', color='gray')
        ax.set_xlim(0, 0.5)
        ax.set_xlabel('settlement / B')
        ax.set_ylabel('pressure (kPa)')
        ax.set_title(r'Rigid rough strip footing on sand, $\phi$ = %g$^\circ$, B = %g m' % (phi, width))
        ax.legend(fontsize=7, loc='lower right')
        ax.grid(alpha=0.3)
        fig.tight_layout()
        fig.savefig(plot, dpi=120)
    return summary


def report_example(directory, log, variables, seconds):
    """run_example's numbers and plot: footing.json, footing.png."""
    footing([os.path.join(directory, 'footing.dat')], [f"d = {100 * float(variables['d']):g} cm"],
            phi=float(variables['phi']), plot=os.path.join(directory, 'footing.png'),
            json_path=os.path.join(directory, 'footing.json'))


def add_arguments(p):
    p.add_argument('--dat', action='append', required=True)
    p.add_argument('--label', action='append')
    p.add_argument('--phi', type=float, default=30.0)
    p.add_argument('--gamma', type=float, default=GAMMA)
    p.add_argument('--width', type=float, default=WIDTH)
    p.add_argument('--plot')
    p.add_argument('--json')


def main(args):
    footing(args.dat, args.label, args.phi, args.gamma, args.width, args.plot, args.json)
