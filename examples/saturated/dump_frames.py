"""The frames of a LAMMPS text dump (dump custom), for the plot scripts beside it."""
import numpy as np


def frames(path):
    """All frames of a dump custom file: [(step, {column: values})]."""
    out = []
    for block in open(path).read().split("ITEM: TIMESTEP")[1:]:
        lines = block.strip().split("\n")
        start = next(k for k, line in enumerate(lines) if line.startswith("ITEM: ATOMS"))
        names = lines[start].split()[2:]
        values = np.array([[float(x) for x in line.split()] for line in lines[start + 1:]])
        out.append((int(lines[0]), {name: values[:, k] for k, name in enumerate(names)}))
    return out
