#!/usr/bin/python3
"""SPH_SOIL benchmark: particle-steps per second per core, side by side with LAMMPS's own
sph/taitwater and smd/ulsph on the same 2D layout (in.bench_*), as ratios from one run.

    bench/benchmark.py [--lmp build/lmp] [--repeat 1] [--json FILE] [--bars] [--callgrind] [--parallel]
                       [--refinement] [--levels] [--showcases [--run-showcases]]

Each input runs on 1 MPI rank; the best of --repeat runs counts, the styles taking turns. --bars also times the short
aluminium-bar example on all cores. --callgrind adds instructions per particle-step of each style, counted by
valgrind's callgrind over 50 steps minus a run of 0 steps (the set-up): a figure that does not drift with the load
of the machine. --levels measures a time step per level (fix sph/soil stepping level) against one global step on
two statically refined layouts of in.bench_refined at 1.4 mm (a band of a tenth of the block refined, and its right
half): instructions per step (callgrind, 200 steps minus 0) and loop seconds (interleaved, the median of --repeat, at
least 3) in both modes, each speed-up against the ideal N / sum 1/n of the layout's level populations. --parallel times a refined run of about 100k particles at two levels (in.bench_refined) on 1 and 2
ranks: the parallel efficiency after splits, with LAMMPS's breakdown of where the time goes. --refinement adds, for
the aluminium bars at the comparison's spacing, the instructions per particle-step and per soil particle-step of the
coarse and the statically refined (fine) lattice (callgrind, 40 steps minus 0: what refinement costs per particle,
free of the load of the machine), and the cost figures of the latest refinement comparison (doc/
refinement_comparison.json, written by python3 -m sph_soil refinement, an hour on 2 cores: not rerun here): each run's wall
time per particle-step against the coarse run's, its wall time against its fine run's and its surface RMS from that
run against the coarse run's. --showcases adds every refinement showcase's answer and cost against its uniform
run at the finest spacing (doc/showcases.json, written by python3 -m sph_soil showcase: hours on 2 cores, so read,
not rerun; --run-showcases runs the configurations missing from its work directory first). Prints JSON. lmp runs through the tools' runner (tools/sph_soil/runner.py):
--lmp, else $SPH_SOIL_LMP, else lmp of the build directory of SPH_SOIL_LAMMPS.
"""
import argparse
import json
import os
import re
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
# The one place outside the tools' package that puts tools/ on Python's path (the command line
# gets it from PYTHONPATH=tools): this script keeps its own command, bench/benchmark.py.
sys.path.insert(0, os.path.join(ROOT, 'tools'))
from sph_soil.logs import Log  # noqa: E402
from sph_soil.runner import Lammps, add_lmp_argument  # noqa: E402

# name: input and its variables; sph_soil_cohesive is the same layout with a cohesive soil in
# tension (the loop with the artificial stress)
STYLES = {'sph_soil': ('in.bench_sph_soil', []),
          'sph_soil_cohesive': ('in.bench_sph_soil', ['-var', 'cohesion', '1.0e5']),
          'sph_soil_saturated': ('in.bench_sph_soil', ['-var', 'material', 'saturated']),
          'sph_soil_water': ('in.bench_sph_soil', ['-var', 'material', 'water']),
          'sph_soil_corrected': ('in.bench_sph_soil', ['-var', 'correction', 'yes']),
          'sph_soil_corrected_full': ('in.bench_sph_soil', ['-var', 'correction', 'full']),
          'sph_taitwater': ('in.bench_taitwater', []), 'smd_ulsph': ('in.bench_ulsph', [])}


def run(lmp, infile, workdir, np=1, extra=()):
    log = Log(lmp.run(infile, workdir, np=np, log='log.bench', extra=extra, check=True).log)
    loop = log.loops()[-1]
    seconds, procs, steps, atoms = loop.seconds, loop.procs, loop.steps, loop.atoms
    # sph/soil builds its own list and prints its mean (LAMMPS's count is 0 for it)
    neighs = (log.findall(r'^SPH_SOIL neighbours per atom: (\S+)', re.M) or
              log.findall(r'Ave neighs/atom = (\S+)'))
    # LAMMPS's breakdown of the loop time: each section's average over ranks, as a fraction
    sections = {name: value / seconds for name, value in log.timing_breakdown().items()}
    return {'seconds': seconds, 'procs': procs, 'steps': steps, 'atoms': atoms,
            'particle_steps_per_second_per_core': atoms * steps / seconds / procs,
            'neighbours_per_atom': float(neighs[-1]) if neighs else None,
            'pair_fraction': sections.get('pair'),
            'time_fractions': sections}


def instructions(lmp, infile, workdir, steps, extra=()):
    """Instructions of a whole lmp process (1 rank, no mpirun) counted by callgrind."""
    out = os.path.join(workdir, f'callgrind.{steps}')
    lmp.run(infile, workdir, np=None, prefix=['valgrind', '--tool=callgrind', f'--callgrind-out-file={out}'],
            variables=[('steps', steps)], log='none', extra=extra, check=True, stdout=subprocess.DEVNULL,
            stderr=subprocess.DEVNULL)
    for line in open(out):
        if line.startswith('summary:') or line.startswith('totals:'):
            return int(line.split()[1])
    raise SystemExit(f'benchmark: no instruction total in {out}')


def instructions_per_particle_step(lmp, infile, workdir, atoms, steps=50, extra=()):
    return (instructions(lmp, infile, workdir, steps, extra) -
            instructions(lmp, infile, workdir, 0, extra)) / (atoms * steps)


def lammps_version(lmp):
    text = lmp.help_text()
    m = re.search(r'Simulator - (.*)', text)
    return m.group(1).strip() if m else 'unknown'


def machine():
    model = ''
    try:
        for line in open('/proc/cpuinfo'):
            if line.startswith('model name'):
                model = line.split(':', 1)[1].strip()
                break
    except OSError:
        pass
    return {'cores': os.cpu_count(), 'cpu': model}


def comparison_costs():
    """The latest refinement comparison's cost and accuracy figures (doc/refinement_comparison.json, written by
    python3 -m sph_soil refinement): each run's wall time per (soil) particle-step against the coarse run's, its wall
    time against its fine run's (of as many levels), and its surface RMS from that fine run against the coarse
    run's."""
    comparison = os.path.join(ROOT, 'doc', 'refinement_comparison.json')
    if not os.path.exists(comparison):
        return {}
    with open(comparison) as f:
        runs = json.load(f)
    out = {'comparison': {}}
    for problem, entries in runs.items():
        coarse = entries.get('coarse', {})
        rows = {}
        for key, e in entries.items():
            row = {k: e.get(k) for k in ('run', 'wall_seconds', 'wall_us_per_particle_step',
                                         'wall_us_per_soil_particle_step', 'surface_rms_vs_fine_m', 'reference')}
            for k in ('wall_us_per_particle_step', 'wall_us_per_soil_particle_step'):
                if e.get(k) and coarse.get(k):
                    row[k + '_to_coarse'] = e[k] / coarse[k]
            if e.get('wall_time_vs_fine') is not None:
                row['wall_seconds_to_fine'] = e['wall_time_vs_fine']
            # the coarse run's distance from the same fine run
            coarse_rms = coarse.get('surface_rms_vs_fine_L2_m' if e.get('reference') == 'fine_L2'
                                    else 'surface_rms_vs_fine_m')
            if e.get('surface_rms_vs_fine_m') is not None and coarse_rms:
                row['rms_vs_fine_to_coarse'] = e['surface_rms_vs_fine_m'] / coarse_rms
            rows[key] = row
        out['comparison'][problem] = rows
    out['comparison_note'] = ('from doc/refinement_comparison.json (python3 -m sph_soil refinement, 2 ranks), '
                              'not rerun by this script')
    return out


def showcases(lmp, run_missing):
    """The refinement showcases (python3 -m sph_soil showcase): each configuration's answer, wall time
    and cost against the uniform run at the finest spacing; with run_missing, the configurations not
    yet run are run first (hours)."""
    if run_missing:
        subprocess.run([sys.executable, '-m', 'sph_soil', 'showcase', '--run', '--lmp', lmp.binary], check=True,
                       cwd=os.path.join(ROOT, 'tools'), env=dict(os.environ, PYTHONPATH=os.path.join(ROOT, 'tools')),
                       stdout=subprocess.DEVNULL)
    path = os.path.join(ROOT, 'doc', 'showcases.json')
    if not os.path.exists(path):
        return {}
    with open(path) as f:
        return {'showcases': json.load(f), 'note': 'from doc/showcases.json (python3 -m sph_soil showcase, '
                                                    '2 ranks, one batch)'}


def refinement_costs(lmp, work):
    """Instructions per particle-step of the bars, coarse and fine (examples/refinement/in.refinement -var steps N),
    and the latest comparison's figures (comparison_costs())."""
    infile = os.path.join(ROOT, 'examples', 'refinement', 'in.refinement')
    out = {'note': 'aluminium bars, d = 2 mm, the first 40 steps; the walls (never split) are the same in both runs'}
    for mode in ('coarse', 'fine'):
        extra = ['-var', 'problem', 'bars', '-var', 'mode', mode]
        # the particle counts from the set-up's own log: all atoms, and the wall groups
        setup = run(lmp, infile, work, extra=extra + ['-var', 'steps', '0'])
        walls = sum(int(n) for n in Log(os.path.join(work, 'log.bench')).findall(
            r'^(\d+) atoms in group (?:floor|left)$', re.M))
        soil = setup['atoms'] - walls
        per_step = (instructions(lmp, infile, work, 40, extra) - instructions(lmp, infile, work, 0, extra)) / 40
        out[mode] = {'particles': setup['atoms'], 'walls': walls,
                     'instructions_per_particle_step': per_step / (soil + walls),
                     'instructions_per_soil_particle_step': per_step / soil}
        print(f'benchmark: bars {mode}: {per_step / (soil + walls):.0f} instructions/particle-step, '
              f'{per_step / soil:.0f} per soil particle-step', file=sys.stderr)
    for key in ('instructions_per_particle_step', 'instructions_per_soil_particle_step'):
        out['fine_to_coarse_' + key] = out['fine'][key] / out['coarse'][key]
    out.update(comparison_costs())
    return out


LEVEL_LAYOUTS = {'band': '0.18', 'half': '0.1'}


def level_stepping(lmp, work, repeat):
    """A time step per level against one global step on in.bench_refined's refined layouts: the ideal speed-up from
    the populations (the input prints it), instructions per step and interleaved loop seconds, global and level."""
    infile = os.path.join(HERE, 'in.bench_refined')
    out = {'note': 'bars block at d = 1.4 mm, refined once from x = from on (band: 0.18, a tenth of it; half: 0.1), '
                   '1 rank, fix balance weighted by step_period; speed-up = global / level'}
    for name, start in LEVEL_LAYOUTS.items():
        base = ['-var', 'd', '0.0014', '-var', 'from', start]
        entry = {'from_m': float(start)}
        run(lmp, infile, work, extra=base + ['-var', 'stepping', 'level', '-var', 'steps', '0'])
        m = Log(os.path.join(work, 'log.bench')).search(
            r'levels: (\d+) soil particles, (\S+) evaluations per step: ideal speed-up (\S+)')
        entry['soil_particles'], entry['evaluations_per_step'], entry['ideal_speedup'] = \
            int(m.group(1)), float(m.group(2)), float(m.group(3))
        for mode in ('global', 'level'):
            extra = base + ['-var', 'stepping', mode]
            entry[f'instructions_per_step_{mode}'] = (instructions(lmp, infile, work, 200, extra) -
                                                     instructions(lmp, infile, work, 0, extra)) / 200
        seconds = {'global': [], 'level': []}
        for _ in range(max(repeat, 3)):
            for mode in ('global', 'level'):
                seconds[mode].append(run(lmp, infile, work, extra=base + ['-var', 'stepping', mode,
                                                                          '-var', 'steps', '1200'])['seconds'])
        for mode in seconds:
            entry[f'loop_seconds_{mode}'] = sorted(seconds[mode])[len(seconds[mode]) // 2]
        entry['speedup_instructions'] = entry['instructions_per_step_global'] / entry['instructions_per_step_level']
        entry['speedup_seconds'] = entry['loop_seconds_global'] / entry['loop_seconds_level']
        for key in ('instructions', 'seconds'):
            entry[f'fraction_of_ideal_{key}'] = entry[f'speedup_{key}'] / entry['ideal_speedup']
        print(f'benchmark: levels, {name}: ideal {entry["ideal_speedup"]:.3f}, instructions '
              f'{entry["speedup_instructions"]:.3f}, seconds {entry["speedup_seconds"]:.3f}', file=sys.stderr)
        out[name] = entry
    return out


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    add_lmp_argument(p)
    p.add_argument('--repeat', type=int, default=1)
    p.add_argument('--json', default=None)
    p.add_argument('--bars', action='store_true', help='also time the short aluminium-bar example')
    p.add_argument('--callgrind', action='store_true', help='also count instructions per particle-step')
    p.add_argument('--parallel', action='store_true',
                   help='also time the refined run (in.bench_refined, ~100k particles at two levels) '
                        'on 1 and 2 ranks: the parallel efficiency after splits')
    p.add_argument('--refinement', action='store_true',
                   help='also count the instructions of coarse and refined bars per (soil) particle-step and '
                        'add the latest refinement comparison\'s cost figures')
    p.add_argument('--levels', action='store_true',
                   help='also measure a time step per level against one global step on two refined layouts')
    p.add_argument('--showcases', action='store_true',
                   help='also report the refinement showcases\' cost and accuracy (doc/showcases.json)')
    p.add_argument('--run-showcases', action='store_true',
                   help='with --showcases: run the showcases\' missing configurations first (hours)')
    a = p.parse_args()
    lmp = Lammps(a.lmp).require()

    results = {}
    with tempfile.TemporaryDirectory() as work:
        # round robin: on a shared machine the speed drifts; each style gets a run in every
        # round, so that the best runs of all styles come from the same conditions
        for _ in range(a.repeat):
            for name, (infile, extra) in STYLES.items():
                r = run(lmp, os.path.join(HERE, infile), work, extra=extra)
                if name not in results or r['seconds'] < results[name]['seconds']:
                    results[name] = r
        for name in STYLES:
            print(f'benchmark: {name}: {results[name]["particle_steps_per_second_per_core"]:.3g} '
                  f'particle-steps/s/core', file=sys.stderr)
        if a.bars:
            ncores = os.cpu_count() or 1
            r = run(lmp, os.path.join(ROOT, 'examples', 'aluminium_bars', 'in.aluminium_bars'), work,
                    np=ncores, extra=['-var', 'short', '1'])
            r['note'] = 'short mode (300 steps); atoms include wall particles'
            results['aluminium_bars_short'] = r
        if a.parallel:
            # 1 and 2 ranks in turn; the best of --repeat each; one global step, and a time step per
            # level with the balance weighted by each particle's share of the evaluations
            for key, stepping in (('refined_parallel', 'global'), ('refined_parallel_levels', 'level')):
                best = {}
                for _ in range(a.repeat):
                    for np in (1, 2):
                        r = run(lmp, os.path.join(HERE, 'in.bench_refined'), work, np=np,
                                extra=['-var', 'stepping', stepping])
                        if np not in best or r['seconds'] < best[np]['seconds']:
                            best[np] = r
                efficiency = best[1]['seconds'] / (2 * best[2]['seconds'])
                results[key] = {
                    'note': 'aluminium bars at 0.7 mm, the right half refined once (0.5, 0.5), fix balance '
                            f'weighted by step_period, stepping {stepping}; efficiency = t(1 rank) / (2 t(2 ranks))',
                    'one_rank': best[1], 'two_ranks': best[2], 'efficiency': efficiency}
                print(f'benchmark: refined run ({stepping}), {best[1]["atoms"]} atoms: 2-rank efficiency '
                      f'{efficiency:.3f}', file=sys.stderr)
        if a.callgrind:
            for name, (infile, extra) in STYLES.items():
                n = instructions_per_particle_step(lmp, os.path.join(HERE, infile), work,
                                                   results[name]['atoms'], extra=extra)
                results[name]['instructions_per_particle_step'] = n
                print(f'benchmark: {name}: {n:.0f} instructions/particle-step', file=sys.stderr)

        if a.refinement:
            results['refinement'] = refinement_costs(lmp, work)
        if a.levels:
            results['level_stepping'] = level_stepping(lmp, work, a.repeat)
        if a.showcases:
            results['showcases'] = showcases(lmp, a.run_showcases)

    ours = results['sph_soil']['particle_steps_per_second_per_core']
    summary = {
        'layout': '200 x 100 square lattice, support radius 2.4 spacings, 500 steps, 1 rank',
        'machine': machine(),
        'results': results,
        'ratio_sph_soil_to_sph_taitwater': ours / results['sph_taitwater']['particle_steps_per_second_per_core'],
        'ratio_sph_soil_to_smd_ulsph': ours / results['smd_ulsph']['particle_steps_per_second_per_core'],
        'ratio_cohesive_to_cohesionless': results['sph_soil_cohesive']['particle_steps_per_second_per_core'] / ours,
        'lammps': lammps_version(lmp),
    }
    text = json.dumps(summary, indent=2)
    print(text)
    if a.json:
        with open(a.json, 'w') as f:
            f.write(text + '\n')


if __name__ == '__main__':
    main()
