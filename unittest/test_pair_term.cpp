// The pair term's pieces that are not covered by the LAMMPS-level tests: the mirrored stress of
// a free-slip wall image.
#include "soil_pair_terms.h"
#include "soil_wall_images.h"

#include "gtest/gtest.h"

#include <cmath>

using namespace SPHSoil;

// A wall along x (normal y): the image keeps the normal stresses and flips the shear stresses
// that couple y with x and z, so the sum has no shear traction on the wall: (sum n) x n = 0.
TEST(PairTerm, MirroredStressOfAFreeSlipWallHasNoShearTraction)
{
  const double stress[6] = {-3.0, -5.0, -4.0, 1.5, 0.7, -0.9};
  const double ny[3] = {0.0, 1.0, 0.0};
  double sum[6];
  mirrored_stress_sum(stress, ny, sum);
  const double expected[6] = {-6.0, -10.0, -8.0, 0.0, 1.4, 0.0};
  for (int k = 0; k < 6; k++) EXPECT_NEAR(sum[k], expected[k], 1e-15) << k;

  // any normal: the traction of the sum is normal to the wall, and twice the soil's normal stress
  const double angle = 0.3;
  const double n[3] = {std::cos(angle) * std::sin(1.1), std::sin(angle) * std::sin(1.1), std::cos(1.1)};
  mirrored_stress_sum(stress, n, sum);
  static const int voigt[3][3] = {{0, 3, 4}, {3, 1, 5}, {4, 5, 2}};
  double traction[3], soil_traction[3];
  for (int a = 0; a < 3; a++) {
    traction[a] = soil_traction[a] = 0.0;
    for (int b = 0; b < 3; b++) {
      traction[a] += sum[voigt[a][b]] * n[b];
      soil_traction[a] += stress[voigt[a][b]] * n[b];
    }
  }
  const double normal = traction[0] * n[0] + traction[1] * n[1] + traction[2] * n[2];
  const double soil_normal = soil_traction[0] * n[0] + soil_traction[1] * n[1] + soil_traction[2] * n[2];
  for (int a = 0; a < 3; a++) EXPECT_NEAR(traction[a], normal * n[a], 1e-14) << a;
  EXPECT_NEAR(normal, 2.0 * soil_normal, 1e-14);
  // and the trace is kept: the mirror is a rotation-like congruence
  EXPECT_NEAR(sum[0] + sum[1] + sum[2], 2.0 * (stress[0] + stress[1] + stress[2]), 1e-14);
}

// Coulomb friction between the two: mu = 0 is the free-slip sum, a large mu the no-slip sum
// 2 sigma; in between, the sum's shear traction is the share lambda = mu |sigma_nn| / |sigma_nt|
// of the no-slip one, so the traction of the image stress never exceeds mu times its normal part.
TEST(PairTerm, FrictionalStressSumLiesBetweenFreeSlipAndNoSlip)
{
  const double stress[6] = {-3.0, -5.0, -4.0, 1.5, 0.7, -0.9};
  const double n[3] = {0.0, 1.0, 0.0};
  double free_slip[6], sum[6];
  mirrored_stress_sum(stress, n, free_slip);
  EXPECT_EQ(frictional_stress_sum(stress, n, 0.0, sum), 0.0);
  for (int k = 0; k < 6; k++) EXPECT_NEAR(sum[k], free_slip[k], 1e-15) << k;
  EXPECT_EQ(frictional_stress_sum(stress, n, 10.0, sum), 1.0);
  for (int k = 0; k < 6; k++) EXPECT_NEAR(sum[k], 2.0 * stress[k], 1e-15) << k;

  // |sigma_nt| = |(1.5, -0.9)| = 1.749, sigma_nn = -5: mu = 0.2 lets through 1/1.749 of it
  const double shear = std::hypot(1.5, 0.9), mu = 0.2;
  const double share = frictional_stress_sum(stress, n, mu, sum);
  EXPECT_NEAR(share, mu * 5.0 / shear, 1e-15);
  EXPECT_NEAR(std::hypot(sum[3], sum[5]), mu * std::fabs(sum[1]), 1e-14);
  EXPECT_NEAR(sum[4], 2.0 * stress[4], 1e-15);    // xz, in the wall's plane: untouched
  // a soil pulling on the wall (sigma_nn > 0) transmits no shear
  const double tension[6] = {1.0, 2.0, 1.0, 1.5, 0.0, 0.0};
  EXPECT_EQ(frictional_stress_sum(tension, n, 0.5, sum), 0.0);
  EXPECT_NEAR(sum[3], 0.0, 1e-15);
}
