"""The bearing capacity of a smooth strip footing on weightless soil against Prandtl's c N_c
(examples/bearing_capacity).

Runs examples/bearing_capacity/in.bearing_capacity for phi = 0 and phi = 20 degrees (psi = 0,
Drucker-Prager with the exact plane-strain fit) at two resolutions (B/d = 10 and 20 by default),
each in its own directory under --workdir, and reads bearing.dat (q against the settlement,
averaged over 0.01 s) and the log's last line. The limit pressure is the mean of q over the last
third of the push: settlement 0.10-0.15 B (the input's f_limit, an average over every step of
that part). Also reported: q at settlements 0.05 B and 0.10 B, the largest q, and the early
mean of q over settlements 0.02-0.05 B (of the 0.01 s averages), after the curve has bent and
before the footing has sunk far into the soil. Prandtl:
N_c = 2 + pi for phi = 0, (N_q - 1) cot(phi) with N_q = exp(pi tan phi) tan^2(45 + phi/2)
otherwise (14.83 at 20 degrees). --check-speed adds a run at half the speed for each phi at the
coarse resolution (inertia and artificial viscosity: the limit pressure should not move by more
than a couple of percent).

The smooth footing (free-slip mirror walls) needs the soil's tension cut-off (--tension 0, the
default here): without it, the soil particle at the footing's corner, on the free surface, goes
into growing mean tension (phi = 0 has no apex), is pulled into the footing and the run stops
at a settlement of about 0.04 B (doc/validation.rst). Prandtl's stress field has no mean
tension anywhere, so the cut-off T = 0 leaves the exact limit load unchanged (lower-bound
theorem). --tension none runs without it; --slip noslip gives the rough footing, whose N_c is
the same for weightless soil.

The box is 12 B wide and 5 B deep (--width, --depth): in one 8 B x 2.5 B, which holds
Prandtl's mechanism, the model's own mechanism at phi = 20 (psi = 0) reaches the smooth floor
and the limit comes out box-limited, 0.79 c N_c at every resolution (doc/validation.rst).

--refine N (and the other refinement options of the slope's and the vertical cut's studies:
--stepping, --buffer, ...) splits the particles that strain, N levels deep, with the footing's
wall particles at the finest level's spacing; the showcase (python3 -m sph_soil showcase
bearing-capacity) compares such runs with the uniform ones.

Prints JSON, writes --json, the plot --plot (q / c against settlement / B with the Prandtl
lines) and a picture of the failure mechanisms of the finest runs (--mechanism: the soil
coloured by its accumulated maximum shear strain at the end of the push, phi = 0 and 20 side
by side); --doc copies plot and picture to doc/img/bearing_capacity.png and
doc/img/bearing_capacity_mechanism.png.

  python3 -m sph_soil bearing-capacity [--lmp build/lmp] [--np 2] [--resolutions 10 20] [--phis 0 20]
                                      [--speed 0.1] [--tension 0] [--slip freeslip] [--check-speed]
                                      [--width 12] [--depth 5] [--refine N [--stepping level] ...]
                                      [--workdir /tmp/sph_soil_bearing_capacity] [--doc]
                                      [--json examples/bearing_capacity/bearing_capacity.json]
                                      [--plot examples/bearing_capacity/bearing_capacity.png]
                                      [--mechanism examples/bearing_capacity/bearing_capacity_mechanism.png]
"""
import glob
import math
import os
import shutil

import numpy as np

from .. import paths, refine_options, report, runner
from ..dumps import read_ave_time
from ..inputs import input_variables
from ..logs import Log

COMMAND = 'bearing-capacity'
EARLY = (0.02, 0.05)    # settlements / B: the early mean of q, after the curve has bent, before the footing sinks in
EXDIR = paths.example_dir('bearing_capacity')
EXAMPLE = paths.example_input('bearing_capacity')
DEFAULTS = input_variables(EXAMPLE)
B = 1.0


def prandtl_nc(phi):
    if phi == 0.0:
        return 2.0 + math.pi
    t = math.tan(math.radians(phi))
    nq = math.exp(math.pi * t) * math.tan(math.radians(45.0 + 0.5 * phi)) ** 2
    return (nq - 1.0) / t


def measure(directory, phi, resolution, speed, c, slip, tension, returncode, seconds, log='log.lammps'):
    """A finished push (bearing.dat, the log, frame.*.png in directory): the limit pressure
    from the log's last line, q at settlements 0.05 B and 0.10 B, the largest q, the curve."""
    log = Log(os.path.join(directory, log))
    m = log.search(r'limit pressure q = (\S+) Pa = \S+ c, q / \(c N_c\) = (\S+) .*soil inside the '
                   r'footing: (\d+)')
    data = read_ave_time(os.path.join(directory, 'bearing.dat'))
    settle, q = data[:, 2], data[:, 3]
    nc = prandtl_nc(phi)
    result = {'phi_deg': phi, 'B_over_d': resolution, 'd_m': B / resolution, 'speed_m_per_s': speed,
              'slip': slip, 'tension_cutoff': tension, 'N_c': round(nc, 4),
              'finished': returncode == 0 and m is not None,
              'wall_seconds': None if seconds is None else round(seconds, 1),
              'directory': directory}
    if m:
        result.update({'q_limit_Pa': float(m.group(1)), 'q_limit_over_cNc': float(m.group(2)),
                       'soil_inside_footing': int(m.group(3))})
        left = log.findall(r'soil that left the box: ([0-9.eE+-]+)')
        if left:    # particles squeezed out at the footing's corner (their mass in initial particles)
            result['soil_left_box_particles'] = float(left[-1])
    else:
        err = log.findall(r'ERROR.*')
        result['error'] = err[-1] if err else f'exit code {returncode}'
        result['stopped_at_settlement_over_B'] = round(float(settle[-1]), 4) if len(settle) else 0.0
    for s in (0.05, 0.10):
        if len(settle) and settle[-1] >= s:
            result[f'q_at_{s:.2f}B_over_cNc'] = round(float(np.interp(s, settle, q)) / (c * nc), 4)
    if len(q):
        result['q_max_over_cNc'] = round(float(q.max()) / (c * nc), 4)
    early = (settle >= EARLY[0]) & (settle < EARLY[1])
    if len(settle) and settle[-1] >= EARLY[1]:
        result['q_early_over_cNc'] = round(float(q[early].mean()) / (c * nc), 4)
    result['settlement'] = settle.tolist()
    result['q_over_c'] = (q / c).tolist()
    end = glob.glob(os.path.join(directory, 'frame.end.*.png'))
    result['frame'] = end[0] if end else None
    return result


def run(lmp, args, phi, resolution, speed):
    d = B / resolution
    tag = (f'phi{phi:g}_Bd{resolution:g}_v{speed:g}_{args.slip}_T{args.tension}_box{args.width:g}x{args.depth:g}'
           f'{refine_options.tag(args)}')
    directory = os.path.join(args.workdir, tag)
    os.makedirs(directory, exist_ok=True)
    for old in glob.glob(os.path.join(directory, 'frame.*.png')):
        os.remove(old)
    done = lmp.run(EXAMPLE, directory, np=args.np, copy=True, variables=[
        ('phi', f'{phi:g}'), ('d', f'{d:.10g}'), ('speed', f'{speed:g}'), ('c', f'{args.c:g}'),
        ('slip', args.slip), ('tension', '-1' if args.tension == 'none' else args.tension),
        ('width', f'{args.width:g}'), ('depth', f'{args.depth:g}')] + refine_options.variables(args))
    result = measure(directory, phi, resolution, speed, args.c, args.slip, args.tension, done.returncode,
                     done.seconds)
    result.update(refine_options.summary(args, d), refinement=refine_options.title(args).lstrip(', '))
    return result


def curves_plot(runs, speed, phis, resolutions, footing, out):
    """q / c against settlement / B, one line per run, with Prandtl's c N_c of each phi."""
    plt = report.pyplot()
    fig, ax = plt.subplots(figsize=(7.5, 4.6))
    colours = {phi: c for phi, c in zip(phis, ['tab:blue', 'tab:red', 'tab:green', 'tab:purple'])}
    for r in runs:
        ranks = sorted(resolutions, reverse=True)
        style = ['-', '--', '-.', (0, (5, 1, 1, 1, 1, 1))][min(ranks.index(r['B_over_d']), 3)]
        if r['speed_m_per_s'] != speed:
            style = ':'
        label = f"phi = {r['phi_deg']:g}, B/d = {r['B_over_d']:g}"
        if r.get('refinement'):
            label += f", {r['refinement']}"
        if r['speed_m_per_s'] != speed:
            label += f", {r['speed_m_per_s']:g} m/s"
        if 'q_limit_over_cNc' in r:
            label += f": {r['q_limit_over_cNc']:.3f} c N_c"
        else:
            label += ': stopped'
        ax.plot(r['settlement'], r['q_over_c'], style, color=colours[r['phi_deg']], label=label)
    for phi in phis:
        ax.axhline(prandtl_nc(phi), color=colours[phi], lw=0.8, alpha=0.6)
        ax.text(0.001, prandtl_nc(phi) + 0.15, f'Prandtl c N_c, phi = {phi:g}: {prandtl_nc(phi):.2f} c',
                color=colours[phi], fontsize=7)
    ax.axvspan(0.10, 0.15, color='0.9', zorder=0)
    ax.set_xlabel('settlement / B')
    ax.set_ylabel('q / c')
    ax.set_title(f"Strip footing ({footing}) on weightless soil, psi = 0, E/c = 1000: "
                 'q against Prandtl (grey: limit-pressure window)', fontsize=8)
    ax.legend(fontsize=7, loc='center right')
    ax.set_xlim(0.0, max(max(r['settlement']) for r in runs if r['settlement']))
    fig.tight_layout()
    fig.savefig(out, dpi=110)


def public(r):
    """A run's entry of the JSON: without the curve and the frame."""
    return {k: v for k, v in r.items() if k not in ('settlement', 'q_over_c', 'frame')}


def report_example(directory, log, variables, seconds):
    """run_example's numbers and plot of the one push (phi and B/d of the input):
    bearing_capacity.json, bearing_capacity.png."""
    phi, c = float(variables['phi']), float(variables['c'])
    resolution = round(B / float(variables['d']), 6)
    r = measure(directory, phi, resolution, float(variables['speed']), c, variables['slip'],
                variables['tension'], 0, seconds, log)
    report.write_json(public(r), os.path.join(directory, 'bearing_capacity.json'), indent=1, end='')
    curves_plot([r], r['speed_m_per_s'], [phi], [resolution],
                'smooth' if variables['slip'] == 'freeslip' else 'rough', os.path.join(directory, 'bearing_capacity.png'))


def add_arguments(p):
    runner.add_arguments(p)
    p.add_argument('--resolutions', type=float, nargs='+', default=[10, 20], help='B / d')
    p.add_argument('--phis', type=float, nargs='+', default=[0.0, 20.0])
    p.add_argument('--speed', type=float, default=0.1, help='push speed (m/s), B = 1 m')
    p.add_argument('--c', type=float, default=10000.0, help='cohesion (Pa)')
    p.add_argument('--tension', default='0', help="the soil's tension cut-off (Pa) or 'none'")
    p.add_argument('--slip', default='freeslip', choices=['freeslip', 'noslip'])
    p.add_argument('--width', type=float, default=12.0, help='soil layer width / B')
    p.add_argument('--depth', type=float, default=5.0, help='soil layer depth / B')
    p.add_argument('--check-speed', action='store_true',
                   help='also run each phi at half the speed at the coarsest resolution')
    p.add_argument('--workdir', default='/tmp/sph_soil_bearing_capacity')
    p.add_argument('--json', default=os.path.join(EXDIR, 'bearing_capacity.json'))
    p.add_argument('--plot', default=os.path.join(EXDIR, 'bearing_capacity.png'))
    p.add_argument('--mechanism', default=os.path.join(EXDIR, 'bearing_capacity_mechanism.png'))
    p.add_argument('--doc', action='store_true', help='copy plot and picture to doc/img/')
    refine_options.add_arguments(p, every=int(DEFAULTS['check']))


def showcase_answer(summary):
    """A showcase configuration's answer (studies/showcase.py) from this study's JSON of one push:
    the limit pressure q / (c N_c) and the push's wall time, with the run's refinement fields."""
    runs = summary['runs']
    if len(runs) != 1 or 'q_limit_over_cNc' not in runs[0]:
        raise ValueError(f'bearing capacity: a showcase configuration is one finished push, got {runs}')
    r = runs[0]
    return {**{k: r[k] for k in ('spacing_m', 'finest_spacing_m', 'refined', 'stepping', 'buffer', 'ease',
                                  'split')},
            'critical': r['q_limit_over_cNc'], 'half_width': 0.0, 'stands_up_to': None, 'fails_from': None,
            'wall_seconds_all_runs': r['wall_seconds']}


def main(args):
    lmp = runner.from_arguments(args)
    runs = []
    for phi in args.phis:
        for resolution in sorted(args.resolutions):
            runs.append(run(lmp, args, phi, resolution, args.speed))
        if args.check_speed:
            runs.append(run(lmp, args, phi, min(args.resolutions), 0.5 * args.speed))
    summary = {'definition': 'limit pressure: mean of q over the last third of the push '
                             '(settlement 0.10-0.15 B); q = the footing particles\' reaction / B',
               'footing': 'smooth' if args.slip == 'freeslip' else 'rough',
               'tension_cutoff_Pa': args.tension, 'box_width_over_B': args.width,
               'box_depth_over_B': args.depth,
               'runs': [public(r) for r in runs]}
    for r in summary['runs']:
        if 'q_limit_over_cNc' in r:
            r['error_percent'] = round(100.0 * (r['q_limit_over_cNc'] - 1.0), 2)
    if args.check_speed:
        checks = []
        for phi in args.phis:
            base = [r for r in runs if r['phi_deg'] == phi and r['B_over_d'] == min(args.resolutions)
                    and r['speed_m_per_s'] == args.speed]
            half = [r for r in runs if r['phi_deg'] == phi and r['speed_m_per_s'] == 0.5 * args.speed]
            if base and half and 'q_limit_Pa' in base[0] and 'q_limit_Pa' in half[0]:
                checks.append({'phi_deg': phi, 'B_over_d': min(args.resolutions),
                               'q_limit_half_over_full': round(half[0]['q_limit_Pa'] / base[0]['q_limit_Pa'], 4)})
        summary['speed_check'] = checks
    report.write_json(summary, args.json, indent=1, end='')

    plt = report.pyplot()
    if args.plot:
        curves_plot(runs, args.speed, args.phis, args.resolutions, summary['footing'], args.plot)
    if args.mechanism:
        finest = [r for r in runs if r['B_over_d'] == max(args.resolutions) and r['speed_m_per_s'] == args.speed
                  and r['frame']]
        if finest:
            fig, axes = plt.subplots(len(finest), 1, figsize=(8, 3.2 * len(finest)))
            axes = np.atleast_1d(axes)
            for ax, r in zip(axes, finest):
                ax.imshow(plt.imread(r['frame']))
                ax.set_axis_off()
                ax.set_title(f"phi = {r['phi_deg']:g}, B/d = {r['B_over_d']:g}, settlement "
                             f"{r['settlement'][-1]:.2f} B: max. shear strain (blue 0, cyan 0.05, "
                             'yellow 0.15, red >= 0.4)', fontsize=8)
            fig.tight_layout()
            fig.savefig(args.mechanism, dpi=110)
    if args.doc:
        img = paths.DOC_IMG
        if args.plot:
            shutil.copy(args.plot, os.path.join(img, 'bearing_capacity.png'))
        if args.mechanism and os.path.exists(args.mechanism):
            shutil.copy(args.mechanism, os.path.join(img, 'bearing_capacity_mechanism.png'))
