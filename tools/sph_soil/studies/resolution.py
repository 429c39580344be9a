"""The aluminium bars' resolution study with one dissipation at every spacing (issue 28, item 5).

Runs examples/refinement/in.refinement's uniform bars (in examples/refinement/resolution) (mode coarse) at the spacings SPACINGS
(4, 2 and 1 mm; --finest adds 0.5 mm, about 80 minutes on 2 cores) with the artificial viscosity of
the 2 mm lattice's h = 2.4 mm on every pair (-var h0 1: pair_style sph/soil viscosity_h0), so that
halving the spacing no longer halves the dissipation (doc/theory.rst 5.9). For each run: the final
surface's RMS distance from the measured one, the runout and the failure angle (the measures of
the refinement comparison, refinement.final_state(), with the thresholds of the 2 mm lattice at
every spacing; the surface the 0.5 level of the SPH volume fraction); for each pair of
successive spacings the RMS difference of their surfaces over x up to the finer run's runout, and
the observed order log2(e_1 / e_2) of two successive differences. Writes
doc/refinement_resolution.json and doc/img/refinement_bars_fixed_dissipation.png.

  python3 -m sph_soil resolution              # run what is missing (all cores), then measure
  python3 -m sph_soil resolution --finest     # also 0.5 mm
  python3 -m sph_soil resolution --measure-only

A run is skipped when its final dump is newer than the input and the binary.
"""
import os

from .. import paths, report, runner, verification
from ..dumps import read_dump
from . import refinement

COMMAND = 'resolution'
SPACINGS = (0.004, 0.002, 0.001)
FINEST = 0.0005
# in.refinement's -var h0 1: the h of the problem's own lattice (1.2 d) on every pair
VISCOSITY_H0 = 1.2 * refinement.PROBLEMS['bars']['d']


def name_of(spacing):
    # in.refinement's name for -var mode coarse -var h0 1 -var spacing D
    return f'bars_coarse_h0_d{spacing:g}'


def run_missing(lmp, spacings, np_, directory):
    for d in spacings:
        name = name_of(d)
        dump = os.path.join(directory, f'dump.{name}.final')
        if (os.path.exists(dump) and os.path.getmtime(dump) > os.path.getmtime(refinement.INPUT)
                and os.path.getmtime(dump) > os.path.getmtime(lmp.binary)):
            print(f'== {name}: up to date', flush=True)
            continue
        print(f'== {name}', flush=True)
        variables = [('problem', 'bars'), ('mode', 'coarse'), ('h0', '1'), ('spacing', f'{d:g}')]
        if not lmp.run(refinement.INPUT, directory, np=np_, variables=variables, log=f'log.{name}').ok:
            print(f'== {name} stopped with an error (see log.{name})', flush=True)


def measure(spacings, directory):
    """The runs' measures (refinement.final_state(): the comparison's, with its thresholds of the
    2 mm lattice at every spacing), the successive surface differences and the observed orders;
    and the runs' profiles."""
    runs, profiles = [], {}
    for d in spacings:
        dump = os.path.join(directory, f'dump.{name_of(d)}.final')
        if not os.path.exists(dump):
            continue
        measures, profiles[d] = refinement.final_state(read_dump(dump), 'bars', d * d, 1.2 * d)
        runs.append(dict(spacing_m=d, particles=measures['soil_particles'],
                         surface_rms_vs_experiment_m=round(measures['surface_rms_vs_experiment_m'], 6),
                         runout_m=round(measures['runout_m'], 4),
                         failure_angle_deg=measures['failure_angle_deg']))
    differences = []
    for coarse, fine in zip(runs, runs[1:]):
        rms = refinement.surface_rms_between(profiles[fine['spacing_m']], profiles[coarse['spacing_m']],
                                             fine['runout_m'])
        differences.append(dict(spacings_m=[coarse['spacing_m'], fine['spacing_m']], surface_rms_difference_m=round(rms, 6),
                                angle_difference_deg=round(fine['failure_angle_deg'] - coarse['failure_angle_deg'], 2)))
    orders = []
    for first, second in zip(differences, differences[1:]):
        e1, e2 = first['surface_rms_difference_m'], second['surface_rms_difference_m']
        a1, a2 = abs(first['angle_difference_deg']), abs(second['angle_difference_deg'])
        surface_order = verification.order_of_differences(e1, e2)
        angle_order = verification.order_of_differences(a1, a2)
        orders.append(dict(spacings_m=first['spacings_m'] + second['spacings_m'][1:],
                           surface_order=None if surface_order is None else round(surface_order, 2),
                           angle_order=None if angle_order is None else round(angle_order, 2)))
    return dict(viscosity_h0_m=VISCOSITY_H0, runs=runs, successive=differences, observed_order=orders), profiles


def plot(result, profiles, path):
    plt = report.pyplot()
    experiment = refinement.experiment('bars')
    fig, ax = plt.subplots(figsize=(9, 3.4))
    for run in result['runs']:
        grid, top, *_ = profiles[run['spacing_m']]
        ax.plot(grid, top, label=f"{1000 * run['spacing_m']:g} mm: {1000 * run['surface_rms_vs_experiment_m']:.2f} mm "
                                 f"from measured, runout {run['runout_m']:.3f} m, {run['failure_angle_deg']:.2f} deg")
    ax.plot(experiment[:, 0], experiment[:, 1], 'ko', ms=4, label='measured')
    ax.set_xlim(0, 0.55)
    ax.set_ylim(0, 0.11)
    ax.set_xlabel('x (m)')
    ax.set_ylabel('surface height (m)')
    ax.set_title(f'Aluminium bars, the artificial viscosity of h = {1000 * VISCOSITY_H0:g} mm at every spacing '
                 '(viscosity_h0)', fontsize=10)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(path, dpi=110)


def add_arguments(p):
    runner.add_arguments(p, np=os.cpu_count() or 1)
    p.add_argument('--finest', action='store_true', help='also 0.5 mm (about 80 minutes on 2 cores)')
    p.add_argument('--measure-only', action='store_true', help='measure the runs there, run nothing')
    p.add_argument('--dir', default=os.path.join(refinement.DIRECTORY, 'resolution'),
                   help='where the runs are (default: examples/refinement/resolution, apart from the '
                        'comparison\'s runs)')


def main(a):
    spacings = SPACINGS + ((FINEST,) if a.finest else ())
    if not a.measure_only:
        os.makedirs(a.dir, exist_ok=True)
        run_missing(runner.from_arguments(a, build=True), spacings, a.np, a.dir)
    result, profiles = measure(spacings, a.dir)
    report.write_json(result, os.path.join(paths.ROOT, 'doc', 'refinement_resolution.json'), indent=1)
    plot(result, profiles, os.path.join(paths.ROOT, 'doc', 'img', 'refinement_bars_fixed_dissipation.png'))
