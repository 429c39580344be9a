"""Collapse of a non-cohesive soil block (examples/soil_collapse; doc/theory.rst 6.2): the final
free surface, the runout and the failure line of a finished run, with the definitions of the
refinement comparison's collapse problem (runout: the furthest x where the surface stands higher
than one spacing; failure line: the boundary of the soil that moved less than 0.75 spacings).
There are no measured data for it.

  python3 -m sph_soil soil-collapse [--dir examples/soil_collapse] [--json FILE] [--plot FILE]
"""
import os

from .. import logs, paths, report
from .aluminium_bars import collapse_measures, initial_and_final

COMMAND = 'soil-collapse'
HEIGHT = 2.0    # m, the block's initial height (in.soil_collapse)


def measure(directory, height=HEIGHT):
    """collapse_measures() with the spacing of the run's lattice as runout height and 0.75 of it
    as the displacement that counts as moved."""
    spacing = initial_and_final(directory)[4]
    return collapse_measures(directory, height, spacing, 0.75 * spacing)


def plot(m, out):
    s = m['summary']
    plt = report.pyplot()
    fig, ax = plt.subplots(figsize=(9, 3.6))
    ax.scatter(m['x'], m['y'], s=1.0, c='0.75', label='particles (final)', rasterized=True)
    ax.plot(m['grid'], m['grid_surface'], 'b-', lw=1.2, label='surface (volume fraction 0.5)')
    ax.axvline(s['runout_m'], color='b', ls=':', lw=0.8)
    ax.plot(m['failure_x'], m['failure_y'], 'r-', lw=1.2, label=f"failure line ({s['failure_angle_deg']:.1f} deg)")
    ax.set_xlabel('x (m)')
    ax.set_ylabel('height (m)')
    ax.set_aspect('equal')
    ax.set_ylim(0, 1.1 * HEIGHT)
    ax.set_title(f"Soil collapse, d = {100 * s['spacing_m']:.3g} cm: runout {s['runout_m']:.2f} m")
    ax.legend(fontsize=7, loc='upper right')
    fig.tight_layout()
    fig.savefig(out, dpi=150)


def soil_collapse(directory, json_path=None, plot_path=None, wall_seconds=None):
    m = measure(directory)
    m['summary']['wall_seconds'] = wall_seconds if wall_seconds is not None else logs.wall_seconds(directory)
    report.write_json(m['summary'], json_path, indent=2)
    if plot_path:
        plot(m, plot_path)
    return m['summary']


def report_example(directory, log, variables, seconds):
    """run_example's numbers and plot: soil_collapse.json, soil_collapse.png."""
    soil_collapse(directory, os.path.join(directory, 'soil_collapse.json'),
                  os.path.join(directory, 'soil_collapse.png'), seconds)


def add_arguments(p):
    report.add_run_arguments(p, paths.example_dir('soil_collapse'), 'dump.initial, dump.final')


def main(a):
    soil_collapse(a.dir, a.json, a.plot)
