"""The readers of what LAMMPS writes: logs (sph_soil.logs), dumps and fix ave/time files
(sph_soil.dumps), on small fixture files and the examples' reference logs."""
import glob
import os
import time

import numpy as np
import pytest

from sph_soil import dumps, logs, paths

FIXTURES = os.path.join(os.path.dirname(os.path.abspath(__file__)), 'fixtures')
TWO_RUNS = os.path.join(FIXTURES, 'log.two_runs')


def test_thermo_tables_of_a_run_that_stopped():
    tables = logs.Log(TWO_RUNS).thermo_tables()
    assert len(tables) == 2
    header, rows = tables[0]
    assert header == ['Step', 'Time', 'Atoms', 'c_ke']
    # the warning inside the table is skipped, not taken as its end
    assert [r[0] for r in rows] == [0, 50, 100]
    # the second run stopped without 'Loop time': its rows still count
    assert tables[1][1] == [[100, 0.002, 120, 2.5e-05], [200, 0.004, 150, 3.0e-05]]
    assert logs.Log(TWO_RUNS).last_thermo_table() == tables[1]


def test_log_facts():
    log = logs.Log(TWO_RUNS)
    assert log.release() == '4Jul26'
    assert log.loops() == [logs.Loop(1.5, 2, 100, 120)]
    assert log.error().startswith('ERROR: Particle 7 became unstable at step 201')
    assert log.total_wall_seconds() == 65
    assert log.timing_breakdown() == {'pair': 0.6, 'neigh': 0.1, 'comm': 0.2}
    assert log.search(r'variable d index (\S+)').group(1) == '0.002'


def test_a_log_without_a_table(tmp_path):
    path = tmp_path / 'log.empty'
    path.write_text('no version line\n')
    with pytest.raises(ValueError):
        logs.Log(str(path)).last_thermo_table()
    with pytest.raises(ValueError):
        logs.Log(str(path)).release()


def test_reference_logs_have_a_release_and_a_table():
    references = glob.glob(os.path.join(paths.EXAMPLES, '*', 'log.*.short.*'))
    assert references
    for path in references:
        log = logs.Log(path)
        assert log.release() == os.path.basename(path).split('.')[1]
        header, rows = log.last_thermo_table()
        assert header[0] == 'Step' and rows and all(len(r) == len(header) for r in rows)


def test_release_order():
    assert sorted(['4Jul26', '29Sep21', '4Feb25'], key=logs.release_key) == ['29Sep21', '4Feb25', '4Jul26']


def test_run_logs_newest_first_without_references(tmp_path):
    for k, name in enumerate(['log.lammps', 'log.29Sep21.x.short.1', 'log.x.run']):
        (tmp_path / name).write_text(f'Total wall time: 0:00:0{k}\n')
        os.utime(tmp_path / name, (time.time() + k, time.time() + k))
    assert [os.path.basename(p) for p in logs.run_logs(str(tmp_path))] == ['log.x.run', 'log.lammps']
    assert logs.wall_seconds(str(tmp_path)) == 2


def test_dump_last_snapshot():
    s = dumps.read_dump(os.path.join(FIXTURES, 'dump.two_snapshots'))
    assert sorted(s) == ['c_soil[1]', 'id', 'type', 'x', 'y']
    np.testing.assert_array_equal(s['id'], [1, 2, 3])
    np.testing.assert_allclose(s['x'], [0.15, 0.35, 0.5])


def test_ave_time_rows(tmp_path):
    data = dumps.read_ave_time(os.path.join(FIXTURES, 'ave_time.dat'))
    assert data.shape == (4, 4)
    np.testing.assert_allclose(data[:, 2], [0, 0.001, 0.0015, 0.0016])
    # a run that stopped after one row still gives rows and columns
    (tmp_path / 'one.dat').write_text('# TimeStep v_time\n0 0\n')
    assert dumps.read_ave_time(str(tmp_path / 'one.dat')).shape == (1, 2)
