"""The structure of the package's sources: its files (a .h and its .cpp count as one), their
sizes, who includes whom, and any circle of includes, at the working tree or at a git revision;
a picture with one column per layer (styles, LAMMPS-side helpers, refinement, pure physics) and
the JSON of the same.

  python3 -m sph_soil structure [--rev REV] [--plot FILE] [--json FILE]
"""
import os
import re
import subprocess

from . import paths, report

COMMAND = 'structure'
SOURCES = 'src/SPH_SOIL'
# the layers, in the order dependencies should run (a file of a layer may use those after it)
# (the atom style holds the state that every layer above reads; an internal fix is created by
# the helper that needs it)
INTERNAL_FIXES = ('fix_sph_soil_walls', 'fix_sph_soil_skin')
UTILITIES = ('sph_soil_compat', 'sph_soil_input', 'sph_soil_offenders', 'sph_soil_memory',
             'sph_soil_fixes')
LAYERS = [
    ('LAMMPS styles', lambda name: (re.match(r'(pair|fix|compute)_sph_soil', name) and
                                    name not in INTERNAL_FIXES) or
     name in ('sph_soil_set', 'sph_soil_refine')),
    ('refinement (LAMMPS side)', lambda name: name.startswith('sph_soil_refine_') or
     name in ('sph_soil_splitter',) or name.startswith('sph_soil_criterion')),
    ('LAMMPS-side helpers', lambda name: name.startswith('sph_soil_') and name not in UTILITIES),
    ('state: atom style, internal fixes', lambda name: name.startswith('atom_vec_sph_soil') or
     name in INTERNAL_FIXES),
    ('LAMMPS utilities', lambda name: name in UTILITIES),
    ('pure physics', lambda name: name.startswith('soil_')),
]


def add_arguments(p):
    p.add_argument('--rev', help='a git revision (default: the working tree)')
    p.add_argument('--plot', help='the picture (PNG)')
    p.add_argument('--json', help='the numbers')


def sources(rev=None):
    """{file name: text} of the package's .h and .cpp files."""
    root = paths.ROOT
    if rev is None:
        directory = os.path.join(root, SOURCES)
        return {f: open(os.path.join(directory, f)).read() for f in sorted(os.listdir(directory))
                if f.endswith(('.h', '.cpp'))}
    names = subprocess.run(['git', 'ls-tree', '--name-only', f'{rev}:{SOURCES}'], cwd=root,
                           capture_output=True, text=True, check=True).stdout.split()
    return {f: subprocess.run(['git', 'show', f'{rev}:{SOURCES}/{f}'], cwd=root, capture_output=True,
                              text=True, check=True).stdout
            for f in names if f.endswith(('.h', '.cpp'))}


def rooms(files):
    """{room: {'lines': n, 'uses': set of rooms}}: a room is a file name without its extension."""
    result = {}
    for name, text in files.items():
        room = os.path.splitext(name)[0]
        entry = result.setdefault(room, {'lines': 0, 'uses': set()})
        entry['lines'] += text.count('\n')
        for included in re.findall(r'^#include "([^"]+)\.h"', text, re.M):
            if included != room and f'{included}.h' in files:
                entry['uses'].add(included)
    return result


def circles(graph):
    """The strongly connected components of more than one room (Tarjan)."""
    index, low, stack, on_stack, found = {}, {}, [], set(), []

    def visit(v):
        index[v] = low[v] = len(index)
        stack.append(v)
        on_stack.add(v)
        for w in graph[v]['uses']:
            if w not in index:
                visit(w)
                low[v] = min(low[v], low[w])
            elif w in on_stack:
                low[v] = min(low[v], index[w])
        if low[v] == index[v]:
            component = []
            while True:
                w = stack.pop()
                on_stack.discard(w)
                component.append(w)
                if w == v:
                    break
            if len(component) > 1:
                found.append(sorted(component))

    for v in sorted(graph):
        if v not in index:
            visit(v)
    return found


def layer_of(room):
    for k, (_, matches) in enumerate(LAYERS):
        if matches(room):
            return k
    return len(LAYERS) - 1


def summary(graph):
    return {'rooms': len(graph), 'lines': sum(r['lines'] for r in graph.values()),
            'largest': max(graph, key=lambda r: graph[r]['lines']),
            'largest_lines': max(r['lines'] for r in graph.values()),
            'includes': sum(len(r['uses']) for r in graph.values()),
            'circles': circles(graph),
            'against_the_layers': sorted(f'{a} -> {b}' for a in graph for b in graph[a]['uses']
                                         if layer_of(b) < layer_of(a)),
            'files': {room: {'lines': r['lines'], 'uses': sorted(r['uses'])}
                      for room, r in sorted(graph.items())}}


def plot(graph, out, title):
    plt = report.pyplot()
    columns = [sorted((r for r in graph if layer_of(r) == k), key=lambda r: -graph[r]['lines'])
               for k in range(len(LAYERS))]
    height = max(len(c) for c in columns)
    fig, ax = plt.subplots(figsize=(3.4 * len(LAYERS), 0.3 * height + 1.6))
    where = {}
    for k, column in enumerate(columns):
        for row, room in enumerate(column):
            where[room] = (k * 3.4, -row)
    in_circle = {room for c in circles(graph) for room in c}
    for room, (x, y) in where.items():
        for used in graph[room]['uses']:
            u, v = where[used]
            against = layer_of(used) < layer_of(room) or (room in in_circle and used in in_circle)
            ax.annotate('', xy=(u, v), xytext=(x + 2.2, y),
                        arrowprops=dict(arrowstyle='->', lw=0.4, alpha=0.8 if against else 0.25,
                                        color='red' if against else 'steelblue'))
    largest = max(r['lines'] for r in graph.values())
    for room, (x, y) in where.items():
        width = 2.2 * graph[room]['lines'] / largest
        ax.add_patch(plt.Rectangle((x, y - 0.35), width, 0.7, color='red' if room in in_circle else '0.8'))
        ax.text(x + 0.05, y, f"{room}  {graph[room]['lines']}", va='center', fontsize=7)
    for k, (name, _) in enumerate(LAYERS):
        ax.text(k * 3.4, 1.0, name, fontsize=9, weight='bold')
    s = summary(graph)
    ax.set_title(f"{title}: {s['rooms']} files, {s['lines']} lines, {s['includes']} includes, "
                 f"{len(s['circles'])} circle(s); red: a circle, or an include against the layers",
                 fontsize=9)
    ax.set_xlim(-0.2, 3.4 * len(LAYERS))
    ax.set_ylim(-height, 1.6)
    ax.axis('off')
    fig.tight_layout()
    fig.savefig(out, dpi=130)
    plt.close(fig)


def main(args):
    graph = rooms(sources(args.rev))
    s = summary(graph)
    print(f"{args.rev or 'working tree'}: {s['rooms']} files (.h + .cpp), {s['lines']} lines, "
          f"{s['includes']} includes; largest {s['largest']} ({s['largest_lines']} lines)")
    print(f"circles: {s['circles'] or 'none'}")
    print(f"includes against the layers: {s['against_the_layers'] or 'none'}")
    if args.json:
        report.write_json(s, args.json, echo=False)
    if args.plot:
        plot(graph, args.plot, args.rev or 'working tree')
