// Cubic spline kernel: normalisation by quadrature and derivatives against finite differences.
#include "soil_kernel.h"

#include "gtest/gtest.h"

#include <cmath>

using SPHSoil::CubicSpline;

namespace {
constexpr double PI = 3.14159265358979323846;

// integral of W over R^D using the radial form: 2 pi r W dr (2D), 4 pi r^2 W dr (3D),
// composite Simpson on [0, 2h] split at the kink q = 1.
double radial_integral(int dimension, double h, int n)
{
  auto integrand = [&](double r) {
    const double w = CubicSpline::value(dimension, r, h);
    return dimension == 2 ? 2.0 * PI * r * w : 4.0 * PI * r * r * w;
  };
  double total = 0.0;
  for (int piece = 0; piece < 2; piece++) {
    const double a = piece * h, b = (piece + 1) * h, dr = (b - a) / n;
    double s = integrand(a) + integrand(b);
    for (int k = 1; k < n; k++) s += (k % 2 ? 4.0 : 2.0) * integrand(a + k * dr);
    total += s * dr / 3.0;
  }
  return total;
}
}    // namespace

TEST(CubicSpline, NormalisedIn2DAnd3D)
{
  for (double h : {0.001, 0.37, 2.5}) {
    EXPECT_NEAR(radial_integral(2, h, 2000), 1.0, 1.0e-6) << "2D, h = " << h;
    EXPECT_NEAR(radial_integral(3, h, 2000), 1.0, 1.0e-6) << "3D, h = " << h;
  }
}

TEST(CubicSpline, NormalisedOnA2DCartesianGrid)
{
  // a direct 2D quadrature (not using radial symmetry): midpoint rule on a fine grid
  const double h = 1.0;
  const int n = 800;
  const double dx = 4.0 * h / n;
  double sum = 0.0;
  for (int i = 0; i < n; i++)
    for (int j = 0; j < n; j++) {
      const double x = -2.0 * h + (i + 0.5) * dx, y = -2.0 * h + (j + 0.5) * dx;
      sum += CubicSpline::value(2, std::sqrt(x * x + y * y), h) * dx * dx;
    }
  EXPECT_NEAR(sum, 1.0, 1.0e-5);
}

TEST(CubicSpline, CompactSupportAndContinuity)
{
  for (int dim : {2, 3}) {
    EXPECT_EQ(CubicSpline::value(dim, 2.0, 1.0), 0.0);
    EXPECT_EQ(CubicSpline::value(dim, 2.5, 1.0), 0.0);
    EXPECT_EQ(CubicSpline::derivative(dim, 2.0, 1.0), 0.0);
    // continuous value and first derivative at q = 1
    EXPECT_NEAR(CubicSpline::value(dim, 1.0 - 1e-12, 1.0), CubicSpline::value(dim, 1.0, 1.0), 1e-10);
    EXPECT_NEAR(CubicSpline::derivative(dim, 1.0 - 1e-12, 1.0),
                CubicSpline::derivative(dim, 1.0, 1.0), 1e-10);
  }
  EXPECT_NEAR(CubicSpline::value(2, 0.0, 1.0), 10.0 / (7.0 * PI), 1e-15);
  EXPECT_NEAR(CubicSpline::value(3, 0.0, 1.0), 1.0 / PI, 1e-15);
}

TEST(CubicSpline, DerivativesMatchFiniteDifferences)
{
  const double h = 0.3, eps = 1.0e-6;
  for (int dim : {2, 3}) {
    for (double q = 0.05; q < 2.0; q += 0.0731) {
      const double r = q * h;
      const double fd = (CubicSpline::value(dim, r + eps, h) - CubicSpline::value(dim, r - eps, h)) / (2 * eps);
      const double scale = std::fabs(CubicSpline::derivative(dim, 0.5 * h, h));
      EXPECT_NEAR(CubicSpline::derivative(dim, r, h), fd, 1e-6 * scale) << "dim " << dim << " q " << q;
      EXPECT_NEAR(CubicSpline::gradient_factor(dim, r, h) * r, CubicSpline::derivative(dim, r, h),
                  1e-12 * scale);
      const double fd2 = (CubicSpline::derivative(dim, r + eps, h) - CubicSpline::derivative(dim, r - eps, h)) / (2 * eps);
      const double scale2 = std::fabs(CubicSpline::second_derivative(dim, 0.0, h));
      if (std::fabs(q - 1.0) > 1e-3)
        EXPECT_NEAR(CubicSpline::second_derivative(dim, r, h), fd2, 1e-5 * scale2) << "dim " << dim << " q " << q;
    }
  }
}

TEST(CubicSpline, GradientOfAnOffsetKernelMatchesFiniteDifferencesIn3D)
{
  // grad W(x) = x * gradient_factor(|x|), checked component-wise
  const double h = 0.7, eps = 1e-6;
  const double x[3] = {0.31, -0.52, 0.44};
  auto w = [&](double a, double b, double c) { return CubicSpline::value(3, std::sqrt(a * a + b * b + c * c), h); };
  const double r = std::sqrt(x[0] * x[0] + x[1] * x[1] + x[2] * x[2]);
  const double g = CubicSpline::gradient_factor(3, r, h);
  const double fd[3] = {(w(x[0] + eps, x[1], x[2]) - w(x[0] - eps, x[1], x[2])) / (2 * eps),
                        (w(x[0], x[1] + eps, x[2]) - w(x[0], x[1] - eps, x[2])) / (2 * eps),
                        (w(x[0], x[1], x[2] + eps) - w(x[0], x[1], x[2] - eps)) / (2 * eps)};
  for (int k = 0; k < 3; k++) EXPECT_NEAR(g * x[k], fd[k], 1e-7);
}

TEST(CubicSpline, SecondDerivativeChangesSignAtTwoThirds)
{
  for (int dim : {2, 3}) {
    EXPECT_LT(CubicSpline::second_derivative(dim, 0.66, 1.0), 0.0);
    EXPECT_GT(CubicSpline::second_derivative(dim, 0.67, 1.0), 0.0);
    EXPECT_NEAR(CubicSpline::second_derivative(dim, 2.0 / 3.0, 1.0), 0.0, 1e-14);
  }
}

TEST(CubicSpline, GradientFactorFromInverseAgrees)
{
  for (double h : {0.0012, 0.7, 3.0})
    for (double q = 0.01; q < 2.2; q += 0.037) {
      const double r = q * h;
      EXPECT_NEAR(CubicSpline::gradient_factor_from_inverse<2>(r, 1.0 / h, h / r),
                  CubicSpline::gradient_factor(2, r, h), 1e-13 * std::fabs(CubicSpline::gradient_factor(2, 0.0, h)));
      EXPECT_NEAR(CubicSpline::gradient_factor_from_inverse<3>(r, 1.0 / h, h / r),
                  CubicSpline::gradient_factor(3, r, h), 1e-13 * std::fabs(CubicSpline::gradient_factor(3, 0.0, h)));
    }
}
