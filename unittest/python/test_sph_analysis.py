#!/usr/bin/python3
"""Tests of tools/sph_analysis.py (free surface, runout and failure line of the analysis scripts)."""
import os
import sys
import unittest

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', '..', 'tools'))
import sph_analysis  # noqa: E402

D = 0.002
H = 1.2 * D


def lattice(nx, ny, d=D):
    xs, ys = np.meshgrid(np.arange(0.5 * d, nx * d, d), np.arange(0.5 * d, ny * d, d))
    return xs.ravel(), ys.ravel()


class SurfaceTest(unittest.TestCase):
    def test_kernel_is_normalised(self):
        # integral of W over the plane by a fine midpoint rule
        step = H / 100
        g = np.arange(-2 * H + 0.5 * step, 2 * H, step)
        gx, gy = np.meshgrid(g, g)
        total = sph_analysis.kernel_2d(np.hypot(gx, gy), H).sum() * step * step
        self.assertAlmostEqual(total, 1.0, places=5)

    def test_block_top_is_the_cell_edge(self):
        # 100 x 50 particles: the top row at 0.099 m, its cells end at 0.1 m
        x, y = lattice(100, 50)
        top = sph_analysis.surface_height(x, y, D * D, H, np.array([0.05, 0.1, 0.15]))
        np.testing.assert_allclose(top, 0.1, atol=0.02 * D)

    def test_particle_far_above_does_not_hide_the_surface(self):
        # the column is evaluated from the top down in blocks: a lone particle 0.2 m above the
        # block (many blocks of points above its surface) is not material, the block's top is
        x, y = lattice(100, 50)
        top = sph_analysis.surface_height(np.r_[x, 0.1], np.r_[y, 0.3], D * D, H, np.array([0.05, 0.1, 0.15]))
        np.testing.assert_allclose(top, 0.1, atol=0.02 * D)

    def test_single_particle_is_not_material(self):
        top = sph_analysis.surface_height(np.array([0.0]), np.array([0.5 * D]), D * D, H, np.array([0.0]))
        self.assertEqual(top[0], 0.0)

    def test_layers_count(self):
        x = np.arange(0.0, 0.05, D)
        one = sph_analysis.surface_height(x, np.full_like(x, 0.5 * D), D * D, H, np.array([0.025]))[0]
        two = sph_analysis.surface_height(np.r_[x, x], np.r_[np.full_like(x, 0.5 * D), np.full_like(x, 1.5 * D)],
                                         D * D, H, np.array([0.025]))[0]
        self.assertGreater(one, 0.5 * D)        # a continuous layer is material...
        self.assertLess(one, D)                 # ...ending below its cells' top edge
        self.assertAlmostEqual(two, 2 * D, delta=0.02 * D)

    def test_runout_ignores_scattered_particles(self):
        x, y = lattice(100, 10)                  # a 0.2 m x 0.02 m layer
        xs = np.r_[x, 0.3, 0.35]                 # and two particles far ahead
        ys = np.r_[y, 0.5 * D, 0.5 * D]
        run, _, _ = sph_analysis.runout(xs, ys, D * D, H, 0.002, D)
        self.assertAlmostEqual(run, 0.2, delta=D)

    def test_refined_particles_make_the_same_surface(self):
        # the same block at half the spacing, with h = 0.6 d_coarse (static refinement (0.5, 0.5))
        x, y = lattice(200, 100, 0.5 * D)
        top = sph_analysis.surface_height(x, y, 0.25 * D * D, 0.5 * H, np.array([0.05]))
        self.assertAlmostEqual(top[0], 0.1, delta=0.02 * D)

    def test_failure_line_of_a_slope(self):
        # particles above the line y = 0.1 - x (45 degrees) moved, the others did not
        x, y = lattice(100, 50)
        moved = y > 0.1 - x
        _, _, angle = sph_analysis.failure_line(x, y, moved, D, 0.1)
        self.assertAlmostEqual(angle, 45.0, delta=1.0)


if __name__ == '__main__':
    unittest.main()
