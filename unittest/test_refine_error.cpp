// Kernel gradient error of one split and the instability conditions (doc/theory.rst section 5).
#include "soil_refine_error.h"

#include "gtest/gtest.h"

#include <cmath>

using namespace SPHSoil;
using Case = NeighbourSmoothing;

TEST(RefineError, VanishesWhenDaughtersCoincideWithTheParent)
{
  for (int dim : {2, 3}) {
    // (3D on a fixed, coarser quadrature: the adaptive one would take seconds)
    const int cells = dim == 3 ? 16 : 64;
    const double zero = kernel_gradient_error_fixed(dim, 0.0, 1.0, 1.2, Case::UNREFINED, cells);
    EXPECT_LT(zero, 1e-14) << "dimension " << dim;
    EXPECT_LT(kernel_gradient_error(2, 0.0, 1.0, 1.2, Case::UNREFINED).value, 1e-14);
    // and grows from zero as the daughters move apart
    const double small = kernel_gradient_error_fixed(dim, 0.01, 1.0, 1.2, Case::UNREFINED, cells);
    const double large = kernel_gradient_error_fixed(dim, 0.3, 1.0, 1.2, Case::UNREFINED, cells);
    EXPECT_GT(small, 0.0);
    EXPECT_GT(large, 100.0 * small);
  }
}

TEST(RefineError, PositiveForRealSplits)
{
  for (auto c : {Case::UNREFINED, Case::REFINED}) {
    EXPECT_GT(kernel_gradient_error(2, 0.5, 0.5, 1.2, c).value, 1e-3);
    EXPECT_GT(kernel_gradient_error(2, 0.55, 0.7, 1.2, c).value, 1e-4);
  }
  EXPECT_GT(kernel_gradient_error_fixed(3, 0.5, 0.5, 1.2, Case::UNREFINED, 16), 1e-3);
  // coinciding daughters with a smaller h are not the parent either
  EXPECT_GT(kernel_gradient_error(2, 0.0, 0.5, 1.2, Case::UNREFINED).value, 1e-3);
}

TEST(RefineError, QuadratureConverges)
{
  // refining the quadrature changes E by less than 0.1% (here far less)
  const double points[3][2] = {{0.5, 0.5}, {0.3, 0.7}, {0.7, 0.3}};
  for (const auto &p : points)
    for (auto c : {Case::UNREFINED, Case::REFINED}) {
      const double coarse = kernel_gradient_error_fixed(2, p[0], p[1], 1.2, c, 32);
      const double fine = kernel_gradient_error_fixed(2, p[0], p[1], 1.2, c, 128);
      EXPECT_NEAR(coarse, fine, 1e-3 * fine) << p[0] << " " << p[1];
      const auto adaptive = kernel_gradient_error(2, p[0], p[1], 1.2, c);
      EXPECT_NEAR(adaptive.value, fine, 1e-4 * fine);
      EXPECT_LE(adaptive.error_estimate, 1e-5 * adaptive.value);
    }
  const double coarse3 = kernel_gradient_error_fixed(3, 0.5, 0.5, 1.2, Case::UNREFINED, 8);
  const double fine3 = kernel_gradient_error_fixed(3, 0.5, 0.5, 1.2, Case::UNREFINED, 32);
  EXPECT_NEAR(coarse3, fine3, 1e-3 * fine3);
}

TEST(RefineError, DaughterGradientsTendToTheParentsGradient)
{
  // at points inside and around the support, the summed daughter gradient approaches the
  // parent's as eps_r -> 0 and alpha_r -> 1, in 2D and 3D
  const double x[3][3] = {{0.3, 0.2, 0.1}, {1.1, -0.4, 0.5}, {-1.7, 0.9, -0.3}};
  for (int dim : {2, 3})
    for (const auto &point : x) {
      double previous = HUGE_VAL, first = 0.0;
      for (double t : {0.2, 0.1, 0.05, 0.01}) {
        const double d = gradient_difference_squared(dim, t, 1.0 - t, 1.2, Case::UNREFINED, point);
        EXPECT_LT(d, previous) << "dimension " << dim << " t " << t;
        if (t == 0.2) first = d;
        previous = d;
      }
      // second order in t: (0.01 / 0.2)^2 = 2.5e-3
      EXPECT_LT(previous, 1e-2 * first);
    }
}

TEST(RefineError, InstabilityConditionsByHand)
{
  // the paper's recommendation (0.5, 0.5) is stable for d_ij = d_ref, r_a = 1.2:
  // 2/3 * 0.5 * 1.2 = 0.4 < 0.5; 0.4 + 0.5 = 0.9 < 1; (1.5 * 1.2)/3 + 0.25 = 0.85 < 1
  auto c = instability_conditions(0.5, 0.5, 1.2, 1.0);
  EXPECT_FALSE(c.daughters_too_close);
  EXPECT_FALSE(c.refined_neighbours);
  EXPECT_FALSE(c.unrefined_neighbour);
  EXPECT_TRUE(stable_refinement(0.5, 0.5, 1.2, 1.0));
  // (0.55, 0.7) is not: 2/3 * 0.7 * 1.2 = 0.56 > 0.55 and 0.56 + 0.55 = 1.11 > 1
  c = instability_conditions(0.55, 0.7, 1.2, 1.0);
  EXPECT_TRUE(c.daughters_too_close);
  EXPECT_TRUE(c.refined_neighbours);
  EXPECT_FALSE(c.unrefined_neighbour);    // 1.7 * 1.2 / 3 + 0.275 = 0.955 < 1
  EXPECT_FALSE(stable_refinement(0.55, 0.7, 1.2, 1.0));
  // compressed neighbours (0.85 d_ref) make (0.5, 0.5) unstable through Cond. 2 (0.9 > 0.85)
  c = instability_conditions(0.5, 0.5, 1.2, 0.85);
  EXPECT_FALSE(c.daughters_too_close);
  EXPECT_TRUE(c.refined_neighbours);
  EXPECT_FALSE(c.unrefined_neighbour);
  // Cond. 2 is the more restrictive of 2 and 3 wherever Cond. 1 is not violated
  for (double eps = 0.2; eps <= 0.8; eps += 0.05)
    for (double alpha = 0.2; alpha <= 0.8; alpha += 0.05)
      for (double d : {1.0, 0.85}) {
        const auto k = instability_conditions(eps, alpha, 1.2, d);
        if (!k.daughters_too_close && k.unrefined_neighbour) EXPECT_TRUE(k.refined_neighbours);
      }
}

// With the Wendland C2 kernel (W'' < 0 only for r < h/2) the conditions use 1/2 for 2/3: the
// paper's unstable (0.55, 0.7) becomes stable at d_ij = d_ref
TEST(RefineError, InstabilityConditionsFollowTheKernelsInflection)
{
  const double q = WendlandC2::INFLECTION;
  auto c = instability_conditions(0.55, 0.7, 1.2, 1.0, q);
  EXPECT_FALSE(c.daughters_too_close);    // 0.5 * 0.7 * 1.2 = 0.42 < 0.55
  EXPECT_FALSE(c.refined_neighbours);     // 0.42 + 0.55 = 0.97 < 1
  EXPECT_FALSE(c.unrefined_neighbour);    // 0.5 * 1.7 * 1.2 / 2 + 0.275 = 0.785 < 1
  c = instability_conditions(0.3, 0.7, 1.2, 0.85, q);
  EXPECT_TRUE(c.daughters_too_close);     // 0.42 > 0.3
  EXPECT_FALSE(c.refined_neighbours);     // 0.72 < 0.85
  // the cubic spline's default is the paper's
  EXPECT_EQ(instability_conditions(0.55, 0.7, 1.2, 1.0).any(),
            instability_conditions(0.55, 0.7, 1.2, 1.0, CubicSpline::INFLECTION).any());
}

TEST(RefineError, WendlandKernelErrorVanishesForCoincidingDaughtersAndIsPositiveOtherwise)
{
  KernelKind wendland;
  ASSERT_TRUE(kernel_kind("wendland2", wendland));
  EXPECT_LT(kernel_gradient_error_fixed(2, 0.0, 1.0, 1.2, Case::UNREFINED, 64, wendland), 1e-14);
  const double e = kernel_gradient_error(2, 0.5, 0.5, 1.2, Case::UNREFINED, 1e-5, 256, wendland).value;
  EXPECT_GT(e, 1e-3);
  EXPECT_NE(e, kernel_gradient_error(2, 0.5, 0.5, 1.2, Case::UNREFINED).value);
}

// a defect's two pushes (neighbours, daughters) against reference values
static void expect_defect(const SplitStressDefect &defect, double neighbours, double daughters,
                          double tolerance = 1e-5)
{
  EXPECT_NEAR(defect.neighbours, neighbours, tolerance);
  EXPECT_NEAR(defect.daughters, daughters, tolerance);
}

// What a split does to a soil at rest (doc/theory.rst 5.11): the stress-balance defect, against
// an independent sum over the lattice (numpy; the cubic spline, 2D, r_a = 1.2)
TEST(RefineError, SplitStressDefectAgainstAnIndependentLatticeSum)
{
  // daughters on the parent's site with its h: the lattice is unchanged
  expect_defect(split_stress_defect(2, 0.0, 1.0, 1.2), 0.0, 0.0, 1e-12);
  // the package's default split, and the near-balanced (0.4, 0.9)
  expect_defect(split_stress_defect(2, 0.5, 0.5, 1.2), 0.233877, 1.067237);
  expect_defect(split_stress_defect(2, 0.4, 0.9, 1.2), 0.005113, 0.009034);
  // 3D: zero for coinciding daughters, of the same order otherwise
  EXPECT_LT(split_stress_defect(3, 0.0, 1.0, 1.2).neighbours, 1e-12);
  SplitStressDefect cube = split_stress_defect(3, 0.5, 0.5, 1.2);
  EXPECT_GT(cube.neighbours, 0.05);
  EXPECT_GT(cube.daughters, cube.neighbours);
}

// The edge of a refined zone, against an independent sum (numpy: a coarse half-lattice under
// the half-lattice of daughters, the cubic spline, 2D, r_a = 1.2)
TEST(RefineError, LevelEdgeDefectAgainstAnIndependentLatticeSum)
{
  // coinciding daughters with the parent's h: no edge at all
  expect_defect(level_edge_defect(2, 0.0, 1.0, 1.2), 0.0, 0.0, 1e-12);
  expect_defect(level_edge_defect(2, 0.5, 0.5, 1.2), 0.085966, 0.378434);
  expect_defect(level_edge_defect(2, 0.5, 0.9, 1.2), 0.005055, 0.047416);
  SplitStressDefect cube = level_edge_defect(3, 0.5, 0.5, 1.2);
  EXPECT_GT(cube.neighbours, 0.01);
  EXPECT_GT(cube.daughters, cube.neighbours);
}
