"""The aluminium-bar block released by a lifted gate (examples/gate) against the instantaneous
release (examples/aluminium_bars) and the measured surface of Bui et al. 2008.

    python3 -m sph_soil gate                        # 2 mm, 0.25 0.5 1 2 m/s (~6 min, 2 cores)
    python3 -m sph_soil gate --speeds 0.5 1 --np 4 --out /tmp/gate -- -var gate_slip noslip
    python3 -m sph_soil gate --plot-only            # only the plot, from the runs in --out
    python3 -m sph_soil gate --runs [LABEL=]DIR ... [--json gate.json] [--plot gate.png] [--experiment DIR]

Runs in.gate at each speed and in.aluminium_bars, each in its own directory under --out (not in
the source tree; extra lmp arguments after -- go to every run), then compares them (gate.png,
gate.json in examples/gate) and copies the output of the default speed (1 m/s: gate_force.dat,
log.gate.run, the frames at 0.06 s and 0.11 s after the start of the lift and the final one)
into examples/gate. One run at a time. --runs compares finished runs without running any.

Each DIR is a finished run: of in.gate (it holds gate_force.dat; the lift speed, hold time and
the gate's slip condition are read from the "gate: lift at ..." line of its log) or of
in.aluminium_bars (no gate_force.dat: the instantaneous release). It needs dump.initial and
dump.final.

For each run it reports, with the functions of the aluminium-bars study and
sph_soil.analysis (the same definitions as that study's JSON):
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
import glob
import math
import os
import re
import shutil
import sys

import numpy as np

from .. import logs, paths, report, runner
from ..dumps import read_ave_time
from . import aluminium_bars

COMMAND = 'gate'
HERE = paths.example_dir('gate')
RHO0, G, H, PHI = 2650.0, 9.81, 0.1, 19.8     # examples/gate and examples/aluminium_bars
SPEEDS = ['0.25', '0.5', '1', '2']
DEFAULT_SPEED = '1'     # in.gate's: its output is copied into examples/gate


def gate_settings(directory):
    """(speed, hold, slip) from the "gate: lift at ..." line that in.gate prints."""
    newest = logs.run_logs(directory)
    m = logs.Log(newest[0]).search(r'^gate: lift at (\S+) m/s after (\S+) s, (.+?) gate;', re.M) if newest else None
    if not m:
        sys.exit(f'gate: no "gate: lift at" line in the log of {directory}')
    return float(m.group(1)), float(m.group(2)), m.group(3)


def read_force(path):
    """gate_force.dat: time, lift, Fx, Fy (fix ave/time rows after the step)."""
    data = read_ave_time(path)
    return data[:, 1], data[:, 2], data[:, 3], data[:, 4]


def surface_measures(directory, surface_exp, failure_exp):
    """The measures of the aluminium-bars study for one run, and the surface to plot."""
    m = aluminium_bars.measure(directory, surface_exp, failure_exp, height=H)
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


def compare(runs, experiment=aluminium_bars.EXPERIMENT, json_path=None, plot_path=None):
    """The table of finished runs ([(label or None, directory)]) and its plot."""
    surface_exp, failure_exp = aluminium_bars.read_experiment(experiment)
    k0 = 1.0 - math.sin(math.radians(PHI))
    f0 = 0.5 * k0 * RHO0 * G * H * H
    table = {'K0': round(k0, 6), 'half_K0_gamma_H2_N_per_m': round(f0, 3),
             'experiment': {'runout_m': 0.43}, 'runs': []}
    curves = []
    for label, directory in runs:
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
        row['wall_seconds'] = logs.wall_seconds(directory)
        table['runs'].append(row)
        curves.append((row, grid, grid_surface, series if gate else None))

    report.write_json(table, json_path, indent=1)
    if not plot_path:
        return
    plt = report.pyplot()
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
    fig.savefig(plot_path, dpi=120)
    print(f'gate: plot written to {plot_path}', file=sys.stderr)


def run_speeds(lmp, np, speeds, out, extra):
    """in.gate at each speed and in.aluminium_bars, each in a directory of its own under `out`;
    returns the (label, directory) of every run."""
    runs = []
    for speed in speeds:
        runs.append((f'{speed} m/s', os.path.join(out, f'speed_{speed}')))
        if lmp:
            done = lmp.run(os.path.join(HERE, 'in.gate'), runs[-1][1], np=np, variables=[('speed', speed)],
                           log='log.gate.run', extra=extra, check=True)
            print(f'gate: {runs[-1][1]} done in {done.seconds:.0f} s on {np} ranks', flush=True)
    runs.append(('instantaneous', os.path.join(out, 'instantaneous')))
    if lmp:
        done = lmp.run(paths.example_input('aluminium_bars'), runs[-1][1], np=np, log='log.aluminium_bars.run',
                       extra=extra, check=True)
        print(f'gate: {runs[-1][1]} done in {done.seconds:.0f} s on {np} ranks', flush=True)
    return runs


def copy_default_speed(out):
    """The default speed's output next to the input: gate_force.dat, log.gate.run, and the frames
    at 0.06 s and 0.11 s after the start of the lift and the last one (not t = 0)."""
    default = os.path.join(out, f'speed_{DEFAULT_SPEED}')
    if not os.path.exists(os.path.join(default, 'gate_force.dat')):
        return
    for name in ('gate_force.dat', 'log.gate.run'):
        shutil.copy(os.path.join(default, name), HERE)
    for old in glob.glob(os.path.join(HERE, 'frame.*.png')):
        os.remove(old)
    frames = sorted(glob.glob(os.path.join(default, 'frame.*.png')))
    for frame in frames[1:3] + frames[-1:]:
        shutil.copy(frame, HERE)


def report_example(directory, log, variables, seconds):
    """run_example's numbers and plot of the one lift (in.gate's speed): gate.json, gate.png."""
    compare([(None, directory)], json_path=os.path.join(directory, 'gate.json'),
            plot_path=os.path.join(directory, 'gate.png'))


def add_arguments(p):
    runner.add_arguments(p)
    p.add_argument('--speeds', nargs='+', default=SPEEDS, help='lift speeds in m/s (default: %(default)s)')
    p.add_argument('--out', default='/tmp/sph_soil_gate', help='where the runs go (default: %(default)s)')
    p.add_argument('--plot-only', action='store_true', help='run nothing: compare the runs in --out')
    p.add_argument('--runs', nargs='+', metavar='[LABEL=]DIR', default=None,
                   help='compare these finished runs of in.gate or in.aluminium_bars instead (no runs)')
    p.add_argument('--experiment', default=aluminium_bars.EXPERIMENT,
                   help='directory with surface.csv (default: examples/aluminium_bars/experiment)')
    p.add_argument('--json', default=None, help='write the table here (default: examples/gate/gate.json, '
                   'none with --runs)')
    p.add_argument('--plot', default=None, help='PNG plot (default: examples/gate/gate.png, none with --runs)')
    p.add_argument('extra', nargs='*', help='extra lmp arguments for every run (after --)')


def main(a):
    if a.runs:
        runs = [tuple(arg.split('=', 1)) if '=' in arg else (None, arg) for arg in a.runs]
        compare(runs, a.experiment, a.json, a.plot)
        return
    lmp = None if a.plot_only else runner.from_arguments(a)
    runs = run_speeds(lmp, a.np, a.speeds, a.out, a.extra)
    compare(runs, a.experiment, a.json or os.path.join(HERE, 'gate.json'), a.plot or os.path.join(HERE, 'gate.png'))
    copy_default_speed(a.out)
    print(f'gate: gate.png, gate.json and the {DEFAULT_SPEED} m/s run\'s output in {HERE}; runs in {a.out}')
