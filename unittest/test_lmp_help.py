#!/usr/bin/python3
"""`lmp -h` reports the LAMMPS release of the source tree and lists every SPH_SOIL style.

    unittest/test_lmp_help.py --lmp build/lmp --lammps-src <tree> --package src/SPH_SOIL

The styles are read from the package's headers (AtomStyle(...), PairStyle(...), ...), so a
new style is checked without editing this test; each must appear in its own section of the
help text, and SPH_SOIL among the installed packages. Internal styles, named in capitals as
LAMMPS names its own (fix SPH_SOIL_WALLS, which the pair style creates), are not listed by lmp -h
and not looked for.
"""
import argparse
import glob
import re
import subprocess
import sys

SECTIONS = {'AtomStyle': 'Atom styles', 'PairStyle': 'Pair styles', 'FixStyle': 'Fix styles',
            'ComputeStyle': 'Compute styles', 'CommandStyle': 'Command styles'}


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument('--lmp', required=True)
    p.add_argument('--lammps-src', required=True)
    p.add_argument('--package', required=True)
    a = p.parse_args()

    text = subprocess.run([a.lmp, '-h'], capture_output=True, text=True, check=True).stdout
    problems = []
    with open(f'{a.lammps_src}/src/version.h') as f:
        version = re.search(r'#define LAMMPS_VERSION "([^"]+)"', f.read()).group(1)
    if f'Simulator - {version}' not in text:
        problems.append(f'lmp -h does not report LAMMPS {version}')
    packages = re.search(r'Installed packages:\s*\n\s*\n(.*?)\n\s*\n', text, re.S)
    if not packages or 'SPH_SOIL' not in packages.group(1).split():
        problems.append('SPH_SOIL is not among the installed packages')

    # the help text's sections: '* Pair styles:' followed by words
    sections, current = {}, None
    for line in text.splitlines():
        m = re.match(r'\* (.*? styles):?\s*$', line)
        if m:
            current = m.group(1)
            sections[current] = set()
        elif current:
            sections[current].update(line.split())
    styles = []
    for header in sorted(glob.glob(f'{a.package}/*.h')):
        for kind, name in re.findall(r'^(\w+Style)\(([^,]+),', open(header).read(), re.M):
            if name.isupper():
                continue
            styles.append((kind, name))
            if name not in sections.get(SECTIONS[kind], set()):
                problems.append(f'{kind} {name} ({header}) is not listed under "{SECTIONS[kind]}"')
    print(f'lmp -h: LAMMPS {version}, {len(styles)} SPH_SOIL styles checked: '
          + ', '.join(f'{k[:-5].lower()} {n}' for k, n in styles))
    for line in problems:
        print('  ' + line)
    sys.exit(1 if problems or not styles else 0)


if __name__ == '__main__':
    main()
