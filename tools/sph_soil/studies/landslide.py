"""A 3D landslide over terrain (examples/landslide_3d, examples/shallow_landslide): the deposit of a
finished run, measured from its final dump so that refinement does not move the measures (a split
keeps the volume where it was, not the topmost particle). The slide is all the soil of
landslide_3d, and the patch that fails (type 2) of shallow_landslide, whose standing mantle is
measured apart (how much of it moved onto the floor):

  - runout_m: the x that 99% of the slide's volume lies behind (the front, without stragglers);
  - deposit_height_m: the largest thickness of the deposit, the soil's volume (mass / rho0) in a
    column of CELL x CELL over the ground divided by the cell's area, on the valley floor (beyond
    the hillside's toe); CELL is one length for every run (0.4 m, twice the coarsest spacing
    run), so that runs of any spacing are measured alike;
  - deposit_volume_fraction_on_floor: the share of the slide's volume beyond the toe;
  - standing_volume_on_floor_m3 (shallow_landslide): the mantle's volume beyond the toe.

Writes JSON and a plot: the deposit's thickness seen from above, and the front against time
(landslide.dat). With --run it first runs an example (a copy of its input, in --workdir) at
spacing --d with the refinement options of the failure studies (refine_options), and measures
that run; the JSON then also holds the configuration (spacing, refinement), its wall time and
the fields that a showcase reads (showcase_answer: the runout as the answer).

  python3 -m sph_soil landslide [--dir examples/landslide_3d] [--json FILE] [--plot FILE]
  python3 -m sph_soil landslide --dir examples/shallow_landslide
  python3 -m sph_soil landslide --run --example shallow_landslide --d 0.1 [--refine 2 --stepping level
                                --balance] [--np 2] [--workdir DIR] [--json FILE] [--plot FILE]
"""
import os
import re
import shutil

import numpy as np

from .. import logs, paths, refine_options, report, runner
from ..dumps import read_ave_time, read_dump

COMMAND = 'landslide'
# example -> its final dump, and the type of the soil that slides (None: all of it)
EXAMPLES = {'landslide_3d': ('dump.landslide_3d.final', None),
            'shallow_landslide': ('dump.shallow_landslide.final', 2)}
RHO0 = 1850.0       # the examples' soil density (kg/m^3)
CELL = 0.4          # the deposit's columns (m)


def terrain(directory):
    """The terrain's toe and extent, from the terrain.lmp beside the run (the include file)."""
    with open(os.path.join(directory, 'terrain.lmp')) as f:
        text = f.read()
    return {name: float(re.search(rf'variable\s+terrain_{name}\s+equal\s+(\S+)', text).group(1))
            for name in ('xlo', 'xhi', 'ylo', 'yhi', 'toe')}


def example_of(directory):
    """The example whose final dump is in `directory`."""
    found = [name for name, (dump, _) in EXAMPLES.items() if os.path.exists(os.path.join(directory, dump))]
    if not found:
        raise SystemExit(f'landslide: no final dump ({", ".join(d for d, _ in EXAMPLES.values())}) in {directory}')
    return found[0]


def deposit(s, toe, cell=CELL, slide_type=None):
    """The measures of the module's docstring from a final dump `s` (read_dump)."""
    standing = None
    if slide_type is not None:
        rest = s['type'] != slide_type
        standing = float((s['mass'][rest] / RHO0)[s['x'][rest] > toe].sum())
        s = {name: column[~rest] for name, column in s.items()}
    volume = s['mass'] / RHO0
    order = np.argsort(s['x'])
    cumulative = np.cumsum(volume[order]) / volume.sum()
    runout = float(s['x'][order][np.searchsorted(cumulative, 0.99)])
    floor = s['x'] > toe
    ix = np.floor(s['x'][floor] / cell).astype(int)
    iy = np.floor(s['y'][floor] / cell).astype(int)
    columns = {}
    for a, b, v in zip(ix, iy, volume[floor]):
        columns[(a, b)] = columns.get((a, b), 0.0) + v
    height = max(columns.values()) / cell ** 2 if columns else 0.0
    out = {'runout_m': round(runout, 4), 'deposit_height_m': round(height, 4),
           'deposit_volume_fraction_on_floor': round(float(volume[floor].sum() / volume.sum()), 4),
           'soil_particles': int(len(volume)), 'deepest_level': int(s['c_soil'].max())}
    if standing is not None:
        out['standing_volume_on_floor_m3'] = round(standing, 4)
    return out


def measure(directory, spacing=None):
    """The deposit of the run in `directory`; its spacing (the lattice's) from the newest run log
    unless given."""
    if spacing is None:
        spacing = next(float(m.group(1)) for m in (logs.Log(path).search(r'Lattice spacing in x,y,z = (\S+)')
                                                   for path in logs.run_logs(directory)) if m)
    dump, slide_type = EXAMPLES[example_of(directory)]
    s = read_dump(os.path.join(directory, dump))
    out = {'spacing_m': spacing, **deposit(s, terrain(directory)['toe'], slide_type=slide_type)}
    return out, s


def plot(summary, s, history, toe, out):
    plt = report.pyplot()
    fig, (top, front) = plt.subplots(1, 2, figsize=(11, 4), gridspec_kw={'width_ratios': [2.2, 1]})
    order = np.argsort(s['z'])
    sc = top.scatter(s['x'][order], s['y'][order], c=s['v_height'][order], s=2.0, cmap='viridis',
                     rasterized=True)
    fig.colorbar(sc, ax=top, label='height above the ground (m)')
    top.axvline(toe, color='0.5', ls=':', lw=0.8, label='toe of the hillside')
    top.axvline(summary['runout_m'], color='r', ls='--', lw=0.8, label='runout (99% of the volume)')
    top.set_aspect('equal')
    top.set_xlabel('x (m)')
    top.set_ylabel('y (m)')
    top.legend(fontsize=7, loc='upper left')
    top.set_title(f"deposit, d = {100 * summary['spacing_m']:g} cm: runout {summary['runout_m']:.2f} m, "
                  f"thickness {summary['deposit_height_m']:.2f} m", fontsize=9)
    if history is not None:
        front.plot(history[:, 1], history[:, 2], 'k-', lw=1.0)
    front.set_xlabel('time (s)')
    front.set_ylabel('front: largest x of the soil (m)')
    fig.tight_layout()
    fig.savefig(out, dpi=130)


def landslide(directory, json_path=None, plot_path=None, wall_seconds=None, spacing=None):
    summary, s = measure(directory, spacing)
    summary['wall_seconds'] = wall_seconds if wall_seconds is not None else logs.wall_seconds(directory)
    report.write_json(summary, json_path, indent=2)
    if plot_path:
        data = os.path.join(directory, 'landslide.dat')
        history = read_ave_time(data) if os.path.exists(data) else None
        plot(summary, s, history, terrain(directory)['toe'], plot_path)
    return summary


def report_example(directory, log, variables, seconds):
    """run_example's numbers and plot: EXAMPLE.json, EXAMPLE.png."""
    name = example_of(directory)
    landslide(directory, os.path.join(directory, f'{name}.json'), os.path.join(directory, f'{name}.png'),
              seconds, float(variables['d']))


def run(lmp, args):
    """Run the example at spacing args.d with the refinement options in a directory of its own
    (a copy of the input: an edit of the example cannot change a run under way); its deposit
    with the configuration's fields."""
    source = os.path.join(paths.example_dir(args.example), f'in.{args.example}')
    directory = os.path.join(args.workdir, f'{args.example}_d{args.d:g}{refine_options.tag(args)}')
    os.makedirs(directory, exist_ok=True)
    for old in os.listdir(directory):
        if old.startswith('frame.') or old.startswith('dump.'):
            os.remove(os.path.join(directory, old))
    shutil.copy(source, os.path.join(directory, f'in.{args.example}'))
    for name in ('terrain.lmp', 'terrain.stl'):
        shutil.copy(os.path.join(os.path.dirname(source), name), directory)
    done = lmp.run(os.path.join(directory, f'in.{args.example}'), directory, np=args.np,
                   variables=[('d', f'{args.d:g}')] + refine_options.variables(args))
    if not done.ok:
        raise SystemExit(f'landslide: {" ".join(done.command)} failed with exit code {done.returncode}')
    summary = landslide(directory, None, args.plot, round(done.seconds, 1), args.d)
    summary.update(refine_options.summary(args, args.d), ranks=args.np,
                   refinement=refine_options.title(args).lstrip(', '))
    report.write_json(summary, args.json, indent=2)
    return summary


def showcase_answer(summary):
    """A showcase configuration's answer (studies/showcase.py) from this study's JSON of one run:
    the runout (m), with the deposit's thickness beside it, and the run's wall time."""
    return {**{k: summary.get(k) for k in ('spacing_m', 'finest_spacing_m', 'refined', 'stepping', 'buffer',
                                          'ease', 'split', 'deposit_height_m', 'deposit_volume_fraction_on_floor',
                                          'standing_volume_on_floor_m3')},
            'critical': summary['runout_m'], 'half_width': 0.0, 'stands_up_to': None, 'fails_from': None,
            'wall_seconds_all_runs': summary['wall_seconds']}


def add_arguments(p):
    report.add_run_arguments(p, paths.example_dir('landslide_3d'),
                             'a final dump, landslide.dat, terrain.lmp')
    p.add_argument('--run', action='store_true', help='run --example first (in --workdir) and measure that run')
    p.add_argument('--example', choices=sorted(EXAMPLES), default='shallow_landslide',
                   help='with --run: the example (default: %(default)s)')
    p.add_argument('--d', type=float, default=0.2, help='with --run: the soil\'s spacing (m; default: %(default)s)')
    p.add_argument('--workdir', default='/tmp/sph_soil_landslide', help='with --run: where the run goes')
    runner.add_arguments(p)
    refine_options.add_arguments(p, every=16)


def main(a):
    if a.run:
        run(runner.from_arguments(a), a)
    else:
        landslide(a.dir, a.json, a.plot)
