#!/usr/bin/python3
"""Errors reach the screen and the log of a plain batch run of lmp, on 1 and 2 MPI ranks.

    PYTHONPATH=tools unittest/test_batch_errors.py --lmp build/lmp --mpirun mpirun [--workdir DIR]

Each case runs lmp as a separate process, the way a user does (`lmp -in in.x > out`, or under
mpirun; through the tools' runner, sph_soil.runner), provokes an error of the package and asserts
that the message is in what the process wrote to its standard output (the screen) and in the log
file:
- a data file with a negative mass: an error of the rank that reads the atom (error->one),
  the path whose message LAMMPS 29Sep2021 lost with exceptions on;
- a run that goes unstable: a collective error (every rank stops with the same message);
- a runaway refinement (every particle split at every step down to level 30, as threshold 0 does
  in a deforming soil) under a process limit, `ulimit -v 3000000` over
  mpirun and its ranks, as a batch system sets one: the memory guard of fix sph/soil/refine
  stops it with its message, naming RLIMIT_AS, before an allocation fails (no bad_alloc, no
  "Failed to allocate", no signal). It takes 7 splits, a few seconds. Not under AddressSanitizer
  (tools/sanitize.sh), which reserves terabytes of address space for its shadow memory: no
  process can start under such a limit there.
A race can hide the second case's loss (LAMMPS 29Sep2021 does not flush the log at an error,
and mpirun may kill rank 0 when another rank exits first), so the test also reads the package's
sources: every error is raised through SPHSoilCompat::error_all/error_one, which flush.
LAMMPS writes its log file on rank 0 only, so an error->one raised on another rank reaches the
screen (mpirun forwards every rank's output) but not the log; that case checks the screen.
"""
import argparse
import os
import re
import shutil
import subprocess
import sys

from sph_soil.runner import Lammps

DATA = """bad data file

2 atoms
1 atom types

0 1 xlo xhi
0 1 ylo yhi
0 1 zlo zhi

Atoms # sph/soil

1 1 {mass1} 0.1 1000 0 0.25 0.5 0.5
2 1 {mass2} 0.1 1000 0 0.75 0.5 0.5
"""

READ_DATA = """units si
atom_style sph/soil
processors * 1 1
read_data bad.data
"""

UNSTABLE = """units si
dimension 2
boundary p p p
atom_style sph/soil
atom_modify map array
processors * 1 1
lattice sq 0.01
region box block 0 20 0 16 -0.5 0.5
create_box 1 box
create_atoms 1 box
sph_soil/set all mass 0.265 h 0.012 density 2650
group one id 300
velocity one set 1e308 1e308 0 units box
pair_style sph/soil
pair_coeff 1 1 soil 2650 0.7e6 0.3 19.8 0 0
fix integrate all sph/soil
timestep 2.0e-5
neighbor 0.002 bin
run 10
"""

RUNAWAY = """units si
dimension 2
boundary p p p
atom_style sph/soil
atom_modify map array
lattice sq 0.01 origin 0.5 0.5 0.0
region box block 0 10 0 10 -0.5 0.5
create_box 1 box
create_atoms 1 box
sph_soil/set all mass 0.265 h 0.012 density 2650
pair_style sph/soil
pair_coeff 1 1 soil 2650 0.7e6 0.3 19.8 0 0
fix integrate all sph/soil cfl 0.1
fix refine all sph/soil/refine 1 criterion all maxlevel 30
run 20
"""
# the limit, in kB: Open MPI's mpirun and ranks start in about 0.2 GB of address space
ADDRESS_SPACE_KB = 3000000
# what an allocation failure or a crash writes instead of the guard's message
CRASHES = ('bad_alloc', 'Failed to allocate', 'Failed to reallocate', 'signal', 'Signal')


def run_case(args, name, np, inputs, files, message, in_log=True, address_space_kb=None):
    work = os.path.join(args.workdir, name)
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    for filename, text in files.items():
        with open(os.path.join(work, filename), 'w') as f:
            f.write(text)
    with open(os.path.join(work, 'in.case'), 'w') as f:
        f.write(inputs)
    # one rank: lmp alone, as a user runs it; more: under mpirun. LAMMPS's own log.lammps.
    # A process limit: a shell sets it and runs the whole launch (mpirun and its ranks inherit it).
    outer = ['bash', '-c', f'ulimit -v {address_space_kb} && exec "$@"', 'bash'] if address_space_kb else []
    with open(os.path.join(work, 'screen'), 'w') as screen:
        run = Lammps(args.lmp, args.mpirun).run('in.case', work, np=np if np > 1 else None, log=None,
                                               screen=None, stdout=screen, stderr=subprocess.STDOUT,
                                               timeout=120, outer=outer)
    screen_text = open(os.path.join(work, 'screen')).read()
    log_path = os.path.join(work, 'log.lammps')
    log_text = open(log_path).read() if os.path.exists(log_path) else ''
    problems = []
    if run.returncode == 0:
        problems.append('lmp exited with status 0')
    if run.returncode < 0:
        problems.append(f'lmp was killed by signal {-run.returncode}')
    # (a message given in parts: each must be there, the numbers between them may vary)
    parts = [message] if isinstance(message, str) else message
    if not all(part in screen_text for part in parts):
        problems.append('message not on the screen')
    if in_log and not all(part in log_text for part in parts):
        problems.append('message not in log.lammps')
    problems += [f'the screen shows "{crash}"' for crash in CRASHES if crash in screen_text]
    status = 'ok' if not problems else 'FAILED: ' + '; '.join(problems)
    print(f'{name} ({np} rank{"s" if np > 1 else ""}): {status}')
    if problems:
        print('--- screen (last 15 lines):\n' + ''.join(screen_text.splitlines(True)[-15:]))
        print('--- log.lammps (last 10 lines):\n' + ''.join(log_text.splitlines(True)[-10:]))
    return not problems


def sanitized(lmp):
    """Whether lmp runs under AddressSanitizer (it links libasan)."""
    linked = subprocess.run(['ldd', lmp], capture_output=True, text=True).stdout
    return 'libasan' in linked


def raw_error_calls(source_dir):
    """Lines of the package that raise an error without SPHSoilCompat's flush."""
    found = []
    for name in sorted(os.listdir(source_dir)):
        if name == 'sph_soil_compat.h' or not name.endswith(('.cpp', '.h')):
            continue
        with open(os.path.join(source_dir, name)) as f:
            for number, line in enumerate(f, 1):
                if re.search(r'error->(all|one)\(', line):
                    found.append(f'{name}:{number}: {line.strip()}')
    return found


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument('--lmp', required=True)
    p.add_argument('--mpirun', default='mpirun')
    p.add_argument('--workdir', default=os.path.join(os.getcwd(), 'batch_errors'))
    args = p.parse_args()

    bad_first = {'bad.data': DATA.format(mass1=-1.0, mass2=1.0)}
    bad_second = {'bad.data': DATA.format(mass1=1.0, mass2=-2.0)}
    source_dir = os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', 'src', 'SPH_SOIL')
    raw = raw_error_calls(source_dir)
    print(f'errors raised through SPHSoilCompat: {"ok" if not raw else "FAILED"}')
    for line in raw:
        print('  ' + line)
    ok = not raw
    # error->one on rank 0 (atom 1 at x = 0.25 is rank 0's on two ranks)
    for np in (1, 2):
        ok &= run_case(args, f'data_file_error_np{np}', np, READ_DATA, bad_first,
                       'Invalid mass -1 of atom 1 in Atoms section of data file: must be finite and > 0')
    # error->one on rank 1 (atom 2 at x = 0.75): the screen only, see the docstring
    ok &= run_case(args, 'data_file_error_rank1_np2', 2, READ_DATA, bad_second,
                   'Invalid mass -2 of atom 2 in Atoms section of data file: must be finite and > 0', in_log=False)
    # a collective error in a run
    for np in (1, 2):
        ok &= run_case(args, f'unstable_run_np{np}', np, UNSTABLE, {},
                       'became unstable at step 1')
    # the memory guard under a process limit (a collective error: the first rank short of
    # memory names itself)
    if sanitized(args.lmp):
        print('refinement_under_ulimit: skipped, lmp runs under AddressSanitizer')
    else:
        for np in (1, 2):
            ok &= run_case(args, f'refinement_under_ulimit_np{np}', np, RUNAWAY, {},
                           ['ERROR: Fix sph/soil/refine: splitting 409600 particles at step 7 would '
                            'make 1.64e+06 particles', 'more than rank 0 may allocate (it would need',
                            'and RLIMIT_AS (ulimit -v) limits its address space to 3.07 GB, of which '
                            'it holds', 'lower maxlevel or limit the refinement to a region'],
                           address_space_kb=ADDRESS_SPACE_KB)
    sys.exit(0 if ok else 1)


if __name__ == '__main__':
    main()
