"""The convergence study's logic (studies/convergence.py) without LAMMPS: its judgement of a
sequence of answers, the dissipation's share, the reuse of saved runs, the checks' declarations."""
import json
import os
import types

import pytest

from sph_soil import inputs, verification
from sph_soil.studies import convergence
from sph_soil.studies import convergence_checks as checks


def fake_runs(values, spacings):
    return [{'spacing': d, 'answers': {'settlement': v}} for d, v in zip(spacings, values)]


ELASTIC = checks.CHECKS['elastic']


def test_second_order_sequence_converges_to_its_extrapolate():
    spacings = (0.4, 0.2, 0.1, 0.05)
    values = [1.0 + 0.3 * d ** 2 for d in spacings]     # error C d^2
    summary = convergence.judge(ELASTIC, spacings, fake_runs(values, spacings), [])
    entry = summary['settlement']
    assert entry['observed_order'] == pytest.approx(2.0)
    assert entry['extrapolated'] == pytest.approx(1.0)
    assert entry['converges'] is True
    assert len(entry['triples']) == 2


def test_a_sequence_that_stalls_or_is_off_does_not_converge():
    spacings = (0.4, 0.2, 0.1)
    # order 1/2: too slow
    slow = [1.0 + 0.1 * d ** 0.5 for d in spacings]
    assert convergence.judge(ELASTIC, spacings, fake_runs(slow, spacings), [])['settlement']['converges'] is False
    # converging fast, but to 1.05: the extrapolate is 5% off
    off = [1.05 + 0.3 * d ** 2 for d in spacings]
    entry = convergence.judge(ELASTIC, spacings, fake_runs(off, spacings), [])['settlement']
    assert entry['extrapolated'] == pytest.approx(1.05) and entry['converges'] is False
    # oscillating: no order, no extrapolate
    wobble = [1.02, 0.99, 1.01]
    entry = convergence.judge(ELASTIC, spacings, fake_runs(wobble, spacings), [])['settlement']
    assert entry['observed_order'] is None and entry['converges'] is False
    # settled: the two finest agree to the measure's noise, at the reference (or not)
    for values, right in (([1.0188, 1.0002, 1.0004], True), ([1.05, 1.0302, 1.0304], False)):
        entry = convergence.judge(ELASTIC, spacings, fake_runs(values, spacings), [])['settlement']
        assert entry['observed_order'] is None and entry['settled'] is True and entry['converges'] is right


def test_the_dissipation_share_is_the_finest_answers_relative_change():
    spacings = (0.2, 0.1, 0.05)
    runs = fake_runs([1.1, 1.05, 1.02], spacings)
    half = {'dissipation_factor': 0.5, 'answers': {'settlement': 1.0098}}
    double = {'dissipation_factor': 2.0, 'answers': {'settlement': 1.0506}}
    entry = convergence.judge(ELASTIC, spacings, runs, [half, double])['settlement']
    assert entry['dissipation']['0.5']['change'] == pytest.approx(-0.01)
    assert entry['dissipation']['2']['change'] == pytest.approx(0.03)
    # an answer a run did not give (it stopped) is None, not a crash
    assert entry['dissipation'] and convergence.judge(ELASTIC, spacings, runs, [
        {'dissipation_factor': 2.0, 'answers': {}}])['settlement']['dissipation']['2'] is None


class FakeLammps:
    """Counts the runs and leaves the log line the elastic check reads."""
    def __init__(self):
        self.runs = []

    def run(self, infile, directory, np=1, variables=(), copy=False):
        os.makedirs(directory, exist_ok=True)
        self.runs.append(dict(variables))
        d = float(dict(variables)['d'])
        with open(os.path.join(directory, 'log.lammps'), 'w') as f:
            f.write('print "elastic column: d = ${d} m: settlement of the top row $(f_last[1]:%.8e) m = '
                    '$(f_last[1]/v_s_exact:%.6f) of exact, force on the wall $(f_last[2]:%.8e) N/m = '
                    '$(f_last[2]/v_F_exact:%.6f) of exact"\n'
                    'elastic column: d = 0.1 m, exact settlement of the top row 1e-3 m, exact wall force 5e3 N/m\n'
                    f'elastic column: d = {d} m: settlement of the top row 1e-3 m = {1 + d:.6f} of exact, '
                    f'force on the wall 5e3 N/m = {1 - d:.6f} of exact\n')
        with open(os.path.join(directory, 'column.txt'), 'w') as f:
            f.write('# time settlement force\n0 0 0\n0.1 1e-3 5e3\n')
        return types.SimpleNamespace(returncode=0, seconds=0.1)


def arguments(tmp_path, **kw):
    base = dict(spacings=None, short=True, no_dissipation=False, dissipation=[0.5, 2.0], workdir=str(tmp_path),
                rerun=False, remeasure=False, members=None, np=1, json=None, plot=None, var=None)
    base.update(kw)
    return types.SimpleNamespace(**base)


def test_runs_are_saved_and_not_run_again(tmp_path):
    lmp = FakeLammps()
    result = convergence.convergence(lmp, ELASTIC, arguments(tmp_path))
    assert [r['d'] for r in lmp.runs] == [f'{d:.10g}' for d in ELASTIC.short_spacings]
    own = f'{ELASTIC.dissipation:g}'                 # the check's own dissipation
    assert all(r['viscosity'] == own for r in lmp.runs)
    # the answers as the log gave them, the order of a linear error 1
    assert result['answers']['settlement']['values'] == pytest.approx([1 + d for d in ELASTIC.short_spacings])
    assert result['answers']['settlement']['observed_order'] == pytest.approx(1.0, abs=1e-4)
    convergence.convergence(lmp, ELASTIC, arguments(tmp_path))
    assert len(lmp.runs) == 3                       # saved: not run again
    convergence.convergence(lmp, ELASTIC, arguments(tmp_path, rerun=True))
    assert len(lmp.runs) == 6
    # the dissipation's runs at the finest spacing, with alpha = beta scaled (d = 0.1 is saved)
    convergence.convergence(lmp, ELASTIC, arguments(tmp_path, short=False, spacings=[0.4, 0.2, 0.1]))
    assert [(r['d'], r['viscosity']) for r in lmp.runs[6:]] == [
        ('0.4', own), ('0.2', own), ('0.1', f'{0.5 * ELASTIC.dissipation:g}'), ('0.1', f'{2 * ELASTIC.dissipation:g}')]
    with open(os.path.join(tmp_path, 'elastic', 'd0.1_dissipation2', 'answers.json')) as f:
        assert json.load(f)['answers'] == {'settlement': 1.1, 'wall_force': 0.9}
    # a variant of the scheme: its own runs, the variable in each
    convergence.convergence(lmp, ELASTIC, arguments(tmp_path, var=[('correction', 'yes')]))
    assert len(lmp.runs) == 13 and all(r['correction'] == 'yes' for r in lmp.runs[10:])
    assert os.path.exists(os.path.join(tmp_path, 'elastic', 'd0.025_correctionyes', 'answers.json'))


def test_remeasure_reads_the_saved_runs_again_without_running_them(tmp_path):
    lmp = FakeLammps()
    convergence.convergence(lmp, ELASTIC, arguments(tmp_path))
    log = os.path.join(tmp_path, 'elastic', 'd0.1', 'log.lammps')
    with open(log) as f:
        text = f.read()
    with open(log, 'w') as f:
        f.write(text.replace('= 1.100000 of exact', '= 1.200000 of exact'))
    assert convergence.convergence(lmp, ELASTIC, arguments(tmp_path))['answers']['settlement']['values'][0] == 1.1
    result = convergence.convergence(lmp, ELASTIC, arguments(tmp_path, remeasure=True))
    assert result['answers']['settlement']['values'][0] == 1.2 and len(lmp.runs) == 3


def test_a_run_that_stops_gives_no_answer_and_names_why(tmp_path):
    class Stopping(FakeLammps):
        def run(self, infile, directory, np=1, variables=(), copy=False):
            os.makedirs(directory, exist_ok=True)
            with open(os.path.join(directory, 'log.lammps'), 'w') as f:
                f.write('ERROR: sph/soil: particle 12 unstable at step 40\n')
            return types.SimpleNamespace(returncode=1, seconds=0.1)
    result = convergence.convergence(Stopping(), ELASTIC, arguments(tmp_path))
    assert result['answers']['settlement']['values'] == [None, None, None]
    assert 'particle 12 unstable' in result['runs'][0]['error']


def test_every_check_is_declared_consistently():
    for check in checks.CHECKS.values():
        assert os.path.exists(check.infile), check.name
        variables = inputs.input_variables(check.infile)
        # the input has the variables the check sets, with the dissipation the check says
        assert check.spacing_variable in variables and check.dissipation_variable in variables, check.name
        assert float(variables[check.dissipation_variable]) == check.dissipation, check.name
        for name, _ in check.variables:
            assert name in variables, (check.name, name)
        assert verification.constant_ratio(check.spacings) and verification.constant_ratio(check.short_spacings)
        assert len(check.spacings) >= 3 and check.answers


def test_uneven_spacings_are_refused():
    with pytest.raises(ValueError):
        verification.constant_ratio((0.1, 0.05, 0.03))
    with pytest.raises(SystemExit, match='no check'):
        checks.check('nonsense')


def test_a_check_that_solves_takes_its_answer_from_several_runs(tmp_path):
    calls = []

    def solve(lmp, directory, variables, np):
        d = float(dict(variables)['d'])
        calls.append(d)
        if d < 0.03:
            raise RuntimeError('vertical cut: [3.0, 4.5] is not a bracket')
        return {'critical_ratio': 1.0 + d, 'half_width': 0.002}

    cut = checks.Check('cut', 'vertical_cut', 'a cut', 'a reference', spacings=(0.1, 0.05, 0.025),
                       short_spacings=(0.1, 0.05, 0.025), answers={'critical_ratio': 'ratio'}, measure=None,
                       solve=solve)
    result = convergence.convergence(None, cut, arguments(tmp_path))
    assert calls == [0.1, 0.05, 0.025]
    assert result['answers']['critical_ratio']['values'][:2] == [1.1, 1.05]
    assert result['runs'][0]['diagnostics'] == {'half_width': 0.002}
    assert 'not a bracket' in result['runs'][2]['error'] and result['runs'][2]['returncode'] == 1
    # saved, a failure too (it is a result): not solved again, not even with --remeasure
    convergence.convergence(None, cut, arguments(tmp_path, remeasure=True))
    assert calls == [0.1, 0.05, 0.025]


def test_an_ensemble_answers_its_members_mean_with_their_spread(tmp_path):
    import dataclasses

    class Members(FakeLammps):
        def run(self, infile, directory, np=1, variables=(), copy=False):
            done = super().run(infile, directory, np, variables, copy)
            seed = int(dict(variables)['seed'])
            d = float(dict(variables)['d'])
            with open(os.path.join(directory, 'log.lammps'), 'a') as f:     # the last line counts
                f.write(f'elastic column: d = {d} m: settlement of the top row 1e-3 m = {1 + d + 0.01 * seed:.6f} '
                        f'of exact, force on the wall 5e3 N/m = 1.0 of exact\n')
            return done

    check = dataclasses.replace(ELASTIC, ensemble=3, member_variables=(('perturb', '0.01'),))
    lmp = Members()
    result = convergence.convergence(lmp, check, arguments(tmp_path))
    assert len(lmp.runs) == 9 and {r['perturb'] for r in lmp.runs} == {'0.01'}
    assert sorted({r['seed'] for r in lmp.runs}) == ['1', '2', '3']
    first = result['runs'][0]
    assert first['answers']['settlement'] == pytest.approx(1.1 + 0.02)         # the mean of seeds 1-3
    assert first['diagnostics']['settlement_spread'] == pytest.approx(0.01)     # their sample deviation
    assert first['diagnostics']['settlement_members'] == pytest.approx([1.11, 1.12, 1.13])
    # --members overrides the check's size
    convergence.convergence(lmp, check, arguments(tmp_path, members=4))
    assert len(lmp.runs) == 12
