// The geometry of one split and the CSPM interpolation (soil_refine_split.h), without LAMMPS.
#include "soil_refine_split.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

using namespace SPHSoil;

TEST(Split, DaughtersSitOnTheCornersOfASquareOrCube)
{
  for (int dimension : {2, 3}) {
    double offsets[MAX_DAUGHTERS][3];
    const int count = daughter_offsets(dimension, 0.5, 0.01, offsets);
    ASSERT_EQ(count, dimension == 3 ? 8 : 4);
    double sum[3] = {0, 0, 0};
    for (int k = 0; k < count; k++)
      for (int a = 0; a < 3; a++) {
        sum[a] += offsets[k][a];
        const double expected = a < dimension ? 0.0025 : 0.0;
        EXPECT_DOUBLE_EQ(std::fabs(offsets[k][a]), expected) << "daughter " << k << " axis " << a;
      }
    // centred on the parent: the centre of mass and the angular momentum are kept
    for (int a = 0; a < 3; a++) EXPECT_NEAR(sum[a], 0.0, 1e-18);
    // all corners distinct
    for (int k = 0; k < count; k++)
      for (int l = k + 1; l < count; l++) {
        double d2 = 0;
        for (int a = 0; a < 3; a++) d2 += (offsets[k][a] - offsets[l][a]) * (offsets[k][a] - offsets[l][a]);
        EXPECT_GT(d2, 0.0);
      }
  }
}

TEST(Split, LevelSpacingHalves)
{
  EXPECT_EQ(level_spacing(0.002, 0), 0.002);
  EXPECT_EQ(level_spacing(0.002, 1), 0.001);
  EXPECT_EQ(level_spacing(0.002, 3), 0.00025);
}

TEST(Split, CspmReproducesAConstantFieldExactly)
{
  // irregular neighbours with unequal volumes and smoothing lengths
  std::mt19937 random(7);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  for (int dimension : {2, 3}) {
    CspmSum<3> sum;
    const double field[3] = {-1234.5, 0.0371, 2650.0};
    for (int j = 0; j < 40; j++) {
      const double r = 2.4 * uniform(random), h = 0.8 + 0.6 * uniform(random);
      sum.add(dimension, 0.5 + uniform(random), r, h, field);
    }
    double out[3];
    ASSERT_TRUE(sum.result(out));
    for (int k = 0; k < 3; k++) EXPECT_NEAR(out[k], field[k], 1e-14 * std::fabs(field[k]));
  }
}

TEST(Split, CspmIsAWeightedAverage)
{
  // two neighbours at the same distance and h: the average weighted by volume
  CspmSum<1> sum;
  const double a = 1.0, b = 4.0;
  sum.add(2, 1.0, 0.5, 1.0, &a);
  sum.add(2, 3.0, 0.5, 1.0, &b);
  double out;
  ASSERT_TRUE(sum.result(&out));
  EXPECT_NEAR(out, (1.0 * a + 3.0 * b) / 4.0, 1e-15);
  // beyond the support nothing is added
  CspmSum<1> empty;
  empty.add(2, 1.0, 2.5, 1.0, &a);
  EXPECT_FALSE(empty.result(&out));
}

// The merged particle of a family: mass, momentum, force and volume are the sums, the position
// the centre of mass, other values the mass averages; a constant field stays constant
TEST(Split, MergeSumConservesMassMomentumAndVolume)
{
  std::mt19937 random(7);
  std::uniform_real_distribution<double> uniform(0.5, 1.5);
  MergeSum<2> sum;
  double mass = 0.0, volume = 0.0, momentum[3] = {0, 0, 0}, moment[3] = {0, 0, 0}, force[3] = {0, 0, 0};
  double weighted = 0.0;
  for (int k = 0; k < 8; k++) {
    const double m = uniform(random), rho = 2000.0 * uniform(random);
    const double x[3] = {uniform(random), uniform(random), uniform(random)};
    const double v[3] = {uniform(random) - 1.0, uniform(random), -uniform(random)};
    const double f[3] = {uniform(random), -uniform(random), uniform(random)};
    const double value[2] = {-3.5, uniform(random)};
    sum.add(m, rho, x, v, f, value);
    mass += m;
    volume += m / rho;
    weighted += m * value[1];
    for (int a = 0; a < 3; a++) {
      momentum[a] += m * v[a];
      moment[a] += m * x[a];
      force[a] += f[a];
    }
  }
  EXPECT_EQ(sum.count, 8);
  EXPECT_DOUBLE_EQ(sum.mass, mass);
  EXPECT_DOUBLE_EQ(sum.mass / sum.density(), volume);
  double x[3], v[3], values[2];
  sum.position(x);
  sum.velocity(v);
  sum.averages(values);
  for (int a = 0; a < 3; a++) {
    EXPECT_NEAR(sum.mass * v[a], momentum[a], 1e-14);
    EXPECT_NEAR(x[a], moment[a] / mass, 1e-15);
    EXPECT_DOUBLE_EQ(sum.force[a], force[a]);
  }
  EXPECT_NEAR(values[0], -3.5, 1e-15);
  EXPECT_NEAR(values[1], weighted / mass, 1e-15);
}
