#!/usr/bin/python3
"""The terrains of examples/landslide_3d and examples/shallow_landslide: a hillside that steepens to
35 degrees above a flat valley floor, with a channel along the fall line, each written into its
example's directory as a triangle mesh (terrain.stl, ASCII STL, what a digital elevation model
exported for LAMMPS's create_atoms mesh looks like) and as the same surface's height for the input
script (terrain.lmp: the box, and an atom-style variable `ground` = the terrain's height under each
particle, which places the soil on it).

    z(x, y) = tan(35 deg) L ln(1 + exp((x_toe - x) / L)) + k y^2

The first term runs at 35 degrees up the hill (x < x_toe) and bends over a length L into the flat
floor (x > x_toe); the second is the channel. Two terrains: landslide_3d's (a deep channel, 6 m
wide) and shallow_landslide's (a shallow one, 9 m wide: room for a soil mantle over the whole
hillside). The surface is one fact with two outputs: edit the constants here and run this script
(examples/landslide_3d/terrain.py) to rewrite the files.
"""
import math
import os

SLOPE_DEG = 35.0      # the hillside's steepest angle
TOE = 6.0             # where the hillside meets the floor (m)
BEND = 1.0            # the length over which it bends into the floor (m)
X_RANGE = (-0.5, 18.0)
# example: the channel's curvature k (1/m), the terrain's extent across it (m)
TERRAINS = {
    'landslide_3d': (0.15, (-3.0, 3.0)),        # 1.35 m higher 3 m off its axis
    'shallow_landslide': (0.05, (-4.5, 4.5)),   # 0.8 m higher 4 m off its axis
}
CELL = 0.5            # the mesh's cell (m): two triangles each; create_atoms places the wall
                      # particles on them at the density the input asks for
EXAMPLES = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def height(x, y, channel):
    return math.tan(math.radians(SLOPE_DEG)) * BEND * math.log1p(math.exp((TOE - x) / BEND)) + channel * y * y


def lammps_expression(x, y, channel):
    """height() in LAMMPS's variable syntax, of the names x and y."""
    return (f'{math.tan(math.radians(SLOPE_DEG)):.12g}*{BEND:g}*ln(1.0+exp(({TOE:g}-{x})/{BEND:g}))'
            f'+{channel:g}*{y}*{y}')


def facets(channel, y_range):
    nx = round((X_RANGE[1] - X_RANGE[0]) / CELL)
    ny = round((y_range[1] - y_range[0]) / CELL)
    def vertex(i, j):
        x, y = X_RANGE[0] + i * CELL, y_range[0] + j * CELL
        return (x, y, height(x, y, channel))
    for i in range(nx):
        for j in range(ny):
            a, b, c, d = vertex(i, j), vertex(i + 1, j), vertex(i + 1, j + 1), vertex(i, j + 1)
            yield a, b, c
            yield a, c, d


def normal(a, b, c):
    u = [b[k] - a[k] for k in range(3)]
    v = [c[k] - a[k] for k in range(3)]
    n = [u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]]
    size = math.sqrt(sum(q * q for q in n))
    return [q / size for q in n]


def write(example, channel, y_range):
    with open(os.path.join(EXAMPLES, example, 'terrain.stl'), 'w') as f:
        f.write('solid terrain\n')
        for tri in facets(channel, y_range):
            f.write('  facet normal {:.6g} {:.6g} {:.6g}\n    outer loop\n'.format(*normal(*tri)))
            for p in tri:
                f.write('      vertex {:.6f} {:.6f} {:.6f}\n'.format(*p))
            f.write('    endloop\n  endfacet\n')
        f.write('endsolid terrain\n')
    top = max(height(X_RANGE[0], y, channel) for y in y_range)
    with open(os.path.join(EXAMPLES, example, 'terrain.lmp'), 'w') as f:
        f.write('# written by terrain.py (the same surface as terrain.stl): the extent of the terrain, its\n'
                '# height under a particle (ground) and under the point (v_xx, v_yy) (ground_at, for\n'
                '# create_atoms ... var ... set x xx set y yy)\n')
        f.write(f'variable        terrain_xlo equal {X_RANGE[0]:g}\nvariable        terrain_xhi equal {X_RANGE[1]:g}\n'
                f'variable        terrain_ylo equal {y_range[0]:g}\nvariable        terrain_yhi equal {y_range[1]:g}\n'
                f'variable        terrain_top equal {top:.6g}\n'
                f'variable        terrain_toe equal {TOE:g}\n'
                f'variable        ground atom {lammps_expression("x", "y", channel)}\n'
                f'variable        xx internal 0.0\nvariable        yy internal 0.0\nvariable        zz internal 0.0\n'
                f'variable        ground_at equal {lammps_expression("v_xx", "v_yy", channel)}\n')



def main():
    for example, (channel, y_range) in TERRAINS.items():
        write(example, channel, y_range)


if __name__ == '__main__':
    main()
