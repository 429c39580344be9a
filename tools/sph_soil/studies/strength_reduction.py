"""A factor of safety by strength reduction (examples/slope): the factor F by which c and tan(phi)
must be divided for a slope (or any input) to fail, found by bisection over LAMMPS runs.

The input takes the factor as the LAMMPS variable F (-var F value), divides its soil's strength by
it (c_F = c / F, tan(phi_F) = tan(phi) / F, as examples/slope/in.slope does) and writes a
monitored displacement against time to a file (--data; columns: time, displacement, ...). A run
fails when the monitored point is still moving at the end: when it has moved more than --creep
(default 0.1%) of --length over the last --late (default 30%) of the run. A slope that stands
settles and stops, one that fails keeps moving (slowly near the critical F, which is why a fixed
displacement at a fixed time is not the criterion). Starting from a bracket that stands at its low
end and fails at its high end (both run to check), --steps bisections narrow it; the factor of
safety is reported as the bracket's middle, +- half its width. Every run's late movement is in the
JSON, so another threshold can be applied to the same runs. Prints JSON, writes --json and a plot
(--plot) of the monitored displacement against time for every run.

  python3 -m sph_soil strength-reduction [--input examples/slope/in.slope] [--lmp build/lmp] [--np 2]
                              [--d 0.5] [--var NAME VALUE] [--low 1.0] [--high 2.0] [--steps 4]
                              [--refine [N]] [--stepping global|level] [--criterion strain|shear_strain_rate]
                              [--threshold T] [--every N] [--balance] [--buffer B] [--ease T] [--split EPS ALPHA]
                              [--data slope.dat] [--length 10] [--creep 0.001] [--late 0.3]
                              [--reference 1.4] [--workdir /tmp/sph_soil_strength_reduction]
                              [--json examples/slope/slope.json] [--plot examples/slope/slope.png]
"""
import os

import numpy as np

from .. import analysis, bisection, paths, refine_options, report, runner
from ..dumps import read_ave_time
from ..inputs import input_variables

COMMAND = 'strength-reduction'
DATA, LENGTH, CREEP, LATE = 'slope.dat', 10.0, 0.001, 0.3     # examples/slope's monitor and criterion
REFERENCE = 1.4     # the published factor of safety (Griffiths & Lane 1999, example 1)
# examples/slope's own defaults: its spacing (m) and refinement check interval
DEFAULTS = input_variables(paths.example_input('slope'))


def measure(directory, factor, data=DATA, length=LENGTH, creep=CREEP, late=LATE, seconds=None):
    """A finished run of one factor: the monitored displacement at the end and over the last
    `late` share of the run, and whether it fails."""
    values = read_ave_time(os.path.join(directory, data))
    t, moved = values[:, 1], values[:, 2]    # fix ave/time: step, then the values
    movement = analysis.late_movement(t, moved, late)
    return {'F': factor, 'moved_m': round(float(moved[-1]), 5), 'late_movement_m': round(movement, 5),
            'fails': movement > creep * length, 'wall_seconds': None if seconds is None else round(seconds, 1),
            'time': t.tolist(), 'moved': moved.tolist()}


def run(lmp, args, factor):
    tag = f'd{args.d:g}{refine_options.tag(args)}_' + ''.join(f'{name}{value}_' for name, value in args.var)
    directory = os.path.join(args.workdir, f'{tag}F{factor:.4f}')
    done = lmp.run(os.path.abspath(args.input), directory, np=args.np, check=True,
                   variables=[('F', f'{factor:.6g}'), ('d', f'{args.d:g}')] + refine_options.variables(args) +
                   [tuple(v) for v in args.var])
    return measure(directory, factor, args.data, args.length, args.creep, args.late, done.seconds)


def plot(runs, title, out):
    """The monitored displacement against time, one line per run (red: fails, blue: stands)."""
    plt = report.pyplot()
    fig, ax = plt.subplots(figsize=(7, 4.2))
    for r in sorted(runs, key=lambda r: r['F']):
        ax.plot(r['time'], np.array(r['moved']) * 1000.0, color='tab:red' if r['fails'] else 'tab:blue',
                label=f"F = {r['F']:.3f} ({'fails' if r['fails'] else 'stands'})")
    ax.set_xlabel('time (s)')
    ax.set_ylabel('monitored displacement (mm)')
    ax.set_title(title)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(out, dpi=120)


def report_example(directory, log, variables, seconds):
    """run_example's numbers and plot of the one factor run (examples/slope): slope.json, slope.png."""
    factor = float(variables['F'])
    r = measure(directory, factor, seconds=seconds)
    report.write_json({k: v for k, v in r.items() if k not in ('time', 'moved')},
                      os.path.join(directory, 'slope.json'), indent=2)
    plot([r], f"slope, F = {factor:g}: {'fails' if r['fails'] else 'stands'} (factor of safety: "
              f'reference {REFERENCE:g})', os.path.join(directory, 'slope.png'))


def add_arguments(p):
    runner.add_arguments(p)
    p.add_argument('--input', default=paths.example_input('slope'))
    p.add_argument('--d', type=float, default=float(DEFAULTS['d']),
                   help='the particle spacing (m; the input\'s -var d)')
    p.add_argument('--var', nargs=2, action='append', default=[], metavar=('NAME', 'VALUE'),
                   help='another LAMMPS variable for every run (e.g. --var tend 20)')
    p.add_argument('--low', type=float, default=1.0)
    p.add_argument('--high', type=float, default=2.0)
    p.add_argument('--steps', type=int, default=4)
    refine_options.add_arguments(p, every=int(DEFAULTS['check']))
    p.add_argument('--data', default=DATA)
    p.add_argument('--length', type=float, default=LENGTH, help='the length the creep threshold refers to (m)')
    p.add_argument('--creep', type=float, default=CREEP)
    p.add_argument('--late', type=float, default=LATE)
    p.add_argument('--reference', type=float, default=REFERENCE,
                   help='the published factor of safety (Griffiths & Lane 1999, example 1)')
    p.add_argument('--workdir', default='/tmp/sph_soil_strength_reduction')
    p.add_argument('--json', default=None)
    p.add_argument('--plot', default=None)


def main(args):
    lmp = runner.from_arguments(args)
    runs, lo, hi = bisection.bisect(lambda factor: run(lmp, args, factor), args.low, args.high, args.steps,
                                    'strength_reduction')
    result = bisection.summary(runs, lo, hi, 'F')
    factor = result['critical']
    report.write_json({
        'input': os.path.relpath(os.path.abspath(args.input), paths.ROOT), 'variables': dict(args.var),
        **refine_options.summary(args, args.d),
        'criterion': f'fails when the monitored displacement grows by more than {args.creep:g} x '
                     f'{args.length:g} m over the last {100 * args.late:.0f}% of the run',
        **result, 'reference': args.reference, 'ratio_to_reference': round(factor / args.reference, 4),
    }, args.json, indent=2)
    if args.plot:
        plot(runs, f'strength reduction, d = {args.d:g} m{refine_options.title(args)}: F = {factor:.3f} '
                   f'+- {result["half_width"]:.3f} (reference {args.reference:g})', args.plot)
