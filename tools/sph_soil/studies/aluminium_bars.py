"""Aluminium-bar collapse (examples/aluminium_bars) against Bui et al. 2008's measurements.

Reads the LAMMPS dumps of a finished run (dump.initial: id type x y; dump.final:
id type x y ...), computes
  - the final free surface: the 0.5 level of the SPH volume fraction of the particles
    (sph_soil.analysis; particle volume d^2, h = 1.2 d as set by the example), i.e. the
    surface of the continuum the particles stand for, and its RMS difference from the measured
    surface at the measured x;
  - the runout: the furthest x at which that surface is higher than 2 mm;
  - the same two from the particles' tops (at each x the highest centre within one spacing,
    + d/2), which also count single particles that have left the body: *_particle_top;
  - the failure line: the upper boundary of the soil that moved less than 1.5 mm (per column
    of width d, the top of the unmoved particles), and its angle from a straight-line fit
    over the columns where the boundary lies between 5% and 95% of the initial height;
prints a JSON summary and writes a PNG plot of simulation vs experiment.

  python3 -m sph_soil aluminium-bars --dir examples/aluminium_bars [--spacing 0.002]
"""
import math
import os
import sys

import numpy as np

from .. import analysis, logs, paths, report
from ..dumps import read_dump

COMMAND = 'aluminium-bars'
EXPERIMENT = os.path.join(paths.example_dir('aluminium_bars'), 'experiment')
RUNOUT_THRESHOLD = 0.002    # m: the height above which the surface counts for the runout


def read_csv(path):
    return np.loadtxt(path, delimiter=',', skiprows=1)


def read_experiment(directory=EXPERIMENT):
    """The measured surface and failure line (surface.csv, failure.csv: x, y)."""
    return read_csv(os.path.join(directory, 'surface.csv')), read_csv(os.path.join(directory, 'failure.csv'))


def initial_and_final(directory):
    """Initial and final positions of the same particles (dump.initial, dump.final), by id,
    and the spacing of the initial lattice."""
    initial = read_dump(os.path.join(directory, 'dump.initial'))
    final = read_dump(os.path.join(directory, 'dump.final'))
    order0 = np.argsort(initial['id'])
    order1 = np.argsort(final['id'])
    if not np.array_equal(initial['id'][order0], final['id'][order1]):
        sys.exit(f'aluminium-bars: dump.initial and dump.final of {directory} hold different particles')
    x0, y0 = initial['x'][order0], initial['y'][order0]
    x1, y1 = final['x'][order1], final['y'][order1]
    spacing = float(np.min(np.diff(np.unique(np.round(x0, 9)))))
    return x0, y0, x1, y1, spacing


def collapse_measures(directory, height, runout_threshold, moved, spacing=None):
    """Surface, runout and failure line of a collapse run (dump.initial, dump.final in
    directory): the summary's 'particles', 'spacing_m', 'runout_m', 'runout_particle_top_m',
    'failure_angle_deg', and the arrays to plot ('x', 'y': final positions, 'grid',
    'grid_surface': the simulated surface, 'failure_x', 'failure_y': the failure line)."""
    x0, y0, x1, y1, lattice = initial_and_final(directory)
    spacing = spacing or lattice
    volume, h = spacing * spacing, 1.2 * spacing
    run, grid, grid_surface = analysis.runout(x1, y1, volume, h, runout_threshold, spacing)
    has_moved = np.hypot(x1 - x0, y1 - y0) >= moved
    fx, fy, angle = analysis.failure_line(x0, y0, has_moved, spacing, height)
    summary = {'particles': int(len(x1)), 'spacing_m': spacing, 'runout_m': round(run, 5),
               'runout_particle_top_m': round(analysis.runout_particle_top(x1, y1, spacing, runout_threshold), 5),
               'failure_angle_deg': round(angle, 2)}
    return {'summary': summary, 'x': x1, 'y': y1, 'volume': volume, 'h': h, 'grid': grid,
            'grid_surface': grid_surface, 'failure_x': fx, 'failure_y': fy}


def measure(directory, surface_exp, failure_exp, spacing=None, moved=0.0015, height=0.1):
    """The measures of one run (dump.initial, dump.final in directory) against the experiment:
    {'summary': the JSON summary, 'x', 'y': final positions, 'grid', 'grid_surface': the
    simulated surface, 'failure_x', 'failure_y': the failure line}."""
    m = collapse_measures(directory, height, RUNOUT_THRESHOLD, moved, spacing)
    s, x1, y1 = m['summary'], m['x'], m['y']
    spacing = s['spacing_m']
    sim_surface = analysis.surface_height(x1, y1, m['volume'], m['h'], surface_exp[:, 0])
    surface_rms = float(np.sqrt(np.mean((sim_surface - surface_exp[:, 1]) ** 2)))
    top_surface = analysis.particle_top(x1, y1, surface_exp[:, 0], spacing)
    top_rms = float(np.sqrt(np.mean((top_surface - surface_exp[:, 1]) ** 2)))
    exp_slope = np.polyfit(failure_exp[:, 0], failure_exp[:, 1], 1)[0]
    exp_angle = math.degrees(math.atan(-exp_slope))
    m['summary'] = {
        'particles': s['particles'],
        'spacing_m': spacing,
        'surface_rms_m': round(surface_rms, 6),
        'runout_m': s['runout_m'],
        'runout_experiment_m': 0.43,
        'surface_rms_particle_top_m': round(top_rms, 6),
        'runout_particle_top_m': s['runout_particle_top_m'],
        'failure_angle_deg': s['failure_angle_deg'],
        'failure_angle_experiment_deg': round(exp_angle, 2),
    }
    return m


def plot(m, surface_exp, failure_exp, out):
    summary = m['summary']
    x1, y1, run, grid, grid_surface = m['x'], m['y'], summary['runout_m'], m['grid'], m['grid_surface']
    fx, fy, angle, exp_angle = m['failure_x'], m['failure_y'], summary['failure_angle_deg'], \
        summary['failure_angle_experiment_deg']
    spacing, surface_rms = summary['spacing_m'], summary['surface_rms_m']
    plt = report.pyplot()
    fig, ax = plt.subplots(figsize=(9, 3.6))
    ax.scatter(x1, y1, s=1.0, c='0.75', label='particles (final)', rasterized=True)
    ax.plot(grid, grid_surface, 'b-', lw=1.2, label='simulated surface (volume fraction 0.5)')
    ax.axvline(run, color='b', ls=':', lw=0.8)
    ax.plot(surface_exp[:, 0], surface_exp[:, 1], 'ko', ms=4, label='measured surface')
    ax.plot(fx, fy, 'r-', lw=1.2, label=f'simulated failure line ({angle:.1f} deg)')
    ax.plot(failure_exp[:, 0], failure_exp[:, 1], 'rs', ms=4, mfc='none',
            label=f'measured failure line ({exp_angle:.1f} deg)')
    ax.set_xlabel('x (m)')
    ax.set_ylabel('height (m)')
    ax.set_aspect('equal')
    ax.set_xlim(0, max(0.5, x1.max() + 0.01))
    ax.set_ylim(0, 0.11)
    ax.set_title(f'Aluminium bars, d = {spacing * 1000:.3g} mm: surface RMS {surface_rms * 1000:.1f} mm, '
                 f'runout {run:.3f} m (measured 0.43 m)')
    ax.legend(fontsize=7, loc='upper right')
    fig.tight_layout()
    fig.savefig(out, dpi=150)
    print(f'aluminium-bars: plot written to {out}', file=sys.stderr)


def validate(directory, json_path=None, plot_path=None, wall_seconds=None, experiment=None, spacing=None,
             moved=0.0015, height=0.1):
    surface_exp, failure_exp = read_experiment(experiment or os.path.join(directory, 'experiment'))
    m = measure(directory, surface_exp, failure_exp, spacing, moved, height)
    m['summary']['wall_seconds'] = wall_seconds if wall_seconds is not None else logs.wall_seconds(directory)
    report.write_json(m['summary'], json_path, indent=2)
    plot(m, surface_exp, failure_exp, plot_path or os.path.join(directory, 'validation.png'))
    return m['summary']


def report_example(directory, log, variables, seconds):
    """run_example's numbers and plot: validation.json, validation.png."""
    validate(directory, os.path.join(directory, 'validation.json'), os.path.join(directory, 'validation.png'),
             wall_seconds=seconds)


def add_arguments(p):
    p.add_argument('--dir', default='examples/aluminium_bars', help='directory with dump.initial, dump.final')
    p.add_argument('--spacing', type=float, default=None, help='particle spacing d (default: from the dump)')
    p.add_argument('--experiment', default=None, help='directory with surface.csv and failure.csv')
    p.add_argument('--moved', type=float, default=0.0015, help='displacement that counts as moved (m)')
    p.add_argument('--height', type=float, default=0.1, help='initial height of the block (m)')
    p.add_argument('--json', default=None, help='write the summary here too')
    p.add_argument('--plot', default=None, help='PNG plot (default: <dir>/validation.png)')
    p.add_argument('--wall-seconds', type=float, default=None, help='wall time of the run')


def main(a):
    validate(a.dir, a.json, a.plot, a.wall_seconds, a.experiment, a.spacing, a.moved, a.height)
