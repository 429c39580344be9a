"""The one way the tools launch LAMMPS: which binary, how many MPI ranks, the input variables, the
environment, and how long it took.

    lmp = Lammps('/path/to/lmp')               # or Lammps(): $SPH_SOIL_LMP, else the build dir's lmp
    result = lmp.run('in.slope', '/tmp/run', np=2, variables=[('F', '1.2')])
    result.seconds, result.returncode, result.log

The command is `mpirun -np N [--oversubscribe] lmp -in INPUT -var NAME VALUE ... -log LOG
-screen none EXTRA...`; np=None runs lmp itself, without mpirun (a serial run, or one under a
wrapper such as valgrind: prefix=['valgrind', ...]); outer=[...] runs the whole launch, mpirun
included, under a command of its own (a shell that sets a process limit for mpirun and its ranks:
outer=['bash', '-c', 'ulimit -v 3000000 && exec "$@"', 'bash']). More ranks than cores get
--oversubscribe (Open MPI refuses them otherwise). The environment is the caller's (LD_LIBRARY_PATH included,
for a binary copied away from its build) plus Open MPI's permission to run as root, which the
machines of this project need, and LAMMPS_POTENTIALS pointing at the checkout's potentials/,
where the examples' material files are (inputs run from scratch directories find them there).
"""
import argparse
import glob
import os
import shutil
import subprocess
import time
from dataclasses import dataclass

from . import paths

BINARY_VARIABLE = 'SPH_SOIL_LMP'


class LammpsNotFound(SystemExit):
    pass


def default_binary(environ=os.environ):
    """$SPH_SOIL_LMP, else lmp in the build directory of the selected release (paths.build_dir())."""
    return environ.get(BINARY_VARIABLE) or os.path.join(paths.build_dir(environ), 'lmp')


def environment(base=os.environ):
    env = dict(base)
    env.update(OMPI_ALLOW_RUN_AS_ROOT='1', OMPI_ALLOW_RUN_AS_ROOT_CONFIRM='1',
               LAMMPS_POTENTIALS=paths.POTENTIALS)
    return env


@dataclass
class Result:
    command: list
    directory: str
    returncode: int
    seconds: float
    log: str        # path of the log file (None with log=None)

    @property
    def ok(self):
        return self.returncode == 0


class Lammps:
    """A LAMMPS binary and the mpirun that launches it."""

    def __init__(self, binary=None, mpirun='mpirun'):
        self.binary = os.path.abspath(binary or default_binary())
        self.mpirun = mpirun

    def require(self):
        """Stop with a hint when the binary does not exist (the tools do not build LAMMPS)."""
        if not os.access(self.binary, os.X_OK):
            raise LammpsNotFound(f'sph_soil: no LAMMPS binary {self.binary}: build it with '
                                 f'bash tools/build.sh, or give one with --lmp or ${BINARY_VARIABLE}')
        return self

    def command(self, infile, np=1, variables=(), log='log.lammps', screen='none', extra=(), prefix=(),
                outer=()):
        cmd = list(outer)
        if np is not None:
            cmd += [self.mpirun, '-np', str(np)]
            if np > (os.cpu_count() or 1):
                cmd.append('--oversubscribe')
        cmd += list(prefix) + [self.binary, '-in', infile]
        for name, value in variables:
            cmd += ['-var', name, str(value)]
        if log is not None:
            cmd += ['-log', log]
        if screen is not None:
            cmd += ['-screen', screen]
        return cmd + list(extra)

    def run(self, infile, directory, np=1, variables=(), log='log.lammps', screen='none', extra=(),
            prefix=(), outer=(), check=False, stdout=None, stderr=None, timeout=None, copy=False):
        """Run in `directory` (made if missing), with the files the input reads beside it linked
        in (link_inputs); check=True raises CalledProcessError on failure. copy=True runs a copy
        of the input made in `directory`: LAMMPS reads its input as it goes, and an edit of the
        example during a long study must not change a run under way."""
        os.makedirs(directory, exist_ok=True)
        link_inputs(infile, directory)
        if copy:
            target = os.path.join(directory, os.path.basename(infile))
            if os.path.abspath(target) != os.path.abspath(infile):
                shutil.copy(infile, target)
            infile = target
        cmd = self.command(infile, np, variables, log, screen, extra, prefix, outer)
        start = time.time()
        done = subprocess.run(cmd, cwd=directory, env=environment(), stdout=stdout, stderr=stderr,
                              timeout=timeout)
        seconds = time.time() - start
        if check and done.returncode != 0:
            raise subprocess.CalledProcessError(done.returncode, cmd)
        log_path = None if log in (None, 'none') else os.path.join(directory, log)
        return Result(cmd, directory, done.returncode, seconds, log_path)

    def help_text(self):
        """What `lmp -h` prints."""
        return subprocess.run([self.binary, '-h'], capture_output=True, text=True,
                              env=environment()).stdout


# the files an input reads from its own directory (LAMMPS reads them from the working directory):
# data files, surfaces for create_atoms mesh, files it includes
INPUT_FILES = ('data.*', '*.stl', '*.lmp')


def link_inputs(infile, directory):
    """Symbolic links in `directory` to the files beside `infile` that it may read (INPUT_FILES),
    so that an example runs in a scratch directory as in its own."""
    source = os.path.dirname(os.path.abspath(infile))
    if os.path.abspath(directory) == source:
        return
    for pattern in INPUT_FILES:
        for path in glob.glob(os.path.join(source, pattern)):
            target = os.path.join(directory, os.path.basename(path))
            if os.path.lexists(target):
                os.remove(target)
            os.symlink(path, target)


def add_lmp_argument(parser):
    parser.add_argument('--lmp', default=None,
                        help=f'LAMMPS binary (default: ${BINARY_VARIABLE}, else lmp of the build directory '
                             'of SPH_SOIL_LAMMPS: build/ or build-<release>/; BUILD_DIR overrides)')


def variable_setting(text):
    """An argparse type: 'NAME=VALUE' -> (NAME, VALUE), an input variable set with -var."""
    name, equals, value = text.partition('=')
    if not name or not equals:
        raise argparse.ArgumentTypeError(f"'{text}': NAME=VALUE expected")
    return name, value


def add_variable_argument(parser, help):
    """--var NAME=VALUE, repeatable: (name, value) pairs in args.var ([] without any)."""
    parser.add_argument('--var', action='append', default=[], type=variable_setting, metavar='NAME=VALUE',
                        help=help)


def add_arguments(parser, np=2):
    """--lmp, --np and --mpirun of a command that runs LAMMPS."""
    add_lmp_argument(parser)
    parser.add_argument('--np', type=int, default=np, help='MPI ranks (default: %(default)s)')
    parser.add_argument('--mpirun', default='mpirun', help='MPI launcher (default: %(default)s)')


def from_arguments(args, build=False):
    """The Lammps of --lmp and --mpirun; build=True first builds the default binary with
    tools/build.sh when it is missing (as the studies that write the docs always did)."""
    if build and not args.lmp:
        build_if_missing(default_binary())
    return Lammps(args.lmp, args.mpirun).require()


def build_if_missing(path):
    """Run tools/build.sh (the build of the release selected by SPH_SOIL_LAMMPS) unless `path` exists."""
    if not os.path.exists(path):
        subprocess.run(['bash', os.path.join(paths.ROOT, 'tools', 'build.sh')], check=True)
