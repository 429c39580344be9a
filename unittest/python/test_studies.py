"""The studies' declarations and the command line: the refinement comparison's run matrix
against its logs and the numbers of doc/refinement_comparison.json, the regression's tolerance,
the examples' variables, and --help listing every study."""
import json
import os
import re
import subprocess
import sys

import pytest

from sph_soil import cli, examples, paths, regression
from sph_soil.logs import Log
from sph_soil.studies import EXAMPLE_REPORTS, STUDIES, refinement

REFINEMENT_LOGS = {name[len('log.'):] for name in os.listdir(refinement.DIRECTORY)
                   if name.startswith('log.') and '.short.' not in name}


def matrix(problem, two_levels=True):
    return {f'{problem}_{run.key}' for run in refinement.RUNS
            if (problem == 'bars' or not run.bars_only) and (two_levels or not run.two_levels)}


def test_refinement_matrix_names_its_logs():
    # the names the matrix gives are the ones in.refinement wrote (log.<problem>_<key>)
    assert len({run.key for run in refinement.RUNS}) == len(refinement.RUNS)
    assert matrix('bars') | matrix('collapse') == REFINEMENT_LOGS
    assert len(matrix('bars', two_levels=False)) == 15 and len(matrix('collapse')) == 12


def test_refinement_run_variables():
    run = next(r for r in refinement.RUNS if r.key == 'dynamic_0.5_0.5_t10_shear_strain_rate_L2')
    assert dict(run.variables('bars')) == {'problem': 'bars', 'mode': 'dynamic', 'eps': '0.5', 'alpha': '0.5',
                                           'h0': '0', 'threshold': '10', 'criterion': 'shear_strain_rate',
                                           'maxlevel': '2'}


def test_refinement_logs_give_the_published_costs():
    # what the comparison reads from each log: the numbers of doc/refinement_comparison.json
    with open(os.path.join(paths.DOC, 'refinement_comparison.json')) as f:
        published = json.load(f)
    for problem, entries in published.items():
        for key, e in entries.items():
            loop, atoms, particle_steps, steps, error = refinement.read_log(
                os.path.join(refinement.DIRECTORY, f'log.{problem}_{key}'))
            assert (max(atoms), atoms[-1], particle_steps, steps, error) == (
                e['peak_particles'], e['final_particles'], e['particle_steps'], e['steps'], e['error'])
            if e['completed']:
                assert round(loop, 1) == e['wall_seconds']


def table(rows, columns=('Step', 'Atoms', 'v_x', 'c_count')):
    return list(columns), [list(map(float, r)) for r in rows]


def test_regression_tolerance():
    ref = table([[0, 100, 1.5, 40], [50, 100, 2.5, 400]])
    assert regression.compare(ref, ref) == []
    # rtol 1e-6 on continuous columns, 5% + 10 on counts
    assert regression.compare(ref, table([[0, 100, 1.5 * (1 + 9e-7), 40], [50, 100, 2.5, 400 * 1.05 + 10]])) == []
    assert regression.compare(ref, table([[0, 100, 1.5 * (1 + 2e-6), 40], [50, 100, 2.5, 431]])) == [
        f'row 0 column v_x: reference 1.5, new {1.5 * (1 + 2e-6)!r}', 'row 1 column c_count: reference 400.0, new 431.0']
    assert regression.compare(ref, table([[0, 101, 1.5, 40], [50, 100, 2.5, 400]])) == [
        'row 0 column Atoms: reference 100.0, new 101.0']
    assert regression.compare(ref, table([[0, 100, 1.5, 40]])) == ['1 thermo rows, reference has 2']


def test_reference_of_the_release_else_the_newest(tmp_path):
    for release in ('29Sep21', '4Feb25'):
        (tmp_path / f'log.{release}.x.short.2').write_text('')
    assert regression.reference_log(str(tmp_path), 'x', 2, '29Sep21').endswith('log.29Sep21.x.short.2')
    assert regression.reference_log(str(tmp_path), 'x', 2, '4Jul26').endswith('log.4Feb25.x.short.2')
    assert regression.reference_log(str(tmp_path), 'x', 1, '4Jul26') is None


def test_every_example_has_a_report():
    inputs = {name for name in os.listdir(paths.EXAMPLES) if os.path.exists(paths.example_input(name))}
    assert set(EXAMPLE_REPORTS) == inputs
    assert all(hasattr(module, 'report_example') for module in EXAMPLE_REPORTS.values())


def test_input_variables_with_command_line_overrides():
    variables = examples.input_variables(paths.example_input('bearing_capacity'), ['-var', 'phi', '20', '-echo', 'both'])
    assert variables['phi'] == '20' and variables['d'] == '0.1' and variables['slip'] == 'freeslip'
    assert examples.input_variables(paths.example_input('atom_style'))['height'] == '0.1'


def test_help_lists_every_study():
    text = cli.parser().format_help()
    for module in STUDIES + [examples, regression]:
        assert re.search(rf'^\s+{module.COMMAND}\b', text, re.M), module.COMMAND


def test_command_line_entry_point():
    env = dict(os.environ, PYTHONPATH=os.path.join(paths.ROOT, 'tools'))
    done = subprocess.run([sys.executable, '-m', 'sph_soil', 'refinement', '--help'], capture_output=True,
                          text=True, env=env, cwd=paths.ROOT)
    assert done.returncode == 0 and '--two-levels' in done.stdout


def test_unknown_problem_is_refused():
    with pytest.raises(SystemExit, match='unknown problem'):
        cli.main(['refinement', '--compare-only', 'slope'])


class RecordingLammps:
    """A stand-in for runner.Lammps that records the runs of a study (no MPI, no LAMMPS)."""

    def __init__(self, binary):
        self.binary = binary
        self.runs = []

    def run(self, infile, directory, np=1, variables=(), log='log.lammps', **options):
        self.runs.append((log, dict(variables)))
        return type('Result', (), {'ok': True})()


def test_refinement_runs_what_is_missing(tmp_path):
    binary = tmp_path / 'lmp'
    binary.write_text('')
    os.utime(binary, (0, 0))    # built long ago
    lmp = RecordingLammps(str(binary))
    refinement.run_matrix(lmp, ['bars'], 2, only='dynamic_0.55', directory=str(tmp_path))
    assert [log for log, _ in lmp.runs] == ['log.bars_dynamic_0.55_0.5', 'log.bars_dynamic_0.55_0.6',
                                             'log.bars_dynamic_0.55_0.7', 'log.bars_dynamic_0.55_0.5_h0',
                                             'log.bars_dynamic_0.55_0.6_h0', 'log.bars_dynamic_0.55_0.7_h0']
    # a final dump newer than the input and the binary: that run is up to date
    (tmp_path / 'dump.collapse_coarse.final').write_text('')
    lmp.runs = []
    refinement.run_matrix(lmp, ['collapse'], 2, directory=str(tmp_path))
    assert len(lmp.runs) == len(matrix('collapse')) - 1 and 'log.collapse_coarse' not in dict(lmp.runs)
    lmp.runs = []
    refinement.run_matrix(lmp, ['bars'], 2, only='_L2', two_levels=True, directory=str(tmp_path))
    assert [v['maxlevel'] for _, v in lmp.runs] == ['2', '2', '2']


def test_earth_pressure_references():
    """Coulomb's horizontal active coefficient and Lancellotta's passive lower bound at phi = 30,
    delta = 20 (the numbers of doc/validation.rst), and Rankine's for a smooth wall."""
    from sph_soil.studies import retaining_wall
    assert retaining_wall.limit(30.0, 20.0, False) == pytest.approx(0.2794, abs=1e-4)
    assert retaining_wall.lancellotta(30.0, 20.0) == pytest.approx(4.633, abs=1e-3)
    assert retaining_wall.lancellotta(30.0, 0.0) == pytest.approx(3.0, rel=1e-12)
    assert retaining_wall.limit(30.0, 0.0, True) == pytest.approx(3.0, rel=1e-12)


def test_sliding_block_measures_a_rigid_block(tmp_path):
    """block.dat of a block that slides exactly as a rigid one, with the floor's shear mu times
    its normal force: acceleration 1 times the rigid block's, shear / normal error 0."""
    from sph_soil.studies import sliding_block
    import math
    mu, ratio = 0.4, 1.5
    theta = math.atan(ratio * mu)
    a = sliding_block.G * (math.sin(theta) - mu * math.cos(theta))
    rows = ['# Time-averaged data for fix out', '# TimeStep v_t c_block v_shear v_normal']
    for k in range(101):
        t = 0.001 * k
        rows.append(f'{k} {t} {a * t} {mu * 10.0} 10.0')
    path = tmp_path / 'block.dat'
    path.write_text('\n'.join(rows) + '\n')
    result, _ = sliding_block.measure(str(path), mu, ratio)
    assert result['acceleration_over_rigid'] == pytest.approx(1.0, rel=1e-9)
    assert result['shear_over_normal_error'] == pytest.approx(0.0, abs=1e-12)


def test_levels_names_are_those_in_refinement_gives(lmp, tmp_path):
    # the deep-refinement study finds each run's final dump by the name in.refinement builds
    from sph_soil.studies import levels
    cases = [r for r in levels.runs('collapse', [1, 2])] + [levels.runs('bars', [2])[-1]]
    cases += [(levels.uniform_name('bars', 0.0005), '', [('problem', 'bars'), ('mode', 'coarse'), ('h0', '1'),
                                                          ('spacing', '0.0005')], 0, False)]
    for name, _, variables, _, _ in cases:
        result = lmp.run(refinement.INPUT, str(tmp_path), variables=list(variables) + [('steps', '0')],
                         log='log.test', check=True)
        assert Log(result.log).search(r'^refinement: run (\S+) ', re.M).group(1) == name
