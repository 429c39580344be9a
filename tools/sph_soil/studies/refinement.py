"""The refinement paper's Section IV comparison: coarse, fine and dynamic runs.

Runs the comparison's matrix (RUNS, declared once below: coarse, fine and the dynamic runs of
each problem) in examples/refinement on all cores, then reads the runs'
examples/refinement/{log,dump}.<problem>_<run>.* and, for each run, reports
  - wall_seconds: the sum of the run segments' loop times (LAMMPS "Loop time of ...");
  - wall_us_per_particle_step: wall_seconds over the particle-steps (walls included; the atoms
    of the thermo rows times the steps between them), in microseconds on all ranks together;
  - wall_us_per_soil_particle_step: the same over the soil's particle-steps only (the wall
    particles, the same in every run and never split, taken out: they have no partner among
    themselves and no stress to integrate, so they dilute the coarse run's figure most);
  - peak_particles, final_particles: from the thermo output (walls included, same in every run);
  - surface_rms_vs_fine_m: RMS difference of the final free surface from the fine run's, over
    x in [0, the fine run's runout], the surface being the 0.5 level of the SPH volume fraction
    (sph_soil.analysis: the surface of the continuum the particles stand for; a particle of
    level l has the volume (d 2^-l)^2 and h = 1.2 d alpha_r^l);
    A run of two levels (name ending _L2) is measured against the fine run of two levels
    (fine_L2), and the coarse, fine and paper's dynamic runs also against that one
    (surface_rms_vs_fine_L2_m: what the second level changes);
  - wall_time_vs_fine: wall_seconds over the fine run's (of as many levels);
  - surface_rms_vs_experiment_m (aluminium bars only): the same against the measured surface;
  - runout_m: the furthest x where that surface stands higher than one coarse spacing (2 mm for
    the bars, as in the aluminium-bars study);
  - failure_angle_deg: the angle of the boundary of the soil that moved less than 0.75 coarse
    spacings (1.5 mm for the bars, as in the aluminium-bars study), by initial position;
    daughters carry their parent's initial position (fix store/state is inherited);
  - instability_index: the fraction of soil particles whose nearest neighbour is closer than a
    third of their own spacing. In a lattice the nearest neighbour sits at one spacing, and
    compression alone brings it to about 0.85; pairs at a third of it only form when particles
    clump (the compressive instability that the paper reports as clumps and cracks).
Writes doc/refinement_comparison.json, doc/refinement_comparison.rst (tables) and the pictures
doc/img/refinement_<problem>_frames.png (one row per run), _surface.png and _cost.png (accuracy
against cost: RMS vs fine against the wall time as a fraction of the fine run's).

  python3 -m sph_soil refinement [bars] [collapse]        # run what is missing, then compare
  python3 -m sph_soil refinement --only 'dynamic_0.5' bars  # only the runs whose name matches
  python3 -m sph_soil refinement --two-levels bars          # also maxlevel 2 (the fine run: 1.5 h)
  python3 -m sph_soil refinement --compare-only             # the table and pictures of the runs there

A run is skipped when its final dump is newer than the input and the binary (delete
dump.*.final to force it); a run that stops with an error is reported as stopped. Without --lmp,
a missing lmp is built first (tools/build.sh).
"""
import glob
import json
import math
import os
import re
from dataclasses import dataclass

import numpy as np

from .. import analysis, paths, report, runner
from ..dumps import read_dump
from ..logs import Log

COMMAND = 'refinement'
DIRECTORY = paths.example_dir('refinement')
INPUT = os.path.join(DIRECTORY, 'in.refinement')

PROBLEMS = {
    'bars': dict(d=0.002, height=0.1, times=(0.06, 0.11, 0.6), title='Aluminium bars (Bui et al. 2008)',
                 experiment='examples/aluminium_bars/experiment/surface.csv'),
    'collapse': dict(d=0.04, height=2.0, times=(0.25, 0.45, 1.8), title='Soil collapse (doc/theory.rst 6.2)',
                     experiment=None),
}


@dataclass(frozen=True)
class Run:
    """One run of the comparison: in.refinement's variables (as strings, the way they enter the
    run's name) and the label of the tables and figures."""
    label: str
    mode: str
    eps: str = '0.5'
    alpha: str = '0.5'
    h0: str = '0'
    threshold: str = '0.05'
    criterion: str = 'strain'
    maxlevel: str = '1'
    bars_only: bool = False     # criteria whose thresholds are the bars' rates and strains
    two_levels: bool = False    # run only with --two-levels

    @property
    def key(self):
        """The run's name without its problem, as in.refinement builds it (log.<problem>_<key>)."""
        key = f'dynamic_{self.eps}_{self.alpha}' if self.mode == 'dynamic' else self.mode
        if self.h0 == '1':
            key += '_h0'
        if self.threshold != '0.05':
            key += f'_t{self.threshold}'
        if self.criterion != 'strain':
            key += f'_{self.criterion}'
        if self.maxlevel != '1':
            key += f'_L{self.maxlevel}'
        return key

    def variables(self, problem):
        return [('problem', problem), ('mode', self.mode), ('eps', self.eps), ('alpha', self.alpha),
                ('h0', self.h0), ('threshold', self.threshold), ('criterion', self.criterion),
                ('maxlevel', self.maxlevel)]


# the paper's four (separation, smoothing) pairs, each also with the artificial viscosity that
# follows the level (pair_style sph/soil viscosity_h0: every level dissipates as the coarse one)
PAIRS = [('0.5', '0.5'), ('0.55', '0.5'), ('0.55', '0.6'), ('0.55', '0.7')]
RUNS = ([Run('coarse', 'coarse'), Run('fine (static 0.5, 0.5)', 'fine')] +
        [Run(f'dynamic ({e}, {a})', 'dynamic', e, a) for e, a in PAIRS] +
        [Run(f'dynamic ({e}, {a}), viscosity_h0', 'dynamic', e, a, h0='1') for e, a in PAIRS] +
        # (0.5, 0.5) at thresholds above the paper's 0.05
        [Run(f'dynamic (0.5, 0.5), threshold {t}', 'dynamic', threshold=t) for t in ('0.1', '0.2')] +
        # criteria beyond the paper's (bars only): the shear strain rate and the shear strain
        [Run(f'dynamic (0.5, 0.5), shear rate > {t}/s', 'dynamic', threshold=t, criterion='shear_strain_rate',
             bars_only=True) for t in ('10', '20')] +
        [Run('dynamic (0.5, 0.5), shear strain > 1', 'dynamic', threshold='1.0', criterion='shear_strain',
             bars_only=True)] +
        # two levels (maxlevel 2), against the lattice refined twice: their RMS and cost are
        # measured against that fine run (reference()); the fine run alone takes about 1.5 h on
        # 2 cores, so only with --two-levels
        [Run('fine, 2 levels (static)', 'fine', maxlevel='2', bars_only=True, two_levels=True),
         Run('dynamic (0.5, 0.5), shear rate > 10/s, 2 levels', 'dynamic', threshold='10',
             criterion='shear_strain_rate', maxlevel='2', bars_only=True, two_levels=True),
         Run('dynamic (0.5, 0.5), 2 levels', 'dynamic', maxlevel='2', bars_only=True, two_levels=True)])
LABELS = {run.key: run.label for run in RUNS}


def reference(key):
    """The fine run a run is measured against: the one with as many levels."""
    return 'fine_L2' if key.endswith('_L2') else 'fine'


def read_log(path):
    """Sum of loop times, the Atoms column of every thermo table, the particle-steps (atoms
    integrated over the steps between thermo rows, each interval at its end's count), the
    steps, and whether it ended cleanly."""
    log = Log(path)
    loop = sum(l.seconds for l in log.loops())
    atoms = []
    particle_steps = 0.0
    steps = 0
    last_step = None
    for header, rows in log.thermo_tables():
        if 'Atoms' not in header:
            continue
        a, s = header.index('Atoms'), header.index('Step')
        for row in rows:
            n, step = int(row[a]), int(row[s])
            atoms.append(n)
            if last_step is not None and step > last_step:
                particle_steps += n * (step - last_step)
                steps += step - last_step
            last_step = step
    return loop, atoms, particle_steps, steps, log.error()


def smoothing_ratio(key):
    """alpha_r of a run: the fine run splits with (0.5, 0.5), a dynamic one with its own."""
    if key.startswith('dynamic_'):
        return float(key.split('_')[2])
    return 0.5


def instability_index(x, y, spacing, cell):
    """Fraction of particles whose nearest neighbour is closer than a third of their spacing."""
    keys = np.floor(np.stack([x / cell, y / cell], axis=1)).astype(np.int64)
    cells = {}
    for i, key in enumerate(map(tuple, keys)):
        cells.setdefault(key, []).append(i)
    close = np.zeros(len(x), dtype=bool)
    for (cx, cy), members in cells.items():
        members = np.array(members)
        others = [cells.get((cx + a, cy + b), []) for a in (-1, 0, 1) for b in (-1, 0, 1)]
        others = np.array([j for group in others for j in group])
        dx = x[members][:, None] - x[others][None, :]
        dy = y[members][:, None] - y[others][None, :]
        r = np.sqrt(dx * dx + dy * dy)
        r[members[:, None] == others[None, :]] = np.inf
        close[members] = r.min(axis=1) < spacing[members] / 3.0
    return float(close.mean())


def measure_run(log, dump, problem, key, label):
    """One run's entry of the comparison (costs from its log; surface, runout, failure angle and
    instability from its final dump) and its profile (grid, surface, x, y, volume, h), or None
    for a run that stopped."""
    spec = PROBLEMS[problem]
    d = spec['d']
    loop, atoms, particle_steps, steps, error = read_log(log)
    entry = dict(run=label, wall_seconds=round(loop, 1), peak_particles=max(atoms) if atoms else None,
                 final_particles=atoms[-1] if atoms else None, particle_steps=particle_steps,
                 steps=steps,
                 wall_us_per_particle_step=1e6 * loop / particle_steps if particle_steps else None,
                 error=error)
    if error or not os.path.exists(dump):
        # a run that stopped: its loop time misses the segment it stopped in, so no cost
        entry['completed'] = False
        at = re.search(r'at step (\d+)', error or '')
        if at:
            entry['run'] = f'{label} (stopped at step {at.group(1)})'
        for field in ('wall_seconds', 'wall_us_per_particle_step'):
            entry[field] = None
        return entry, None
    entry['completed'] = True
    s = read_dump(dump)
    level = s['c_soil[2]']
    spacing = d * 0.5 ** level
    h = 1.2 * d * smoothing_ratio(key) ** level
    measures, profile = final_state(s, problem, spacing ** 2, h)
    entry.update(measures)
    entry['instability_index'] = round(instability_index(s['x'], s['y'], spacing, d), 5)
    return entry, profile


def final_state(s, problem, volume, h):
    """What every study of a problem reads from a final dump `s` (particles of `volume` and `h`,
    arrays or scalars): runout, failure angle, soil particles and, with an experiment, the
    surface's RMS distance from it; and the profile (grid, surface, x, y, volume, h). The
    thresholds are the problem's coarse spacing d's, at any spacing of the run: the runout where
    the surface stands higher than d, the failure line of the soil that moved less than 0.75 d,
    fitted per column of width d."""
    spec = PROBLEMS[problem]
    d = spec['d']
    x, y = s['x'], s['y']
    measures = {}
    measures['runout_m'], grid, top = analysis.runout(x, y, volume, h, d, d)
    moved = np.hypot(x - s['f_origin[1]'], y - s['f_origin[2]']) > 0.75 * d
    measures['failure_angle_deg'] = round(analysis.failure_line(s['f_origin[1]'], s['f_origin[2]'], moved, d,
                                                                spec['height'])[2], 2)
    measures['soil_particles'] = int(len(x))
    if spec['experiment']:
        exp = experiment(problem)
        sim = analysis.surface_height(x, y, volume, h, exp[:, 0])
        measures['surface_rms_vs_experiment_m'] = float(np.sqrt(np.mean((sim - exp[:, 1]) ** 2)))
    return measures, (grid, top, x, y, volume, h)


def surface_rms_between(fine, run, reach):
    """RMS difference between the surface of profile `run` and that of profile `fine` (as
    final_state() gives them) over x in [0, reach]."""
    grid_f, top_f, *_ = fine
    at = grid_f[grid_f <= reach]
    _, _, x, y, volume, h = run
    sim = analysis.surface_height(x, y, volume, h, at)
    return float(np.sqrt(np.mean((sim - top_f[grid_f <= reach]) ** 2)))


def experiment(problem):
    """The measured surface of a problem (x, y), or None."""
    path = PROBLEMS[problem]['experiment']
    return np.loadtxt(os.path.join(paths.ROOT, path), delimiter=',', skiprows=1) if path else None


def analyse(directory, problem):
    results = {}
    profiles = {}
    for key, label in LABELS.items():
        name = f'{problem}_{key}'
        log = os.path.join(directory, f'log.{name}')
        if not os.path.exists(log):
            continue
        results[key], profile = measure_run(log, os.path.join(directory, f'dump.{name}.final'), problem, key, label)
        if profile:
            profiles[key] = profile
    coarse = results.get('coarse', {})
    if coarse.get('completed'):
        walls = coarse['final_particles'] - coarse['soil_particles']
        for e in results.values():
            soil_steps = e['particle_steps'] - walls * e['steps']
            e['wall_us_per_soil_particle_step'] = (1e6 * e['wall_seconds'] / soil_steps
                                                   if soil_steps > 0 and e['wall_seconds'] else None)
    def rms_from(fine, run):
        return surface_rms_between(profiles[fine], profiles[run], results[fine]['runout_m'])

    for key in profiles:
        fine = reference(key)
        if fine in profiles:
            results[key]['surface_rms_vs_fine_m'] = rms_from(fine, key)
            results[key]['reference'] = fine
            results[key]['wall_time_vs_fine'] = results[key]['wall_seconds'] / results[fine]['wall_seconds']
    # the one-level runs against the two-level fine run too (what a second level buys)
    if 'fine_L2' in profiles:
        for key in ('coarse', 'fine', 'dynamic_0.5_0.5'):
            if key in profiles:
                results[key]['surface_rms_vs_fine_L2_m'] = rms_from('fine_L2', key)
                results[key]['wall_time_vs_fine_L2'] = results[key]['wall_seconds'] / results['fine_L2']['wall_seconds']
    return results, profiles


def frames_figure(directory, problem, out):
    plt = report.pyplot()
    import matplotlib.image as mpimg
    rows = []
    for key, label in LABELS.items():
        files = []
        for k in (1, 2, 3):
            found = sorted(glob.glob(os.path.join(directory, f'frame_{problem}_{key}_{k}.*.png')),
                           key=os.path.getmtime)
            files.append(found[-1] if found else None)
        if any(files):
            rows.append((label, files))
    if not rows:
        return
    fig, axes = plt.subplots(len(rows), 3, figsize=(15, 1.2 * len(rows) + 0.6), squeeze=False)
    for r, (label, files) in enumerate(rows):
        for c, path in enumerate(files):
            ax = axes[r][c]
            ax.axis('off')
            if path:
                ax.imshow(mpimg.imread(path))
            if r == 0:
                ax.set_title(f't = {PROBLEMS[problem]["times"][c]} s', fontsize=10)
            if c == 0:
                ax.text(-0.01, 0.5, label, transform=ax.transAxes, ha='right', va='center', fontsize=9)
    fig.suptitle(PROBLEMS[problem]['title'] + ': strain measure (blue 0 to red >= 0.3)', fontsize=11)
    fig.subplots_adjust(left=0.13, right=0.99, top=0.9, bottom=0.01, wspace=0.02, hspace=0.05)
    fig.savefig(out, dpi=110)
    plt.close(fig)


def surface_figure(problem, profiles, out):
    plt = report.pyplot()
    fig, ax = plt.subplots(figsize=(9, 3.4))
    for key, label in LABELS.items():
        if key in profiles:
            grid, top, *_ = profiles[key]
            ax.plot(grid, top, label=label, lw=1.2 if key.startswith('dynamic') else 2.0)
    spec = PROBLEMS[problem]
    if spec['experiment']:
        exp = experiment(problem)
        ax.plot(exp[:, 0], exp[:, 1], 'ko', ms=3, label='experiment')
    ax.set_xlabel('x (m)')
    ax.set_ylabel('surface height (m)')
    ax.set_title(spec['title'] + ': final free surface')
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(out, dpi=110)
    plt.close(fig)


def cost_figure(problem, results, out):
    """Accuracy against cost: each run's surface RMS from the fine run's against its wall time
    as a fraction of the fine run's, the paper's configuration (dynamic (0.5, 0.5), threshold
    0.05) marked."""
    points = [(key, label, r) for key, label in LABELS.items() for r in [results.get(key)]
              if r and r.get('completed') and r.get('surface_rms_vs_fine_m') is not None
              and key != reference(key)]
    if not points:
        return
    plt = report.pyplot()
    fig, ax = plt.subplots(figsize=(8, 4.6))
    for key, label, r in points:
        x, y = r['wall_time_vs_fine'], 1000 * r['surface_rms_vs_fine_m']
        paper = key == 'dynamic_0.5_0.5'
        marker = 's' if key == 'coarse' else ('*' if paper else ('^' if key.endswith('_h0') else
                                                                ('D' if key.endswith('_L2') else 'o')))
        ax.plot(x, y, marker, ms=14 if paper else 8, color='C3' if paper else ('k' if key == 'coarse' else 'C0'))
        ax.annotate(label + (' (the paper\'s)' if paper else ''), (x, y), xytext=(6, 3),
                    textcoords='offset points', fontsize=7)
    coarse = results.get('coarse', {}).get('surface_rms_vs_fine_m')
    if coarse:
        ax.axhline(500 * coarse, color='grey', lw=0.8, ls='--')
        ax.text(1.0, 500 * coarse, ' half the coarse run\'s RMS', fontsize=7, va='bottom', ha='right')
    ax.axvline(0.35, color='grey', lw=0.8, ls=':')
    ax.text(0.35, ax.get_ylim()[1], ' 0.35 of the fine run\'s time', fontsize=7, va='top')
    ax.set_xlim(0.0, 1.05)
    ax.set_xlabel('wall time / fine run\'s wall time (2 levels: the fine run of 2 levels)')
    ax.set_ylabel('final surface RMS from the fine run\'s (mm)')
    ax.set_title(PROBLEMS[problem]['title'] + ': accuracy against cost')
    fig.tight_layout()
    fig.savefig(out, dpi=110)
    plt.close(fig)


def table_rows(entries, cols):
    """The rows of a table of `entries` (dicts) in columns (field, header, format): distances of
    surfaces (fields ending in _m that are an RMS or a difference) in mm; a missing value of a run
    that stopped is 'stopped', else '-'."""
    rows = []
    for e in entries:
        row = []
        for field, _, fmt in cols:
            v = e.get(field)
            if v is None or (isinstance(v, float) and math.isnan(v)):
                row.append('stopped' if not e.get('completed') and field != 'run' else '-')
            elif field.endswith('_m') and ('rms' in field or 'difference' in field):
                row.append(fmt.format(1000 * v))
            else:
                row.append(fmt.format(v))
        rows.append(row)
    return rows


def table(problem, results):
    cols = [('run', 'run', '{}'), ('wall_seconds', 'wall (s)', '{:.0f}'),
            ('wall_us_per_particle_step', 'us/particle-step', '{:.3f}'),
            ('wall_us_per_soil_particle_step', 'us/soil p.-step', '{:.3f}'),
            ('wall_time_vs_fine', 'wall / fine', '{:.2f}'), ('peak_particles', 'peak N', '{}'),
            ('final_particles', 'final N', '{}'), ('surface_rms_vs_fine_m', 'RMS vs fine (mm)', '{:.2f}'),
            ('surface_rms_vs_experiment_m', 'RMS vs exp. (mm)', '{:.2f}'),
            ('runout_m', 'runout (m)', '{:.3f}'), ('failure_angle_deg', 'failure angle', '{:.1f}'),
            ('instability_index', 'instability', '{:.4f}')]
    if not PROBLEMS[problem]['experiment']:
        cols = [c for c in cols if c[0] != 'surface_rms_vs_experiment_m']
    rows = table_rows([results[key] for key in LABELS if key in results], cols)
    return report.rst_table([c[1] for c in cols], rows)


def run_matrix(lmp, problems, np, only=None, two_levels=False, directory=DIRECTORY):
    """Run the comparison's runs of `problems` in `directory` (those whose name matches the
    regular expression `only`), skipping those whose final dump is newer than the input and
    the binary; a run that stops with an error is reported and the next one runs."""
    for problem in problems:
        for run in RUNS:
            if (run.bars_only and problem != 'bars') or (run.two_levels and not two_levels):
                continue
            name = f'{problem}_{run.key}'
            if only and not re.search(only, name):
                continue
            dump = os.path.join(directory, f'dump.{name}.final')
            if (os.path.exists(dump) and os.path.getmtime(dump) > os.path.getmtime(INPUT)
                    and os.path.getmtime(dump) > os.path.getmtime(lmp.binary)):
                print(f'== {name}: up to date', flush=True)
                continue
            print(f'== {name}', flush=True)
            for old in glob.glob(os.path.join(directory, f'frame_{name}_*.png')):
                os.remove(old)
            if not lmp.run(INPUT, directory, np=np, variables=run.variables(problem), log=f'log.{name}').ok:
                print(f'== {name} stopped with an error (see log.{name})', flush=True)


def compare(directory, problems):
    """The comparison's JSON (doc/refinement_comparison.json, the problems not compared kept),
    its generated page doc/refinement_comparison.rst and the pictures in doc/img/."""
    jpath = os.path.join(paths.DOC, 'refinement_comparison.json')
    summary = json.load(open(jpath)) if os.path.exists(jpath) else {}
    os.makedirs(paths.DOC_IMG, exist_ok=True)
    for problem in problems:
        results, profiles = analyse(directory, problem)
        if not results:
            print(f'refinement: no runs of {problem} in {directory}')
            continue
        summary[problem] = results
        frames_figure(directory, problem, os.path.join(paths.DOC_IMG, f'refinement_{problem}_frames.png'))
        surface_figure(problem, profiles, os.path.join(paths.DOC_IMG, f'refinement_{problem}_surface.png'))
        cost_figure(problem, results, os.path.join(paths.DOC_IMG, f'refinement_{problem}_cost.png'))
    report.write_json(summary, jpath, indent=1, end='')

    page = ['Refinement comparison (generated)', '=' * 33, '',
            'Written by ``python3 -m sph_soil refinement`` (tools/sph_soil/studies/refinement.py)',
            '(examples/refinement, 2 MPI ranks). Columns: see the study\'s docstring.', '']
    for problem in ('bars', 'collapse'):
        if problem not in summary:
            continue
        title = PROBLEMS[problem]['title']
        page += [title, '"' * len(title), '', table(problem, summary[problem]), '',
                 f'.. image:: img/refinement_{problem}_frames.png', '   :width: 100%', '',
                 f'.. image:: img/refinement_{problem}_surface.png', '   :width: 80%', '',
                 f'.. image:: img/refinement_{problem}_cost.png', '   :width: 70%', '']
    # the discussion of the numbers is written by hand beside the generated page
    if os.path.exists(os.path.join(paths.DOC, 'refinement_comparison_notes.rst')):
        page += ['.. include:: refinement_comparison_notes.rst', '']
    with open(os.path.join(paths.DOC, 'refinement_comparison.rst'), 'w') as f:
        f.write('\n'.join(page))


def report_example(directory, log, variables, seconds):
    """run_example's numbers and plot of the one run in.refinement makes (by default the bars,
    dynamic (0.5, 0.5)): refinement.json, its entry of the comparison (without a fine run to
    measure it against), and refinement.png, its final surface (with the measured one for the
    bars); a run without a final state (the short mode) shows its particle count instead."""
    problem = variables['problem']
    run = Run('', **{name: variables[name] for name in ('mode', 'eps', 'alpha', 'h0', 'threshold', 'criterion',
                                                        'maxlevel')})
    entry, profile = measure_run(log, os.path.join(directory, f'dump.{problem}_{run.key}.final'), problem, run.key,
                                 LABELS.get(run.key, run.key))
    report.write_json({problem: {run.key: entry}}, os.path.join(directory, 'refinement.json'))
    out = os.path.join(directory, 'refinement.png')
    if profile:
        surface_figure(problem, {run.key: profile}, out)
        return
    plt = report.pyplot()
    fig, ax = plt.subplots(figsize=(7, 3.5))
    for header, rows in Log(log).thermo_tables():
        if 'Atoms' in header:
            ax.plot([r[header.index('Step')] for r in rows], [r[header.index('Atoms')] for r in rows], 'k.-')
    ax.set_xlabel('step')
    ax.set_ylabel('particles (walls included)')
    ax.set_title(f'{PROBLEMS[problem]["title"]}, {entry["run"]}: no final state (short run)', fontsize=9)
    fig.tight_layout()
    fig.savefig(out, dpi=110)


def add_arguments(p):
    runner.add_arguments(p, np=os.cpu_count() or 1)
    p.add_argument('problems', nargs='*', default=list(PROBLEMS), help='bars, collapse (default: both)')
    p.add_argument('--only', default=None, help='only the runs whose name (e.g. bars_dynamic_0.5_0.5) '
                   'matches this regular expression')
    p.add_argument('--two-levels', action='store_true',
                   help='also maxlevel 2 against the lattice refined twice (bars; the fine run takes 1.5 h)')
    p.add_argument('--compare-only', action='store_true', help='run nothing: compare the runs there')
    p.add_argument('--dir', default=DIRECTORY, help='where the runs are (default: examples/refinement)')


def main(a):
    unknown = set(a.problems) - set(PROBLEMS)
    if unknown:
        raise SystemExit(f'refinement: unknown problem(s) {sorted(unknown)}: bars or collapse')
    if not a.compare_only:
        run_matrix(runner.from_arguments(a, build=True), a.problems, a.np, a.only, a.two_levels, a.dir)
    compare(a.dir, a.problems)
