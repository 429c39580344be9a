// The stress diffusion (soil_stress_diffusion.h, doc/theory.rst 2.8) on a square lattice with a
// free surface: the renormalised gradient is exact for a linear stress in every row, the surface
// included; the diffusion then leaves a linear stress alone pair by pair, diffuses a row-to-row
// zigzag at full strength, and keeps the sum of V sigma.
#include "soil_kernel_cubic.h"
#include "soil_stress_diffusion.h"

#include "gtest/gtest.h"

#include <cmath>
#include <vector>

using namespace SPHSoil;

namespace {

constexpr int D = 2, N = gradient_size<2>(), M = moment_size<2>(), C = diffused_components<2>();
constexpr double SPACING = 0.01, H = 1.2 * SPACING, VOLUME = SPACING * SPACING;

// a lattice 9 wide and 8 high, its top row at y = 0: the rows y = -7d ... 0
struct Lattice {
  std::vector<double> x, y;
  Lattice()
  {
    for (int row = 0; row < 8; row++)
      for (int column = -4; column <= 4; column++) {
        x.push_back(column * SPACING);
        y.push_back(-row * SPACING);
      }
  }
  int size() const { return (int) x.size(); }
  // the gradient factor F of the pair, false beyond the support
  bool pair(int a, int b, double dx[3], double &r2, double &factor) const
  {
    dx[0] = x[a] - x[b];
    dx[1] = y[a] - y[b];
    dx[2] = 0.0;
    r2 = dx[0] * dx[0] + dx[1] * dx[1];
    if (a == b || r2 >= 4.0 * H * H) return false;
    const double r = std::sqrt(r2);
    factor = CubicSpline::gradient_factor_inside<2>(r, 1.0 / H, H / r);
    return true;
  }
  // the sums of every particle (both shares of each pair), then G
  std::vector<double> gradients(const std::vector<std::vector<double>> &stress,
                                std::vector<bool> &valid) const
  {
    std::vector<double> sums((size_t) size() * N, 0.0);
    for (int a = 0; a < size(); a++)
      for (int b = a + 1; b < size(); b++) {
        double dx[3], r2, factor;
        if (!pair(a, b, dx, r2, factor)) continue;
        double difference[C], pair_sums[N] = {0.0};
        for (int k = 0; k < C; k++) difference[k] = stress[b][k] - stress[a][k];
        gradient_pair_sums<D>(dx, factor, difference, pair_sums);
        for (int k = 0; k < N; k++) {
          sums[(size_t) a * N + k] += VOLUME * pair_sums[k];
          sums[(size_t) b * N + k] += VOLUME * pair_sums[k];
        }
      }
    valid.assign(size(), false);
    for (int a = 0; a < size(); a++) valid[a] = renormalised_gradient<D>(&sums[(size_t) a * N], 0.05);
    return sums;
  }
  // each particle's diffusion rate
  std::vector<std::vector<double>> rates(const std::vector<std::vector<double>> &stress) const
  {
    std::vector<bool> valid;
    const auto g = gradients(stress, valid);
    std::vector<std::vector<double>> rate(size(), std::vector<double>(C, 0.0));
    for (int a = 0; a < size(); a++)
      for (int b = a + 1; b < size(); b++) {
        double dx[3], r2, factor;
        if (!valid[a] || !valid[b] || !pair(a, b, dx, r2, factor)) continue;
        double term[C];
        stress_diffusion_pair<D>(stress[a].data(), stress[b].data(), &g[(size_t) a * N + M],
                                 &g[(size_t) b * N + M], dx, r2, H, factor, 100.0 * H, term);
        for (int k = 0; k < C; k++) {
          rate[a][k] += VOLUME * term[k];
          rate[b][k] -= VOLUME * term[k];
        }
      }
    return rate;
  }
};

// a geostatic stress with K0 = 0.5 under a surface at y = d/2, and a lateral gradient in the
// shear: linear in x and y
std::vector<double> linear_stress(double x, double y)
{
  const double vertical = 19620.0 * (y - 0.5 * SPACING);
  return {0.5 * vertical, vertical, 0.5 * vertical, 300.0 * x - 50.0 * y};
}

}    // namespace

TEST(StressDiffusion, RenormalisedGradientIsExactForALinearStressAtTheSurfaceToo)
{
  const Lattice lattice;
  std::vector<std::vector<double>> stress;
  for (int a = 0; a < lattice.size(); a++) stress.push_back(linear_stress(lattice.x[a], lattice.y[a]));
  std::vector<bool> valid;
  const auto g = lattice.gradients(stress, valid);
  const double exact[C][D] = {{0.0, 0.5 * 19620.0}, {0.0, 19620.0}, {0.0, 0.5 * 19620.0}, {300.0, -50.0}};
  for (int a = 0; a < lattice.size(); a++) {
    ASSERT_TRUE(valid[a]) << "particle " << a << " (a corner's tensor is invertible)";
    for (int k = 0; k < C; k++)
      for (int d = 0; d < D; d++)
        EXPECT_NEAR(g[(size_t) a * N + M + k * D + d], exact[k][d], 1e-8 * 19620.0)
            << "particle " << a << " component " << k << " direction " << d;
  }
}

TEST(StressDiffusion, LeavesALinearStressAloneAndDiffusesAZigzag)
{
  const Lattice lattice;
  std::vector<std::vector<double>> stress, zigzag;
  for (int a = 0; a < lattice.size(); a++) {
    stress.push_back(linear_stress(lattice.x[a], lattice.y[a]));
    // the same with every second row 20 Pa more compressed
    auto z = stress.back();
    const int row = (int) std::lround(-lattice.y[a] / SPACING);
    if (row % 2 == 1)
      for (int k = 0; k < C; k++) z[k] -= 20.0;
    zigzag.push_back(z);
  }
  const auto linear = lattice.rates(stress);
  for (int a = 0; a < lattice.size(); a++)
    for (int k = 0; k < C; k++) EXPECT_NEAR(linear[a][k], 0.0, 1e-6) << a << " " << k;

  const auto rates = lattice.rates(zigzag);
  double sum[C] = {0.0};
  for (int a = 0; a < lattice.size(); a++) {
    const int row = (int) std::lround(-lattice.y[a] / SPACING);
    // the rows of the interior move towards their neighbours' mean: the compressed ones relax
    // (a positive rate), the others compress
    if (row >= 2 && row <= 5) {
      if (row % 2 == 1) EXPECT_GT(rates[a][1], 0.0) << a;
      else EXPECT_LT(rates[a][1], 0.0) << a;
    }
    for (int k = 0; k < C; k++) sum[k] += VOLUME * rates[a][k];
  }
  // each pair gives one what it takes from the other
  for (int k = 0; k < C; k++) EXPECT_NEAR(sum[k], 0.0, 1e-9) << k;
}

// A particle whose partners lie on one line has a singular first-moment tensor: no gradient,
// its pairs not diffused
TEST(StressDiffusion, SingularMomentIsNotTrusted)
{
  double sums[N] = {0.0};
  const double dx[3] = {SPACING, 0.0, 0.0};
  const double difference[C] = {1.0, 2.0, 3.0, 4.0};
  gradient_pair_sums<D>(dx, -1.0 / (SPACING * SPACING), difference, sums);
  EXPECT_FALSE(renormalised_gradient<D>(sums, 0.05));
  for (int k = M; k < N; k++) EXPECT_EQ(sums[k], 0.0) << k;
}
