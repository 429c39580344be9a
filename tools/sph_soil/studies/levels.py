"""Deep refinement against converged uniform runs: maxlevel 1, 2 and 3, merging off and on.

The refinement comparison's second part (issue 28, item 7). Runs examples/refinement/in.refinement's
dynamic runs (separation and smoothing 0.5) in examples/refinement/levels, for each problem, each
criterion of CRITERIA (the strain measure since the particle's own split, the default, for both;
the shear strain rate above 10/s for the bars), each maxlevel of --maxlevels (default 1 and 2)
and merging off and on (`merge T`, MERGE_TIME of the problem; with merging the run goes on to
REST of the problem, where the soil has come to rest, and the particles left there are counted).
Every run keeps the artificial viscosity of the coarse h on every level (-var h0 1), so that it
is measured against the uniform lattice at its finest spacing d / 2^maxlevel with the same
dissipation (mode coarse -var spacing; the bars' are the resolution study's runs, in
examples/refinement/resolution, python3 -m sph_soil resolution [--finest]; missing ones are run
here with --references). For each run:
  - completed, or where it stopped (the instability guard's step);
  - surface_rms_vs_uniform_m: the RMS distance of its final free surface (at the problem's last
    frame time) from that of the uniform run at its finest spacing, over x up to that run's
    runout; uniform_difference_m: the difference of that uniform run from the next coarser one
    (the resolution study's successive difference: what a halving of the spacing still changes);
  - surface_rms_vs_experiment_m (bars), runout_m, failure_angle_deg (refinement.final_state());
  - peak and final soil particles, and with merging the soil particles at rest (REST) over the
    initial ones;
  - most_unbalanced: the most pairs more than one level apart at any check (the fix's log line
    at the end of each run segment); merges and the clusters of orphans among them;
  - wall_seconds (LAMMPS's loop times).
Writes doc/refinement_levels.json, doc/refinement_levels.rst (a table per problem) and
doc/img/refinement_levels_<problem>.png (surfaces, and particles over time).

  python3 -m sph_soil levels collapse                    # maxlevel 1 and 2 of the collapse
  python3 -m sph_soil levels bars --maxlevels 1 2 3      # (maxlevel 2 of the bars: half an hour a run on
                                                         # 2 cores; the uniform 0.5 mm reference an hour)
  python3 -m sph_soil levels --references collapse       # also the uniform runs it lacks
  python3 -m sph_soil levels --compare-only

A run is skipped when its log ends cleanly and is newer than the input and the binary.
"""
import glob
import json
import os
import re

from .. import paths, report, runner
from ..dumps import read_dump
from ..logs import Log
from . import refinement

COMMAND = 'levels'
DIRECTORY = os.path.join(refinement.DIRECTORY, 'levels')
# (label, in.refinement's criterion, threshold) per problem
CRITERIA = {'bars': [('strain since split > 0.05', 'strain', '0.05'),
                     ('shear rate > 10/s', 'shear_strain_rate', '10')],
            'collapse': [('strain since split > 0.05', 'strain', '0.05')]}
# the hold time of merging: about a tenth of the time the soil takes to come to rest
MERGE_TIME = {'bars': '0.05', 'collapse': '0.1'}
# with merging, the run goes on to this time (s), where the soil rests
REST = {'bars': '1.0', 'collapse': '4'}


def run_name(problem, criterion, threshold, maxlevel, merge):
    """in.refinement's name of a dynamic run of (0.5, 0.5) with -var h0 1."""
    name = f'{problem}_dynamic_0.5_0.5_h0'
    if threshold != '0.05':
        name += f'_t{threshold}'
    if criterion != 'strain':
        name += f'_{criterion}'
    if maxlevel != 1:
        name += f'_L{maxlevel}'
    if merge:
        name += f'_merge{MERGE_TIME[problem]}'
    return name


def uniform_spacing(problem, maxlevel):
    return refinement.PROBLEMS[problem]['d'] * 0.5 ** maxlevel


def uniform_name(problem, spacing):
    return f'{problem}_coarse_h0_d{spacing:g}'


def uniform_directory(problem):
    """Where the uniform runs are: the bars' in the resolution study's directory."""
    return os.path.join(refinement.DIRECTORY, 'resolution') if problem == 'bars' else DIRECTORY


def runs(problem, maxlevels):
    """The matrix of a problem: (name, label, variables, maxlevel, merge)."""
    out = []
    for label, criterion, threshold in CRITERIA[problem]:
        for maxlevel in maxlevels:
            for merge in (False, True):
                variables = [('problem', problem), ('mode', 'dynamic'), ('h0', '1'), ('criterion', criterion),
                             ('threshold', threshold), ('maxlevel', str(maxlevel))]
                if merge:
                    variables += [('merge', MERGE_TIME[problem]), ('rest', REST[problem])]
                text = f'{label}, maxlevel {maxlevel}, ' + (f'merge {MERGE_TIME[problem]} s' if merge else 'no merging')
                out.append((run_name(problem, criterion, threshold, maxlevel, merge), text, variables, maxlevel,
                            merge))
    return out


def up_to_date(log, lmp_binary):
    return (os.path.exists(log) and os.path.getmtime(log) > os.path.getmtime(refinement.INPUT)
            and os.path.getmtime(log) > os.path.getmtime(lmp_binary) and 'Total wall time' in open(log).read())


def run_missing(lmp, problems, maxlevels, np_, references, only):
    os.makedirs(DIRECTORY, exist_ok=True)
    for problem in problems:
        todo = [(name, variables) for name, _, variables, _, _ in runs(problem, maxlevels)]
        if references:
            for maxlevel in sorted(set(maxlevels) | {m - 1 for m in maxlevels if m > 1}):
                spacing = uniform_spacing(problem, maxlevel)
                todo.append((uniform_name(problem, spacing),
                             [('problem', problem), ('mode', 'coarse'), ('h0', '1'), ('spacing', f'{spacing:g}')]))
        for name, variables in todo:
            directory = uniform_directory(problem) if '_coarse_' in name else DIRECTORY
            if only and not re.search(only, name):
                continue
            if up_to_date(os.path.join(directory, f'log.{name}'), lmp.binary):
                print(f'== {name}: up to date', flush=True)
                continue
            print(f'== {name}', flush=True)
            os.makedirs(directory, exist_ok=True)
            for old in glob.glob(os.path.join(directory, f'frame_{name}_*.png')):
                os.remove(old)
            if not lmp.run(refinement.INPUT, directory, np=np_, variables=variables, log=f'log.{name}').ok:
                print(f'== {name} stopped with an error (see log.{name})', flush=True)


def uniform_profile(problem, maxlevel):
    """The final state of the uniform run at spacing d / 2^maxlevel: (measures, profile), or None."""
    spacing = uniform_spacing(problem, maxlevel)
    dump = os.path.join(uniform_directory(problem), f'dump.{uniform_name(problem, spacing)}.final')
    if not os.path.exists(dump):
        return None
    return refinement.final_state(read_dump(dump), problem, spacing * spacing, 1.2 * spacing)


def log_counts(path):
    """From a run's log: the most pairs out of balance at a check, the merges and clusters of
    orphans (summed over the run segments), the soil particles at rest (the input's last print),
    and the soil particle count over time (from the thermo output: Atoms less the walls)."""
    text = open(path).read()
    segments = re.findall(r'(\d+) merges \((\d+) of them clusters of orphans\); the most pairs more than one '
                          r'level apart at a check: (\d+)', text)
    at_rest = re.search(r'refinement: at t = ([\d.]+) s, (\d+) soil particles', text)
    return dict(most_unbalanced=max((int(s[2]) for s in segments), default=0),
                merges=sum(int(s[0]) for s in segments), clusters=sum(int(s[1]) for s in segments),
                rest_time_s=float(at_rest.group(1)) if at_rest else None,
                soil_particles_at_rest=int(at_rest.group(2)) if at_rest else None)


def particles_over_time(path):
    times, atoms = [], []
    for header, rows in Log(path).thermo_tables():
        if 'Atoms' in header and 'v_time' in header:
            t, a = header.index('v_time'), header.index('Atoms')
            for row in rows:
                times.append(float(row[t]))
                atoms.append(int(row[a]))
    return times, atoms


def measure(problem, maxlevels):
    """Every run of the problem there: its entry and its profile."""
    entries, profiles = {}, {}
    uniform = {m: uniform_profile(problem, m) for m in set(maxlevels) | {m - 1 for m in maxlevels}}
    for name, label, _, maxlevel, merge in runs(problem, maxlevels):
        log = os.path.join(DIRECTORY, f'log.{name}')
        if not os.path.exists(log):
            continue
        key = name[len(problem) + 1:]
        entry, profile = refinement.measure_run(log, os.path.join(DIRECTORY, f'dump.{name}.final'), problem, key,
                                                label)
        entry.update(log_counts(log))
        entry['maxlevel'], entry['merge'] = maxlevel, merge
        if profile:
            profiles[name] = profile
            entry['initial_soil_particles'] = initial = _initial_soil_particles(problem)
            if entry['soil_particles_at_rest']:
                entry['at_rest_over_initial'] = round(entry['soil_particles_at_rest'] / initial, 3)
            reference, coarser = uniform.get(maxlevel), uniform.get(maxlevel - 1)
            if reference:
                measures, reference_profile = reference
                entry['uniform_spacing_m'] = uniform_spacing(problem, maxlevel)
                entry['surface_rms_vs_uniform_m'] = refinement.surface_rms_between(
                    reference_profile, profile, measures['runout_m'])
                if coarser:
                    entry['uniform_difference_m'] = refinement.surface_rms_between(
                        reference_profile, coarser[1], measures['runout_m'])
        entries[name] = entry
    return entries, profiles, uniform


def _initial_soil_particles(problem):
    # in.refinement's soil block: 0.2 x 0.1 m (bars) or 4 x 2 m (collapse) on the lattice of d
    spec = refinement.PROBLEMS[problem]
    length = 0.2 if problem == 'bars' else 4.0
    return int(round(length / spec['d'])) * int(round(spec['height'] / spec['d']))


def figure(problem, entries, profiles, uniform, out):
    plt = report.pyplot()
    fig, (top, bottom) = plt.subplots(2, 1, figsize=(9, 6.4))
    for maxlevel, state in sorted(uniform.items()):
        if state:
            grid, height, *_ = state[1]
            top.plot(grid, height, 'k-', lw=2.4 - 0.5 * maxlevel, alpha=0.5,
                     label=f'uniform {1000 * uniform_spacing(problem, maxlevel):g} mm')
    for name, entry in entries.items():
        style = '--' if entry['merge'] else '-'
        if name in profiles:
            grid, height, *_ = profiles[name]
            top.plot(grid, height, style, lw=1.0, label=entry['run'])
        times, atoms = particles_over_time(os.path.join(DIRECTORY, f'log.{name}'))
        bottom.plot(times, atoms, style, lw=1.0, label=entry['run'])
    spec = refinement.PROBLEMS[problem]
    if spec['experiment']:
        exp = refinement.experiment(problem)
        top.plot(exp[:, 0], exp[:, 1], 'ko', ms=3, label='measured')
    top.set_xlabel('x (m)')
    top.set_ylabel('surface height (m)')
    top.set_title(f'{spec["title"]}: final surface (t = {spec["times"][-1]} s), dynamic and uniform', fontsize=10)
    top.legend(fontsize=6, ncol=2)
    bottom.set_xlabel('t (s)')
    bottom.set_ylabel('particles (walls included)')
    bottom.set_title('particles over time (dashed: merging)', fontsize=10)
    fig.tight_layout()
    fig.savefig(out, dpi=110)
    plt.close(fig)


COLUMNS = [('run', 'run', '{}'), ('wall_seconds', 'wall (s)', '{:.0f}'),
           ('surface_rms_vs_uniform_m', 'RMS vs uniform (mm)', '{:.2f}'),
           ('uniform_difference_m', 'uniform vs coarser (mm)', '{:.2f}'),
           ('surface_rms_vs_experiment_m', 'RMS vs exp. (mm)', '{:.2f}'), ('runout_m', 'runout (m)', '{:.3f}'),
           ('failure_angle_deg', 'angle', '{:.1f}'), ('peak_particles', 'peak N', '{}'),
           ('final_particles', 'final N', '{}'), ('at_rest_over_initial', 'at rest / initial', '{:.2f}'),
           ('merges', 'merges', '{}'), ('clusters', 'of them clusters', '{}'),
           ('most_unbalanced', 'unbalanced', '{}')]


def table(entries, experiment):
    cols = [c for c in COLUMNS if experiment or c[0] != 'surface_rms_vs_experiment_m']
    rows = refinement.table_rows(entries.values(), cols)
    return report.rst_table([c[1] for c in cols], rows)


# the maxlevels measured: every one whose runs are there, whichever --maxlevels ran (a run of
# maxlevel 2 alone must not drop the rows of maxlevel 1 from the page)
MAXLEVELS = (1, 2, 3)


def compare(problems, maxlevels=MAXLEVELS):
    jpath = os.path.join(paths.DOC, 'refinement_levels.json')
    summary = json.load(open(jpath)) if os.path.exists(jpath) else {}
    for problem in problems:
        entries, profiles, uniform = measure(problem, maxlevels)
        if not entries:
            print(f'levels: no runs of {problem} in {DIRECTORY}')
            continue
        summary[problem] = entries
        figure(problem, entries, profiles, uniform, os.path.join(paths.DOC_IMG, f'refinement_levels_{problem}.png'))
    report.write_json(summary, jpath, indent=1)
    page = ['Deep refinement against uniform runs (generated)', '=' * 48, '',
            'Written by ``python3 -m sph_soil levels`` (tools/sph_soil/studies/levels.py): dynamic runs of',
            '``examples/refinement/in.refinement`` with the artificial viscosity of the coarse h on every level,',
            'each against the uniform lattice at its finest spacing with the same dissipation. Columns: see the',
            'study\'s docstring.', '']
    for problem in ('bars', 'collapse'):
        if problem not in summary:
            continue
        title = refinement.PROBLEMS[problem]['title']
        page += [title, '"' * len(title), '', table(summary[problem], refinement.PROBLEMS[problem]['experiment']), '',
                 f'.. image:: img/refinement_levels_{problem}.png', '   :width: 90%', '']
    with open(os.path.join(paths.DOC, 'refinement_levels.rst'), 'w') as f:
        f.write('\n'.join(page))


def add_arguments(p):
    runner.add_arguments(p, np=1)
    p.add_argument('problems', nargs='*', default=list(refinement.PROBLEMS), help='bars, collapse (default: both)')
    p.add_argument('--maxlevels', nargs='+', type=int, default=[1, 2], help='maxlevel values (default: 1 2)')
    p.add_argument('--references', action='store_true', help='also run the uniform runs that are missing')
    p.add_argument('--only', default=None, help='only the runs whose name matches this regular expression')
    p.add_argument('--compare-only', action='store_true', help='run nothing: measure the runs there')


def main(a):
    unknown = set(a.problems) - set(refinement.PROBLEMS)
    if unknown:
        raise SystemExit(f'levels: unknown problem(s) {sorted(unknown)}: bars or collapse')
    if not a.compare_only:
        run_missing(runner.from_arguments(a, build=True), a.problems, a.maxlevels, a.np, a.references, a.only)
    compare(a.problems)
