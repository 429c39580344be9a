"""--lmp: a LAMMPS binary for the few tests that run it briefly (they are skipped without one)."""
import pytest


def pytest_addoption(parser):
    parser.addoption('--lmp', default=None, help='LAMMPS binary for the tests that run it')


@pytest.fixture
def lmp(request):
    path = request.config.getoption('--lmp')
    if not path:
        pytest.skip('no --lmp given')
    from sph_soil.runner import Lammps
    return Lammps(path).require()
