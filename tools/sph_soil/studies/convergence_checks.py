"""The classic checks as resolution sequences: what each runs at a particle spacing, what it
answers and against which reference (convergence.py beside it runs them and judges the sequence).

A check is one Check in CHECKS: an example input, the variables that set the spacing and the
dissipation (Monaghan's alpha = beta, the examples' `viscosity`), its sequence of spacings
(coarsest first, a constant ratio), and measure(directory, spacing) -> {answer: value / reference}, every
answer a ratio to its exact or published value, so that 1 is right. Each check says where its
reference comes from. A new check is one entry here.
"""
import importlib.util
import os
from dataclasses import dataclass

from .. import paths
from ..inputs import input_variables
from .. import bisection
from . import aluminium_bars, bearing_capacity, elastic_column, retaining_wall, vertical_cut


COHESION = float(input_variables(paths.example_input('bearing_capacity'))['c'])   # Pa


@dataclass
class Check:
    name: str
    example: str                  # the example's directory under examples/
    title: str                    # what the check is, for plots and tables
    reference: str                # the exact or published answer, and where it comes from
    spacings: tuple               # the default sequence (m), coarsest first, a constant ratio
    short_spacings: tuple         # a quick sequence (the ctest's)
    answers: dict                 # answer key -> what it is (a ratio to its reference)
    measure: object               # measure(directory, spacing) -> {answer key: value, and diagnostics: numbers
                                  # that are not judged, such as the soil inside a footing}
    input: str = None             # the input's file name (default in.<example>)
    variables: tuple = ()         # fixed -var settings of every run
    spacing_variable: str = 'd'
    dissipation_variable: str = 'viscosity'
    dissipation: float = 1.0      # the example's own value of the dissipation variable
    solve: object = None          # solve(lmp, directory, variables, np) -> measure()'s dict, for a check
                                  # whose answer takes several runs (a bisection); None: one run
    ensemble: int = 1             # members per point (a chaotic problem), each with its own seed:
    member_variable: str = 'seed'     # the variable that takes the member's number
    member_variables: tuple = ()      # and the variables that make a member differ (the perturbation)

    @property
    def infile(self):
        return os.path.join(paths.EXAMPLES, self.example, self.input or f'in.{self.example}')

    @property
    def primary(self):
        """The answer the study judges first (the first declared)."""
        return next(iter(self.answers))


def measure_elastic(directory, spacing):
    try:
        r = elastic_column.measure(directory)
    except SystemExit as e:
        raise RuntimeError(str(e)) from None
    return {'settlement': r['settlement_over_exact'], 'wall_force': r['wall_force_over_exact']}


def measure_prandtl(directory, spacing):
    r = bearing_capacity.measure(directory, phi=0.0, resolution=bearing_capacity.B / spacing, speed=None,
                                 c=COHESION, slip=None, tension=None, returncode=0, seconds=None)
    if not r['finished']:
        raise RuntimeError(f"prandtl: the run in {directory} stopped: {r.get('error')}")
    return {'q_limit': r['q_limit_over_cNc'], 'q_early': r.get('q_early_over_cNc'),
            'soil_inside_footing': r['soil_inside_footing'],
            'soil_left_box_particles': r.get('soil_left_box_particles', 0.0)}


def measure_rankine(delta):
    def measure(directory, spacing):
        result = retaining_wall.earth_pressure([f"run={os.path.join(directory, 'wall_force.dat')}@{delta:g}"],
                                               echo=False)
        r = result['runs']['run']
        return {'K_final': r['final_over_limit'], 'swing': r['swing_last_20_percent']}
    return measure


def example_script(example, name):
    """A plotting script beside an example (examples/EXAMPLE/NAME.py), as a module."""
    path = os.path.join(paths.EXAMPLES, example, f'{name}.py')
    spec = importlib.util.spec_from_file_location(f'sph_soil_example_{name}', path)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


PRANDTL_ANSWERS = {'q_limit': 'the limit pressure (mean of q over settlements 0.10-0.15 B) / (c N_c)',
                   'q_early': 'the mean of q over settlements 0.02-0.05 B / (c N_c)'}
TERZAGHI_TIMES = (0.05, 0.2)    # T_v of the answers


def measure_terzaghi(directory, spacing):
    compare = example_script('saturated', 'compare_consolidation')
    table = compare.degrees(os.path.join(directory, 'consolidation.txt'), TERZAGHI_TIMES)
    return {f'U_at_Tv_{tv:g}': row['U'] / row['U_terzaghi'] for tv, row in zip(TERZAGHI_TIMES, table)}


CUT_BRACKET = (3.0, 4.5)      # gamma H / c: stands at the first, fails at the second
CUT_STEPS = 7                 # bisections: the critical ratio to +- 0.006 (0.16% of Pastor's)


def solve_vertical_cut(lmp, directory, variables, np):
    """The critical gamma H / c of the vertical cut at one spacing, by bisection (each ratio's run
    in a directory of its own), over the middle of Pastor et al.'s bounds."""
    reference = 0.5 * sum(vertical_cut.PASTOR)

    def run(ratio):
        sub = os.path.join(directory, f'ratio{ratio:.4f}')
        done = lmp.run(vertical_cut.EXAMPLE, sub, np=np, copy=True,
                       variables=list(variables) + [('ratio', f'{ratio:.6g}')])
        try:
            return vertical_cut.measure(sub, ratio, seconds=done.seconds)
        except SystemExit as e:
            raise RuntimeError(str(e)) from None

    try:
        runs, low, high = bisection.bisect(run, *CUT_BRACKET, CUT_STEPS, 'vertical cut')
    except SystemExit as e:
        raise RuntimeError(str(e)) from None
    return {'critical_ratio': 0.5 * (low + high) / reference, 'half_width': 0.5 * (high - low) / reference,
            'runs': len(runs)}


BARS_RUNOUT, BARS_ANGLE = 0.43, 32.9     # Bui et al. 2008's measured runout (m) and failure angle (deg)


def measure_bars(directory, spacing):
    surface, failure = aluminium_bars.read_experiment()
    try:
        s = aluminium_bars.measure(directory, surface, failure, spacing=spacing)['summary']
    except (SystemExit, KeyError) as e:
        raise RuntimeError(f'aluminium bars: the run in {directory} did not finish: {e}') from None
    return {'runout': s['runout_m'] / BARS_RUNOUT, 'failure_angle': s['failure_angle_deg'] / BARS_ANGLE,
            'surface_rms_m': s['surface_rms_m']}


CHECKS = {c.name: c for c in [
    Check('elastic', 'elastic_column',
          'an elastic column settling under its own weight in a smooth box',
          'the exact solution of the rate form (examples/elastic_column: within 0.04% of the small-strain one)',
          spacings=(0.1, 0.05, 0.025, 0.0125), short_spacings=(0.1, 0.05, 0.025),
          answers={'settlement': "the top row's settlement / exact",
                   'wall_force': "the soil's force on a side wall / exact"},
          measure=measure_elastic),
    Check('prandtl-smooth', 'bearing_capacity',
          'a smooth rigid strip footing on weightless phi = 0 soil (box 8 B x 2.5 B)',
          "Prandtl: q = (2 + pi) c",
          spacings=(0.1, 0.05, 0.025), short_spacings=(0.2, 0.1, 0.05),
          answers=PRANDTL_ANSWERS, measure=measure_prandtl,
          variables=(('phi', '0'), ('width', '8'), ('depth', '2.5'))),
    Check('prandtl-rough', 'bearing_capacity',
          'a strip footing with a rough base on weightless phi = 0 soil (box 8 B x 2.5 B)',
          "Prandtl: q = (2 + pi) c (the same for a rough footing on weightless soil)",
          spacings=(0.1, 0.05, 0.025), short_spacings=(0.2, 0.1, 0.05),
          answers=PRANDTL_ANSWERS, measure=measure_prandtl,
          variables=(('phi', '0'), ('width', '8'), ('depth', '2.5'), ('slip', 'noslip'))),
    Check('rankine-smooth', 'retaining_wall',
          'active earth pressure on a smooth wall, phi = 30 degrees',
          "Rankine: K_a = (1 - sin phi) / (1 + sin phi) = 1/3",
          spacings=(0.05, 0.025, 0.0125), short_spacings=(0.1, 0.05, 0.025),
          answers={'K_final': 'K over the last 10% of the travel / K_a'},
          measure=measure_rankine(0.0)),
    Check('rankine-rough', 'retaining_wall',
          'active earth pressure on a rough wall, phi = 30, delta = 20 degrees',
          "Coulomb: K_a cos(delta) = 0.279",
          spacings=(0.05, 0.025, 0.0125), short_spacings=(0.1, 0.05, 0.025),
          answers={'K_final': 'K over the last 10% of the travel / (K_a cos delta)'},
          measure=measure_rankine(20.0), variables=(('delta', '20'),)),
    Check('terzaghi', 'saturated', "one-dimensional consolidation under a drained piston",
          "Terzaghi's degree of consolidation U(T_v) (compressible pore water: doc/theory.rst 7)",
          spacings=(0.01, 0.005, 0.0025, 0.00125), short_spacings=(0.01, 0.005, 0.0025),
          answers={'U_at_Tv_0.2': 'U at T_v = 0.2 / Terzaghi', 'U_at_Tv_0.05': 'U at T_v = 0.05 / Terzaghi'},
          measure=measure_terzaghi, input='in.consolidation', variables=(('time', '0.1'),),
          dissipation=0.1),
    Check('vertical-cut', 'vertical_cut', 'the critical height of a vertical cut in phi = 0 soil',
          'Pastor, Thai & Francescato (2000): gamma H / c between 3.772 and 3.786 (their middle, 3.779)',
          spacings=(0.1, 0.05, 0.025), short_spacings=(0.1, 0.05, 0.025),
          answers={'critical_ratio': f'the critical gamma H / c by bisection ({CUT_STEPS} steps) / 3.779'},
          measure=None, solve=solve_vertical_cut),
    Check('bars', 'aluminium_bars', "the collapse of Bui et al. 2008's aluminium bars (an ensemble per spacing)",
          'the measured runout, 0.43 m, and failure angle, 32.9 degrees',
          spacings=(0.004, 0.002, 0.001), short_spacings=(0.008, 0.004, 0.002),
          answers={'runout': 'the runout / 0.43 m', 'failure_angle': 'the failure angle / 32.9 degrees'},
          measure=measure_bars, ensemble=5, member_variables=(('perturb', '0.01'),)),
]}

def check(name):
    if name not in CHECKS:
        raise SystemExit(f"convergence: no check '{name}'; the checks: {', '.join(CHECKS)}")
    return CHECKS[name]
