"""The critical height of a vertical cut in phi = 0 soil (examples/vertical_cut), by bisection.

Runs examples/vertical_cut/in.vertical_cut for a ratio gamma H / c at a time, each in its own
directory under --workdir, and calls a run failed when the crest is still moving at the end:
when it has moved more than --creep (default 0.1%) of H out of the face over the last 30% of the
run (0.63 to 0.9 s). A cut that stands settles by a few mm and stops, oscillating by less than
0.07% of H about its rest; one that fails keeps moving, slowly near the critical ratio (a fixed
displacement at a fixed time calls such a creeping failure stable). Every run's late creep is
in the JSON, so another threshold can be applied to the same runs. Starting from a bracket that stands at
its low end and fails at its high end (both are run to check), --steps bisections narrow it;
the critical ratio is reported as the bracket's middle, against Pastor, Thai & Francescato
(2000): 3.772 to 3.786. Prints JSON, writes --json and a plot (--plot) of the crest's
displacement against time for every run.

  python3 -m sph_soil vertical-cut [--lmp build/lmp] [--np 2] [--d 0.025] [--low 3.0] [--high 4.5]
                        [--steps 4] [--creep 0.001] [--refine [N]] [--stepping global|level]
                        [--criterion strain|shear_strain_rate] [--threshold T] [--every N] [--balance]
                        [--buffer B] [--ease T] [--split EPS ALPHA]
                        [--workdir /tmp/sph_soil_vertical_cut]
                        [--json examples/vertical_cut/vertical_cut.json]
                        [--plot examples/vertical_cut/vertical_cut.png]
"""
import os

import numpy as np

from .. import analysis, bisection, paths, refine_options, report, runner
from ..dumps import read_ave_time
from ..inputs import input_variables
from ..logs import Log

COMMAND = 'vertical-cut'
EXAMPLE = paths.example_input('vertical_cut')
DEFAULTS = input_variables(EXAMPLE)    # the input's own spacing and check interval
HEIGHT = 1.0
PASTOR = (3.772, 3.786)
CREEP = 0.001       # failure: the crest moves more than this times H over the last 30% of the run


def measure(directory, ratio, creep=CREEP, seconds=None, log='log.lammps'):
    """A finished run of one ratio (cut.dat and the log in directory): the crest's displacement
    at the end and over the last 30% of the run, and whether it fails."""
    data = read_ave_time(os.path.join(directory, 'cut.dat'))
    moved = float(data[-1, 2])
    late = analysis.late_movement(data[:, 1], data[:, 2])
    if not Log(os.path.join(directory, log)).search(r'vertical cut: gamma H / c = .*: the crest moved'):
        raise SystemExit(f'vertical_cut: the run in {directory} did not finish')
    return {'ratio': ratio, 'crest_moved_m': round(moved, 5), 'late_creep_m': round(late, 5),
            'fails': late > creep * HEIGHT, 'wall_seconds': None if seconds is None else round(seconds, 1),
            'time': data[:, 1].tolist(), 'moved': data[:, 2].tolist()}


def run(lmp, args, ratio):
    directory = os.path.join(args.workdir, f'd{args.d:g}{refine_options.tag(args)}_ratio{ratio:.4f}')
    done = lmp.run(EXAMPLE, directory, np=args.np, check=True,
                   variables=[('ratio', f'{ratio:.6g}'), ('d', f'{args.d:g}')] + refine_options.variables(args))
    return measure(directory, ratio, args.creep, done.seconds)


def plot(runs, title, out):
    """The crest's displacement against time, one line per run (red: fails, blue: stands)."""
    plt = report.pyplot()
    fig, ax = plt.subplots(figsize=(7, 4.2))
    for r in sorted(runs, key=lambda r: r['ratio']):
        ax.plot(r['time'], 100 * np.array(r['moved']) / HEIGHT, color='tab:red' if r['fails'] else 'tab:blue',
                label=f"gamma H / c = {r['ratio']:.3f}: {'fails' if r['fails'] else 'stands'} "
                      f"(last 30%: {100 * r['late_creep_m'] / HEIGHT:.2f}% of H)")
    ax.set_xlabel('time (s)')
    ax.set_ylabel("crest's displacement out of the face / H (%)")
    ax.set_title(title, fontsize=9)
    ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(out, dpi=110)


def report_example(directory, log, variables, seconds):
    """run_example's numbers and plot of the one ratio run: vertical_cut.json, vertical_cut.png."""
    ratio = float(variables['ratio'])
    r = measure(directory, ratio, seconds=seconds, log=log)
    report.write_json({k: v for k, v in r.items() if k not in ('time', 'moved')},
                      os.path.join(directory, 'vertical_cut.json'))
    plot([r], f"Vertical cut, phi = 0, d = {100 * float(variables['d']):g} cm: gamma H / c = {ratio:g} "
              f"{'fails' if r['fails'] else 'stands'} (Pastor 2000: critical 3.78)",
         os.path.join(directory, 'vertical_cut.png'))


def add_arguments(p):
    runner.add_arguments(p)
    p.add_argument('--d', type=float, default=float(DEFAULTS['d']))
    p.add_argument('--low', type=float, default=3.0)
    p.add_argument('--high', type=float, default=4.5)
    p.add_argument('--steps', type=int, default=4)
    p.add_argument('--creep', type=float, default=CREEP,
                   help='failure: the crest moves more than this times H over the last 30%% of the run')
    refine_options.add_arguments(p, every=int(DEFAULTS['check']))
    p.add_argument('--workdir', default='/tmp/sph_soil_vertical_cut')
    p.add_argument('--json')
    p.add_argument('--plot')


def main(args):
    lmp = runner.from_arguments(args)
    runs, low, high = bisection.bisect(lambda ratio: run(lmp, args, ratio), args.low, args.high, args.steps,
                                       'vertical_cut')
    result = bisection.summary(runs, low, high, 'ratio')
    critical = result['critical']
    summary = {**refine_options.summary(args, args.d), 'late_creep_threshold_over_H': args.creep, **result,
               'pastor_2000': PASTOR, 'critical_over_reference': critical / (0.5 * sum(PASTOR))}
    report.write_json(summary, args.json, indent=1, end='')
    if args.plot:
        plot(runs, f'Vertical cut, phi = 0, d = {100 * args.d:g} cm{refine_options.title(args)}: critical '
                   f'gamma H / c = {critical:.2f} +- {result["half_width"]:.2f} (Pastor 2000: 3.78)', args.plot)
