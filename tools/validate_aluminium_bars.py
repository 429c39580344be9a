#!/usr/bin/python3
"""Compare a simulated aluminium-bar collapse with Bui et al. 2008's measurements.

Reads the LAMMPS dumps of examples/aluminium_bars (dump.initial: id type x y; dump.final:
id type x y ...), computes
  - the final free surface: the 0.5 level of the SPH volume fraction of the particles
    (tools/sph_analysis.py; particle volume d^2, h = 1.2 d as set by the example), i.e. the
    surface of the continuum the particles stand for, and its RMS difference from the measured
    surface at the measured x;
  - the runout: the furthest x at which that surface is higher than 2 mm;
  - the same two from the particles' tops (at each x the highest centre within one spacing,
    + d/2), which also count single particles that have left the body: *_particle_top;
  - the failure line: the upper boundary of the soil that moved less than 1.5 mm (per column
    of width d, the top of the unmoved particles), and its angle from a straight-line fit
    over the columns where the boundary lies between 5% and 95% of the initial height;
prints a JSON summary and writes a PNG plot of simulation vs experiment.

  tools/validate_aluminium_bars.py --dir examples/aluminium_bars [--spacing 0.002]
"""
import argparse
import json
import math
import os
import re
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import sph_analysis  # noqa: E402


def read_csv(path):
    return np.loadtxt(path, delimiter=',', skiprows=1)


def particle_top(x, y, at, spacing):
    """Top of the particles within one spacing of each position (0 where there are none)."""
    heights = np.zeros(len(at))
    for k, xa in enumerate(at):
        near = np.abs(x - xa) <= spacing
        heights[k] = y[near].max() + 0.5 * spacing if near.any() else 0.0
    return heights


def runout_particle_top(x, y, spacing, threshold=0.002):
    """Furthest x (particle edge) whose column still stands higher than the threshold."""
    edges = np.arange(0.0, x.max() + 2 * spacing, spacing)
    top = particle_top(x, y, edges, 0.5 * spacing)
    high = edges[top > threshold]
    return float(high.max() + 0.5 * spacing) if len(high) else 0.0


def wall_seconds(directory):
    """Wall time of the newest LAMMPS log in the directory (not the reference logs)."""
    logs = [os.path.join(directory, n) for n in os.listdir(directory)
            if n.startswith('log.') and '.short.' not in n]
    for path in sorted(logs, key=os.path.getmtime, reverse=True):
        m = re.findall(r'Total wall time: (\d+):(\d+):(\d+)', open(path).read())
        if m:
            h, mi, s = (int(v) for v in m[-1])
            return h * 3600 + mi * 60 + s
    return None


def measure(directory, surface_exp, failure_exp, spacing=None, moved=0.0015, height=0.1):
    """The measures of one run (dump.initial, dump.final in directory) against the experiment:
    {'summary': the JSON summary, 'x', 'y': final positions, 'grid', 'grid_surface': the
    simulated surface, 'failure_x', 'failure_y': the failure line}."""
    initial = sph_analysis.read_dump(os.path.join(directory, 'dump.initial'))
    final = sph_analysis.read_dump(os.path.join(directory, 'dump.final'))
    order0 = np.argsort(initial['id'])
    order1 = np.argsort(final['id'])
    if not np.array_equal(initial['id'][order0], final['id'][order1]):
        sys.exit(f'validate: dump.initial and dump.final of {directory} hold different particles')
    x0, y0 = initial['x'][order0], initial['y'][order0]
    x1, y1 = final['x'][order1], final['y'][order1]
    spacing = spacing or float(np.min(np.diff(np.unique(np.round(x0, 9)))))

    volume, h = spacing * spacing, 1.2 * spacing
    sim_surface = sph_analysis.surface_height(x1, y1, volume, h, surface_exp[:, 0])
    surface_rms = float(np.sqrt(np.mean((sim_surface - surface_exp[:, 1]) ** 2)))
    run, grid, grid_surface = sph_analysis.runout(x1, y1, volume, h, 0.002, spacing)
    top_surface = particle_top(x1, y1, surface_exp[:, 0], spacing)
    top_rms = float(np.sqrt(np.mean((top_surface - surface_exp[:, 1]) ** 2)))
    top_run = runout_particle_top(x1, y1, spacing)
    has_moved = np.hypot(x1 - x0, y1 - y0) >= moved
    fx, fy, angle = sph_analysis.failure_line(x0, y0, has_moved, spacing, height)
    exp_slope = np.polyfit(failure_exp[:, 0], failure_exp[:, 1], 1)[0]
    exp_angle = math.degrees(math.atan(-exp_slope))
    summary = {
        'particles': int(len(x1)),
        'spacing_m': spacing,
        'surface_rms_m': round(surface_rms, 6),
        'runout_m': round(run, 5),
        'runout_experiment_m': 0.43,
        'surface_rms_particle_top_m': round(top_rms, 6),
        'runout_particle_top_m': round(top_run, 5),
        'failure_angle_deg': round(angle, 2),
        'failure_angle_experiment_deg': round(exp_angle, 2),
    }
    return {'summary': summary, 'x': x1, 'y': y1, 'grid': grid, 'grid_surface': grid_surface,
            'failure_x': fx, 'failure_y': fy}


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument('--dir', default='examples/aluminium_bars', help='directory with dump.initial, dump.final')
    p.add_argument('--spacing', type=float, default=None, help='particle spacing d (default: from the dump)')
    p.add_argument('--experiment', default=None, help='directory with surface.csv and failure.csv')
    p.add_argument('--moved', type=float, default=0.0015, help='displacement that counts as moved (m)')
    p.add_argument('--height', type=float, default=0.1, help='initial height of the block (m)')
    p.add_argument('--json', default=None, help='write the summary here too')
    p.add_argument('--plot', default=None, help='PNG plot (default: <dir>/validation.png)')
    p.add_argument('--wall-seconds', type=float, default=None, help='wall time of the run')
    a = p.parse_args()

    exp_dir = a.experiment or os.path.join(a.dir, 'experiment')
    surface_exp = read_csv(os.path.join(exp_dir, 'surface.csv'))
    failure_exp = read_csv(os.path.join(exp_dir, 'failure.csv'))
    m = measure(a.dir, surface_exp, failure_exp, a.spacing, a.moved, a.height)
    summary = m['summary']
    summary['wall_seconds'] = a.wall_seconds if a.wall_seconds is not None else wall_seconds(a.dir)
    x1, y1, run, grid, grid_surface = m['x'], m['y'], summary['runout_m'], m['grid'], m['grid_surface']
    fx, fy, angle, exp_angle = m['failure_x'], m['failure_y'], summary['failure_angle_deg'], \
        summary['failure_angle_experiment_deg']
    spacing, surface_rms = summary['spacing_m'], summary['surface_rms_m']
    text = json.dumps(summary, indent=2)
    print(text)
    if a.json:
        with open(a.json, 'w') as f:
            f.write(text + '\n')

    import matplotlib
    matplotlib.use('Agg')
    import matplotlib.pyplot as plt
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
    out = a.plot or os.path.join(a.dir, 'validation.png')
    fig.savefig(out, dpi=150)
    print(f'validate: plot written to {out}', file=sys.stderr)


if __name__ == '__main__':
    main()
