#!/usr/bin/python3
"""Draw the refinement-parameter map (the dynamic-refinement paper's Fig. 1) from the CSV of
sph_soil_refine_map: log10 E as a grey map for case (a) h(x) = h_p and case (b)
h(x) = alpha_r h_p, the instability lines for d_ij/d_ref = 1.0 and 0.85, the paper's studied
points and its recommended box [0.5, 0.58]^2.

    tools/plot_refine_map.py refine_map.csv refine_map.png [--ra 1.2]
"""
import argparse

import numpy as np
import matplotlib
matplotlib.use('Agg')
import matplotlib.pyplot as plt


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument('csv')
    p.add_argument('png')
    p.add_argument('--ra', type=float, default=1.2)
    a = p.parse_args()
    data = np.genfromtxt(a.csv, delimiter=',', names=True)
    eps = np.unique(data['eps_r'])
    alpha = np.unique(data['alpha_r'])
    ra = a.ra

    fig, axes = plt.subplots(1, 2, figsize=(11, 4.8), sharey=True)
    for ax, column, title in ((axes[0], 'E_a', 'a) h(x) = h_p'), (axes[1], 'E_b', r'b) h(x) = $\alpha_r h_p$')):
        grid = np.full((len(alpha), len(eps)), np.nan)
        for row in data:
            i = np.searchsorted(alpha, row['alpha_r'])
            j = np.searchsorted(eps, row['eps_r'])
            grid[i, j] = np.log10(max(row[column], 1e-12))
        mesh = ax.pcolormesh(eps, alpha, grid, cmap='Greys_r', shading='nearest')
        fig.colorbar(mesh, ax=ax, label=r'$\log_{10} E$')
        al = np.linspace(alpha.min(), alpha.max(), 200)
        # the instability conditions as lines in the (eps_r, alpha_r) plane (unstable side hatched by label)
        ax.plot(2.0 / 3.0 * al * ra, al, 'r-', lw=1.5, label='Cond. 1 (unstable left)')
        for d, style in ((1.0, '-'), (0.85, '--')):
            ax.plot(d - 2.0 / 3.0 * al * ra, al, 'b' + style, lw=1.5,
                    label=f'Cond. 2, $d_{{ij}}/d_{{ref}}$ = {d} (unstable right)')
            ax.plot(2.0 * (d - (1.0 + al) * ra / 3.0), al, 'g' + style, lw=1.0,
                    label=f'Cond. 3, $d_{{ij}}/d_{{ref}}$ = {d}')
        for e, al_ in ((0.5, 0.5), (0.55, 0.5), (0.55, 0.6), (0.55, 0.7)):
            ax.plot(e, al_, 'ko', ms=6)
        ax.add_patch(plt.Rectangle((0.5, 0.5), 0.08, 0.08, fill=False, ec='orange', lw=2,
                                   label='recommended box'))
        ax.set_xlim(eps.min(), eps.max())
        ax.set_ylim(alpha.min(), alpha.max())
        ax.set_xlabel(r'$\epsilon_r$')
        ax.set_title(title)
    axes[0].set_ylabel(r'$\alpha_r$')
    axes[1].legend(fontsize=6, loc='lower right')
    fig.suptitle(f'Kernel gradient error of one split and instability conditions, $r_a$ = {ra}')
    fig.tight_layout()
    fig.savefig(a.png, dpi=130)


if __name__ == '__main__':
    main()
