"""Run one example the way its input runs by default and leave its plot (PNG) and its numbers
(JSON) beside it, in examples/NAME/ (what tools/run_example.sh does after the build).

    python3 -m sph_soil run-example aluminium_bars [--np N] [-- extra lmp arguments, e.g. -var d 0.001]
    python3 -m sph_soil run-example slope --no-run      # only the plot and numbers of the run there

The run: mpirun -np N lmp -in in.NAME -log log.NAME.run [extra arguments] in examples/NAME, on
all cores by default, its screen output on the terminal. Then the example's study measures it
(sph_soil.studies.EXAMPLE_REPORTS) with the input's variables: those the input declares
(variable NAME index|equal|string VALUE), overridden by the -var arguments given.
"""
import os
import time

from . import paths, runner
from .inputs import input_variables
from .studies import EXAMPLE_REPORTS

COMMAND = 'run-example'


def run_example(name, lmp, np, extra=(), run=True):
    directory = paths.example_dir(name)
    infile = os.path.join(directory, f'in.{name}')
    if not os.path.exists(infile):
        raise SystemExit(f'run_example: no {infile}')
    start = time.time()
    seconds = None
    if run:
        done = lmp.run(f'in.{name}', directory, np=np, log=f'log.{name}.run', screen=None, extra=extra)
        if not done.ok:
            raise SystemExit(f'run_example: {" ".join(done.command)} failed with exit code {done.returncode}')
        seconds = float(round(done.seconds))
        print(f'run_example: {name} done in {seconds:.0f} s on {np} ranks', flush=True)
    EXAMPLE_REPORTS[name].report_example(directory, os.path.join(directory, f'log.{name}.run'),
                                         input_variables(infile, extra), seconds)
    print(f'run_example: output in {directory}:')
    for entry in sorted(os.listdir(directory)):
        if os.path.getmtime(os.path.join(directory, entry)) >= start - (0 if run else 1e9):
            print(f'  {entry}')


def add_arguments(p):
    runner.add_arguments(p, np=os.cpu_count() or 1)
    p.add_argument('example', choices=sorted(EXAMPLE_REPORTS), metavar='EXAMPLE',
                   help='one of: ' + ', '.join(sorted(EXAMPLE_REPORTS)))
    p.add_argument('--no-run', action='store_true', help='run nothing: measure and plot the run there')
    p.add_argument('extra', nargs='*', help='extra lmp arguments (after --)')


def main(a):
    lmp = None if a.no_run else runner.from_arguments(a)
    run_example(a.example, lmp, a.np, a.extra, not a.no_run)
