"""What a LAMMPS input declares: its variables and their default values, so that a study's
defaults are the example's own (one fact in one place: the input)."""
import re


def input_variables(infile, extra=()):
    """The input's variables as it runs with the lmp arguments `extra`: NAME -> value (a string):
    the first value of each 'variable NAME index|equal|string VALUE' line (a constant, or the
    text of a formula), then each '-var NAME VALUE' of `extra`."""
    variables = {}
    with open(infile) as f:
        for line in f:
            m = re.match(r'variable\s+(\w+)\s+(?:index|equal|string)\s+(\S+)', line)
            if m and m.group(1) not in variables:
                variables[m.group(1)] = m.group(2)
    extra = list(extra)
    for k, word in enumerate(extra[:-2]):
        if word in ('-var', '-v'):
            variables[extra[k + 1]] = extra[k + 2]
    return variables
