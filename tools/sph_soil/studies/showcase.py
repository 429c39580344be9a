"""Refinement showcases: a failure with a narrow shear zone solved coarse, with dynamic refinement
and uniformly at the finest spacing, each configuration's answer against its cost.

A showcase is a study run in several configurations with the same options: a bisection
(vertical-cut: the critical gamma H / c of a vertical cut; strength-reduction: the factor of
safety of examples/slope, the answer the middle of the last bracket) or one run (bearing-capacity:
the limit pressure of a strip footing, its q / (c N_c); shallow-landslide: the runout of the
patch that fails in examples/shallow_landslide, its deposit's thickness beside it), each as: uniform lattices at two or three spacings (their convergence) and dynamic
refinement (maxlevel 1, 2, 3 from coarser lattices down to the finest uniform spacing, with a
time step per level or one global step). Each configuration's study writes its JSON and
plot under --workdir/<showcase>/ (name.json, name.png); configurations whose JSON is there are
not run again (--run runs the missing ones, in the order listed; without --run only the
existing ones are reported). The report compares every configuration with the finest uniform
run: its answer, whether it is within the difference between the two finest uniform runs (the
issue's tolerance: refinement should reach the finest answer as well as that answer is
converged), and its wall time as a fraction of the finest uniform run's (all runs of the
configuration, the same machine and rank count).

Writes doc/showcases.json (every showcase reported, those not asked for now kept as they were;
bench/benchmark.py --showcases includes it),
doc/showcases.rst (a table per showcase) and doc/img/showcase_<name>.png (answer against wall
time, the uniform runs' convergence joined by a line).

  python3 -m sph_soil showcase [vertical-cut slope bearing-capacity shallow-landslide] [--run] [--lmp build/lmp] [--np 2]
                               [--workdir /tmp/sph_soil_showcase]
"""
import argparse
import json
import os
import sys

import numpy as np

from .. import paths, report
from . import bearing_capacity, landslide, strength_reduction, vertical_cut

COMMAND = 'showcase'

# name, label, the study's command-line options (the showcase's own 'options' are added: a
# bisection's bracket); 'answer' turns a study's JSON into the fields compare() reads (critical,
# half_width, stands_up_to, fails_from, wall_seconds_all_runs and the refinement's), by default
# the JSON itself (a bisection's summary has them)
SHOWCASES = {
    'vertical-cut': {
        'study': vertical_cut,
        # the refined configurations check every 48 steps (the soil moves far less than a spacing)
        'options': ['--low', '3.5', '--high', '4.5', '--steps', '3', '--every', '48'],
        'title': 'Vertical cut, phi = 0: critical gamma H / c (Pastor et al. 2000: 3.772-3.786)',
        'quantity': 'critical gamma H / c', 'reference': 0.5 * sum(vertical_cut.PASTOR),
        'configurations': [
            ('u5', 'uniform 5 cm', ['--d', '0.05']),
            ('u25', 'uniform 2.5 cm', ['--d', '0.025']),
            ('u125', 'uniform 1.25 cm', ['--d', '0.0125']),
            ('l1_level', 'maxlevel 1 from 2.5 cm, a step per level',
             ['--d', '0.025', '--refine', '1', '--stepping', 'level', '--balance']),
            ('l2_level', 'maxlevel 2 from 5 cm, a step per level',
             ['--d', '0.05', '--refine', '2', '--stepping', 'level', '--balance']),
            ('l2_global', 'maxlevel 2 from 5 cm, one global step',
             ['--d', '0.05', '--refine', '2', '--balance']),
            ('l3_level', 'maxlevel 3 from 10 cm, a step per level',
             ['--d', '0.1', '--refine', '3', '--stepping', 'level', '--balance']),
            ('l2_level_buffer', 'maxlevel 2 from 5 cm, a step per level, buffer 1',
             ['--d', '0.05', '--refine', '2', '--stepping', 'level', '--balance', '--buffer', '1']),
            ('l3_level_buffer', 'maxlevel 3 from 10 cm, a step per level, buffer 1',
             ['--d', '0.1', '--refine', '3', '--stepping', 'level', '--balance', '--buffer', '1']),
        ]},
    'slope': {
        'study': strength_reduction, 'options': ['--low', '1.25', '--high', '1.5', '--steps', '1'],
        'title': 'Slope (Griffiths & Lane 1999, example 1): factor of safety (their FE: 1.4)',
        'quantity': 'factor of safety', 'reference': strength_reduction.REFERENCE,
        'configurations': [
            ('u05', 'uniform 0.5 m', ['--d', '0.5']),
            ('u025', 'uniform 0.25 m', ['--d', '0.25']),
            ('u0125', 'uniform 0.125 m', ['--d', '0.125']),
            # the input's refinement: a buffer of one support, walls at the finest spacing
            ('l1_from05_level', 'maxlevel 1 from 0.5 m, a step per level, buffer 1',
             ['--d', '0.5', '--refine', '1', '--stepping', 'level', '--balance']),
            ('l1_from05_level_nobuffer', 'maxlevel 1 from 0.5 m, a step per level, no buffer',
             ['--d', '0.5', '--refine', '1', '--stepping', 'level', '--balance', '--buffer', '0']),
            ('l2_level', 'maxlevel 2 from 0.5 m, a step per level, buffer 1',
             ['--d', '0.5', '--refine', '2', '--stepping', 'level', '--balance']),
            ('l2_global', 'maxlevel 2 from 0.5 m, one global step, buffer 1',
             ['--d', '0.5', '--refine', '2', '--balance']),
            ('l1_from025_level', 'maxlevel 1 from 0.25 m, a step per level, buffer 1',
             ['--d', '0.25', '--refine', '1', '--stepping', 'level', '--balance']),
        ]},
    'bearing-capacity': {
        # phi = 0 in the box 8 B x 2.5 B, which holds its mechanism; no picture of the mechanism.
        # The refinement checks every 64 steps (16 of the coarse level's with maxlevel 2; a
        # configuration's own --every comes later and wins): the footing moves 0.2 mm between
        # checks, a hundredth of the finest spacing
        'study': bearing_capacity, 'answer': bearing_capacity.showcase_answer,
        'options': ['--phis', '0', '--width', '8', '--depth', '2.5', '--mechanism', '', '--every', '64'],
        'title': 'Smooth strip footing, phi = 0 (Prandtl): limit pressure q / (c N_c)',
        'quantity': 'limit pressure q / (c N_c)', 'reference': 1.0,
        'configurations': [
            ('u10', 'uniform B/d = 10', ['--resolutions', '10']),
            ('u20', 'uniform B/d = 20', ['--resolutions', '20']),
            ('u40', 'uniform B/d = 40', ['--resolutions', '40']),
            ('l1_level', 'maxlevel 1 from B/d = 10, a step per level, buffer 1',
             ['--resolutions', '10', '--refine', '1', '--stepping', 'level', '--balance']),
            ('l2_level', 'maxlevel 2 from B/d = 10, a step per level, buffer 1',
             ['--resolutions', '10', '--refine', '2', '--stepping', 'level', '--balance']),
            ('l2_global', 'maxlevel 2 from B/d = 10, one global step, buffer 1',
             ['--resolutions', '10', '--refine', '2', '--balance']),
            ('l2_level_nobuffer', 'maxlevel 2 from B/d = 10, a step per level, no buffer',
             ['--resolutions', '10', '--refine', '2', '--stepping', 'level', '--balance', '--buffer', '0']),
            ('l2_level_N16', 'maxlevel 2 from B/d = 10, a step per level, buffer 1, checks every 16 steps',
             ['--resolutions', '10', '--refine', '2', '--stepping', 'level', '--balance', '--every', '16']),
            ('l1_from20_level', 'maxlevel 1 from B/d = 20, a step per level, buffer 1',
             ['--resolutions', '20', '--refine', '1', '--stepping', 'level', '--balance']),
        ]},
    'shallow-landslide': {
        # 3D: the uniform 5 cm run (about 5 hours on 2 cores by the measured scaling) is left to
        # --run; the finest run measured may be 10 cm
        'study': landslide, 'answer': landslide.showcase_answer,
        'options': ['--run', '--example', 'shallow_landslide'],
        'title': 'Shallow landslide in 3D: runout of the patch that fails (99% of its volume behind)',
        'quantity': 'runout (m)', 'reference': None, 'target': 0.1,
        # beside the answer, in the JSON and the table
        'extra': ('deposit_height_m', 'deposit_volume_fraction_on_floor', 'standing_volume_on_floor_m3'),
        'configurations': [
            ('u20', 'uniform 20 cm', ['--d', '0.2']),
            ('u10', 'uniform 10 cm', ['--d', '0.1']),
            ('l1_level', 'maxlevel 1 from 20 cm, a step per level',
             ['--d', '0.2', '--refine', '1', '--stepping', 'level', '--balance']),
            ('l2_level', 'maxlevel 2 from 20 cm, a step per level',
             ['--d', '0.2', '--refine', '2', '--stepping', 'level', '--balance']),
            ('u5', 'uniform 5 cm', ['--d', '0.05']),
        ]},
}


def run_configuration(showcase, name, options, args):
    """One configuration's study, in this process (the study's own main)."""
    directory = os.path.join(args.workdir, showcase)
    os.makedirs(directory, exist_ok=True)
    study = SHOWCASES[showcase]['study']
    argv = [*SHOWCASES[showcase]['options'], *options, '--np', str(args.np),
            '--workdir', os.path.join(directory, 'runs'), '--json', os.path.join(directory, f'{name}.json'),
            '--plot', os.path.join(directory, f'{name}.png')] + (['--lmp', args.lmp] if args.lmp else [])
    print(f'showcase {showcase}: {name}: python3 -m sph_soil {study.COMMAND} {" ".join(argv)}', file=sys.stderr,
          flush=True)
    parser = argparse.ArgumentParser(prog=study.COMMAND)
    study.add_arguments(parser)
    try:
        study.main(parser.parse_args(argv))
    except SystemExit as e:     # e.g. the bracket does not hold for this configuration: go on
        print(f'showcase {showcase}: {name} gave no result: {e}', file=sys.stderr, flush=True)


def compare(showcase, results):
    """Every configuration against the finest uniform one. results: name -> its study's JSON."""
    spec = SHOWCASES[showcase]
    uniform = sorted((r['spacing_m'], name) for name, r in results.items() if not r['refined'])
    if not uniform:
        return None
    finest = results[uniform[0][1]]
    # the tolerance: the difference between the two finest uniform runs' answers
    tolerance = abs(finest['critical'] - results[uniform[1][1]]['critical']) if len(uniform) > 1 else None
    by_spacing = {spacing: results[name] for spacing, name in uniform}
    growth = uniform_growth(uniform, results)
    rows = []
    for name, label, _ in spec['configurations']:
        if name not in results:
            continue
        r = results[name]
        # the uniform run at this configuration's finest spacing, if it was run
        same = by_spacing.get(r.get('finest_spacing_m', r['spacing_m'])) if r['refined'] else None
        rows.append({
            **{field: r.get(field) for field in spec.get('extra', ())},
            'name': name, 'label': label, 'spacing_m': r['spacing_m'],
            'finest_spacing_m': r.get('finest_spacing_m', r['spacing_m']), 'refined': r['refined'],
            'stepping': r.get('stepping'), 'buffer': r.get('buffer'), 'ease': r.get('ease'),
            'split': r.get('split'), 'critical': r['critical'], 'half_width': r['half_width'],
            'stands_up_to': r['stands_up_to'], 'fails_from': r['fails_from'],
            'wall_seconds': r['wall_seconds_all_runs'],
            'cost_over_finest_uniform': round(r['wall_seconds_all_runs'] / finest['wall_seconds_all_runs'], 3),
            'difference_from_finest_uniform': round(r['critical'] - finest['critical'], 5),
            'within_tolerance': None if tolerance is None else abs(r['critical'] - finest['critical']) <= tolerance + 1e-12,
            'difference_from_uniform_at_its_spacing': None if same is None else round(r['critical'] - same['critical'], 5),
            'cost_over_uniform_at_its_spacing':
                None if same is None else round(r['wall_seconds_all_runs'] / same['wall_seconds_all_runs'], 3),
        })
        if r['refined'] and same is None and growth:
            # finer than every uniform run: against the finest one's time extrapolated
            halvings = np.log2(finest['spacing_m'] / rows[-1]['finest_spacing_m'])
            estimate = finest['wall_seconds_all_runs'] * growth ** halvings
            rows[-1]['cost_over_uniform_at_its_spacing_extrapolated'] = round(r['wall_seconds_all_runs'] / estimate, 3)
    return {'title': spec['title'], 'quantity': spec['quantity'], 'reference': spec['reference'],
            'target': spec.get('target', 0.2), 'extra': list(spec.get('extra', ())), 'finest_uniform': uniform[0][1],
            'finest_uniform_spacing_m': uniform[0][0], 'tolerance': tolerance,
            'uniform_cost_growth_per_halving': None if growth is None else round(growth, 2), 'configurations': rows}


def uniform_growth(uniform, results):
    """The wall time's growth per halving of the spacing between the two finest uniform runs
    (None with fewer than two): what extrapolates a uniform run finer than those measured."""
    if len(uniform) < 2:
        return None
    (fine, name), (coarse, other) = uniform[:2]
    return (results[name]['wall_seconds_all_runs'] / results[other]['wall_seconds_all_runs']) ** \
        (1.0 / np.log2(coarse / fine))


def figure(showcase, summary, out):
    """The answer (a bisection's bracket as an error bar) against the wall time of all runs."""
    plt = report.pyplot()
    fig, ax = plt.subplots(figsize=(7.5, 6.0))
    rows = summary['configurations']
    uniform = sorted((r for r in rows if not r['refined']), key=lambda r: r['wall_seconds'])
    ax.errorbar([r['wall_seconds'] for r in uniform], [r['critical'] for r in uniform],
                yerr=[r['half_width'] for r in uniform], color='black', marker='s', capsize=3,
                label='uniform (convergence)')
    for r in uniform:
        ax.annotate(f"{r['spacing_m']:g} m", (r['wall_seconds'], r['critical']), textcoords='offset points',
                    xytext=(5, 5), fontsize=8)
    markers = {1: 'o', 2: 'D', 3: '^'}
    for r in rows:
        if r['refined']:
            colour = 'tab:green' if r.get('split') else 'tab:red' if r['stepping'] == 'level' else 'tab:blue'
            ax.errorbar([r['wall_seconds']], [r['critical']], yerr=[r['half_width']], capsize=3,
                        marker=markers.get(r['refined'], 'v'), linestyle='none', color=colour,
                        label=f"{r['label']} ({r['cost_over_finest_uniform']:.2f}x)")
    finest = next(r for r in rows if r['name'] == summary['finest_uniform'])
    if summary['tolerance']:
        ax.axhspan(finest['critical'] - summary['tolerance'], finest['critical'] + summary['tolerance'],
                   color='0.9', zorder=0, label='finest uniform +- its difference from the next')
    if summary['reference'] is not None:
        ax.axhline(summary['reference'], color='tab:green', linestyle='--',
                   label=f"published: {summary['reference']:g}")
    target = summary.get('target', 0.2)
    ax.axvline(target * finest['wall_seconds'], color='0.5', linestyle=':', label=f'{target:g}x the finest uniform run')
    ax.set_xscale('log')
    ax.set_xlabel('wall time of the configuration, all runs (s, 2 ranks)')
    ax.set_ylabel(summary['quantity'])
    ax.set_title(summary['title'], fontsize=9)
    ax.legend(fontsize=6.5, loc='upper center', bbox_to_anchor=(0.5, -0.16), ncol=2)
    fig.tight_layout()
    fig.savefig(out, dpi=110)


def at_its_spacing(r):
    """The table's last column: the difference from and the cost over the uniform run at the
    configuration's finest spacing, or the cost over that run's extrapolated time (~)."""
    if r['cost_over_uniform_at_its_spacing'] is not None:
        return f"{r['difference_from_uniform_at_its_spacing']:+.4g} / {r['cost_over_uniform_at_its_spacing']:.2f}"
    if r.get('cost_over_uniform_at_its_spacing_extrapolated') is not None:
        return f"- / ~{r['cost_over_uniform_at_its_spacing_extrapolated']:.2f} (extrapolated)"
    return '-'


def table(summary):
    extra = summary.get('extra', [])
    header = ['configuration', 'finest spacing (m)', 'stands up to', 'fails from', 'answer', *extra,
              'from finest uniform', 'within', 'wall (s)', 'cost / finest uniform',
              'from / cost of uniform at its spacing']
    def bound(value):
        return '-' if value is None else f'{value:g}'

    def answer(r):      # a bisection's middle and half width, or one run's value
        return f"{r['critical']:.4g} +- {r['half_width']:.3g}" if r['half_width'] else f"{r['critical']:.4f}"

    rows = [[r['label'], f"{r['finest_spacing_m']:g}", bound(r['stands_up_to']), bound(r['fails_from']),
             answer(r), *[bound(r.get(field)) for field in extra], f"{r['difference_from_finest_uniform']:+.4g}",
             {True: 'yes', False: 'no', None: '-'}[r['within_tolerance']], f"{r['wall_seconds']:.0f}",
             f"{r['cost_over_finest_uniform']:.2f}",
             at_its_spacing(r)]
            for r in summary['configurations']]
    return report.rst_table(header, rows)


def add_arguments(p):
    p.add_argument('showcases', nargs='*', metavar='SHOWCASE',
                   help=f'the showcases ({", ".join(SHOWCASES)}; default: all)')
    p.add_argument('--run', action='store_true', help='run the configurations whose JSON is missing')
    p.add_argument('--lmp', default=None, help='the LAMMPS executable of the runs')
    p.add_argument('--np', type=int, default=2)
    p.add_argument('--workdir', default='/tmp/sph_soil_showcase')
    p.add_argument('--doc', default=paths.DOC, help='where showcases.json, showcases.rst and img/ go')


def main(args):
    unknown = [s for s in args.showcases if s not in SHOWCASES]
    if unknown:
        raise SystemExit(f'showcase: unknown {", ".join(unknown)} (known: {", ".join(SHOWCASES)})')
    summaries = {}
    for showcase in args.showcases or list(SHOWCASES):
        directory = os.path.join(args.workdir, showcase)
        results = {}
        for name, _, options in SHOWCASES[showcase]['configurations']:
            path = os.path.join(directory, f'{name}.json')
            if not os.path.exists(path) and args.run:
                run_configuration(showcase, name, options, args)
            if os.path.exists(path):
                with open(path) as f:
                    results[name] = SHOWCASES[showcase].get('answer', lambda summary: summary)(json.load(f))
        summaries[showcase] = compare(showcase, results)
    summaries = {k: v for k, v in summaries.items() if v}
    os.makedirs(os.path.join(args.doc, 'img'), exist_ok=True)
    # the showcases reported before and not now keep their entries (and their figures)
    path = os.path.join(args.doc, 'showcases.json')
    reported = {}
    if os.path.exists(path):
        with open(path) as f:
            reported = json.load(f)
    for showcase in summaries:
        figure(showcase, summaries[showcase], os.path.join(args.doc, 'img', f'showcase_{showcase}.png'))
    summaries = {**{k: v for k, v in reported.items() if k not in summaries}, **summaries}
    summaries = {k: summaries[k] for k in SHOWCASES if k in summaries}
    report.write_json(summaries, path, indent=1)
    page = ['Refinement showcases (generated)', '=' * 32, '',
            'Written by ``python3 -m sph_soil showcase`` (tools/sph_soil/studies/showcase.py): each failure (bisected,',
            'or one run) coarse, with dynamic refinement and uniformly at the finest spacing, on 2 ranks of the same machine in one',
            'batch. "within": the answer is within the difference between the two finest uniform runs of the finest',
            'one\'s; wall: all runs of the configuration (a bisection\'s or one run).', '']
    for showcase, summary in summaries.items():
        page += [summary['title'], '"' * len(summary['title']), '', table(summary), '',
                 f'.. image:: img/showcase_{showcase}.png', '   :width: 90%', '']
    with open(os.path.join(args.doc, 'showcases.rst'), 'w') as f:
        f.write('\n'.join(page))
