// The artificial stress of Gray, Monaghan & Swift (2001) against SPH's tensile instability
// (groundwork of cohesive soil): zero without tension, -epsilon sigma / rho^2 along a tensile
// principal direction, objective, and symmetric in the pair (momentum is conserved).
#include "soil_artificial_stress.h"
#include "soil_model_testing.h"

#include "gtest/gtest.h"

#include <cmath>
#include <random>

using namespace SPHSoil;

using SPHSoilTesting::random_rotation;
using SPHSoilTesting::rotate;

TEST(ArtificialStress, ZeroWithoutTension)
{
  const double compression[6] = {-3.0e4, -1.0e4, -2.0e4, 5.0e3, 0.0, 0.0};
  double R[6];
  artificial_stress(compression, 2000.0, 0.3, R);
  for (int k = 0; k < 6; k++) EXPECT_EQ(R[k], 0.0) << k;
}

TEST(ArtificialStress, OpposesEachTensilePrincipalStress)
{
  // tension along x, compression along y and z: R = -epsilon sigma_xx / rho^2 along x only
  const double uniaxial[6] = {1.0e4, -2.0e4, -5.0e3, 0.0, 0.0, 0.0};
  const double rho = 2000.0, epsilon = 0.3;
  double R[6];
  artificial_stress(uniaxial, rho, epsilon, R);
  EXPECT_NEAR(R[0], -epsilon * 1.0e4 / (rho * rho), 1e-18);
  for (int k = 1; k < 6; k++) EXPECT_NEAR(R[k], 0.0, 1e-18) << k;
  // in-plane shear: principal stresses +-tau along the diagonals; only +tau is countered
  const double shear[6] = {0.0, 0.0, 0.0, 2.0e3, 0.0, 0.0};
  artificial_stress(shear, rho, epsilon, R);
  const double r = -epsilon * 2.0e3 / (rho * rho);    // along (1, 1)/sqrt(2)
  EXPECT_NEAR(R[0], 0.5 * r, 1e-18);
  EXPECT_NEAR(R[1], 0.5 * r, 1e-18);
  EXPECT_NEAR(R[3], 0.5 * r, 1e-18);
  EXPECT_NEAR(R[2], 0.0, 1e-18);
}

// R(Q sigma Q^T) = Q R(sigma) Q^T for random rotations and stresses with tension
TEST(ArtificialStress, IsObjective)
{
  std::mt19937 random(7);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  for (int trial = 0; trial < 200; trial++) {
    double stress[6];
    for (int k = 0; k < 6; k++) stress[k] = 1.0e4 * uniform(random);
    double q[3][3];
    random_rotation(random, q);
    double rotated[6], R[6], R_rotated[6], expected[6];
    rotate(q, stress, rotated);
    artificial_stress(stress, 1800.0, 0.3, R);
    artificial_stress(rotated, 1800.0, 0.3, R_rotated);
    rotate(q, R, expected);
    for (int k = 0; k < 6; k++) EXPECT_NEAR(R_rotated[k], expected[k], 1e-14) << "trial " << trial;
  }
}

// the pair's weight (W(r)/W(d))^n, and the pair term m_a m_b (R_a + R_b) w grad W: the forces
// on a and b are opposite to round-off
TEST(ArtificialStress, PairTermIsAntisymmetric)
{
  EXPECT_DOUBLE_EQ(artificial_stress_weight(0.5), 0.0625);
  EXPECT_DOUBLE_EQ(artificial_stress_weight(1.0), 1.0);
  const double sa[6] = {1.0e4, -2.0e3, 0.0, 3.0e3, 0.0, 0.0};
  const double sb[6] = {5.0e3, 4.0e3, -1.0e3, -2.0e3, 0.0, 0.0};
  double Ra[6], Rb[6];
  artificial_stress(sa, 2000.0, 0.3, Ra);
  artificial_stress(sb, 2100.0, 0.3, Rb);
  const double grad_a[3] = {-120.0, 45.0, 0.0};    // dW/dx_a; dW/dx_b = -dW/dx_a
  static const int voigt[3][3] = {{0, 3, 4}, {3, 1, 5}, {4, 5, 2}};
  const double ma = 0.01, mb = 0.011, w = 0.7;
  for (int a = 0; a < 3; a++) {
    double on_a = 0.0, on_b = 0.0;
    for (int c = 0; c < 3; c++) {
      on_a += ma * mb * (Ra[voigt[a][c]] + Rb[voigt[a][c]]) * w * grad_a[c];
      on_b += mb * ma * (Rb[voigt[a][c]] + Ra[voigt[a][c]]) * w * (-grad_a[c]);
    }
    EXPECT_NEAR(on_a + on_b, 0.0, 1e-15 * std::fabs(on_a)) << a;
  }
}

// the plane-strain closed form (the pair loop's in 2D) is the general one for xz = yz = 0:
// random in-plane stresses, with tension along none, one or both in-plane directions and zz,
// and equal principal stresses
TEST(ArtificialStress, PlaneStrainClosedFormIsTheGeneralOne)
{
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int trial = 0; trial < 2000; trial++) {
    double stress[6] = {2.0e4 * u(rng), 2.0e4 * u(rng), 2.0e4 * u(rng), 1.0e4 * u(rng), 0.0, 0.0};
    if (trial % 5 == 0) {
      stress[1] = stress[0];
      stress[3] = 0.0;
    }
    double general[6], closed[6];
    artificial_stress(stress, 1900.0, 0.3, general);
    artificial_stress<2>(stress, 1900.0, 0.3, closed);
    for (int k = 0; k < 6; k++)
      EXPECT_NEAR(closed[k], general[k], 1.0e-12 * 2.0e4 * 0.3 / (1900.0 * 1900.0)) << trial << " " << k;
  }
}
