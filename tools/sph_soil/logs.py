"""LAMMPS log files: the one reader of what a run wrote to its log (thermo tables, loop times,
the release, errors, the wall time, lines that an input prints)."""
import os
import re
from dataclasses import dataclass

MONTHS = 'Jan Feb Mar Apr May Jun Jul Aug Sep Oct Nov Dec'.split()


@dataclass
class Loop:
    """One 'Loop time of S on P procs for N steps with A atoms' line."""
    seconds: float
    procs: int
    steps: int
    atoms: int


class Log:
    def __init__(self, path):
        self.path = path
        with open(path) as f:
            self.text = f.read()

    def thermo_tables(self):
        """Every thermo table, as (column names, rows of floats). A table runs from its 'Step'
        header to 'Loop time' (or the end of a run that stopped); lines that are not a full row
        of numbers (warnings, messages of fixes) are skipped. A header whose table never ended
        is dropped when the next one starts."""
        header, rows, tables = None, [], []
        for line in self.text.splitlines():
            words = line.split()
            if words and words[0] == 'Step':
                header, rows = words, []
                continue
            if header is not None:
                if line.startswith('Loop time'):
                    tables.append((header, rows))
                    header = None
                    continue
                try:
                    values = [float(w) for w in words]
                except ValueError:
                    continue
                if len(values) == len(header):
                    rows.append(values)
        if header is not None and rows:
            tables.append((header, rows))
        return tables

    def last_thermo_table(self):
        tables = self.thermo_tables()
        if not tables:
            raise ValueError(f'no thermo table in {self.path}')
        return tables[-1]

    def loops(self):
        return [Loop(float(s), int(p), int(n), int(a)) for s, p, n, a in
                re.findall(r'Loop time of (\S+) on (\d+) procs for (\d+) steps with (\d+) atoms', self.text)]

    def release(self):
        """The release that wrote the log, from its first line 'LAMMPS (4 Jul 2026 ...)': '4Jul26'."""
        m = re.match(r'LAMMPS \((\d+) (\w+) (\d{4})', self.text)
        if not m:
            raise ValueError(f'{self.path} does not start with a LAMMPS version line')
        return f'{m.group(1)}{m.group(2)}{m.group(3)[2:]}'

    def error(self):
        """The first line starting with ERROR, or None."""
        m = re.search(r'^ERROR.*$', self.text, re.M)
        return m.group(0) if m else None

    def total_wall_seconds(self):
        """Seconds of the last 'Total wall time: H:MM:SS', or None."""
        m = re.findall(r'Total wall time: (\d+):(\d+):(\d+)', self.text)
        if not m:
            return None
        h, mi, s = (int(v) for v in m[-1])
        return h * 3600 + mi * 60 + s

    def timing_breakdown(self):
        """LAMMPS's breakdown of the last loop: section (pair, neigh, ...) -> average seconds."""
        sections = {}
        for name in ('Pair', 'Neigh', 'Comm', 'Output', 'Modify', 'Other'):
            found = re.findall(rf'^{name}\s+\|\s+\S+\s+\|\s+(\S+)', self.text, re.M)
            if found:
                sections[name.lower()] = float(found[-1])
        return sections

    def search(self, pattern, flags=0):
        return re.search(pattern, self.text, flags)

    def findall(self, pattern, flags=0):
        return re.findall(pattern, self.text, flags)


def release_key(release):
    """Sort key of '4Jul26': (2026, 7, 4)."""
    m = re.match(r'(\d+)([A-Za-z]{3})(\d{2})$', release)
    return (2000 + int(m.group(3)), MONTHS.index(m.group(2)) + 1, int(m.group(1))) if m else (0, 0, 0)


def run_logs(directory):
    """The logs of runs in a directory (log.*, not the reference logs log.*.short.*), newest first."""
    logs = [os.path.join(directory, n) for n in os.listdir(directory)
            if n.startswith('log.') and '.short.' not in n]
    return sorted(logs, key=os.path.getmtime, reverse=True)


def wall_seconds(directory):
    """The wall time of the newest log in the directory that has one."""
    for path in run_logs(directory):
        seconds = Log(path).total_wall_seconds()
        if seconds is not None:
            return seconds
    return None
