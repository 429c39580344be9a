"""sph_soil.runner: the command, the environment and the binary it chooses, a run of a stand-in
binary (no MPI), and with --lmp a short run of examples/atom_style under mpirun."""
import os
import re
import stat

import pytest

from sph_soil import paths, runner
from sph_soil.logs import Log
from sph_soil.studies import atom_style


def test_command_under_mpirun():
    lmp = runner.Lammps('/opt/lmp', mpirun='mpiexec')
    assert lmp.command('in.x', np=2, variables=[('d', 0.001), ('mode', 'fine')]) == [
        'mpiexec', '-np', '2', '/opt/lmp', '-in', 'in.x', '-var', 'd', '0.001', '-var', 'mode', 'fine',
        '-log', 'log.lammps', '-screen', 'none']


def test_more_ranks_than_cores_oversubscribe():
    cmd = runner.Lammps('/opt/lmp').command('in.x', np=(os.cpu_count() or 1) + 1)
    assert cmd[3] == '--oversubscribe'


def test_serial_command_with_a_wrapper_and_the_screen():
    cmd = runner.Lammps('/opt/lmp').command('in.x', np=None, log='none', screen=None,
                                            extra=['-var', 'steps', '0'], prefix=['valgrind', '-q'])
    assert cmd == ['valgrind', '-q', '/opt/lmp', '-in', 'in.x', '-log', 'none', '-var', 'steps', '0']


def test_whole_launch_under_an_outer_command():
    outer = ['bash', '-c', 'ulimit -v 3000000 && exec "$@"', 'bash']
    cmd = runner.Lammps('/opt/lmp').command('in.x', np=1, outer=outer)
    assert cmd == outer + ['mpirun', '-np', '1', '/opt/lmp', '-in', 'in.x', '-log', 'log.lammps',
                           '-screen', 'none']


def test_environment(monkeypatch):
    monkeypatch.setenv('LD_LIBRARY_PATH', '/tmp/private_lmp')
    env = runner.environment()
    assert env['OMPI_ALLOW_RUN_AS_ROOT'] == '1' and env['OMPI_ALLOW_RUN_AS_ROOT_CONFIRM'] == '1'
    assert env['LAMMPS_POTENTIALS'] == os.path.join(paths.ROOT, 'potentials')
    assert env['LD_LIBRARY_PATH'] == '/tmp/private_lmp'


@pytest.mark.parametrize('environ, binary', [
    ({}, 'build/lmp'),
    ({'SPH_SOIL_LAMMPS': 'newest'}, 'build/lmp'),
    ({'SPH_SOIL_LAMMPS': '29Sep2021'}, 'build-29Sep2021/lmp'),
    ({'SPH_SOIL_LAMMPS': '29Sep2021', 'BUILD_DIR': '/b'}, '/b/lmp'),
    ({'SPH_SOIL_LMP': '/x/lmp', 'BUILD_DIR': '/b'}, '/x/lmp'),
])
def test_binary_of_the_selected_release(environ, binary):
    assert runner.default_binary(environ) == os.path.join(paths.ROOT, binary)


def test_a_missing_binary_stops_with_a_hint(tmp_path):
    with pytest.raises(SystemExit, match='tools/build.sh'):
        runner.Lammps(str(tmp_path / 'lmp')).require()


def test_run_in_its_directory_with_its_environment(tmp_path):
    # a stand-in for lmp that records its arguments and environment
    fake = tmp_path / 'lmp'
    fake.write_text('#!/bin/sh\necho "$@" > args\necho "$LAMMPS_POTENTIALS" > env\nexit 3\n')
    fake.chmod(fake.stat().st_mode | stat.S_IXUSR)
    result = runner.Lammps(str(fake)).run('in.x', str(tmp_path / 'work'), np=None, variables=[('F', '1.5')])
    assert result.returncode == 3 and not result.ok and result.seconds >= 0.0
    assert result.log == str(tmp_path / 'work' / 'log.lammps')
    assert (tmp_path / 'work' / 'args').read_text().split() == [
        '-in', 'in.x', '-var', 'F', '1.5', '-log', 'log.lammps', '-screen', 'none']
    assert (tmp_path / 'work' / 'env').read_text().strip() == paths.POTENTIALS


@pytest.mark.parametrize('np', [1, 2])
def test_atom_style_example(lmp, tmp_path, np):
    result = lmp.run(paths.example_input('atom_style'), str(tmp_path), np=np, check=True)
    printed = Log(result.log).search(r'^deepest soil particle: sigma_yy = (\S+) Pa \(rho0 g \(H - d/2\) = (\S+) Pa', re.M)
    summary = atom_style.atom_style(str(tmp_path), str(tmp_path / 'atom_style.json'), str(tmp_path / 'atom_style.png'))
    assert summary['deepest_sigma_yy_Pa'] == pytest.approx(float(printed.group(1)), abs=0.01)
    assert summary['deepest_sigma_yy_expected_Pa'] == pytest.approx(float(printed.group(2)), abs=0.01)
    # the dump's 6 significant digits
    assert summary['max_error_sigma_yy_Pa'] < 1e-5 * abs(summary['deepest_sigma_yy_Pa'])
    assert (tmp_path / 'atom_style.png').stat().st_size > 0


def test_variable_settings_parse_once_for_every_command():
    import argparse
    from sph_soil.runner import variable_setting
    assert variable_setting('correction=yes') == ('correction', 'yes')
    assert variable_setting('expr=a=b') == ('expr', 'a=b')          # the first '=' splits
    assert variable_setting('empty=') == ('empty', '')
    for bad in ('correction', '=yes'):
        with pytest.raises(argparse.ArgumentTypeError, match='NAME=VALUE expected'):
            variable_setting(bad)
