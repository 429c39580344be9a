"""Convergence of a classic check as the particle spacing shrinks: each answer at three or four
spacings, its observed order, Richardson's extrapolate with Roache's grid-convergence index, and
its change when the dissipation is halved and doubled.

    python3 -m sph_soil convergence CHECK [--spacings D1 D2 D3 ...] [--short] [--dissipation 0.5 2]
                                          [--no-dissipation] [--var NAME=VALUE ...] [--np 2] [--lmp build/lmp]
                                          [--workdir /tmp/sph_soil_convergence] [--rerun]
                                          [--json F] [--plot F] [--doc] [--require-order P]
    python3 -m sph_soil convergence --list
    python3 -m sph_soil convergence --table        # doc/convergence.json as a reStructuredText table

CHECK is one of studies/convergence_checks.py (--list names them): an example run at each spacing
(coarsest first, a constant ratio; the check's own sequence by default, --short its quick one),
every answer a ratio to its exact or published value (1 is right). Then, at the finest spacing,
the run again with the dissipation (Monaghan's alpha = beta, the example's `viscosity`) times each
factor of --dissipation (0.5 and 2 by default; --no-dissipation skips them). A check of a chaotic
problem (the bars' collapse) runs an ensemble at each point, its members the same run with the
particles moved off their lattice by a tiny random amount (each member its own seed; --members
sets their number): the answer is the members' mean, and its spread is reported. --var sets an
input variable of every run (a variant of the scheme: --var correction=yes). Each run has its
own directory under --workdir/CHECK, and a run whose directory already holds its answers
(answers.json, written after the run with the variables it ran with) is not run again unless
--rerun (--remeasure measures it again).

Per answer the report gives each spacing's value, and for each consecutive triple of spacings the
observed order p = log_r((f3 - f2) / (f2 - f1)), the extrapolate f1 + (f1 - f2) / (r^p - 1) and
the GCI of the finest answer (sph_soil.verification); an oscillating or flat sequence has none.
The dissipation's share is the finest answer's relative change at each factor. The summary's
`converges` is true when the last triple's observed order is at least 1 and its extrapolate lies
within 2% of the reference, or when the two finest answers agree within 0.1% (`settled`: no
order can be observed below the noise of the measure) and lie within 2% of it; --require-order P exits with status 1 unless the primary answer's last
observed order is at least P (the ctest of the short sequence).

Prints the JSON (also to --json) and plots (--plot) each answer against the spacing, with the
reference and the extrapolate, and the error |f - 1| against the spacing on log axes. --doc also
files both with the documentation: the plot as doc/img/convergence_CHECK[_VARIANT].png and the
result under its name in doc/convergence.json (the numbers of doc/validation.rst).
"""
import json
import os
import shutil
import statistics
import sys
import time

from .. import paths, report, runner, verification
from . import convergence_checks as checks

COMMAND = 'convergence'
ORDER_NEEDED = 1.0        # observed order of a converging sequence (issue: answers that converge)
WITHIN = 0.02             # the extrapolate's distance from the reference
SETTLED = 1.0e-3          # two finest answers closer than this have settled: no order to observe


def extra_variables(args):
    """The variant's input variables, --var NAME=VALUE: (name, value) pairs."""
    return [tuple(v) for v in args.var or []]


def tag(spacing, factor, extra=(), member=None):
    """A run's directory: its spacing, dissipation factor, variant and ensemble member."""
    return (f'd{spacing:g}' + ('' if factor == 1.0 else f'_dissipation{factor:g}')
            + ''.join(f'_{name}{value}' for name, value in extra)
            + ('' if member is None else f'_member{member}'))


def members(check, args):
    """The ensemble's size: --members, else the check's own (1: a single run)."""
    return args.members or check.ensemble


def run_point(lmp, check, spacing, factor, args):
    """The answers at one spacing and dissipation: one run's, or an ensemble's mean, with each
    answer's spread (the sample standard deviation over the members) and the members' values
    among the diagnostics."""
    size = members(check, args)
    if size <= 1:
        return run_one(lmp, check, spacing, factor, args)
    runs = [run_one(lmp, check, spacing, factor, args, member=k) for k in range(1, size + 1)]
    point = {k: runs[0][k] for k in ('spacing', 'dissipation_factor', 'dissipation')}
    point.update(returncode=max(r['returncode'] for r in runs),
                 wall_seconds=round(sum(r['wall_seconds'] for r in runs), 1),
                 directory=os.path.dirname(runs[0]['directory']), members=size, answers={}, diagnostics={})
    for key in check.answers:
        values = [r['answers'][key] for r in runs if key in r['answers']]
        if values:
            point['answers'][key] = statistics.mean(values)
            point['diagnostics'][f'{key}_members'] = values
            point['diagnostics'][f'{key}_spread'] = statistics.stdev(values) if len(values) > 1 else None
    errors = [r['error'] for r in runs if r.get('error')]
    if errors:
        point['error'] = f'{len(errors)} of {size} members: {errors[0]}'
    return point


def run_one(lmp, check, spacing, factor, args, member=None):
    """The answers of one run (from its directory when it already holds them)."""
    extra = extra_variables(args)
    directory = os.path.join(args.workdir, check.name, tag(spacing, factor, extra, member))
    variables = list(check.variables) + extra + [(check.spacing_variable, f'{spacing:.10g}'),
                                                 (check.dissipation_variable, f'{check.dissipation * factor:g}')]
    if member is not None:
        variables += list(check.member_variables) + [(check.member_variable, str(member))]
    saved = os.path.join(directory, 'answers.json')
    if not args.rerun and os.path.exists(saved):
        with open(saved) as f:
            previous = json.load(f)
        if previous.get('variables') == [list(v) for v in variables]:
            if args.remeasure and not check.solve:
                return save(check, spacing, previous, saved)
            return previous
    os.makedirs(directory, exist_ok=True)
    run = {'spacing': spacing, 'dissipation_factor': factor, 'dissipation': check.dissipation * factor,
           'variables': [list(v) for v in variables], 'directory': directory}
    start = time.time()
    if check.solve:
        # an answer of several runs, each in a directory of its own under this one
        try:
            measured = check.solve(lmp, directory, variables, args.np)
        except RuntimeError as e:
            measured = e
        run.update(returncode=0 if isinstance(measured, dict) else 1, wall_seconds=round(time.time() - start, 1))
        return save(check, spacing, run, saved, measured)
    done = lmp.run(check.infile, directory, np=args.np, variables=variables, copy=True)
    run.update(returncode=done.returncode, wall_seconds=round(done.seconds, 1))
    return save(check, spacing, run, saved)


def save(check, spacing, run, saved, measured=None):
    """Measure a finished run (its answers, the diagnostics, or the error that stopped it) and
    save it beside the run; `measured`: what a check that solves measured (or its error)."""
    error = None
    if isinstance(measured, Exception):
        measured, error = {}, str(measured)
    elif measured is None:
        try:
            measured = check.measure(run['directory'], spacing)
        except (RuntimeError, OSError, ValueError, IndexError) as e:
            measured, error = {}, str(e)
    run = {k: v for k, v in run.items() if k not in ('answers', 'diagnostics', 'error')}
    run['answers'] = {k: measured[k] for k in check.answers if measured.get(k) is not None}
    run['diagnostics'] = {k: v for k, v in measured.items() if k not in check.answers}
    if error:
        run['error'] = error
    with open(saved, 'w') as f:
        json.dump(run, f, indent=1)
    return run


def judge(check, spacings, runs, dissipation_runs):
    """Per answer: the values, the triples' orders, extrapolates and GCIs, and the dissipation's
    share at the finest spacing."""
    summary = {}
    for key, what in check.answers.items():
        values = [r['answers'].get(key) for r in runs]
        entry = {'what': what, 'values': values, 'errors': [None if v is None else v - 1.0 for v in values]}
        spreads = [r.get('diagnostics', {}).get(f'{key}_spread') for r in runs]
        if any(x is not None for x in spreads):
            entry['spreads'] = spreads      # an ensemble's: the members' standard deviation
        if all(v is not None for v in values) and len(values) >= 3:
            triples = verification.sequence(spacings, values)
            entry['triples'] = triples
            last = triples[-1]
            entry['observed_order'] = last['observed_order']
            entry['extrapolated'] = last['extrapolated']
            entry['gci'] = last['gci']
            entry['converges'] = bool(last['observed_order'] is not None and last['observed_order'] >= ORDER_NEEDED
                                      and abs(last['extrapolated'] - 1.0) <= WITHIN)
            if abs(values[-1] - values[-2]) < SETTLED:
                # the two finest agree to the noise of the measure (a time average, say): the
                # answer has settled, and its differences no longer have an order
                entry['settled'] = True
                entry['converges'] = abs(values[-1] - 1.0) <= WITHIN
        elif all(v is not None for v in values) and len(values) == 2:
            entry['observed_order'] = None
        finest = values[-1]
        entry['dissipation'] = {}
        for r in dissipation_runs:
            v = r['answers'].get(key)
            entry['dissipation'][f"{r['dissipation_factor']:g}"] = (
                None if v is None or finest is None else {'value': v, 'change': (v - finest) / finest})
        summary[key] = entry
    return summary


def ticks(ax, spacings):
    """The spacings themselves as the ticks of a logarithmic axis."""
    ax.set_xticks(list(spacings))
    ax.set_xticklabels([f'{d:g}' for d in spacings])
    ax.minorticks_off()


def plot(check, spacings, summary, out, extra=()):
    plt = report.pyplot()
    keys = list(summary)
    fig, axes = plt.subplots(len(keys), 2, figsize=(10, 3.4 * len(keys)), squeeze=False)
    for (left, right), key in zip(axes, keys):
        entry = summary[key]
        pairs = [(d, v) for d, v in zip(spacings, entry['values']) if v is not None]
        if not pairs:
            continue
        ds, vs = zip(*pairs)
        if entry.get('spreads'):
            spread = [x or 0.0 for d, x in zip(spacings, entry['spreads']) if d in ds]
            left.errorbar(ds, vs, yerr=spread, fmt='o-', capsize=3, label='SPH: ensemble mean +- spread')
        else:
            left.plot(ds, vs, 'o-', label='SPH')
        left.axhline(1.0, color='k', lw=0.8, label='reference')
        if entry.get('extrapolated') is not None:
            left.axhline(entry['extrapolated'], color='tab:green', ls='--', lw=0.8,
                         label=f"extrapolated {entry['extrapolated']:.4f} (p = {entry['observed_order']:.2f})")
        for factor, change in entry['dissipation'].items():
            if change:
                left.plot([ds[-1]], [change['value']], 'x', label=f'dissipation x {factor}')
        left.set_xscale('log')
        ticks(left, ds)
        left.set_xlabel('particle spacing (m)')
        left.set_ylabel(key + ' / reference')
        left.set_title(entry['what'], fontsize=8)
        left.legend(fontsize=7)
        errors = [abs(v - 1.0) for v in vs]
        right.loglog(ds, [max(e, 1e-7) for e in errors], 'o-', label='|answer - reference|')
        for p, style in ((1, ':'), (2, '--')):
            right.loglog(ds, [errors[0] * (d / ds[0]) ** p for d in ds], style, color='grey', lw=0.8,
                         label=f'order {p}')
        ticks(right, ds)
        right.set_xlabel('particle spacing (m)')
        right.set_ylabel('relative error')
        right.legend(fontsize=7)
    fig.suptitle(f'{check.name}: {check.title}' + ''.join(f', {k} {v}' for k, v in extra), fontsize=9)
    fig.tight_layout()
    fig.savefig(out, dpi=110)


def convergence(lmp, check, args):
    spacings = tuple(args.spacings or (check.short_spacings if args.short else check.spacings))
    verification.constant_ratio(spacings)
    runs = [run_point(lmp, check, d, 1.0, args) for d in spacings]
    factors = [] if (args.no_dissipation or args.short) else args.dissipation
    dissipation_runs = [run_point(lmp, check, spacings[-1], f, args) for f in factors]
    summary = judge(check, spacings, runs, dissipation_runs)
    result = {'check': check.name, 'title': check.title, 'reference': check.reference,
              'variant': dict(extra_variables(args)), 'spacings': list(spacings), 'ratio': verification.constant_ratio(spacings),
              'dissipation_variable': check.dissipation_variable, 'dissipation': check.dissipation,
              'answers': summary,
              'runs': [{k: v for k, v in r.items() if k != 'variables'} for r in runs + dissipation_runs]}
    report.write_json(result, args.json, indent=1)
    if args.plot:
        plot(check, spacings, summary, args.plot, extra_variables(args))
    return result


def add_arguments(p):
    p.add_argument('check', nargs='?', help='the check (--list names them)')
    p.add_argument('--list', action='store_true', help='name the checks and stop')
    p.add_argument('--table', action='store_true', help='print doc/convergence.json as a table and stop')
    runner.add_arguments(p)
    p.add_argument('--spacings', type=float, nargs='+', help='coarsest first, a constant ratio')
    p.add_argument('--short', action='store_true', help="the check's quick sequence, without the dissipation's runs")
    p.add_argument('--dissipation', type=float, nargs='+', default=[0.5, 2.0],
                   help='factors of the dissipation at the finest spacing (default: %(default)s)')
    p.add_argument('--no-dissipation', action='store_true')
    p.add_argument('--members', type=int, default=None,
                   help="the ensemble's size of a check that runs ensembles (the check's own by default)")
    runner.add_variable_argument(p, 'an input variable of every run (repeatable): a variant of the scheme')
    p.add_argument('--workdir', default='/tmp/sph_soil_convergence')
    p.add_argument('--rerun', action='store_true', help='run again where answers are saved')
    p.add_argument('--remeasure', action='store_true',
                   help='measure the saved runs again (after a change of what a check measures)')
    p.add_argument('--json')
    p.add_argument('--plot')
    p.add_argument('--doc', action='store_true',
                   help='file the result in doc/convergence.json and the plot in doc/img/')
    p.add_argument('--require-order', type=float, default=None,
                   help="exit 1 unless the primary answer's last observed order is at least this")


DOC_JSON = os.path.join(paths.DOC, 'convergence.json')


def file_with_doc(result, plot_path):
    """The result under its name (check and variant) in doc/convergence.json, and its plot in
    doc/img/."""
    name = result['check'] + ''.join(f'_{k}_{v}' for k, v in result['variant'].items())
    filed = {}
    if os.path.exists(DOC_JSON):
        with open(DOC_JSON) as f:
            filed = json.load(f)
    filed[name] = {k: v for k, v in result.items() if k != 'runs'}
    filed[name]['wall_seconds'] = {f"{r['spacing']:g}" + ('' if r['dissipation_factor'] == 1.0 else
                                                          f" x{r['dissipation_factor']:g}"): r['wall_seconds']
                                   for r in result['runs']}
    report.write_json(dict(sorted(filed.items())), DOC_JSON, indent=1, echo=False)
    if plot_path:
        shutil.copy(plot_path, os.path.join(paths.DOC_IMG, f'convergence_{name}.png'))


def fmt(value, spec):
    return '-' if value is None else format(value, spec)


def table(filed):
    """The filed results (doc/convergence.json) as one reStructuredText table: per check, variant
    and answer, the answers coarsest first, the last triple's observed order, extrapolate and GCI,
    and the finest answer's change with the dissipation halved and doubled."""
    rows = []
    for name, r in filed.items():
        for key, e in r['answers'].items():
            last = (e.get('triples') or [{}])[-1]
            change = {f: (c['change'] if c else None) for f, c in e['dissipation'].items()}
            rows.append([name, key, ', '.join(f'{d:g}' for d in r['spacings']),
                         ', '.join(fmt(v, '.4f') for v in e['values']),
                         'settled' if e.get('settled') else fmt(last.get('observed_order'), '.2f'),
                         fmt(e['values'][-1] if e.get('settled') else last.get('extrapolated'), '.4f'),
                         fmt(last.get('gci'), '.1%'),
                         ' / '.join(fmt(change.get(f), '+.3%') for f in ('0.5', '2')),
                         'yes' if e.get('converges') else 'no'])
    text = report.rst_table(['check', 'answer', 'spacings (m)', 'answer / reference', 'order', 'extrapolated',
                             'GCI', 'dissipation x0.5 / x2', 'converges'], rows)
    return '\n'.join(line.rstrip() for line in text.split('\n'))


def main(args):
    if args.table:
        with open(DOC_JSON) as f:
            print(table(json.load(f)))
        return
    if args.list or not args.check:
        for c in checks.CHECKS.values():
            print(f'{c.name:16s} {c.title}; reference: {c.reference}')
        return
    check = checks.check(args.check)
    lmp = runner.from_arguments(args)
    result = convergence(lmp, check, args)
    if args.doc:
        file_with_doc(result, args.plot)
    if args.require_order is not None:
        order = result['answers'][check.primary].get('observed_order')
        if order is None or order < args.require_order:
            print(f'convergence: {check.name}: the observed order of {check.primary} is {order}, '
                  f'not at least {args.require_order}', file=sys.stderr)
            sys.exit(1)
