"""sph_soil.analysis: free surface, runout and failure line of 2D dumps; the late movement of a
time series."""
import numpy as np
import pytest

from sph_soil import analysis

D = 0.002
H = 1.2 * D


def lattice(nx, ny, d=D):
    xs, ys = np.meshgrid(np.arange(0.5 * d, nx * d, d), np.arange(0.5 * d, ny * d, d))
    return xs.ravel(), ys.ravel()


def test_kernel_is_normalised():
    # integral of W over the plane by a fine midpoint rule
    step = H / 100
    g = np.arange(-2 * H + 0.5 * step, 2 * H, step)
    gx, gy = np.meshgrid(g, g)
    total = analysis.kernel_2d(np.hypot(gx, gy), H).sum() * step * step
    assert total == pytest.approx(1.0, abs=1e-5)


def test_block_top_is_the_cell_edge():
    # 100 x 50 particles: the top row at 0.099 m, its cells end at 0.1 m
    x, y = lattice(100, 50)
    top = analysis.surface_height(x, y, D * D, H, np.array([0.05, 0.1, 0.15]))
    np.testing.assert_allclose(top, 0.1, atol=0.02 * D)


def test_particle_far_above_does_not_hide_the_surface():
    # the column is evaluated from the top down in blocks: a lone particle 0.2 m above the
    # block (many blocks of points above its surface) is not material, the block's top is
    x, y = lattice(100, 50)
    top = analysis.surface_height(np.r_[x, 0.1], np.r_[y, 0.3], D * D, H, np.array([0.05, 0.1, 0.15]))
    np.testing.assert_allclose(top, 0.1, atol=0.02 * D)


def test_single_particle_is_not_material():
    top = analysis.surface_height(np.array([0.0]), np.array([0.5 * D]), D * D, H, np.array([0.0]))
    assert top[0] == 0.0


def test_layers_count():
    x = np.arange(0.0, 0.05, D)
    one = analysis.surface_height(x, np.full_like(x, 0.5 * D), D * D, H, np.array([0.025]))[0]
    two = analysis.surface_height(np.r_[x, x], np.r_[np.full_like(x, 0.5 * D), np.full_like(x, 1.5 * D)],
                                  D * D, H, np.array([0.025]))[0]
    assert 0.5 * D < one < D        # a continuous layer is material, ending below its cells' top edge
    assert two == pytest.approx(2 * D, abs=0.02 * D)


def test_runout_ignores_scattered_particles():
    x, y = lattice(100, 10)                  # a 0.2 m x 0.02 m layer
    xs = np.r_[x, 0.3, 0.35]                 # and two particles far ahead
    ys = np.r_[y, 0.5 * D, 0.5 * D]
    run, _, _ = analysis.runout(xs, ys, D * D, H, 0.002, D)
    assert run == pytest.approx(0.2, abs=D)


def test_particle_top_counts_scattered_particles():
    # the particle-top measures, unlike the surface, see every particle
    x, y = lattice(100, 10)
    xs, ys = np.r_[x, 0.3], np.r_[y, 0.5 * D + 0.004]
    top = analysis.particle_top(xs, ys, np.array([0.1, 0.3, 0.4]), D)
    np.testing.assert_allclose(top, [0.02, 0.006, 0.0], atol=1e-12)
    assert analysis.runout_particle_top(xs, ys, D) == pytest.approx(0.3 + 0.5 * D, abs=1e-9)


def test_refined_particles_make_the_same_surface():
    # the same block at half the spacing, with h = 0.6 d_coarse (static refinement (0.5, 0.5))
    x, y = lattice(200, 100, 0.5 * D)
    top = analysis.surface_height(x, y, 0.25 * D * D, 0.5 * H, np.array([0.05]))
    assert top[0] == pytest.approx(0.1, abs=0.02 * D)


def test_failure_line_of_a_slope():
    # particles above the line y = 0.1 - x (45 degrees) moved, the others did not
    x, y = lattice(100, 50)
    moved = y > 0.1 - x
    _, _, angle = analysis.failure_line(x, y, moved, D, 0.1)
    assert angle == pytest.approx(45.0, abs=1.0)


def test_late_movement_is_the_growth_over_the_last_share():
    t = np.linspace(0.0, 1.0, 11)
    settles = 1.0 - np.exp(-20.0 * t)           # at rest long before the end
    creeps = 0.5 * t                            # still moving
    assert analysis.late_movement(t, settles) < 1e-2
    assert analysis.late_movement(t, creeps) == pytest.approx(0.5 * 0.3)
    assert analysis.late_movement(t, creeps, late=0.5) == pytest.approx(0.5 * 0.5)
