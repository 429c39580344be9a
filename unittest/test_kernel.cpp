// The kernels (cubic spline, Wendland C2), every one by the same tests: normalisation by
// quadrature, compact support and continuity, derivatives against finite differences, the
// inflection point that the refinement's instability conditions use, the pair loop's form of
// the gradient; and the choice by keyword.
#include "soil_gradient_correction.h"
#include "soil_kernels.h"

#include "gtest/gtest.h"

#include <cmath>

using namespace SPHSoil;

namespace {
constexpr double PI = 3.14159265358979323846;

template <class Kernel> class EachKernel : public ::testing::Test {};
using KernelTypes = ::testing::Types<CubicSpline, WendlandC2>;
struct KernelNames {
  template <class Kernel> static std::string GetName(int) { return Kernel::NAME; }
};
TYPED_TEST_SUITE(EachKernel, KernelTypes, KernelNames);

// integral of W over R^D using the radial form: 2 pi r W dr (2D), 4 pi r^2 W dr (3D),
// composite Simpson on [0, 2h] split at q = 1 (the cubic spline's kink)
template <class Kernel> double radial_integral(int dimension, double h, int n)
{
  auto integrand = [&](double r) {
    const double w = Kernel::value(dimension, r, h);
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

TYPED_TEST(EachKernel, NormalisedIn2DAnd3D)
{
  for (double h : {0.001, 0.37, 2.5}) {
    EXPECT_NEAR(radial_integral<TypeParam>(2, h, 2000), 1.0, 1.0e-6) << "2D, h = " << h;
    EXPECT_NEAR(radial_integral<TypeParam>(3, h, 2000), 1.0, 1.0e-6) << "3D, h = " << h;
  }
}

TYPED_TEST(EachKernel, NormalisedOnA2DCartesianGrid)
{
  // a direct 2D quadrature (not using radial symmetry): midpoint rule on a fine grid
  const double h = 1.0;
  const int n = 800;
  const double dx = 4.0 * h / n;
  double sum = 0.0;
  for (int i = 0; i < n; i++)
    for (int j = 0; j < n; j++) {
      const double x = -2.0 * h + (i + 0.5) * dx, y = -2.0 * h + (j + 0.5) * dx;
      sum += TypeParam::value(2, std::sqrt(x * x + y * y), h) * dx * dx;
    }
  EXPECT_NEAR(sum, 1.0, 1.0e-5);
}

TYPED_TEST(EachKernel, CompactSupportAndContinuity)
{
  const double support = TypeParam::SUPPORT;
  for (int dim : {2, 3}) {
    EXPECT_EQ(TypeParam::value(dim, support, 1.0), 0.0);
    EXPECT_EQ(TypeParam::value(dim, support + 0.5, 1.0), 0.0);
    EXPECT_EQ(TypeParam::derivative(dim, support, 1.0), 0.0);
    EXPECT_NEAR(TypeParam::value(dim, support - 1e-9, 1.0), 0.0, 1e-12);
    // continuous value and first derivative at q = 1
    EXPECT_NEAR(TypeParam::value(dim, 1.0 - 1e-12, 1.0), TypeParam::value(dim, 1.0, 1.0), 1e-10);
    EXPECT_NEAR(TypeParam::derivative(dim, 1.0 - 1e-12, 1.0), TypeParam::derivative(dim, 1.0, 1.0), 1e-10);
  }
}

TEST(Kernels, CentralValues)
{
  EXPECT_NEAR(CubicSpline::value(2, 0.0, 1.0), 10.0 / (7.0 * PI), 1e-15);
  EXPECT_NEAR(CubicSpline::value(3, 0.0, 1.0), 1.0 / PI, 1e-15);
  EXPECT_NEAR(WendlandC2::value(2, 0.0, 1.0), 7.0 / (4.0 * PI), 1e-15);
  EXPECT_NEAR(WendlandC2::value(3, 0.0, 1.0), 21.0 / (16.0 * PI), 1e-15);
}

TYPED_TEST(EachKernel, DerivativesMatchFiniteDifferences)
{
  const double h = 0.3, eps = 1.0e-6;
  for (int dim : {2, 3}) {
    for (double q = 0.05; q < TypeParam::SUPPORT; q += 0.0731) {
      const double r = q * h;
      const double fd = (TypeParam::value(dim, r + eps, h) - TypeParam::value(dim, r - eps, h)) / (2 * eps);
      const double scale = std::fabs(TypeParam::derivative(dim, 0.5 * h, h));
      EXPECT_NEAR(TypeParam::derivative(dim, r, h), fd, 1e-6 * scale) << "dim " << dim << " q " << q;
      EXPECT_NEAR(TypeParam::gradient_factor(dim, r, h) * r, TypeParam::derivative(dim, r, h), 1e-12 * scale);
      const double fd2 = (TypeParam::derivative(dim, r + eps, h) - TypeParam::derivative(dim, r - eps, h)) / (2 * eps);
      const double scale2 = std::fabs(TypeParam::second_derivative(dim, 0.0, h));
      if (std::fabs(q - 1.0) > 1e-3)
        EXPECT_NEAR(TypeParam::second_derivative(dim, r, h), fd2, 1e-5 * scale2) << "dim " << dim << " q " << q;
    }
  }
}

TYPED_TEST(EachKernel, GradientOfAnOffsetKernelMatchesFiniteDifferencesIn3D)
{
  // grad W(x) = x * gradient_factor(|x|), checked component-wise
  const double h = 0.7, eps = 1e-6;
  const double x[3] = {0.31, -0.52, 0.44};
  auto w = [&](double a, double b, double c) { return TypeParam::value(3, std::sqrt(a * a + b * b + c * c), h); };
  const double r = std::sqrt(x[0] * x[0] + x[1] * x[1] + x[2] * x[2]);
  const double g = TypeParam::gradient_factor(3, r, h);
  const double fd[3] = {(w(x[0] + eps, x[1], x[2]) - w(x[0] - eps, x[1], x[2])) / (2 * eps),
                        (w(x[0], x[1] + eps, x[2]) - w(x[0], x[1] - eps, x[2])) / (2 * eps),
                        (w(x[0], x[1], x[2] + eps) - w(x[0], x[1], x[2] - eps)) / (2 * eps)};
  for (int k = 0; k < 3; k++) EXPECT_NEAR(g * x[k], fd[k], 1e-7);
}

TYPED_TEST(EachKernel, SecondDerivativeChangesSignAtTheInflection)
{
  const double q = TypeParam::INFLECTION;
  for (int dim : {2, 3}) {
    EXPECT_LT(TypeParam::second_derivative(dim, q - 0.01, 1.0), 0.0);
    EXPECT_GT(TypeParam::second_derivative(dim, q + 0.01, 1.0), 0.0);
    EXPECT_NEAR(TypeParam::second_derivative(dim, q, 1.0), 0.0, 1e-14);
  }
}

TYPED_TEST(EachKernel, GradientFactorInsideTheSupportAgrees)
{
  for (double h : {0.0012, 0.7, 3.0})
    for (double q = 0.01; q < 2.0; q += 0.037) {
      const double r = q * h;
      EXPECT_NEAR(TypeParam::template gradient_factor_inside<2>(r, 1.0 / h, h / r),
                  TypeParam::gradient_factor(2, r, h), 1e-13 * std::fabs(TypeParam::gradient_factor(2, 0.0, h)));
      EXPECT_NEAR(TypeParam::template gradient_factor_inside<3>(r, 1.0 / h, h / r),
                  TypeParam::gradient_factor(3, r, h), 1e-13 * std::fabs(TypeParam::gradient_factor(3, 0.0, h)));
    }
}

TYPED_TEST(EachKernel, ChosenByItsName)
{
  KernelKind kind;
  ASSERT_TRUE(kernel_kind(TypeParam::NAME, kind));
  EXPECT_STREQ(kernel_name(kind), TypeParam::NAME);
  EXPECT_EQ(kernel_support(kind), double(TypeParam::SUPPORT));    // (a value: C++11 odr)
  EXPECT_EQ(kernel_inflection(kind), double(TypeParam::INFLECTION));
  EXPECT_EQ(kernel_value(kind, 2, 0.3, 0.7), TypeParam::value(2, 0.3, 0.7));
  EXPECT_EQ(kernel_gradient_factor(kind, 3, 0.3, 0.7), TypeParam::gradient_factor(3, 0.3, 0.7));
}

TEST(KernelRegistry, UnknownNameIsRefused)
{
  KernelKind kind;
  EXPECT_FALSE(kernel_kind("gaussian", kind));
  EXPECT_EQ(kernel_names(), "cubic, wendland2");
}

// A new kernel is its header and one name in the registry's list: a registry of the package's
// kernels and a dummy one knows the dummy's name, finds it and dispatches to it, with nothing
// else written for it.
struct DummyKernel {
  static constexpr const char *NAME = "dummy";
  static constexpr double SUPPORT = 3.0;
};
struct SupportOf {
  template <class Kernel> double operator()() const { return Kernel::SUPPORT; }
};

TEST(KernelRegistry, ARegisteredDummyKernelIsKnownByItsNameAndDispatchedTo)
{
  using WithDummy = KernelRegistry<CubicSpline, WendlandC2, DummyKernel>;
  EXPECT_EQ(WithDummy::COUNT, 3);
  EXPECT_EQ(WithDummy::names(), "cubic, wendland2, dummy");
  ASSERT_EQ(WithDummy::find("dummy"), 2);
  EXPECT_EQ(WithDummy::find("wendland2"), 1);
  EXPECT_EQ(WithDummy::find("gaussian"), -1);
  EXPECT_EQ(WithDummy::dispatch(2, SupportOf()), 3.0);
  EXPECT_EQ(WithDummy::dispatch(1, SupportOf()), double(WendlandC2::SUPPORT));
  // the package's own registry is the same template over its list
  EXPECT_EQ(Kernels::COUNT, 2);
  EXPECT_EQ(Kernels::dispatch(0, SupportOf()), double(CubicSpline::SUPPORT));
}

// The first moment C = -(1/D) sum_j V_j factor r^2 of the cubic spline on a square lattice at
// h = 1.2 d: 0.9908 (doc/theory.rst 2.6 and 2.7), and the correction: 1 / C for a full kernel,
// none for a cut one (a free surface), linear in between, continuous at both ends
TEST(GradientCorrection, FirstMomentOfALatticeAndTheFade)
{
  const double d = 0.004, h = 1.2 * d;
  double sum = 0.0;
  for (int i = -4; i <= 4; i++)
    for (int j = -4; j <= 4; j++) {
      if (i == 0 && j == 0) continue;
      const double r = d * std::sqrt((double) (i * i + j * j));
      if (r >= 2.0 * h) continue;
      const double factor = SPHSoil::CubicSpline::gradient_factor(2, r, h);
      sum += SPHSoil::first_moment_term(d * d, factor, r * r);
    }
  const double moment = sum / 2;
  EXPECT_NEAR(moment, 0.9908, 5e-5);
  EXPECT_DOUBLE_EQ(SPHSoil::gradient_correction(moment), 1.0 / moment);
  EXPECT_DOUBLE_EQ(SPHSoil::gradient_correction(1.05), 1.0 / 1.05);
  EXPECT_EQ(SPHSoil::gradient_correction(0.5), 1.0);
  EXPECT_EQ(SPHSoil::gradient_correction(0.8), 1.0);
  EXPECT_NEAR(SPHSoil::gradient_correction(0.9 - 1e-12), 1.0 / 0.9, 1e-10);
  EXPECT_DOUBLE_EQ(SPHSoil::gradient_correction(0.85), 1.0 + 0.5 * (1.0 / 0.85 - 1.0));
}

// gradient_correction full: the first-moment tensor recovers a linear velocity field's gradient
// exactly on a free surface, where the scalar moment cannot (the kernel is cut along the
// normal only), and next to a smooth wall whose images move with the particle along the wall
namespace {
struct SurfaceSums {
  double g[4] = {0, 0, 0, 0}, full[6] = {0, 0, 0, 0, 0, 0}, image[6] = {0, 0, 0, 0, 0, 0};
  double normal[3] = {0, 0, 0}, moment = 0.0;
};

// particle i at the origin, the top row of a square lattice (partners at rows <= 0); with
// `wall`, a smooth wall half a spacing above it whose images fill rows >= 1 and carry i's
// tangential velocity and the field's normal one
SurfaceSums surface_sums(const double G[2][2], bool wall)
{
  const double d = 0.004, h = 1.2 * d, n[3] = {0.0, -1.0, 0.0};
  SurfaceSums s;
  for (int i = -4; i <= 4; i++)
    for (int j = -4; j <= 4; j++) {
      if ((i == 0 && j == 0) || (j > 0 && !wall)) continue;
      const double xj[2] = {d * i, d * j};
      const double r = std::sqrt(xj[0] * xj[0] + xj[1] * xj[1]);
      if (r >= 2.0 * h) continue;
      const double factor = SPHSoil::CubicSpline::gradient_factor(2, r, h);
      const double dx[3] = {-xj[0], -xj[1], 0.0};    // x_i - x_j
      double dv[2];                                  // v_j - v_i
      for (int a = 0; a < 2; a++) dv[a] = G[a][0] * xj[0] + G[a][1] * xj[1];
      const bool image = j > 0;
      if (image) dv[0] = 0.0;    // (the wall's normal is y: the image differs only in v_y)
      for (int a = 0; a < 2; a++)
        for (int b = 0; b < 2; b++) s.g[a * 2 + b] += d * d * dv[a] * factor * dx[b];
      SPHSoil::first_moment_tensor_term(d * d, factor, dx, s.full);
      const double share = SPHSoil::first_moment_term(d * d, factor, r * r);
      s.moment += share / 2;
      if (image) {
        SPHSoil::first_moment_tensor_term(d * d, factor, dx, s.image);
        for (int a = 0; a < 3; a++) s.normal[a] += share * n[a];
      }
    }
  const double norm = std::sqrt(s.normal[0] * s.normal[0] + s.normal[1] * s.normal[1]);
  for (int a = 0; a < 3; a++) s.normal[a] = norm > 0.0 ? s.normal[a] / norm : 0.0;
  return s;
}
}    // namespace

TEST(Kernel, FullGradientCorrectionIsExactOnAFreeSurfaceAndAtASmoothWall)
{
  const double G[2][2] = {{0.3, -1.1}, {0.7, -0.45}};
  for (bool wall : {false, true}) {
    SCOPED_TRACE(wall ? "smooth wall" : "free surface");
    const SurfaceSums s = surface_sums(G, wall);
    double plain[6], l_full[6], l_plain[6], out[4];
    for (int k = 0; k < 6; k++) plain[k] = s.full[k] - s.image[k];
    SPHSoil::velocity_gradient_correction<2>(s.full, 1.0, l_full);
    SPHSoil::velocity_gradient_correction<2>(plain, 1.0, l_plain);
    SPHSoil::corrected_velocity_gradient<2>(s.g, s.normal, l_full, l_plain, out);
    for (int a = 0; a < 2; a++)
      for (int b = 0; b < 2; b++) EXPECT_NEAR(out[a * 2 + b], G[a][b], 1e-12) << a << b;
    if (!wall) {
      // the cut kernel: anisotropic, and the scalar moment's correction is not the cure
      EXPECT_NEAR(s.full[0], 0.7860, 5e-5);    // along the surface
      EXPECT_NEAR(s.full[1], 0.4954, 5e-5);    // along the normal
      EXPECT_NEAR(s.full[3], 0.0, 1e-15);
      EXPECT_NEAR(s.moment, 0.6407, 5e-5);
      EXPECT_GT(std::fabs(s.g[0] * SPHSoil::gradient_correction(s.moment) - G[0][0]), 0.05);
    } else {
      // plain sums with the images as partners (the scalar correction's view) miss the
      // tangential stretching next to the wall
      double plain_out[4];
      const double none[3] = {0.0, 0.0, 0.0};
      SPHSoil::corrected_velocity_gradient<2>(s.g, none, l_full, l_full, plain_out);
      EXPECT_GT(std::fabs(plain_out[0] - G[0][0]), 0.05);
    }
  }
  // a kernel too sparse for the tensor keeps the scalar factor
  const double flat[6] = {0.9, 0.05, 0.0, 0.0, 0.0, 0.0};
  double l[6];
  SPHSoil::velocity_gradient_correction<2>(flat, 1.25, l);
  EXPECT_EQ(l[0], 1.25);
  EXPECT_EQ(l[1], 1.25);
  EXPECT_EQ(l[3], 0.0);
  // 3D: the inverse of a general symmetric tensor
  const double m3[6] = {1.1, 0.9, 1.3, 0.1, -0.2, 0.05};
  double l3[6];
  SPHSoil::velocity_gradient_correction<3>(m3, 1.0, l3);
  const double M[3][3] = {{m3[0], m3[3], m3[4]}, {m3[3], m3[1], m3[5]}, {m3[4], m3[5], m3[2]}};
  const double L[3][3] = {{l3[0], l3[3], l3[4]}, {l3[3], l3[1], l3[5]}, {l3[4], l3[5], l3[2]}};
  for (int a = 0; a < 3; a++)
    for (int b = 0; b < 3; b++) {
      double p = 0.0;
      for (int c = 0; c < 3; c++) p += M[a][c] * L[c][b];
      EXPECT_NEAR(p, a == b ? 1.0 : 0.0, 1e-12);
    }
}
