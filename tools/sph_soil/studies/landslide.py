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
(landslide.dat).

  python3 -m sph_soil landslide [--dir examples/landslide_3d] [--json FILE] [--plot FILE]
  python3 -m sph_soil landslide --dir examples/shallow_landslide
"""
import os
import re

import numpy as np

from .. import logs, paths, report
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


def add_arguments(p):
    report.add_run_arguments(p, paths.example_dir('landslide_3d'),
                             'a final dump, landslide.dat, terrain.lmp')


def main(a):
    landslide(a.dir, a.json, a.plot)
