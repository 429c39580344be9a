"""Earth pressure on the retaining wall of examples/retaining_wall against Rankine and Coulomb.

    python3 -m sph_soil retaining-wall [--phi 30] [--height 1] [--json out.json] [--plot out.png]
                                       LABEL=wall_force.dat[@DELTA] [LABEL=wall_force.dat[@DELTA] ...]

Reads the fix ave/time files of in.retaining_wall (time, wall displacement, force, K = force /
(0.5 gamma H^2)); DELTA is the wall's friction angle in degrees (-var delta of the example,
default 0: a smooth wall). A run whose wall moved away from the soil is active, one whose wall
was pushed into it passive. For each run it reports
  - K_at_rest: the mean K while the wall is at rest (displacement 0), against K0 = 1 - sin(phi);
  - K_final: the mean K over the last 10% of the wall's travel, against the limit value: for a
    smooth wall Rankine's Ka = (1 - sin phi)/(1 + sin phi) or Kp = 1/Ka, for a rough one pushed
    into the soil Lancellotta's (2002) lower bound (lancellotta()), for a rough one moved away
    the horizontal part K cos(delta) of Coulomb's
        K = cos^2 phi / (cos delta (1 + s sqrt(sin(phi + delta) sin phi / cos delta))^2)
    with s = +1 active, -1 passive (vertical wall, horizontal surface);
prints them as JSON and plots K against the wall's displacement over H.
"""
import math
import os

import numpy as np

from .. import report
from ..dumps import read_ave_time

COMMAND = 'retaining-wall'


def read(path):
    """displacement, K and the vertical force's K (None in files without it)."""
    data = read_ave_time(path)
    return data[:, 2], data[:, 4], (data[:, 6] if data.shape[1] > 6 else None)


def lancellotta(phi_deg, delta_deg):
    """Lancellotta's (2002, Geotechnique 52:617) lower bound of the passive coefficient of the
    normal (for a vertical wall: horizontal) force, vertical wall, horizontal backfill:
        K_p = cos(delta) / (1 - sin(phi)) (cos(delta) + sqrt(sin^2 phi - sin^2 delta)) exp(2 theta tan phi),
        2 theta = asin(sin(delta) / sin(phi)) + delta
    (4.63 at phi = 30, delta = 20; Rankine's Kp for delta = 0)."""
    phi, delta = math.radians(phi_deg), math.radians(delta_deg)
    two_theta = math.asin(math.sin(delta) / math.sin(phi)) + delta
    return (math.cos(delta) / (1.0 - math.sin(phi)) *
            (math.cos(delta) + math.sqrt(math.sin(phi) ** 2 - math.sin(delta) ** 2)) *
            math.exp(two_theta * math.tan(phi)))


def limit(phi_deg, delta_deg, passive):
    """Horizontal earth pressure coefficient at failure: Rankine (delta = 0) or Coulomb."""
    phi, delta = math.radians(phi_deg), math.radians(delta_deg)
    root = math.sqrt(math.sin(phi + delta) * math.sin(phi) / math.cos(delta))
    k = math.cos(phi) ** 2 / (math.cos(delta) * (1.0 + (-root if passive else root)) ** 2)
    return k * math.cos(delta)


def earth_pressure(runs, phi=30.0, height=1.0, json_path=None, plot=None, echo=True):
    """runs: LABEL=FILE[@DELTA] each; echo prints the JSON."""
    k0 = 1.0 - math.sin(math.radians(phi))
    result = {'phi_deg': phi, 'K0': k0, 'Ka': limit(phi, 0.0, False), 'Kp': limit(phi, 0.0, True),
              'runs': {}}
    curves = []
    for run in runs:
        label, path = run.rsplit('=', 1) if '=' in run else (run, run)
        delta = 0.0
        if '@' in path:
            path, delta = path.rsplit('@', 1)
            delta = float(delta)
        shift, k, kv = read(path)
        travel = shift[np.argmax(np.abs(shift))]
        passive = travel < 0.0
        rest = k[shift == 0.0]
        final = k[np.abs(shift) >= 0.9 * abs(travel)] if travel != 0.0 else k[-1:]
        # the reference: Rankine for a smooth wall, Coulomb's active value for a rough one, and
        # Lancellotta's lower bound for a rough passive wall (Coulomb's passive value is far
        # too high there)
        rough_passive = passive and delta > 0.0
        reference = lancellotta(phi, delta) if rough_passive else limit(phi, delta, passive)
        name = ('Lancellotta' if rough_passive else 'Rankine' if delta == 0.0 else 'Coulomb')
        r = {'wall': 'passive' if passive else 'active', 'delta_deg': delta,
             'K_at_rest': float(rest.mean()) if len(rest) else None,
             'at_rest_over_K0': float(rest.mean() / k0) if len(rest) else None,
             'K_final': float(final.mean()),
             'K_limit': reference,
             'K_coulomb': limit(phi, delta, passive),
             'limit': name + (' Kp' if passive else ' Ka'),
             'final_over_limit': float(final.mean() / reference),
             'travel_over_H': float(abs(travel) / height)}
        # the force settles: its swing (max - min over mean) over the last 20% of the travel
        last = k[np.abs(shift) >= 0.8 * abs(travel)] if travel != 0.0 else k[-1:]
        r['swing_last_20_percent'] = float((last.max() - last.min()) / abs(last.mean()))
        if kv is not None:
            tail = np.abs(shift) >= 0.9 * abs(travel)
            r['vertical_over_horizontal'] = float(np.mean(np.abs(kv[tail]) / np.abs(k[tail])))
            r['tan_delta'] = math.tan(math.radians(delta))
        if passive and delta > 0.0:
            r['lancellotta_lower_bound'] = lancellotta(phi, delta)
            r['final_over_lancellotta'] = float(final.mean() / r['lancellotta_lower_bound'])
        result['runs'][label] = r
        moved = shift != 0.0
        curves.append((label, np.abs(shift[moved]) / height, k[moved], r))
    report.write_json(result, json_path, indent=1, end='', echo=echo)
    if plot:
        plt = report.pyplot()
        kinds = [kind for kind in ('active', 'passive') if any(c[3]['wall'] == kind for c in curves)]
        fig, axes = plt.subplots(1, len(kinds), figsize=(6.5 * len(kinds), 4.2), squeeze=False)
        for ax, kind in zip(axes[0], kinds):
            limits = set()
            for label, x, k, r in curves:
                if r['wall'] != kind:
                    continue
                line, = ax.plot(100 * x, k, label=f"{label}: {r['K_final']:.3f} = {r['final_over_limit']:.3f} x {r['limit']}")
                if r['limit'] + str(r['delta_deg']) not in limits:
                    limits.add(r['limit'] + str(r['delta_deg']))
                    ax.axhline(r['K_limit'], color=line.get_color(), ls='--', lw=0.8)
                    ax.text(0.1, r['K_limit'], f"{r['limit']}" + (f", delta {r['delta_deg']:g}" if r['delta_deg'] else '')
                            + f" = {r['K_limit']:.3f}", fontsize=7, va='bottom')
            ax.axhline(k0, color='grey', ls=':')
            ax.text(0.1, k0, f'K0 = 1 - sin(phi) = {k0:.3f}', color='grey', fontsize=7, va='bottom')
            ax.set_xlabel('wall displacement / H (%)')
            ax.set_ylabel('K = horizontal force / (0.5 gamma H^2)')
            ax.set_title(f"{kind.capitalize()} earth pressure, phi = {phi:g} deg", fontsize=10)
            ax.legend(fontsize=7, loc='upper right' if kind == 'active' else 'lower right')
            if kind == 'active':
                ax.set_ylim(0.2, 0.6)
        fig.tight_layout()
        fig.savefig(plot, dpi=110)
        print(f'plot written to {plot}')

    return result


def report_example(directory, log, variables, seconds):
    """run_example's numbers and plot: retaining_wall.json, retaining_wall.png."""
    label = f"d = {100 * float(variables['d']):g} cm"
    earth_pressure([f"{label}={os.path.join(directory, 'wall_force.dat')}@{variables['delta']}"],
                   phi=float(variables['phi']), json_path=os.path.join(directory, 'retaining_wall.json'),
                   plot=os.path.join(directory, 'retaining_wall.png'))


def add_arguments(p):
    p.add_argument('runs', nargs='+', help='LABEL=FILE[@DELTA]')
    p.add_argument('--phi', type=float, default=30.0)
    p.add_argument('--height', type=float, default=1.0)
    p.add_argument('--json')
    p.add_argument('--plot')


def main(a):
    earth_pressure(a.runs, a.phi, a.height, a.json, a.plot)
