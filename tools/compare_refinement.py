#!/usr/bin/python3
"""The refinement paper's Section IV comparison: coarse, fine and dynamic runs.

Reads examples/refinement/{log,dump}.<problem>_<run>.* written by tools/run_refinement.sh and,
for each run, reports
  - wall_seconds: the sum of the run segments' loop times (LAMMPS "Loop time of ...");
  - wall_us_per_particle_step: wall_seconds over the particle-steps (walls included; the atoms
    of the thermo rows times the steps between them), in microseconds on all ranks together;
  - wall_us_per_soil_particle_step: the same over the soil's particle-steps only (the wall
    particles, the same in every run and never split, taken out: they have no partner among
    themselves and no stress to integrate, so they dilute the coarse run's figure most);
  - peak_particles, final_particles: from the thermo output (walls included, same in every run);
  - surface_rms_vs_fine_m: RMS difference of the final free surface from the fine run's, over
    x in [0, the fine run's runout], the surface being the 0.5 level of the SPH volume fraction
    (tools/sph_analysis.py: the surface of the continuum the particles stand for; a particle of
    level l has the volume (d 2^-l)^2 and h = 1.2 d alpha_r^l);
    A run of two levels (name ending _L2) is measured against the fine run of two levels
    (fine_L2), and the coarse, fine and paper's dynamic runs also against that one
    (surface_rms_vs_fine_L2_m: what the second level changes);
  - wall_time_vs_fine: wall_seconds over the fine run's (of as many levels);
  - surface_rms_vs_experiment_m (aluminium bars only): the same against the measured surface;
  - runout_m: the furthest x where that surface stands higher than one coarse spacing (2 mm for
    the bars, as in tools/validate_aluminium_bars.py);
  - failure_angle_deg: the angle of the boundary of the soil that moved less than 0.75 coarse
    spacings (1.5 mm for the bars, as in tools/validate_aluminium_bars.py), by initial position;
    daughters carry their parent's initial position (fix store/state is inherited);
  - instability_index: the fraction of soil particles whose nearest neighbour is closer than a
    third of their own spacing. In a lattice the nearest neighbour sits at one spacing, and
    compression alone brings it to about 0.85; pairs at a third of it only form when particles
    clump (the compressive instability that the paper reports as clumps and cracks).
Writes doc/refinement_comparison.json, doc/refinement_comparison.rst (tables) and the pictures
doc/img/refinement_<problem>_frames.png (one row per run), _surface.png and _cost.png (accuracy
against cost: RMS vs fine against the wall time as a fraction of the fine run's).

  tools/compare_refinement.py --dir examples/refinement [bars] [collapse]
"""
import argparse
import glob
import json
import math
import os
import re
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import sph_analysis  # noqa: E402

PROBLEMS = {
    'bars': dict(d=0.002, height=0.1, times=(0.06, 0.11, 0.6), title='Aluminium bars (Bui et al. 2008)',
                 experiment='examples/aluminium_bars/experiment/surface.csv'),
    'collapse': dict(d=0.04, height=2.0, times=(0.25, 0.45, 1.8), title='Soil collapse (doc/theory.rst 6.2)',
                     experiment=None),
}
# the paper's four (separation, smoothing) pairs, each also with the artificial viscosity that
# follows the level (pair_style sph/soil viscosity_h0: every level dissipates as the coarse one)
PAIRS = [('0.5', '0.5'), ('0.55', '0.5'), ('0.55', '0.6'), ('0.55', '0.7')]
RUNS = ([('coarse', 'coarse'), ('fine', 'fine (static 0.5, 0.5)')] +
        [(f'dynamic_{e}_{a}', f'dynamic ({e}, {a})') for e, a in PAIRS] +
        [(f'dynamic_{e}_{a}_h0', f'dynamic ({e}, {a}), viscosity_h0') for e, a in PAIRS] +
        [(f'dynamic_0.5_0.5_t{t}', f'dynamic (0.5, 0.5), threshold {t}') for t in ('0.1', '0.2')] +
        # criteria beyond the paper's (bars only): the shear strain rate and the shear strain
        [(f'dynamic_0.5_0.5_t{t}_shear_strain_rate', f'dynamic (0.5, 0.5), shear rate > {t}/s')
         for t in ('10', '20')] +
        [('dynamic_0.5_0.5_t1.0_shear_strain', 'dynamic (0.5, 0.5), shear strain > 1')] +
        # two levels (maxlevel 2), against the lattice refined twice: their RMS and cost are
        # measured against that fine run (reference())
        [('fine_L2', 'fine, 2 levels (static)'),
         ('dynamic_0.5_0.5_t10_shear_strain_rate_L2', 'dynamic (0.5, 0.5), shear rate > 10/s, 2 levels'),
         ('dynamic_0.5_0.5_L2', 'dynamic (0.5, 0.5), 2 levels')])


def reference(key):
    """The fine run a run is measured against: the one with as many levels."""
    return 'fine_L2' if key.endswith('_L2') else 'fine'


def read_log(path):
    """Sum of loop times, the Atoms column of every thermo table, the particle-steps (atoms
    integrated over the steps between thermo rows, each interval at its end's count), the
    steps, and whether it ended cleanly."""
    text = open(path).read()
    loop = sum(float(t) for t in re.findall(r'Loop time of ([0-9.eE+-]+) on', text))
    atoms = []
    particle_steps = 0.0
    steps = 0
    last_step = None
    header = None
    for line in text.splitlines():
        words = line.split()
        if words[:1] == ['Step']:
            header = words
            continue
        if header and len(words) == len(header):
            try:
                n = int(float(words[header.index('Atoms')]))
                step = int(float(words[header.index('Step')]))
            except ValueError:
                header = None
                continue
            atoms.append(n)
            if last_step is not None and step > last_step:
                particle_steps += n * (step - last_step)
                steps += step - last_step
            last_step = step
        else:
            header = None
    error = re.search(r'^ERROR.*$', text, re.M)
    return loop, atoms, particle_steps, steps, error.group(0) if error else None


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


def analyse(directory, problem, root):
    spec = PROBLEMS[problem]
    d = spec['d']
    results = {}
    profiles = {}
    for key, label in RUNS:
        name = f'{problem}_{key}'
        log = os.path.join(directory, f'log.{name}')
        dump = os.path.join(directory, f'dump.{name}.final')
        if not os.path.exists(log):
            continue
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
            results[key] = entry
            continue
        entry['completed'] = True
        s = sph_analysis.read_dump(dump)
        level = s['c_soil[2]']
        spacing = d * 0.5 ** level
        h = 1.2 * d * smoothing_ratio(key) ** level
        x, y = s['x'], s['y']
        entry['runout_m'], grid, top = sph_analysis.runout(x, y, spacing ** 2, h, d, d)
        moved = np.hypot(x - s['f_origin[1]'], y - s['f_origin[2]']) > 0.75 * d
        entry['failure_angle_deg'] = round(sph_analysis.failure_line(s['f_origin[1]'], s['f_origin[2]'], moved, d,
                                                                      spec['height'])[2], 2)
        entry['instability_index'] = round(instability_index(x, y, spacing, d), 5)
        entry['soil_particles'] = int(len(x))
        profiles[key] = (grid, top, x, y, spacing ** 2, h)
        if spec['experiment']:
            exp = np.loadtxt(os.path.join(root, spec['experiment']), delimiter=',', skiprows=1)
            sim = sph_analysis.surface_height(x, y, spacing ** 2, h, exp[:, 0])
            entry['surface_rms_vs_experiment_m'] = float(np.sqrt(np.mean((sim - exp[:, 1]) ** 2)))
        results[key] = entry
    coarse = results.get('coarse', {})
    if coarse.get('completed'):
        walls = coarse['final_particles'] - coarse['soil_particles']
        for e in results.values():
            soil_steps = e['particle_steps'] - walls * e['steps']
            e['wall_us_per_soil_particle_step'] = (1e6 * e['wall_seconds'] / soil_steps
                                                   if soil_steps > 0 and e['wall_seconds'] else None)
    def rms_from(fine, run):
        grid_f, top_f, *_ = profiles[fine]
        reach = results[fine]['runout_m']
        at = grid_f[grid_f <= reach]
        _, _, x, y, volume, h = profiles[run]
        sim = sph_analysis.surface_height(x, y, volume, h, at)
        return float(np.sqrt(np.mean((sim - top_f[grid_f <= reach]) ** 2)))

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
    import matplotlib
    matplotlib.use('Agg')
    import matplotlib.pyplot as plt
    import matplotlib.image as mpimg
    rows = []
    for key, label in RUNS:
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


def surface_figure(problem, profiles, root, out):
    import matplotlib
    matplotlib.use('Agg')
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(9, 3.4))
    for key, label in RUNS:
        if key in profiles:
            grid, top, *_ = profiles[key]
            ax.plot(grid, top, label=label, lw=1.2 if key.startswith('dynamic') else 2.0)
    spec = PROBLEMS[problem]
    if spec['experiment']:
        exp = np.loadtxt(os.path.join(root, spec['experiment']), delimiter=',', skiprows=1)
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
    points = [(key, label, r) for key, label in RUNS for r in [results.get(key)]
              if r and r.get('completed') and r.get('surface_rms_vs_fine_m') is not None
              and key != reference(key)]
    if not points:
        return
    import matplotlib
    matplotlib.use('Agg')
    import matplotlib.pyplot as plt
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
    lines = []
    rows = []
    for key, _ in RUNS:
        if key not in results:
            continue
        e = results[key]
        row = []
        for field, _, fmt in cols:
            v = e.get(field)
            if v is None or (isinstance(v, float) and math.isnan(v)):
                row.append('stopped' if not e.get('completed') and field != 'run' else '-')
            elif field.endswith('_m') and 'rms' in field:
                row.append(fmt.format(1000 * v))
            else:
                row.append(fmt.format(v))
        rows.append(row)
    header = [c[1] for c in cols]
    widths = [max(len(header[k]), *(len(r[k]) for r in rows)) for k in range(len(cols))]
    sep = '  '.join('=' * w for w in widths)
    lines.append(sep)
    lines.append('  '.join(h.ljust(w) for h, w in zip(header, widths)))
    lines.append(sep)
    for r in rows:
        lines.append('  '.join(v.ljust(w) for v, w in zip(r, widths)))
    lines.append(sep)
    return '\n'.join(lines)


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument('--dir', default='examples/refinement')
    p.add_argument('problems', nargs='*', default=['bars', 'collapse'])
    a = p.parse_args()
    root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    jpath = os.path.join(root, 'doc', 'refinement_comparison.json')
    summary = json.load(open(jpath)) if os.path.exists(jpath) else {}
    os.makedirs(os.path.join(root, 'doc', 'img'), exist_ok=True)
    for problem in a.problems:
        results, profiles = analyse(a.dir, problem, root)
        if not results:
            print(f'compare_refinement: no runs of {problem} in {a.dir}')
            continue
        summary[problem] = results
        frames_figure(a.dir, problem, os.path.join(root, 'doc', 'img', f'refinement_{problem}_frames.png'))
        surface_figure(problem, profiles, root, os.path.join(root, 'doc', 'img', f'refinement_{problem}_surface.png'))
        cost_figure(problem, results, os.path.join(root, 'doc', 'img', f'refinement_{problem}_cost.png'))
    with open(jpath, 'w') as f:
        json.dump(summary, f, indent=1)
    print(json.dumps(summary, indent=1))

    page = ['Refinement comparison (generated)', '=' * 33, '',
            'Written by ``tools/compare_refinement.py`` from the runs of ``tools/run_refinement.sh``',
            '(examples/refinement, 2 MPI ranks). Columns: see the script\'s docstring.', '']
    for problem in ('bars', 'collapse'):
        if problem not in summary:
            continue
        title = PROBLEMS[problem]['title']
        page += [title, '"' * len(title), '', table(problem, summary[problem]), '',
                 f'.. image:: img/refinement_{problem}_frames.png', '   :width: 100%', '',
                 f'.. image:: img/refinement_{problem}_surface.png', '   :width: 80%', '',
                 f'.. image:: img/refinement_{problem}_cost.png', '   :width: 70%', '']
    # the discussion of the numbers is written by hand beside the generated page
    if os.path.exists(os.path.join(root, 'doc', 'refinement_comparison_notes.rst')):
        page += ['.. include:: refinement_comparison_notes.rst', '']
    with open(os.path.join(root, 'doc', 'refinement_comparison.rst'), 'w') as f:
        f.write('\n'.join(page))


if __name__ == '__main__':
    main()
