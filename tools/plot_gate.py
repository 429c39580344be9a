#!/usr/bin/python3
"""The aluminium-bar block released by a lifted gate (examples/gate) against the instantaneous
release (examples/aluminium_bars) and the measured surface of Bui et al. 2008.

    tools/plot_gate.py [--json gate.json] [--plot gate.png] [--experiment DIR] [LABEL=]DIR ...

Each DIR is a finished run: of in.gate (it holds gate_force.dat; the lift speed, hold time and
the gate's slip condition are read from the "gate: lift at ..." line of its log) or of
in.aluminium_bars (no gate_force.dat: the instantaneous release). It needs dump.initial and
dump.final. The script runs no LAMMPS (examples/gate/run_speeds.sh runs the runs, then this).

For each run it reports, with the functions of tools/validate_aluminium_bars.py and
tools/sph_analysis.py (the same definitions as that script's JSON):
  - surface_rms_m, runout_m, failure_angle_deg (and the particle-top surface RMS and runout);
  - for gate runs, from gate_force.dat (instantaneous values every 1 ms): the at-rest force,
    the mean horizontal force of the soil on the gate while the gate has not moved (at t = 0
    only with the default hold 0), against 0.5 K0 gamma H^2 (K0 = 1 - sin phi); the peak
    horizontal and the largest vertical force (|Fy|); the time after the start of the lift
    from which the gate carries no force any more (the soil has dropped below its foot), and
    the lift then;
prints a JSON table and writes a plot: the final surfaces beside the measured one (top), the
gate's horizontal force against the time since the start of the lift (bottom).
"""
import argparse
import json
import math
import os
import re
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import validate_aluminium_bars as validate  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
RHO0, G, H, PHI = 2650.0, 9.81, 0.1, 19.8     # examples/gate and examples/aluminium_bars


def newest_log(directory):
    logs = [os.path.join(directory, n) for n in os.listdir(directory)
            if n.startswith('log.') and '.short.' not in n]
    return max(logs, key=os.path.getmtime) if logs else None


def gate_settings(directory):
    """(speed, hold, slip) from the "gate: lift at ..." line that in.gate prints."""
    log = newest_log(directory)
    text = open(log).read() if log else ''
    m = re.search(r'^gate: lift at (\S+) m/s after (\S+) s, (.+?) gate;', text, re.M)
    if not m:
        sys.exit(f'plot_gate: no "gate: lift at" line in the log of {directory}')
    return float(m.group(1)), float(m.group(2)), m.group(3)


def read_force(path):
    """gate_force.dat: time, lift, Fx, Fy (fix ave/time rows after the step)."""
    rows = [line.split() for line in open(path) if line.strip() and not line.startswith('#')]
    data = np.array(rows, dtype=float)
    return data[:, 1], data[:, 2], data[:, 3], data[:, 4]


def surface_measures(directory, surface_exp, failure_exp):
    """The measures of tools/validate_aluminium_bars.py for one run, and the surface to plot."""
    m = validate.measure(directory, surface_exp, failure_exp, height=H)
    keys = ('particles', 'spacing_m', 'surface_rms_m', 'runout_m', 'failure_angle_deg',
            'surface_rms_particle_top_m', 'runout_particle_top_m')
    return {k: m['summary'][k] for k in keys}, m['grid'], m['grid_surface']


def force_measures(directory, hold, f0):
    t, lift, fx, fy = read_force(os.path.join(directory, 'gate_force.dat'))
    rest = lift <= 1.0e-9
    loaded = np.nonzero(np.abs(fx) + np.abs(fy) > 0.0)[0]
    clear = None
    if len(loaded) and loaded[-1] + 1 < len(t):
        clear = loaded[-1] + 1     # from this row on the gate carries no force
    at_rest = float(fx[rest].mean()) if rest.any() else None
    k = int(np.argmax(fx))
    result = {
        'at_rest_force_N_per_m': round(at_rest, 3) if at_rest is not None else None,
        'at_rest_samples': int(rest.sum()),
        'at_rest_over_half_K0_gamma_H2': round(at_rest / f0, 4) if at_rest is not None else None,
        'at_rest_vertical_force_N_per_m': round(float(fy[rest].mean()), 3) if rest.any() else None,
        'peak_force_x_N_per_m': round(float(fx[k]), 3),
        'peak_force_x_time_s': round(float(t[k] - hold), 4),
        'peak_force_x_over_half_K0_gamma_H2': round(float(fx[k]) / f0, 4),
        'max_abs_force_y_N_per_m': round(float(np.abs(fy).max()), 3),
        'gate_clear_time_s': round(float(t[clear] - hold), 4) if clear is not None else None,
        'gate_clear_lift_m': round(float(lift[clear]), 4) if clear is not None else None,
    }
    return result, (t - hold, lift, fx, fy)


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument('runs', nargs='+', help='[LABEL=]DIR of a run of in.gate or in.aluminium_bars')
    p.add_argument('--experiment', default=os.path.join(ROOT, 'examples', 'aluminium_bars', 'experiment'),
                   help='directory with surface.csv (default: examples/aluminium_bars/experiment)')
    p.add_argument('--json', default=None, help='write the table here too')
    p.add_argument('--plot', default=None, help='PNG plot (default: none)')
    a = p.parse_args()

    surface_exp = validate.read_csv(os.path.join(a.experiment, 'surface.csv'))
    failure_exp = validate.read_csv(os.path.join(a.experiment, 'failure.csv'))
    k0 = 1.0 - math.sin(math.radians(PHI))
    f0 = 0.5 * k0 * RHO0 * G * H * H
    table = {'K0': round(k0, 6), 'half_K0_gamma_H2_N_per_m': round(f0, 3),
             'experiment': {'runout_m': 0.43}, 'runs': []}
    curves = []
    for arg in a.runs:
        label, directory = arg.split('=', 1) if '=' in arg else (None, arg)
        gate = os.path.exists(os.path.join(directory, 'gate_force.dat'))
        row = {}
        if gate:
            speed, hold, slip = gate_settings(directory)
            row.update({'run': label or f'gate {speed:g} m/s', 'speed_m_per_s': speed,
                        'hold_s': hold, 'gate_slip': slip})
        else:
            row.update({'run': label or 'instantaneous', 'speed_m_per_s': None})
        measures, grid, grid_surface = surface_measures(directory, surface_exp, failure_exp)
        row.update(measures)
        if gate:
            forces, series = force_measures(directory, hold, f0)
            row.update(forces)
        row['wall_seconds'] = validate.wall_seconds(directory)
        table['runs'].append(row)
        curves.append((row, grid, grid_surface, series if gate else None))

    text = json.dumps(table, indent=1)
    print(text)
    if a.json:
        with open(a.json, 'w') as f:
            f.write(text + '\n')
    if not a.plot:
        return

    import matplotlib
    matplotlib.use('Agg')
    import matplotlib.pyplot as plt
    fig, (top, bottom) = plt.subplots(2, 1, figsize=(9, 7.5), gridspec_kw={'height_ratios': [1.0, 1.1]})
    colours = plt.cm.viridis(np.linspace(0.0, 0.85, max(1, sum(c[3] is not None for c in curves))))
    k = 0
    for row, grid, grid_surface, series in curves:
        if series is None:
            style = dict(color='r', lw=1.6, ls='--')
        else:
            style = dict(color=colours[k], lw=1.2)
            k += 1
        top.plot(grid, grid_surface, label=f"{row['run']}: RMS {row['surface_rms_m'] * 1000:.1f} mm, "
                 f"runout {row['runout_m']:.3f} m, {row['failure_angle_deg']:.1f} deg", **style)
        if series is not None:
            t, lift, fx, fy = series
            bottom.plot(t, fx, label=f"{row['run']}: Fx", **style)
            bottom.plot(t, fy, ls=':', color=style['color'], lw=1.0)
    top.plot(surface_exp[:, 0], surface_exp[:, 1], 'ko', ms=4, label='measured surface (Bui 2008)')
    top.axvline(0.43, color='k', ls=':', lw=0.8)
    top.set_xlabel('x (m)')
    top.set_ylabel('final surface (m)')
    top.set_xlim(0.0, 0.5)
    top.set_ylim(0.0, 0.11)
    top.set_title('Aluminium bars released by a lifted gate and instantaneously: final surfaces')
    top.legend(fontsize=7, loc='upper right')
    bottom.axhline(f0, color='grey', ls='--', lw=0.8)
    bottom.annotate(f"0.5 K0 gamma H^2 = {f0:.1f} N/m", (0.5, f0 + 1.5), xycoords=('axes fraction', 'data'),
                    color='grey', fontsize=8)
    bottom.set_xlabel('time since the start of the lift (s)')
    bottom.set_ylabel('force of the soil on the gate (N/m)')
    bottom.set_title('Horizontal force Fx (solid) and vertical force Fy (dotted) on the gate')
    tmax = max((c[3][0][np.nonzero(np.abs(c[3][2]) > 0)[0][-1]] for c in curves
                if c[3] is not None and (np.abs(c[3][2]) > 0).any()), default=0.5)
    bottom.set_xlim(min(0.0, min((c[3][0].min() for c in curves if c[3] is not None), default=0.0)),
                    1.15 * tmax)
    bottom.set_ylim(top=1.12 * f0)
    bottom.legend(fontsize=7, loc='center right')
    fig.tight_layout()
    fig.savefig(a.plot, dpi=120)
    print(f'plot_gate: plot written to {a.plot}', file=sys.stderr)


if __name__ == '__main__':
    main()
