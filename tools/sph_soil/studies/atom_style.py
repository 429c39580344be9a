"""atom_style sph/soil on its own (examples/atom_style): the state written to a data file and
read back, against the geostatic stress it was given: sigma_yy = rho0 g (y - H) and
sigma_xx = K0 sigma_yy (K0 = 1 - sin phi) in the soil (type 1), from dump.atom_style.

  python3 -m sph_soil atom-style [--dir examples/atom_style] [--json FILE] [--plot FILE]
"""
import math
import os

import numpy as np

from .. import paths, report
from ..dumps import read_dump

COMMAND = 'atom-style'
RHO0, G, HEIGHT, PHI = 2650.0, 9.81, 0.1, 19.8     # in.atom_style


def measure(directory):
    s = read_dump(os.path.join(directory, 'dump.atom_style'))
    soil = s['type'] == 1
    y, sxx, syy = s['y'][soil], s['c_props[1]'][soil], s['c_props[2]'][soil]
    k0 = 1.0 - math.sin(math.radians(PHI))
    expected = RHO0 * G * (y - HEIGHT)
    summary = {'particles': int(len(s['id'])), 'soil_particles': int(soil.sum()),
               'deepest_sigma_yy_Pa': round(float(syy.min()), 2),
               'deepest_sigma_yy_expected_Pa': round(float(expected.min()), 2),
               'max_error_sigma_yy_Pa': float(np.abs(syy - expected).max()),
               'max_error_sigma_xx_Pa': float(np.abs(sxx - k0 * expected).max()), 'K0': k0}
    return summary, y, sxx, syy


def plot(y, sxx, syy, out):
    plt = report.pyplot()
    k0 = 1.0 - math.sin(math.radians(PHI))
    fig, ax = plt.subplots(figsize=(6, 4))
    line = np.linspace(0.0, HEIGHT, 50)
    ax.plot(syy / 1000, y, 'b.', ms=2, label='sigma_yy (particles)')
    ax.plot(sxx / 1000, y, 'r.', ms=2, label='sigma_xx (particles)')
    ax.plot(RHO0 * G * (line - HEIGHT) / 1000, line, 'k-', lw=0.8, label='rho0 g (y - H)')
    ax.plot(k0 * RHO0 * G * (line - HEIGHT) / 1000, line, 'k--', lw=0.8, label='K0 rho0 g (y - H)')
    ax.set_xlabel('stress (kPa)')
    ax.set_ylabel('y (m)')
    ax.set_title('atom_style sph/soil: geostatic stress read back from the data file', fontsize=9)
    ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(out, dpi=110)


def atom_style(directory, json_path=None, plot_path=None):
    summary, y, sxx, syy = measure(directory)
    report.write_json(summary, json_path, indent=2)
    if plot_path:
        plot(y, sxx, syy, plot_path)
    return summary


def report_example(directory, log, variables, seconds):
    """run_example's numbers and plot: atom_style.json, atom_style.png."""
    atom_style(directory, os.path.join(directory, 'atom_style.json'), os.path.join(directory, 'atom_style.png'))


def add_arguments(p):
    report.add_run_arguments(p, paths.example_dir('atom_style'), 'dump.atom_style')


def main(a):
    atom_style(a.dir, a.json, a.plot)
