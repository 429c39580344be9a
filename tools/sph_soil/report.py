"""How the studies hand out their results: JSON printed and written, figures drawn with
matplotlib without a display."""
import json


def pyplot():
    """matplotlib.pyplot on the Agg backend (figures to files; no display needed)."""
    import matplotlib
    matplotlib.use('Agg')
    import matplotlib.pyplot as plt
    return plt


def write_json(data, path=None, indent=1, end='\n', echo=True):
    """Print the JSON text of `data` (echo) and write it to `path` (if given), followed by `end`."""
    text = json.dumps(data, indent=indent)
    if echo:
        print(text)
    if path:
        with open(path, 'w') as f:
            f.write(text + end)
    return text


def add_run_arguments(parser, directory, holds):
    """--dir (a finished run: `holds` the files it needs), --json and --plot of a study that
    measures one run."""
    parser.add_argument('--dir', default=directory, help=f'directory with {holds} (default: %(default)s)')
    parser.add_argument('--json', default=None, help='write the numbers here too')
    parser.add_argument('--plot', default=None, help='PNG plot')


def rst_table(header, rows):
    """A simple reStructuredText table of `header` (strings) and `rows` (lists of strings)."""
    widths = [max(len(header[k]), *(len(r[k]) for r in rows)) for k in range(len(header))]
    sep = '  '.join('=' * w for w in widths)
    lines = [sep, '  '.join(h.ljust(w) for h, w in zip(header, widths)), sep]
    lines += ['  '.join(v.ljust(w) for v, w in zip(r, widths)) for r in rows]
    lines.append(sep)
    return '\n'.join(lines)
