"""The machinery that tools/vertical_cut.py and tools/strength_reduction.py share: one LAMMPS run
in a directory of its own, the late movement that tells a failing run (still moving at the end)
from one that comes to rest, and the bisection of a bracket that stands at its low end and fails
at its high end. Not a command: import it."""
import os
import subprocess
import time


def run_lammps(lmp, np, infile, directory, variables):
    """mpirun -np NP LMP -in INFILE -var NAME VALUE ... in DIRECTORY (log.lammps there, nothing
    on the screen); returns the wall seconds. Sets Open MPI's permission to run as root."""
    os.makedirs(directory, exist_ok=True)
    env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT='1', OMPI_ALLOW_RUN_AS_ROOT_CONFIRM='1')
    command = ['mpirun', '-np', str(np), lmp, '-in', infile]
    for name, value in variables:
        command += ['-var', name, value]
    start = time.time()
    subprocess.run(command + ['-log', 'log.lammps', '-screen', 'none'], cwd=directory, env=env, check=True)
    return time.time() - start


def late_movement(time_values, moved, late=0.3):
    """How far the monitored displacement grows over the last `late` share of the run."""
    window = time_values >= (1.0 - late) * time_values[-1]
    return float(moved[window][-1] - moved[window][0])


def bisect(run, low, high, steps, tool):
    """run(value) -> a dict with 'fails'; runs both ends (the bracket must stand at `low` and fail
    at `high`), then `steps` bisections. Returns every run (in the order run) and the final
    bracket (low, high)."""
    runs = [run(low), run(high)]
    if runs[0]['fails'] or not runs[1]['fails']:
        raise SystemExit(f'{tool}: [{low}, {high}] is not a bracket (it must stand at {low} and fail '
                         f'at {high}): fails {runs[0]["fails"]} and {runs[1]["fails"]}')
    for _ in range(steps):
        middle = 0.5 * (low + high)
        r = run(middle)
        runs.append(r)
        if r['fails']:
            high = middle
        else:
            low = middle
    return runs, low, high
