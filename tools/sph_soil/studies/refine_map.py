"""The refinement-parameter map (doc/refinement_parameters.rst): CSV, summary JSON and figure.

Runs sph_soil_refine_map of the build directory (tools/refine_map/refine_map.cpp, built with the
package, by tools/build.sh if it is missing; its options pass through, e.g. --ra 1.3 or --dimension 3) into doc/refine_map.csv and
doc/refine_map.json, then draws the dynamic-refinement paper's Fig. 1 from the CSV into
doc/img/refine_map.png: log10 E as a grey map for case (a) h(x) = h_p and case (b)
h(x) = alpha_r h_p, the instability lines for d_ij/d_ref = 1.0 and 0.85, the paper's studied
points and its recommended box [0.5, 0.58]^2; and doc/img/refine_map_defect.png, what a split
does to a soil at rest (the stress-balance defect at the coarse neighbours and at the daughters).

    python3 -m sph_soil refine-map                       # 2D, r_a = 1.2, grid 0.2..0.8 step 0.02
    python3 -m sph_soil refine-map -- --ra 1.3           # another ratio h/d
    python3 -m sph_soil refine-map -- --dimension 3 --step 0.05
"""
import os
import subprocess

import numpy as np

from .. import paths, report, runner

COMMAND = 'refine-map'
CSV = os.path.join(paths.DOC, 'refine_map.csv')
JSON = os.path.join(paths.DOC, 'refine_map.json')
PNG = os.path.join(paths.DOC_IMG, 'refine_map.png')
DEFECT_PNG = os.path.join(paths.DOC_IMG, 'refine_map_defect.png')


def grid_of(data, column, eps, alpha):
    """log10 of a CSV column on the (alpha, eps) grid."""
    grid = np.full((len(alpha), len(eps)), np.nan)
    for row in data:
        grid[np.searchsorted(alpha, row['alpha_r']), np.searchsorted(eps, row['eps_r'])] = \
            np.log10(max(row[column], 1e-12))
    return grid


def draw_conditions(plt, ax, alpha, ra):
    """The instability conditions as lines in the (eps_r, alpha_r) plane, the paper's points and
    its recommended box."""
    al = np.linspace(alpha.min(), alpha.max(), 200)
    ax.plot(2.0 / 3.0 * al * ra, al, 'r-', lw=1.5, label='Cond. 1 (unstable left)')
    for d, style in ((1.0, '-'), (0.85, '--')):
        ax.plot(d - 2.0 / 3.0 * al * ra, al, 'b' + style, lw=1.5,
                label=f'Cond. 2, $d_{{ij}}/d_{{ref}}$ = {d} (unstable right)')
        ax.plot(2.0 * (d - (1.0 + al) * ra / 3.0), al, 'g' + style, lw=1.0,
                label=f'Cond. 3, $d_{{ij}}/d_{{ref}}$ = {d}')
    for e, al_ in ((0.5, 0.5), (0.55, 0.5), (0.55, 0.6), (0.55, 0.7)):
        ax.plot(e, al_, 'ko', ms=6)
    ax.add_patch(plt.Rectangle((0.5, 0.5), 0.08, 0.08, fill=False, ec='orange', lw=2, label='recommended box'))


def plot_maps(csv, png, ra, panels, suptitle, label):
    """One map per (column, title) of `panels`, with the instability conditions on each."""
    plt = report.pyplot()
    data = np.genfromtxt(csv, delimiter=',', names=True)
    eps = np.unique(data['eps_r'])
    alpha = np.unique(data['alpha_r'])
    fig, axes = plt.subplots(1, len(panels), figsize=(11, 4.8), sharey=True)
    for ax, (column, title) in zip(axes, panels):
        mesh = ax.pcolormesh(eps, alpha, grid_of(data, column, eps, alpha), cmap='Greys_r', shading='nearest')
        fig.colorbar(mesh, ax=ax, label=label)
        draw_conditions(plt, ax, alpha, ra)
        ax.set_xlim(eps.min(), eps.max())
        ax.set_ylim(alpha.min(), alpha.max())
        ax.set_xlabel(r'$\epsilon_r$')
        ax.set_title(title)
    axes[0].set_ylabel(r'$\alpha_r$')
    axes[-1].legend(fontsize=6, loc='lower right')
    fig.suptitle(suptitle)
    fig.tight_layout()
    fig.savefig(png, dpi=130)


def plot(csv, png, ra=1.2):
    plot_maps(csv, png, ra, (('E_a', 'a) h(x) = h_p'), ('E_b', r'b) h(x) = $\alpha_r h_p$')),
              f'Kernel gradient error of one split and instability conditions, $r_a$ = {ra}', r'$\log_{10} E$')


def plot_defect(csv, png, ra=1.2):
    """The stress-balance defect of a split (doc/theory.rst 5.11): the acceleration at rest in a
    uniform stress p, in units of p / (rho h_p), at the coarse neighbours and at the daughters."""
    plot_maps(csv, png, ra, (('defect_neighbours', 'coarse neighbours'), ('defect_daughters', 'daughters')),
              f'What a split does at rest: acceleration / (p / rho h), $r_a$ = {ra} (times z/h g at depth z)',
              r'$\log_{10}$ (a rho h / p)')


def add_arguments(p):
    p.add_argument('--tool', default=None, help='the sph_soil_refine_map binary (default: the one in the '
                   'build directory of SPH_SOIL_LAMMPS, as --lmp of the other commands)')
    p.add_argument('options', nargs='*', help='sph_soil_refine_map options, after --')


def main(a):
    tool = a.tool or os.path.join(paths.build_dir(), 'sph_soil_refine_map')
    if not a.tool:
        runner.build_if_missing(tool)
    os.makedirs(paths.DOC_IMG, exist_ok=True)
    subprocess.run([tool, '--csv', CSV, '--json', JSON] + a.options, check=True)
    ra = 1.2
    for k, option in enumerate(a.options[:-1]):
        if option == '--ra':
            ra = float(a.options[k + 1])
    plot(CSV, PNG, ra)
    plot_defect(CSV, DEFECT_PNG, ra)
    print('refine_map: doc/refine_map.csv, doc/refine_map.json, doc/img/refine_map.png, doc/img/refine_map_defect.png')
