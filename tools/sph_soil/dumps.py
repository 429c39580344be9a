"""The files LAMMPS writes beside its log: text dumps (dump custom) and the time series of
fix ave/time."""
import numpy as np


def read_dump(path):
    """Last snapshot of a LAMMPS text dump as a dict of column name -> numpy array."""
    with open(path) as f:
        lines = f.read().splitlines()
    start = max(i for i, l in enumerate(lines) if l.startswith('ITEM: ATOMS'))
    names = lines[start].split()[2:]
    rows = [l.split() for l in lines[start + 1:] if l.strip() and not l.startswith('ITEM')]
    data = np.array(rows, dtype=float).reshape(-1, len(names))
    return {n: data[:, k] for k, n in enumerate(names)}


def read_ave_time(path):
    """The rows of a fix ave/time file (comment lines '#' skipped) as a 2D array: column 0 is
    the step, then the values in the order of the fix."""
    return np.loadtxt(path, comments='#', ndmin=2)
