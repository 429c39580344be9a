#!/usr/bin/python3
"""Earth pressure on the retaining wall of examples/retaining_wall against Rankine.

    tools/plot_retaining_wall.py [--phi 30] [--height 1] [--json out.json] [--plot out.png]
                                 LABEL=wall_force.dat [LABEL=wall_force.dat ...]

Reads the fix ave/time files of in.retaining_wall (time, wall displacement, force, K = force /
(0.5 gamma H^2)) and reports for each run
  - K_at_rest: the mean K while the wall is at rest (displacement 0), against K0 = 1 - sin(phi);
  - K_active: the mean K over the last 10% of the wall's travel, against Rankine's
    Ka = (1 - sin phi)/(1 + sin phi);
prints them as JSON and plots K against the displacement over H.
"""
import argparse
import json
import math

import numpy as np


def read(path):
    rows = [list(map(float, line.split())) for line in open(path) if line.strip() and not line.startswith('#')]
    data = np.array(rows)
    return data[:, 2], data[:, 4]    # displacement, K


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument('runs', nargs='+', help='LABEL=FILE')
    p.add_argument('--phi', type=float, default=30.0)
    p.add_argument('--height', type=float, default=1.0)
    p.add_argument('--json')
    p.add_argument('--plot')
    a = p.parse_args()
    s = math.sin(math.radians(a.phi))
    k0, ka = 1.0 - s, (1.0 - s) / (1.0 + s)
    result = {'phi_deg': a.phi, 'K0': k0, 'Ka': ka, 'runs': {}}
    curves = []
    for run in a.runs:
        label, path = run.rsplit('=', 1) if '=' in run else (run, run)
        shift, k = read(path)
        rest = k[shift <= 0.0]
        moved = shift > 0.0
        travel = shift.max()
        last = k[shift >= 0.9 * travel] if travel > 0 else k[-1:]
        r = {'K_at_rest': float(rest.mean()) if len(rest) else None,
             'K_active': float(last.mean()),
             'at_rest_over_K0': float(rest.mean() / k0) if len(rest) else None,
             'active_over_Ka': float(last.mean() / ka),
             'travel_over_H': float(travel / a.height)}
        result['runs'][label] = r
        curves.append((label, shift[moved] / a.height, k[moved], r))
    print(json.dumps(result, indent=1))
    if a.json:
        json.dump(result, open(a.json, 'w'), indent=1)
    if a.plot:
        import matplotlib
        matplotlib.use('Agg')
        import matplotlib.pyplot as plt
        fig, ax = plt.subplots(figsize=(7, 4.2))
        for label, x, k, r in curves:
            ax.plot(100 * x, k, label=f"{label}: K at rest {r['K_at_rest']:.3f}, active {r['K_active']:.3f}")
        ax.axhline(k0, color='grey', ls='--')
        ax.axhline(ka, color='black', ls='--')
        ax.text(0.02, k0 + 0.005, f'K0 = 1 - sin(phi) = {k0:.3f}', color='grey')
        ax.text(0.02, ka - 0.02, f'Rankine Ka = {ka:.3f}', color='black')
        ax.set_xlabel('wall displacement / H (%)')
        ax.set_ylabel('K = horizontal force / (0.5 gamma H^2)')
        ax.set_title(f'Smooth retaining wall moving away from the soil, phi = {a.phi:g} deg')
        ax.set_ylim(0.25, 0.6)
        ax.legend(fontsize=8)
        fig.tight_layout()
        fig.savefig(a.plot, dpi=110)
        print(f'plot written to {a.plot}')


if __name__ == '__main__':
    main()
