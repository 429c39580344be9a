"""Where things are: the checkout, its examples and docs, and the build directory of the LAMMPS
release selected by SPH_SOIL_LAMMPS (the rule of tools/build_dir.sh, which the build scripts use)."""
import os

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
EXAMPLES = os.path.join(ROOT, 'examples')
DOC = os.path.join(ROOT, 'doc')
DOC_IMG = os.path.join(DOC, 'img')
POTENTIALS = os.path.join(ROOT, 'potentials')


def build_dir(environ=os.environ):
    """BUILD_DIR if set; else build/ for SPH_SOIL_LAMMPS unset or 'newest', build-<release>/ otherwise."""
    if environ.get('BUILD_DIR'):
        return environ['BUILD_DIR']
    release = environ.get('SPH_SOIL_LAMMPS') or 'newest'
    return os.path.join(ROOT, 'build' if release == 'newest' else f'build-{release}')


def example_dir(name):
    return os.path.join(EXAMPLES, name)


def example_input(name):
    """examples/NAME/in.NAME"""
    return os.path.join(EXAMPLES, name, f'in.{name}')
