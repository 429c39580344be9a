"""The elastic column of examples/elastic_column against its exact solution: the settlement of its
top row and its force on a side wall as gravity rises and the column comes to rest.

Reads a finished run's column.txt (time, settlement of the top row, force on the right wall) and
its log (the exact values and the answers, each averaged over the last 0.05 s, as ratios to the
exact ones), prints JSON and plots both against time with the exact values.

  python3 -m sph_soil elastic-column [--dir examples/elastic_column] [--json F] [--plot F]

Its convergence as the spacing shrinks: python3 -m sph_soil convergence elastic.
"""
import os

import numpy as np

from .. import paths, report
from ..logs import Log

COMMAND = 'elastic-column'
DIRECTORY = paths.example_dir('elastic_column')


def measure(directory, log='log.lammps'):
    text = Log(os.path.join(directory, log))
    number = r'([-+0-9.eE]+)'
    exact = text.search(rf'exact settlement of the top row {number} m, exact wall force {number} N/m')
    finals = text.findall(rf'elastic column: d = {number} m: settlement of the top row \S+ m = {number} of exact, '
                          rf'force on the wall \S+ N/m = {number} of exact')
    if exact is None or not finals:
        errors = text.findall(r'ERROR.*')
        raise SystemExit(f'elastic-column: the run in {directory} did not finish'
                         + (f': {errors[-1]}' if errors else ''))
    data = np.loadtxt(os.path.join(directory, 'column.txt'), comments='#', ndmin=2)
    final = finals[-1]      # the last line of the run
    return {'d_m': float(final[0]), 'settlement_exact_m': float(exact.group(1)),
            'wall_force_exact_N_per_m': float(exact.group(2)),
            'settlement_over_exact': float(final[1]), 'wall_force_over_exact': float(final[2]),
            'time': data[:, 0], 'settlement': data[:, 1], 'force': data[:, 2]}


def plot(r, out):
    plt = report.pyplot()
    fig, (top, bottom) = plt.subplots(2, 1, figsize=(7, 5.5), sharex=True)
    top.plot(r['time'], 1e3 * r['settlement'], label='SPH')
    top.axhline(1e3 * r['settlement_exact_m'], color='k', ls='--', lw=0.8, label='exact')
    top.set_ylabel('settlement of the top row (mm)')
    top.set_title(f"Elastic column, d = {r['d_m']:g} m: at rest {r['settlement_over_exact']:.4f} x exact "
                  f"(settlement), {r['wall_force_over_exact']:.4f} x exact (wall force)", fontsize=9)
    top.legend(fontsize=8)
    bottom.plot(r['time'], r['force'] / 1e3, label='SPH')
    bottom.axhline(r['wall_force_exact_N_per_m'] / 1e3, color='k', ls='--', lw=0.8, label='exact')
    bottom.set_xlabel('time (s)')
    bottom.set_ylabel('force on the side wall (kN/m)')
    bottom.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(out, dpi=110)


def public(r):
    return {k: v for k, v in r.items() if k not in ('time', 'settlement', 'force')}


def report_example(directory, log, variables, seconds):
    """run_example's numbers and plot: elastic_column.json, elastic_column.png."""
    r = measure(directory, log)
    report.write_json(public(r), os.path.join(directory, 'elastic_column.json'))
    plot(r, os.path.join(directory, 'elastic_column.png'))


def add_arguments(p):
    report.add_run_arguments(p, DIRECTORY, 'column.txt and log.lammps')


def main(args):
    r = measure(args.dir)
    report.write_json(public(r), args.json)
    if args.plot:
        plot(r, args.plot)
