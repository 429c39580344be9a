"""The studies' declarations and the command line: the refinement comparison's run matrix
against its logs and the numbers of doc/refinement_comparison.json, the regression's tolerance,
the examples' variables, and --help listing every study."""
import json
import os
import re
import subprocess
import sys

import pytest

from sph_soil import cli, examples, inputs, paths, regression
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
    variables = inputs.input_variables(paths.example_input('bearing_capacity'), ['-var', 'phi', '20', '-echo', 'both'])
    assert variables['phi'] == '20' and variables['d'] == '0.1' and variables['slip'] == 'freeslip'
    assert inputs.input_variables(paths.example_input('atom_style'))['height'] == '0.1'


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


def test_bisection_summary_and_refinement_options():
    """The bisection's result in the keys every study writes (and showcase reads), and the
    refinement options' input variables and directory tags."""
    from sph_soil import bisection, refine_options
    runs = [{'F': 1.5, 'fails': True, 'wall_seconds': 2.0, 'time': [0.0]},
            {'F': 1.0, 'fails': False, 'wall_seconds': 1.0, 'moved': [0.0]},
            {'F': 1.25, 'fails': False, 'wall_seconds': None}]
    s = bisection.summary(runs, 1.25, 1.5, 'F')
    assert (s['critical'], s['half_width'], s['wall_seconds_all_runs']) == (1.375, 0.125, 3.0)
    assert [r['F'] for r in s['runs']] == [1.0, 1.25, 1.5] and 'time' not in s['runs'][2]
    p = cli.parser()
    args = p.parse_args(['strength-reduction', '--d', '0.5', '--refine', '2', '--stepping', 'level', '--balance'])
    assert refine_options.variables(args) == [('refine', '2'), ('stepping', 'level'), ('criterion', 'strain'),
                                              ('check', '16'), ('balance', '1')]
    assert refine_options.tag(args) == '_refined2_level_balanced'
    assert refine_options.summary(args, 0.5)['finest_spacing_m'] == 0.125
    args = p.parse_args(['vertical-cut', '--refine', '--every', '48'])
    assert refine_options.tag(args) == '_refined_N48' and refine_options.title(args) == ', refined once'
    assert refine_options.variables(p.parse_args(['vertical-cut'])) == [('refine', '0')]
    args = p.parse_args(['vertical-cut', '--refine', '--split', '0.4', '0.9'])
    assert refine_options.variables(args)[-2:] == [('separation', '0.4'), ('smoothing', '0.9')]
    assert refine_options.tag(args) == '_refined_split0.4_0.9' and refine_options.summary(args, 1.0)['split'] == [0.4, 0.9]
    args = p.parse_args(['strength-reduction', '--refine', '--buffer', '1'])
    assert ('buffer', '1') in refine_options.variables(args) and refine_options.tag(args) == '_refined_buffer1'
    assert refine_options.summary(args, 0.5)['buffer'] == 1.0 and ', buffer 1' in refine_options.title(args)
    args = p.parse_args(['strength-reduction', '--refine', '--ease', '0.05'])
    assert ('ease', '0.05') in refine_options.variables(args) and refine_options.tag(args) == '_refined_ease0.05'


def test_showcase_compares_with_the_finest_uniform_run(tmp_path):
    """Each configuration against the finest uniform one: cost ratio, and 'within' the difference
    between the two finest uniform runs; the JSON, table and plot are written."""
    from sph_soil.studies import showcase
    work = tmp_path / 'work' / 'slope'
    work.mkdir(parents=True)

    def result(name, spacing, refined, low, high, seconds):
        r = {'spacing_m': spacing, 'finest_spacing_m': spacing / 2 ** refined, 'refined': refined,
             'stepping': 'level' if refined else None, 'stands_up_to': low, 'fails_from': high,
             'critical': 0.5 * (low + high), 'half_width': 0.5 * (high - low), 'wall_seconds_all_runs': seconds}
        (work / f'{name}.json').write_text(json.dumps(r))
    result('u05', 0.5, 0, 1.375, 1.4375, 10.0)
    result('u025', 0.25, 0, 1.375, 1.40625, 100.0)
    result('u0125', 0.125, 0, 1.40625, 1.4375, 1000.0)
    result('l2_level', 0.5, 2, 1.40625, 1.4375, 150.0)
    result('l1_from05_level', 0.5, 1, 1.4375, 1.5, 50.0)
    doc = tmp_path / 'doc'
    cli.main(['showcase', 'slope', '--workdir', str(tmp_path / 'work'), '--doc', str(doc)])
    summary = json.loads((doc / 'showcases.json').read_text())['slope']
    rows = {r['name']: r for r in summary['configurations']}
    assert summary['finest_uniform'] == 'u0125' and summary['tolerance'] == pytest.approx(0.03125)
    assert rows['l2_level']['cost_over_finest_uniform'] == 0.15 and rows['l2_level']['within_tolerance']
    assert not rows['l1_from05_level']['within_tolerance'] and rows['u025']['within_tolerance']
    # the maxlevel-1 run against the uniform run at its finest spacing (0.25 m)
    assert rows['l1_from05_level']['difference_from_uniform_at_its_spacing'] == pytest.approx(0.078125, abs=1e-5)
    assert rows['l1_from05_level']['cost_over_uniform_at_its_spacing'] == 0.5
    assert rows['u025']['cost_over_uniform_at_its_spacing'] is None
    assert 'maxlevel 2 from 0.5 m' in (doc / 'showcases.rst').read_text()
    assert (doc / 'img' / 'showcase_slope.png').stat().st_size > 0
    with pytest.raises(SystemExit, match='unknown footing'):
        cli.main(['showcase', 'footing', '--workdir', str(tmp_path / 'work'), '--doc', str(doc)])


def report_showcase(tmp_path, showcase):
    """`sph_soil showcase SHOWCASE` on tmp_path/work: its doc directory, its summary and rows by name."""
    doc = tmp_path / 'doc'
    cli.main(['showcase', showcase, '--workdir', str(tmp_path / 'work'), '--doc', str(doc)])
    summary = json.loads((doc / 'showcases.json').read_text())[showcase]
    return doc, summary, {r['name']: r for r in summary['configurations']}


def test_showcase_of_one_run_per_configuration(tmp_path):
    """The bearing-capacity showcase reads each configuration's one push (the study's JSON of
    runs): its limit pressure is the answer, without a bracket; a JSON of another shape is an error."""
    work = tmp_path / 'work' / 'bearing-capacity'
    work.mkdir(parents=True)

    def result(name, resolution, refined, limit, seconds):
        run = {'B_over_d': resolution, 'spacing_m': 1.0 / resolution, 'finest_spacing_m': 1.0 / resolution / 2 ** refined,
               'refined': refined, 'stepping': 'level' if refined else None, 'buffer': 1.0 if refined else None,
               'ease': None, 'split': None, 'q_limit_over_cNc': limit, 'wall_seconds': seconds}
        (work / f'{name}.json').write_text(json.dumps({'runs': [run]}))
    result('u10', 10, 0, 1.09, 5.0)
    result('u20', 20, 0, 1.085, 40.0)
    result('u40', 40, 0, 1.065, 500.0)
    result('l2_level', 10, 2, 1.066, 70.0)
    result('l1_level', 10, 1, 1.07, 15.0)
    doc, summary, rows = report_showcase(tmp_path, 'bearing-capacity')
    assert summary['finest_uniform'] == 'u40' and summary['tolerance'] == pytest.approx(0.02)
    assert rows['l2_level']['within_tolerance'] and rows['l2_level']['cost_over_finest_uniform'] == 0.14
    assert rows['l1_level']['difference_from_uniform_at_its_spacing'] == pytest.approx(-0.015)
    assert rows['l2_level']['half_width'] == 0.0 and rows['l2_level']['stands_up_to'] is None
    table = (doc / 'showcases.rst').read_text()
    assert '1.0660' in table and 'maxlevel 2 from B/d = 10' in table
    (work / 'u10.json').write_text(json.dumps({'runs': []}))
    with pytest.raises(ValueError, match='one finished push'):
        cli.main(['showcase', 'bearing-capacity', '--workdir', str(tmp_path / 'work'), '--doc', str(doc)])


def test_showcase_extrapolates_a_uniform_run_finer_than_those_measured(tmp_path):
    """The shallow-landslide showcase: the runout is the answer; a refined run finer than every
    uniform run is costed against the finest uniform run's time grown per halving as between the
    two finest (here 16x), and the figure marks its own target (0.1x)."""
    work = tmp_path / 'work' / 'shallow-landslide'
    work.mkdir(parents=True)

    def result(name, d, refined, runout, seconds):
        (work / f'{name}.json').write_text(json.dumps({
            'spacing_m': d, 'finest_spacing_m': d / 2 ** refined, 'refined': refined,
            'stepping': 'level' if refined else None, 'buffer': 0.0 if refined else None, 'ease': None,
            'split': None, 'runout_m': runout, 'deposit_height_m': 0.3, 'wall_seconds': seconds}))
    result('u20', 0.2, 0, 10.4, 80.0)
    result('u10', 0.1, 0, 11.0, 1280.0)
    result('l2_level', 0.2, 2, 11.1, 2048.0)
    doc, summary, rows = report_showcase(tmp_path, 'shallow-landslide')
    assert summary['finest_uniform'] == 'u10' and summary['tolerance'] == pytest.approx(0.6)
    assert summary['uniform_cost_growth_per_halving'] == pytest.approx(16.0) and summary['target'] == 0.1
    assert rows['l2_level']['cost_over_uniform_at_its_spacing'] is None
    assert rows['l2_level']['cost_over_uniform_at_its_spacing_extrapolated'] == pytest.approx(0.1)
    assert rows['l2_level']['within_tolerance'] and rows['l2_level']['deposit_height_m'] == 0.3
    assert '~0.10 (extrapolated)' in (doc / 'showcases.rst').read_text()


def test_landslide_runs_an_example_and_measures_it(tmp_path, monkeypatch):
    """--run runs a copy of the example (its terrain beside it) with the spacing and the
    refinement variables, measures the run's final dump and writes the configuration's fields,
    which the showcase's answer reads."""
    from sph_soil import runner
    from sph_soil.studies import landslide
    seen = {}

    def fake_run(self, infile, directory, np=1, variables=(), **kw):
        seen.update(infile=infile, np=np, variables=dict(variables))
        assert os.path.exists(os.path.join(directory, 'terrain.stl'))
        rows = ['ITEM: TIMESTEP', '0', 'ITEM: ATOMS id type x y z mass c_soil v_height',
                '1 2 7.0 0.0 0.1 1.85 2 0.1', '2 1 1.0 0.0 1.0 14.8 0 0.5']
        with open(os.path.join(directory, 'dump.shallow_landslide.final'), 'w') as f:
            f.write('\n'.join(rows) + '\n')
        return runner.Result([], directory, 0, 12.5, None)
    monkeypatch.setattr(runner.Lammps, 'run', fake_run)
    monkeypatch.setattr(runner.Lammps, 'require', lambda self: self)
    out = tmp_path / 'l2.json'
    cli.main(['landslide', '--run', '--d', '0.2', '--refine', '2', '--stepping', 'level', '--balance',
              '--workdir', str(tmp_path / 'runs'), '--json', str(out), '--np', '2'])
    summary = json.loads(out.read_text())
    assert seen['np'] == 2 and seen['infile'].endswith('in.shallow_landslide')
    assert seen['variables']['d'] == '0.2' and seen['variables']['refine'] == '2'
    assert seen['variables']['stepping'] == 'level' and seen['variables']['balance'] == '1'
    assert summary['runout_m'] == pytest.approx(7.0) and summary['wall_seconds'] == 12.5
    assert summary['finest_spacing_m'] == pytest.approx(0.05) and summary['refined'] == 2
    answer = landslide.showcase_answer(summary)
    assert answer['critical'] == pytest.approx(7.0) and answer['wall_seconds_all_runs'] == 12.5


def test_showcase_runs_the_missing_configurations(tmp_path, monkeypatch):
    """--run hands each configuration without a JSON to its study, with the showcase's bracket;
    a configuration whose study stops (no bracket) does not stop the others."""
    from sph_soil.studies import showcase, strength_reduction
    seen = []

    def fake_main(args):
        seen.append((args.d, args.refine, args.buffer, args.low, args.high, args.steps))
        if args.buffer == 0:
            raise SystemExit('strength_reduction: [1.25, 1.5] is not a bracket')
    monkeypatch.setattr(strength_reduction, 'main', fake_main)
    work = tmp_path / 'work'
    (work / 'slope').mkdir(parents=True)
    (work / 'slope' / 'u05.json').write_text(json.dumps({     # there: not run again
        'spacing_m': 0.5, 'refined': 0, 'stands_up_to': 1.375, 'fails_from': 1.5, 'critical': 1.4375,
        'half_width': 0.0625, 'wall_seconds_all_runs': 60.0}))
    cli.main(['showcase', 'slope', '--run', '--workdir', str(work), '--doc', str(tmp_path / 'doc')])
    names = [name for name, _, _ in showcase.SHOWCASES['slope']['configurations']]
    assert len(seen) == len(names) - 1 and seen[0][:3] == (0.25, 0, None)
    assert all(s[3:] == (1.25, 1.5, 1) for s in seen) and 0.0 in [s[2] for s in seen]


def test_landslide_deposit_by_volume():
    """The deposit's measures count volume, not particles: four daughters of a quarter of the
    mass in place of their parent change nothing, and a straggler beyond the 99% line does not
    move the runout."""
    import numpy as np
    from sph_soil.studies import landslide

    def dump(x, volume):
        x = np.asarray(x, dtype=float)
        return {'x': x, 'y': np.zeros_like(x), 'z': np.zeros_like(x), 'mass': landslide.RHO0 * np.asarray(volume),
                'c_soil': np.zeros_like(x)}
    spread = list(np.linspace(6.5, 9.0, 98))
    parent = landslide.deposit(dump([7.3] + spread + [20.0], [8e-3] + [1e-3] * 98 + [1e-5]), toe=6.0)
    split = landslide.deposit(dump([7.25, 7.25, 7.35, 7.35] + spread + [20.0], [2e-3] * 4 + [1e-3] * 98 + [1e-5]),
                              toe=6.0)
    assert parent == {**split, 'soil_particles': parent['soil_particles']}
    assert parent['runout_m'] < 9.01 and parent['deposit_volume_fraction_on_floor'] == 1.0
    # the column [7.2, 7.6) holds the parent's volume and the spread particles in it
    inside = sum(1e-3 for v in spread if 7.2 <= v < 7.6)
    assert parent['deposit_height_m'] == pytest.approx(round((8e-3 + inside) / landslide.CELL ** 2, 4))


def test_landslide_measures_the_slide_apart_from_the_standing_soil():
    """With a slide type (shallow_landslide: the patch, type 2), the deposit is the slide's alone,
    and the standing soil's volume beyond the toe is reported apart."""
    import numpy as np
    from sph_soil.studies import landslide
    x = np.array([7.0, 7.1, 8.0, 2.0, 3.0, 6.5])
    kind = np.array([2, 2, 2, 1, 1, 1], dtype=float)
    volume = np.array([1e-3, 1e-3, 1e-3, 5e-3, 5e-3, 2e-3])
    dump = {'x': x, 'y': np.zeros_like(x), 'z': np.zeros_like(x), 'mass': landslide.RHO0 * volume,
            'c_soil': np.zeros_like(x), 'type': kind}
    alone = landslide.deposit({k: v[kind == 2] for k, v in dump.items()}, toe=6.0)
    both = landslide.deposit(dump, toe=6.0, slide_type=2)
    assert both == {**alone, 'standing_volume_on_floor_m3': 0.002}
    assert both['soil_particles'] == 3 and both['deposit_volume_fraction_on_floor'] == 1.0


def test_runner_links_the_files_an_input_reads(tmp_path):
    """An example run in a scratch directory finds its data, STL and include files."""
    from sph_soil import runner
    source = tmp_path / 'example'
    source.mkdir()
    for name in ('in.case', 'log.case', 'terrain.stl', 'terrain.lmp', 'data.case', 'notes.txt'):
        (source / name).write_text(name)
    work = tmp_path / 'work'
    work.mkdir()
    runner.link_inputs(str(source / 'in.case'), str(work))
    runner.link_inputs(str(source / 'in.case'), str(work))    # again: the links are renewed
    assert sorted(os.listdir(work)) == ['data.case', 'terrain.lmp', 'terrain.stl']
    assert (work / 'terrain.stl').read_text() == 'terrain.stl'
