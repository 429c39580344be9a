"""A block sliding down a frictional incline (examples/sliding_block) against a rigid block.

    python3 -m sph_soil sliding-block                 # 2 mm and 1 mm, tan(theta) = 0.8 and 1.5 mu
    python3 -m sph_soil sliding-block --spacings 0.002 --ratios 1.5 --np 1

Runs in.sliding_block for each spacing and each ratio tan(theta) / mu (one run at a time, each
in its own directory under --workdir) and measures from block.dat (every 1 ms):
  - acceleration: the slope of the block's mean velocity over the second half of the run,
    against a rigid block's g (sin theta - mu cos theta) (sliding) or 0 (sticking);
  - the largest |velocity| (sticking: the block should not move);
  - the floor's shear over its normal force, mean over the second half, against mu (sliding)
    or tan(theta) (sticking).
Prints a JSON table (and writes it to --json) and plots the velocities against a rigid block's
(--plot).
"""
import math
import os

import numpy as np

from .. import paths, report, runner
from ..dumps import read_ave_time

COMMAND = 'sliding-block'
EXDIR = paths.example_dir('sliding_block')
G = 9.81


def measure(path, mu, ratio):
    data = read_ave_time(path)
    t, v, shear, normal = data[:, 1], data[:, 2], data[:, 3], data[:, 4]
    theta = math.atan(ratio * mu)
    rigid = G * (math.sin(theta) - mu * math.cos(theta)) if ratio > 1.0 else 0.0
    late = t >= 0.5 * t[-1]
    slope = float(np.polyfit(t[late], v[late], 1)[0])
    force_ratio = float(np.mean(shear[late] / normal[late]))
    expected_ratio = mu if ratio > 1.0 else math.tan(theta)
    result = {'tan_theta_over_mu': ratio, 'mu': mu, 'acceleration_m_per_s2': slope,
              'rigid_block_m_per_s2': rigid, 'max_abs_velocity_m_per_s': float(np.abs(v).max()),
              'shear_over_normal': force_ratio, 'expected_shear_over_normal': expected_ratio,
              'shear_over_normal_error': force_ratio / expected_ratio - 1.0}
    if rigid:
        result['acceleration_over_rigid'] = slope / rigid
    return result, (t, v, rigid)


def plot_curves(curves, mu, ratios, path):
    plt = report.pyplot()
    fig, ax = plt.subplots(figsize=(6.5, 4.2))
    for label, (t, v, rigid) in curves:
        ax.plot(t, v, label=label)
    for ratio in ratios:
        theta = math.atan(ratio * mu)
        rigid = max(0.0, G * (math.sin(theta) - mu * math.cos(theta)))
        t = np.linspace(0.0, curves[0][1][0][-1], 2)
        ax.plot(t, rigid * t, 'k--', lw=0.8)
    ax.set_xlabel('time (s)')
    ax.set_ylabel('mean velocity along the incline (m/s)')
    ax.set_title(f'block on an incline, mu = {mu:g} (dashed: rigid block)')
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(path, dpi=110)


def report_example(directory, log, variables, seconds):
    """run_example's numbers and plot: sliding_block.json, sliding_block.png."""
    mu, ratio = float(variables['mu']), float(variables['ratio'])
    row, curve = measure(os.path.join(directory, 'block.dat'), mu, ratio)
    row.update({'spacing_m': float(variables['d']), 'seconds': round(seconds, 1)})
    report.write_json({'runs': [row]}, os.path.join(directory, 'sliding_block.json'))
    plot_curves([(f"d = {1000 * float(variables['d']):g} mm", curve)], mu, [ratio],
                os.path.join(directory, 'sliding_block.png'))


def add_arguments(p):
    runner.add_arguments(p, np=1)
    p.add_argument('--spacings', type=float, nargs='+', default=[0.002, 0.001])
    p.add_argument('--ratios', type=float, nargs='+', default=[0.8, 1.5], help='tan(theta) / mu')
    p.add_argument('--mu', type=float, default=0.4)
    p.add_argument('--workdir', default='/tmp/sph_soil_sliding_block')
    p.add_argument('--json', default=os.path.join(EXDIR, 'sliding_block.json'))
    p.add_argument('--plot', default=os.path.join(EXDIR, 'sliding_block.png'))


def main(args):
    lmp = runner.from_arguments(args)
    rows, curves = [], []
    for ratio in args.ratios:
        for d in args.spacings:
            directory = os.path.join(args.workdir, f'd{d:g}_ratio{ratio:g}')
            done = lmp.run(paths.example_input('sliding_block'), directory, np=args.np,
                           variables=[('d', d), ('mu', args.mu), ('ratio', ratio)], check=True)
            row, curve = measure(os.path.join(directory, 'block.dat'), args.mu, ratio)
            row.update({'spacing_m': d, 'particles_over_height': round(0.008 / d), 'seconds': round(done.seconds, 1)})
            rows.append(row)
            curves.append((f'd = {1000 * d:g} mm, tan(theta) = {ratio:g} mu', curve))
    report.write_json({'runs': rows}, args.json)
    if args.plot:
        plot_curves(curves, args.mu, args.ratios, args.plot)
