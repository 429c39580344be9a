// Drucker-Prager soil model (doc/theory.rst section 3): Hooke's law inside the surface, objectivity of the
// Jaumann terms, the flow rule and consistency on the surface, Bui's return mapping, simple shear.
#include "soil_drucker_prager.h"
#include "soil_material.h"
#include "soil_models.h"
#include "soil_model_testing.h"

#include "gtest/gtest.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <string>

using namespace SPHSoil;

namespace {

constexpr double PI = 3.14159265358979323846;
typedef double Matrix[3][3];

// the associated fit unless told: it accepts every dilatancy angle (the exact fit has its own tests)
DruckerPragerParameters soil(double phi, double psi, double c, double bulk = 1.5e6, double nu = 0.3,
                             DruckerPragerFit fit = DruckerPragerFit::associated)
{
  return DruckerPragerParameters(SPHSoilTesting::frictional(phi, psi, c, bulk, nu), fit);
}

void to_matrix(const double v[6], Matrix m)
{
  m[0][0] = v[0]; m[1][1] = v[1]; m[2][2] = v[2];
  m[0][1] = m[1][0] = v[3];
  m[0][2] = m[2][0] = v[4];
  m[1][2] = m[2][1] = v[5];
}

// full contraction a^ab b^ab of two symmetric Voigt tensors
double contract(const double a[6], const double b[6])
{
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2] + 2.0 * (a[3] * b[3] + a[4] * b[4] + a[5] * b[5]);
}

double norm(const double a[6]) { return std::sqrt(contract(a, a)); }

double max_abs(const double a[6])
{
  double m = 0.0;
  for (int k = 0; k < 6; k++) m = std::max(m, std::fabs(a[k]));
  return m;
}

// Hooke's law written independently of the model: 2G edev + K tr(epsdot) delta
void hooke(double bulk, double shear, const double strain_rate[6], double rate[6])
{
  const double trace = strain_rate[0] + strain_rate[1] + strain_rate[2];
  for (int k = 0; k < 6; k++) {
    const double deviatoric = strain_rate[k] - (k < 3 ? trace / 3.0 : 0.0);
    rate[k] = 2.0 * shear * deviatoric + (k < 3 ? bulk * trace : 0.0);
  }
}

// W sigma - sigma W with W^ab = omega^ab, full matrices
void jaumann_reference(const double stress[6], const double spin[3], double rate[6])
{
  Matrix s, w = {{0.0, spin[0], spin[1]}, {-spin[0], 0.0, spin[2]}, {-spin[1], -spin[2], 0.0}}, r;
  to_matrix(stress, s);
  for (int a = 0; a < 3; a++)
    for (int b = 0; b < 3; b++) {
      r[a][b] = 0.0;
      for (int g = 0; g < 3; g++) r[a][b] += w[a][g] * s[g][b] - s[a][g] * w[g][b];
    }
  rate[0] = r[0][0]; rate[1] = r[1][1]; rate[2] = r[2][2];
  rate[3] = r[0][1]; rate[4] = r[0][2]; rate[5] = r[1][2];
}

// gradient of f = sqrt(J2) + alpha I1 - k_c: s/(2 sqrt(J2)) + alpha delta
void yield_gradient(const DruckerPrager &model, const double stress[6], double gradient[6])
{
  const double mean = mean_stress(stress), root = sqrt_j2(stress);
  for (int k = 0; k < 6; k++) {
    const double deviator = stress[k] - (k < 3 ? mean : 0.0);
    gradient[k] = deviator / (2.0 * root) + (k < 3 ? model.alpha_phi() : 0.0);
  }
}

// random symmetric tensor with components uniform in [-scale, scale]
void random_tensor(std::mt19937 &rng, double scale, double t[6])
{
  std::uniform_real_distribution<double> u(-scale, scale);
  for (int k = 0; k < 6; k++) t[k] = u(rng);
}

// a stress exactly on the yield surface: random deviator direction, compressive I1
void random_stress_on_surface(std::mt19937 &rng, const DruckerPrager &model, double stress[6])
{
  std::uniform_real_distribution<double> pressure(1.0e4, 1.0e6);
  random_tensor(rng, 1.0, stress);
  const double mean = mean_stress(stress);
  for (int k = 0; k < 3; k++) stress[k] -= mean;
  const double i1 = -3.0 * pressure(rng);
  const double factor = (model.k_c() - model.alpha_phi() * i1) / sqrt_j2(stress);
  for (int k = 0; k < 6; k++) stress[k] *= factor;
  for (int k = 0; k < 3; k++) stress[k] += i1 / 3.0;
}

// scale of the terms of f, for relative tolerances
double yield_scale(const DruckerPrager &model, const double stress[6])
{
  return sqrt_j2(stress) + model.alpha_phi() * std::fabs(first_invariant(stress)) + model.k_c();
}

// RK4 of d(sigma)/dt = model rate at fixed strain rate and spin
void rk4_step(const DruckerPrager &model, const double strain_rate[6], const double spin[3],
              double dt, double stress[6])
{
  double k1[6], k2[6], k3[6], k4[6], trial[6];
  model.stress_rate(stress, strain_rate, spin, k1);
  for (int k = 0; k < 6; k++) trial[k] = stress[k] + 0.5 * dt * k1[k];
  model.stress_rate(trial, strain_rate, spin, k2);
  for (int k = 0; k < 6; k++) trial[k] = stress[k] + 0.5 * dt * k2[k];
  model.stress_rate(trial, strain_rate, spin, k3);
  for (int k = 0; k < 6; k++) trial[k] = stress[k] + dt * k3[k];
  model.stress_rate(trial, strain_rate, spin, k4);
  for (int k = 0; k < 6; k++) stress[k] += dt / 6.0 * (k1[k] + 2.0 * k2[k] + 2.0 * k3[k] + k4[k]);
}

}    // namespace

/* ---------------------------------------------------------------------- */

TEST(SoilInvariants, PressureSqrtJ2AndStrainMeasure)
{
  const double stress[6] = {-3.0, -6.0, -9.0, 0.0, 0.0, 0.0};
  EXPECT_DOUBLE_EQ(first_invariant(stress), -18.0);
  EXPECT_DOUBLE_EQ(mean_stress(stress), -6.0);
  EXPECT_DOUBLE_EQ(pressure(stress), 6.0);
  EXPECT_DOUBLE_EQ(sqrt_j2(stress), 3.0);    // s = (3, 0, -3): J2 = 9
  // pure shear: sqrt(J2) = tau, so each shear component counts twice
  for (int k = 3; k < 6; k++) {
    double shear[6] = {-5.0, -5.0, -5.0, 0.0, 0.0, 0.0};
    shear[k] = 7.0;
    EXPECT_DOUBLE_EQ(sqrt_j2(shear), 7.0) << "component " << k;
  }
  const double strain[6] = {1.0, 2.0, 3.0, 4.0, 5.0, 6.0};
  EXPECT_DOUBLE_EQ(strain_measure(strain), 14.0);
  // equivalent shear strain: gamma in simple shear (eps_xy = gamma / 2) in every plane, 2 e in
  // pure shear (principal strains e, -e: simple shear seen at 45 degrees), none in compaction
  for (int k = 3; k < 6; k++) {
    double simple[6] = {0.0, 0.0, 0.0, 0.0, 0.0, 0.0};
    simple[k] = 0.15;
    EXPECT_DOUBLE_EQ(shear_strain(simple), 0.3) << "component " << k;
  }
  const double pure[6] = {0.2, -0.2, 0.0, 0.0, 0.0, 0.0};
  EXPECT_DOUBLE_EQ(shear_strain(pure), 0.4);
  const double compaction[6] = {-0.1, -0.1, -0.1, 0.0, 0.0, 0.0};
  EXPECT_NEAR(shear_strain(compaction), 0.0, 1e-15);
}

TEST(DruckerPrager, ConstantsModuliAndWaveSpeed)
{
  // aluminium bars of Bui 2008: K = 0.7 MPa, nu = 0.3 <=> E = 0.84 MPa
  const DruckerPrager bars(soil(19.8, 0.0, 0.0, 0.7e6, 0.3));
  const double shear = 0.84e6 / (2.0 * 1.3);
  EXPECT_NEAR(bars.shear_modulus(), shear, 1.0e-9 * shear);
  const DruckerPrager from_e(FrictionalParameters::from_young_modulus(0.84e6, 0.3, 19.8, 0.0, 0.0));
  EXPECT_NEAR(from_e.bulk_modulus(), 0.7e6, 1.0e-9 * 0.7e6);
  EXPECT_NEAR(from_e.shear_modulus(), shear, 1.0e-9 * shear);
  EXPECT_NEAR(bars.wave_speed(2650.0), std::sqrt((0.7e6 + 4.0 * shear / 3.0) / 2650.0), 1.0e-12);

  // phi = 30: tan = 1/sqrt(3), sqrt(9 + 12/3) = sqrt(13)
  const DruckerPrager cohesive(soil(30.0, 10.0, 2.0e4));
  EXPECT_NEAR(cohesive.alpha_phi(), 1.0 / std::sqrt(3.0 * 13.0), 1.0e-15);
  EXPECT_NEAR(cohesive.k_c(), 3.0 * 2.0e4 / std::sqrt(13.0), 1.0e-9);
  // phi = 0: alpha = 0, k_c = c (plane-strain Tresca/von Mises match)
  const DruckerPrager frictionless(soil(0.0, 0.0, 5.0e3));
  EXPECT_EQ(frictionless.alpha_phi(), 0.0);
  EXPECT_NEAR(frictionless.k_c(), 5.0e3, 1.0e-9);
}

// the plane-strain fit for psi = 0: alpha = sin(phi)/3, k_c = c cos(phi); equal at phi = 0
TEST(DruckerPrager, NonassociatedFitConstants)
{
  DruckerPragerParameters p = soil(30.0, 0.0, 2.0e4);
  p.fit = DruckerPragerFit::nonassociated;
  const DruckerPrager model(p);
  EXPECT_NEAR(model.alpha_phi(), 0.5 / 3.0, 1.0e-15);
  EXPECT_NEAR(model.k_c(), 2.0e4 * std::sqrt(3.0) / 2.0, 1.0e-9);
  // Bui's aluminium bars: 2% stronger than the associated fit
  DruckerPragerParameters bars = soil(19.8, 0.0, 0.0, 0.7e6);
  const double associated = DruckerPrager(bars).alpha_phi();
  bars.fit = DruckerPragerFit::nonassociated;
  EXPECT_NEAR(DruckerPrager(bars).alpha_phi() / associated, 1.0189, 1.0e-4);
  DruckerPragerParameters frictionless = soil(0.0, 0.0, 5.0e3);
  frictionless.fit = DruckerPragerFit::nonassociated;
  EXPECT_EQ(DruckerPrager(frictionless).alpha_phi(), 0.0);
  EXPECT_NEAR(DruckerPrager(frictionless).k_c(), 5.0e3, 1.0e-9);
}

// Plane-strain simple shear from an isotropic stress keeps s_zz = 0 (no dilatancy, no
// volume change), so sqrt(J2) is the in-plane maximum shear stress. On the surface the
// nonassociated fit then reproduces Mohr-Coulomb exactly, tau = c cos(phi) - sigma_m sin(phi);
// the associated fit is weaker by 3 alpha_phi against sin(phi).
TEST(DruckerPrager, NonassociatedFitIsMohrCoulombInPlaneStrainWithoutDilatancy)
{
  const double p0 = 1.0e5, phi = 30.0, c = 5.0e3;
  double strength[2];
  for (int k = 0; k < 2; k++) {
    DruckerPragerParameters p = soil(phi, 0.0, c);
    p.fit = k ? DruckerPragerFit::nonassociated : DruckerPragerFit::associated;
    const DruckerPrager model(p);
    double stress[6];
    SPHSoilTesting::simple_shear(model, p0, stress);
    ASSERT_TRUE(model.on_yield_surface(stress));
    const double mean = 0.5 * (stress[0] + stress[1]);
    EXPECT_NEAR(stress[2], mean, 1.0e-9 * p0);    // s_zz = 0
    strength[k] = SPHSoilTesting::in_plane_shear(stress) / SPHSoilTesting::mohr_coulomb_strength(c, phi, stress);
  }
  EXPECT_NEAR(strength[1], 1.0, 1.0e-9);
  EXPECT_NEAR(strength[0], 0.96, 0.01);    // 3 tan(phi)/sqrt(9 + 12 tan^2 phi) / sin(phi) = 0.961
}

TEST(DruckerPrager, CheckNamesTheParameterAndItsRange)
{
  EXPECT_EQ(DruckerPrager::check(soil(30.0, 0.0, 0.0)), "");
  EXPECT_EQ(DruckerPrager::check(soil(0.0, 0.0, 1.0e4, 1.0e6, -0.99)), "");

  auto expect_message = [](const std::string &message, const std::string &name, const std::string &range) {
    EXPECT_NE(message.find(name), std::string::npos) << message;
    EXPECT_NE(message.find(range), std::string::npos) << message;
  };
  for (double nu : {0.5, 0.7, -1.0, std::nan("")})
    expect_message(DruckerPrager::check(soil(30.0, 0.0, 0.0, 1.0e6, nu)), "Poisson ratio", "(-1, 0.5)");
  for (double phi : {90.0, 120.0, -1.0, std::nan("")})
    expect_message(DruckerPrager::check(soil(phi, 0.0, 0.0)), "friction angle", "[0, 90)");
  for (double bulk : {0.0, -1.0e6, HUGE_VAL, std::nan("")})
    expect_message(DruckerPrager::check(soil(30.0, 0.0, 0.0, bulk)), "bulk modulus", "> 0");
  expect_message(DruckerPrager::check(soil(30.0, 31.0, 0.0)), "dilatancy angle", "[0, phi = 30]");
  expect_message(DruckerPrager::check(soil(30.0, -1.0, 0.0)), "dilatancy angle", "[0, phi = 30]");
  expect_message(DruckerPrager::check(soil(30.0, 0.0, -1.0)), "cohesion", ">= 0");

  EXPECT_EQ(FrictionalParameters::check_young_modulus(0.84e6, 0.3, 19.8, 0.0, 0.0), "");
  expect_message(FrictionalParameters::check_young_modulus(0.0, 0.3, 19.8, 0.0, 0.0), "Young's modulus", "> 0");
  // a bad nu is reported as such, not as the K it would produce
  expect_message(FrictionalParameters::check_young_modulus(1.0e6, 0.6, 19.8, 0.0, 0.0), "Poisson ratio", "(-1, 0.5)");
  expect_message(FrictionalParameters::check_young_modulus(1.0e6, 0.3, 19.8, 25.0, 0.0), "dilatancy angle", "[0, phi");

  EXPECT_THROW(DruckerPrager model(soil(30.0, 0.0, 0.0, 1.0e6, 0.5)), std::invalid_argument);
}

TEST(DruckerPrager, RegistryBuildsItFromTheWordsOfAMaterialLine)
{
  std::string error;
  const auto model = make_model("drucker_prager", {"1.5e6", "0.3", "45", "0", "0"}, error);
  ASSERT_TRUE(model) << error;
  EXPECT_STREQ(model->keyword(), "drucker_prager");
  const double shear = 3.0 * 1.5e6 * 0.4 / 2.6;
  EXPECT_NEAR(model->wave_speed(1850.0), std::sqrt((1.5e6 + 4.0 * shear / 3.0) / 1850.0), 1.0e-12);
  const double inside[6] = {-3.0e4, -3.0e4, -3.0e4, 0.0, 0.0, 0.0};
  EXPECT_LT(model->yield_function(inside), 0.0);
  const auto *dp = dynamic_cast<const DruckerPrager *>(model.get());
  ASSERT_TRUE(dp);
  EXPECT_TRUE(dp->parameters().fit == DruckerPragerFit::exact);

  const auto associated =
      make_model("drucker_prager", {"1.5e6", "0.3", "45", "0", "0", "fit", "associated"}, error);
  ASSERT_TRUE(associated) << error;
  EXPECT_TRUE(dynamic_cast<const DruckerPrager &>(*associated).parameters().fit ==
              DruckerPragerFit::associated);

  auto fails = [](std::vector<std::string> words, const std::string &message) {
    std::string why;
    EXPECT_FALSE(make_model("drucker_prager", words, why));
    EXPECT_EQ(why, message);
  };
  fails({"1.5e6", "0.3", "45", "0"}, "drucker_prager needs 5 parameters (K nu phi psi c), got 4");
  fails({"1.5e6", "0.5", "45", "0", "0"}, "drucker_prager Poisson ratio nu = 0.5 must be in (-1, 0.5)");
  fails({"1.5e6", "x", "45", "0", "0"}, "drucker_prager parameter nu: 'x' is not a finite number");
  fails({"1.5e6", "0.3", "45", "0", "0", "fit", "tresca"},
        "drucker_prager fit 'tresca': must be exact, associated or nonassociated");
  fails({"1.5e6", "0.3", "45", "0", "0", "fit"},
        "drucker_prager fit '': must be exact, associated or nonassociated");
  fails({"1.5e6", "0.3", "45", "0", "0", "hardening", "1"},
        "drucker_prager: unknown option 'hardening' (allowed: fit, tension)");
  fails({"1.5e6", "0.3", "45", "20", "0"},
        "drucker_prager fit exact: no plane-strain fit is exact for dilatancy angle psi = 20 "
        "degrees: the flow potential sqrt(J2) + 3 sin(psi) I1 allows plastic flow in plane strain "
        "only for psi in [0, 11.0958) degrees; choose 'fit associated' or 'fit nonassociated'");
  EXPECT_FALSE(make_model("cam_clay", {}, error));
  EXPECT_EQ(error, "unknown model 'cam_clay' (allowed: drucker_prager, mohr_coulomb)");
}

// The default fit is exact for the dilatancy angle: psi = 0 gives the nonassociated fit to the
// last bit. For psi > 0, plane-strain plastic flow (epsdot^p_zz = 0) needs s_zz = -2 beta sqrt(J2),
// beta = 3 sin(psi); a stress with that s_zz and Mohr-Coulomb's in-plane strength
// tau = c cos(phi) - sigma_m sin(phi) must lie on the surface. The associated fit passes the same
// test with beta = alpha_phi (flow potential = yield function).
TEST(DruckerPrager, ExactFitIsMohrCoulombForTheFlowRulesPlaneStrainFlow)
{
  for (double phi : {19.8, 30.0, 45.0}) {
    const DruckerPrager exact(soil(phi, 0.0, 1.0e4, 1.5e6, 0.3, DruckerPragerFit::exact));
    const DruckerPrager nonassociated(soil(phi, 0.0, 1.0e4, 1.5e6, 0.3, DruckerPragerFit::nonassociated));
    EXPECT_EQ(exact.alpha_phi(), nonassociated.alpha_phi());
    EXPECT_EQ(exact.k_c(), nonassociated.k_c());
  }
  auto surface_stress = [](double phi, double c, double beta, double mean, double stress[6]) {
    const double tau = c * std::cos(phi * PI / 180.0) - mean * std::sin(phi * PI / 180.0);
    const double root_j2 = tau / std::sqrt(1.0 - 3.0 * beta * beta);
    const double szz = -2.0 * beta * root_j2;
    stress[0] = mean + tau;
    stress[1] = mean - tau;
    stress[2] = mean + 1.5 * szz;
    stress[3] = stress[4] = stress[5] = 0.0;
  };
  for (double phi : {10.0, 19.8, 30.0, 45.0})
    for (double psi : {0.0, 2.0, 5.0, 10.0, 11.0}) {
      if (psi > phi) continue;
      const double c = 1.0e4, mean = -5.0e4;
      const DruckerPrager model(soil(phi, psi, c, 1.5e6, 0.3, DruckerPragerFit::exact));
      double stress[6];
      surface_stress(phi, c, 3.0 * std::sin(psi * PI / 180.0), mean, stress);
      EXPECT_NEAR(model.yield_function(stress) / (c - mean), 0.0, 1.0e-13) << phi << " " << psi;
      // the flow rule's out-of-plane plastic strain rate vanishes there: s_zz/(2 sqrt J2) + beta
      const double s_zz = stress[2] - mean_stress(stress);
      EXPECT_NEAR(s_zz / (2.0 * sqrt_j2(stress)) + 3.0 * std::sin(psi * PI / 180.0), 0.0, 1.0e-13);
    }
  for (double phi : {10.0, 19.8, 30.0, 45.0}) {
    const DruckerPrager model(soil(phi, phi, 1.0e4));
    double stress[6];
    surface_stress(phi, 1.0e4, model.alpha_phi(), -5.0e4, stress);
    EXPECT_NEAR(model.yield_function(stress) / 6.0e4, 0.0, 1.0e-13) << phi;
  }
  // psi = 11.0958 is the limit; just below it the fit exists, just above it does not
  EXPECT_EQ(DruckerPrager::check(soil(30.0, 11.09, 0.0, 1.5e6, 0.3, DruckerPragerFit::exact)), "");
  EXPECT_NE(DruckerPrager::check(soil(30.0, 11.1, 0.0, 1.5e6, 0.3, DruckerPragerFit::exact)), "");
  EXPECT_NEAR(DruckerPrager::largest_exact_dilatancy(), 11.0958, 1.0e-4);
}

// Far inside the surface the rate is Hooke's law; on the surface under unloading too.
TEST(DruckerPrager, ElasticStepIsHookesLaw)
{
  std::mt19937 rng(1);
  const double zero_spin[3] = {0.0, 0.0, 0.0};
  for (double phi : {0.0, 19.8, 45.0}) {
    const DruckerPrager model(soil(phi, phi / 2.0, 1.0e4));
    for (int trial = 0; trial < 50; trial++) {
      double stress[6], strain_rate[6], rate[6], expected[6];
      random_tensor(rng, 1.0e3, stress);
      for (int k = 0; k < 3; k++) stress[k] -= 1.0e5;
      ASSERT_LT(model.yield_function(stress), -0.1 * yield_scale(model, stress));
      random_tensor(rng, 1.0, strain_rate);
      model.stress_rate(stress, strain_rate, zero_spin, rate);
      hooke(model.bulk_modulus(), model.shear_modulus(), strain_rate, expected);
      for (int k = 0; k < 6; k++)
        EXPECT_NEAR(rate[k], expected[k], 1.0e-12 * max_abs(expected)) << "phi " << phi << " k " << k;
    }
  }
}

// On the surface the rate is the elastic-plastic rate of doc/theory.rst 3.6: when loading, the plastic part is
// lambdadot (9 K sin(psi) delta + G s/sqrt(J2)) (flow rule of g) and the total rate is tangent to
// f (consistency, which holds for every psi with the plastic multiplier of 3.5); when unloading it is
// the elastic rate. Jaumann terms included (they are tangent to f by themselves).
TEST(DruckerPrager, RateOnTheSurfaceFollowsTheFlowRuleAndStaysTangent)
{
  std::mt19937 rng(2);
  int loading = 0, unloading = 0;
  for (double phi : {10.0, 19.8, 30.0, 45.0})
    for (double psi_fraction : {0.0, 0.5, 1.0})
      for (double c : {0.0, 2.0e4}) {
        const DruckerPrager model(soil(phi, psi_fraction * phi, c));
        const double bulk = model.bulk_modulus(), shear = model.shear_modulus();
        const double sin_psi = std::sin(psi_fraction * phi * PI / 180.0);
        for (int trial = 0; trial < 40; trial++) {
          double stress[6], strain_rate[6], spin[3], rate[6], elastic[6], jaumann[6], gradient[6];
          random_stress_on_surface(rng, model, stress);
          ASSERT_TRUE(model.on_yield_surface(stress));
          random_tensor(rng, 1.0, strain_rate);
          std::uniform_real_distribution<double> u(-1.0, 1.0);
          for (double &w : spin) w = u(rng);
          model.stress_rate(stress, strain_rate, spin, rate);
          hooke(bulk, shear, strain_rate, elastic);
          jaumann_reference(stress, spin, jaumann);
          for (int k = 0; k < 6; k++) elastic[k] += jaumann[k];
          yield_gradient(model, stress, gradient);
          const double scale = norm(gradient) * norm(elastic);
          ASSERT_NEAR(contract(gradient, jaumann), 0.0, 1.0e-12 * norm(gradient) * norm(jaumann));

          if (contract(gradient, elastic) > 1.0e-6 * scale) {
            loading++;
            EXPECT_NEAR(contract(gradient, rate), 0.0, 1.0e-10 * scale);
            // plastic part = lambdadot (9 K sin(psi) delta + G s/sqrt(J2)), lambdadot > 0
            const double mean = mean_stress(stress), root = sqrt_j2(stress);
            double plastic[6], deviator[6];
            for (int k = 0; k < 6; k++) {
              plastic[k] = elastic[k] - rate[k];
              deviator[k] = stress[k] - (k < 3 ? mean : 0.0);
            }
            const double lambdadot = contract(plastic, deviator) / (shear / root * contract(deviator, deviator));
            EXPECT_GT(lambdadot, 0.0);
            for (int k = 0; k < 6; k++) {
              const double expected = lambdadot * ((k < 3 ? 9.0 * bulk * sin_psi : 0.0) + shear / root * deviator[k]);
              EXPECT_NEAR(plastic[k], expected, 1.0e-9 * norm(plastic)) << "phi " << phi << " k " << k;
            }
          } else if (contract(gradient, elastic) < -1.0e-6 * scale) {
            unloading++;
            for (int k = 0; k < 6; k++) EXPECT_NEAR(rate[k], elastic[k], 1.0e-12 * norm(elastic));
          }
        }
      }
  EXPECT_GT(loading, 100);
  EXPECT_GT(unloading, 100);
}

// A counter-clockwise rigid rotation v = Omega (-y, x) has g_xy = -Omega, g_yx = Omega, so
// omega_xy = -Omega. After 45 degrees the direction (1,1)/sqrt(2) carries the former x axis:
// its normal stress must be the former sigma_xx, and sigma_xy = (sigma_xx - sigma_yy)/2.
TEST(DruckerPrager, RigidRotationTurnsTheStressWithTheMaterial2D)
{
  const DruckerPrager model(soil(30.0, 0.0, 1.0e6));
  const double omega = 2.0, angle = PI / 4.0;
  const double strain_rate[6] = {0.0, 0.0, 0.0, 0.0, 0.0, 0.0};
  const double spin[3] = {-omega, 0.0, 0.0};
  double stress[6] = {-3.0e4, -1.0e4, -2.0e4, 0.0, 0.0, 0.0};
  const int steps = 400;
  for (int n = 0; n < steps; n++) rk4_step(model, strain_rate, spin, angle / omega / steps, stress);
  const double along_old_x_axis = 0.5 * (stress[0] + stress[1]) + stress[3];
  EXPECT_NEAR(along_old_x_axis, -3.0e4, 1.0e-6);
  EXPECT_NEAR(stress[3], 0.5 * (-3.0e4 - (-1.0e4)), 1.0e-6);
  EXPECT_NEAR(stress[2], -2.0e4, 1.0e-9);    // sigma_zz untouched by an in-plane rotation
  EXPECT_EQ(stress[4], 0.0);                 // plane strain stays plane strain
  EXPECT_EQ(stress[5], 0.0);
}

// Pure spin about an arbitrary axis for a finite angle: sigma(t) = R sigma0 R^T with
// R = exp(W t), W^ab = omega^ab (so that dx/dt = W x), and I1, J2, det unchanged.
TEST(DruckerPrager, RigidRotationIsObjective3D)
{
  std::mt19937 rng(3);
  const DruckerPrager model(soil(30.0, 10.0, 1.0e7));
  const double strain_rate[6] = {0.0, 0.0, 0.0, 0.0, 0.0, 0.0};
  for (int trial = 0; trial < 5; trial++) {
    double stress0[6], stress[6], spin[3];
    random_tensor(rng, 1.0e5, stress0);
    std::copy(stress0, stress0 + 6, stress);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    for (double &w : spin) w = u(rng);
    const double time = 1.0;
    const int steps = 500;
    for (int n = 0; n < steps; n++) rk4_step(model, strain_rate, spin, time / steps, stress);

    // Rodrigues: exp(W t) = I + sin(theta)/theta (W t) + (1 - cos(theta))/theta^2 (W t)^2
    const Matrix w = {{0.0, spin[0], spin[1]}, {-spin[0], 0.0, spin[2]}, {-spin[1], -spin[2], 0.0}};
    const double theta = time * std::sqrt(spin[0] * spin[0] + spin[1] * spin[1] + spin[2] * spin[2]);
    Matrix rotation, s0, expected;
    for (int a = 0; a < 3; a++)
      for (int b = 0; b < 3; b++) {
        double w2 = 0.0;
        for (int g = 0; g < 3; g++) w2 += w[a][g] * w[g][b];
        rotation[a][b] = (a == b ? 1.0 : 0.0) + std::sin(theta) / theta * time * w[a][b] +
            (1.0 - std::cos(theta)) / (theta * theta) * time * time * w2;
      }
    to_matrix(stress0, s0);
    for (int a = 0; a < 3; a++)
      for (int b = 0; b < 3; b++) {
        expected[a][b] = 0.0;
        for (int g = 0; g < 3; g++)
          for (int e = 0; e < 3; e++) expected[a][b] += rotation[a][g] * s0[g][e] * rotation[b][e];
      }
    const double tolerance = 1.0e-9 * max_abs(stress0);
    const int row[6] = {0, 1, 2, 0, 0, 1}, column[6] = {0, 1, 2, 1, 2, 2};
    for (int k = 0; k < 6; k++)
      EXPECT_NEAR(stress[k], expected[row[k]][column[k]], tolerance) << "theta " << theta << " k " << k;

    EXPECT_NEAR(first_invariant(stress), first_invariant(stress0), tolerance);
    EXPECT_NEAR(sqrt_j2(stress), sqrt_j2(stress0), tolerance);
    Matrix s;
    to_matrix(stress, s);
    auto det = [](const Matrix m) {
      return m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
          m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) + m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
    };
    const double scale3 = std::pow(max_abs(stress0), 3);
    EXPECT_NEAR(det(s), det(s0), 1.0e-9 * scale3);
  }
}

// After the return any stress is admissible to round-off; the return only moves I1 down to the
// apex (cracking) and shrinks the deviator radially; a second return changes nothing.
TEST(DruckerPrager, ReturnMappingIsAdmissibleAndRadial)
{
  std::mt19937 rng(4);
  std::uniform_real_distribution<double> log_scale(2.0, 6.0);
  for (double phi : {0.0, 5.0, 19.8, 30.0, 45.0, 60.0, 80.0, 89.0})
    for (double c : {0.0, 1.0e3, 1.0e5}) {
      const DruckerPrager model(soil(phi, 0.0, c));
      const double alpha = model.alpha_phi(), kc = model.k_c();
      for (int trial = 0; trial < 300; trial++) {
        double before[6], stress[6];
        const double magnitude = std::pow(10.0, log_scale(rng));
        random_tensor(rng, magnitude, before);
        if (trial % 3 == 0)
          for (int k = 0; k < 3; k++) before[k] -= magnitude;    // mostly compressive
        std::copy(before, before + 6, stress);
        const bool inside = model.yield_function(before) <= 0.0;
        const bool changed = model.return_to_admissible(stress);
        const double tolerance = 1.0e-12 * (max_abs(before) + kc);
        EXPECT_EQ(changed, !inside) << "phi " << phi << " c " << c;
        EXPECT_LE(model.yield_function(stress), tolerance) << "phi " << phi << " c " << c;
        if (inside) {
          for (int k = 0; k < 6; k++) EXPECT_EQ(stress[k], before[k]);
        }

        // I1 -> min(I1, k_c/alpha) (no cap for alpha = 0), deviator -> r deviator, r in [0, 1]
        const double i1 = first_invariant(before);
        const double expected_i1 = alpha > 0.0 ? std::min(i1, kc / alpha) : i1;
        EXPECT_NEAR(first_invariant(stress), expected_i1, tolerance);
        const double ratio = sqrt_j2(stress) / sqrt_j2(before);
        EXPECT_LE(ratio, 1.0 + 1.0e-15);
        const double mean_before = mean_stress(before), mean_after = mean_stress(stress);
        for (int k = 0; k < 6; k++) {
          const double s_before = before[k] - (k < 3 ? mean_before : 0.0);
          const double s_after = stress[k] - (k < 3 ? mean_after : 0.0);
          EXPECT_NEAR(s_after, ratio * s_before, tolerance) << "k " << k;
        }

        double again[6];
        std::copy(stress, stress + 6, again);
        model.return_to_admissible(again);
        for (int k = 0; k < 6; k++) EXPECT_NEAR(again[k], stress[k], tolerance);
      }
    }
}

TEST(DruckerPrager, TensionCrackingLeavesNoTensileMeanStressWithoutCohesion)
{
  std::mt19937 rng(5);
  for (double phi : {5.0, 19.8, 30.0, 45.0, 70.0}) {
    const DruckerPrager model(soil(phi, 0.0, 0.0));
    for (int trial = 0; trial < 500; trial++) {
      double stress[6];
      random_tensor(rng, 1.0e5, stress);
      const double scale = max_abs(stress);
      const bool tensile = first_invariant(stress) > 0.0;
      model.return_to_admissible(stress);
      EXPECT_LE(first_invariant(stress), 1.0e-12 * scale);
      // no tensile mean stress and no strength at zero pressure: the stress vanishes
      if (tensile) {
        for (int k = 0; k < 6; k++) EXPECT_NEAR(stress[k], 0.0, 1.0e-12 * scale);
      }
    }
    double hydrostatic_tension[6] = {1.0e4, 1.0e4, 1.0e4, 0.0, 0.0, 0.0};
    EXPECT_TRUE(model.return_to_admissible(hydrostatic_tension));
    for (double component : hydrostatic_tension) EXPECT_NEAR(component, 0.0, 1.0e-11);
  }
  // with cohesion the mean stress is capped at the apex k_c/(3 alpha) instead
  const DruckerPrager cohesive(soil(30.0, 0.0, 1.0e4));
  double tension[6] = {1.0e6, 2.0e6, 0.0, 5.0e5, 0.0, 0.0};
  cohesive.return_to_admissible(tension);
  const double apex = cohesive.k_c() / cohesive.alpha_phi();
  EXPECT_NEAR(first_invariant(tension), apex, 1.0e-9 * apex);
  EXPECT_NEAR(sqrt_j2(tension), 0.0, 1.0e-9 * apex);
}

// phi = 0: sqrt(J2) <= c, pressure-independent, no tension cap (alpha = 0 disables cracking)
TEST(DruckerPrager, FrictionlessSurfaceHasNoTensionCap)
{
  const DruckerPrager model(soil(0.0, 0.0, 5.0e3));
  double tension[6] = {1.0e6, 1.0e6, 1.0e6, 1.0e3, 0.0, 0.0};
  EXPECT_FALSE(model.return_to_admissible(tension));
  EXPECT_EQ(tension[0], 1.0e6);
  double sheared[6] = {2.0e5, 1.0e5, 1.5e5, 2.0e4, 0.0, 0.0};
  EXPECT_TRUE(model.return_to_admissible(sheared));
  EXPECT_NEAR(sqrt_j2(sheared), 5.0e3, 1.0e-9);
  EXPECT_NEAR(first_invariant(sheared), 4.5e5, 1.0e-9);
  EXPECT_NEAR(model.yield_function(sheared), 0.0, 1.0e-9);
}

TEST(DruckerPrager, YieldedFlag)
{
  std::mt19937 rng(6);
  const DruckerPrager sand(soil(30.0, 0.0, 0.0)), clay(soil(20.0, 0.0, 1.0e4));
  for (int trial = 0; trial < 20; trial++) {
    double stress[6];
    random_stress_on_surface(rng, sand, stress);
    EXPECT_TRUE(sand.on_yield_surface(stress));
    for (int k = 3; k < 6; k++) stress[k] *= 0.999;    // slightly inside
    EXPECT_FALSE(sand.on_yield_surface(stress));
  }
  const double zero[6] = {0.0, 0.0, 0.0, 0.0, 0.0, 0.0};
  EXPECT_TRUE(sand.on_yield_surface(zero));    // apex of a cohesionless soil
  EXPECT_FALSE(clay.on_yield_surface(zero));
  // a stress-free cohesionless particle gets the elastic rate (no flow direction at the apex)
  const double strain_rate[6] = {0.1, -0.2, 0.0, 0.3, 0.0, 0.0}, spin[3] = {0.0, 0.0, 0.0};
  double rate[6], expected[6];
  sand.stress_rate(zero, strain_rate, spin, rate);
  hooke(sand.bulk_modulus(), sand.shear_modulus(), strain_rate, expected);
  for (int k = 0; k < 6; k++) EXPECT_DOUBLE_EQ(rate[k], expected[k]);
}

// Plane-strain simple shear v_x = gammadot y under confinement, explicit Euler steps + return:
// Hooke in shear until the surface, then the stress stays on it; before each return the step has
// drifted off the surface only by O(dt^2) (the rate is tangent); sigma_zz evolves through the
// dilatancy (psi > 0); psi = 0 flows at constant I1.
TEST(DruckerPrager, PlaneStrainSimpleShearReachesAndStaysOnTheSurface)
{
  const double gammadot = 1.0, dt = 1.0e-5, p0 = 1.0e5;
  const int steps = 20000;    // total shear strain 0.2
  const double strain_rate[6] = {0.0, 0.0, 0.0, 0.5 * gammadot, 0.0, 0.0};
  const double spin[3] = {0.5 * gammadot, 0.0, 0.0};
  for (double psi : {0.0, 10.0})
    for (double c : {0.0, 5.0e3}) {
      const DruckerPrager model(soil(30.0, psi, c));
      double stress[6] = {-p0, -p0, -p0, 0.0, 0.0, 0.0};
      int first_yield = -1;
      double max_drift = 0.0, max_after = 0.0, min_i1 = 0.0, max_i1 = -1.0e300;
      for (int n = 0; n < steps; n++) {
        const bool on_surface = model.on_yield_surface(stress);
        if (!on_surface && first_yield < 0) {
          const double gamma = n * dt * gammadot;
          ASSERT_NEAR(stress[3], model.shear_modulus() * gamma, 0.01 * model.shear_modulus() * gamma + 1.0e-6);
        }
        double rate[6];
        model.stress_rate(stress, strain_rate, spin, rate);
        for (int k = 0; k < 6; k++) stress[k] += dt * rate[k];
        const double scale = yield_scale(model, stress);
        if (on_surface) max_drift = std::max(max_drift, std::fabs(model.yield_function(stress)) / scale);
        model.return_to_admissible(stress);
        if (model.on_yield_surface(stress) && first_yield < 0) first_yield = n;
        if (first_yield >= 0)
          max_after = std::max(max_after, std::fabs(model.yield_function(stress)) / yield_scale(model, stress));
        min_i1 = std::min(min_i1, first_invariant(stress));
        max_i1 = std::max(max_i1, first_invariant(stress));
        ASSERT_EQ(stress[4], 0.0);
        ASSERT_EQ(stress[5], 0.0);
      }
      SCOPED_TRACE("psi " + std::to_string(psi) + " c " + std::to_string(c));
      ASSERT_GE(first_yield, 0);
      EXPECT_LT(first_yield, steps / 2);
      EXPECT_TRUE(model.on_yield_surface(stress));
      EXPECT_LT(max_after, 1.0e-12);
      EXPECT_LT(max_drift, 1.0e-8);    // a wrong lambdadot drifts ~1e-4 per step
      EXPECT_GT(std::fabs(stress[3]), 0.1 * p0);
      if (psi > 0.0) {
        // dilatancy at constant volume raises the confinement, sigma_zz included
        EXPECT_LT(stress[2], -1.2 * p0);
        EXPECT_LT(first_invariant(stress), -3.6 * p0);
      } else {
        EXPECT_NEAR(min_i1, -3.0 * p0, 1.0e-9 * p0);
        EXPECT_NEAR(max_i1, -3.0 * p0, 1.0e-9 * p0);
      }
    }
}

// phi = 0 (pure cohesion, a Tresca/von Mises soil) in plane-strain simple shear reaches
// sqrt(J2) = c exactly, whatever the mean stress, compression or tension (no cap without
// 'tension'); the exact fit and the others agree for phi = 0
TEST(DruckerPrager, FrictionlessCohesiveSimpleShearReachesSqrtJ2EqualToC)
{
  const double c = 2.0e4;
  for (double p0 : {1.0e5, 0.0, -3.0e4})
    for (DruckerPragerFit fit :
         {DruckerPragerFit::exact, DruckerPragerFit::associated, DruckerPragerFit::nonassociated}) {
      const DruckerPrager model(soil(0.0, 0.0, c, 1.5e6, 0.3, fit));
      EXPECT_EQ(model.tensile_strength(), std::numeric_limits<double>::infinity());
      double stress[6];
      SPHSoilTesting::simple_shear(model, p0, stress);
      EXPECT_NEAR(sqrt_j2(stress), c, 1.0e-12 * c) << "p0 " << p0;
      EXPECT_NEAR(first_invariant(stress), -3.0 * p0, 1.0e-9 * c);
      EXPECT_NEAR(SPHSoilTesting::in_plane_shear(stress), c, 1.0e-12 * c);
    }
}

// the tensile strength: the apex c cot(phi) by default (psi = 0), infinite for phi = 0, 0 without
// cohesion, T when 'tension T' sets one
TEST(DruckerPrager, TensileStrengthIsTheApexOrTheCutOff)
{
  const double c = 1.0e4;
  const DruckerPrager cone(soil(20.0, 0.0, c, 1.5e6, 0.3, DruckerPragerFit::exact));
  EXPECT_NEAR(cone.tensile_strength(), c / std::tan(20.0 * PI / 180.0), 1.0e-9 * c);
  EXPECT_EQ(DruckerPrager(soil(30.0, 0.0, 0.0)).tensile_strength(), 0.0);
  DruckerPragerParameters capped = soil(20.0, 0.0, c, 1.5e6, 0.3, DruckerPragerFit::exact);
  capped.tension = 2.0e3;
  EXPECT_EQ(DruckerPrager(capped).tensile_strength(), 2.0e3);
  capped = soil(0.0, 0.0, c);
  capped.tension = 0.0;
  EXPECT_EQ(DruckerPrager(capped).tensile_strength(), 0.0);
}

// 'tension T' read from a material line; out of [0, apex] it is refused, naming the range
TEST(DruckerPrager, TensionOptionIsReadAndChecked)
{
  std::string error;
  auto model = make_model("drucker_prager", {"1.5e6", "0.3", "20", "0", "1e4", "tension", "3e3"}, error);
  ASSERT_NE(model, nullptr) << error;
  EXPECT_EQ(model->tensile_strength(), 3.0e3);
  model = make_model("drucker_prager", {"1.5e6", "0.3", "0", "0", "1e4", "tension", "1e9", "fit", "associated"}, error);
  ASSERT_NE(model, nullptr) << error;
  EXPECT_EQ(model->tensile_strength(), 1.0e9);
  EXPECT_EQ(make_model("drucker_prager", {"1.5e6", "0.3", "20", "0", "1e4", "tension", "-1"}, error), nullptr);
  EXPECT_EQ(error, "drucker_prager tension = -1: the tensile strength must be >= 0 Pa");
  EXPECT_EQ(make_model("drucker_prager", {"1.5e6", "0.3", "20", "0", "1e4", "tension", "1e5"}, error), nullptr);
  EXPECT_EQ(error, "drucker_prager tension = 100000: the tensile strength must be in [0, 27474.8] Pa, the "
                   "mean stress at the apex of the cone k_c / (3 alpha_phi) of this phi and c (the apex "
                   "limits the tension already)");
  EXPECT_EQ(make_model("drucker_prager", {"1.5e6", "0.3", "20", "0", "1e4", "tension", "x"}, error), nullptr);
  EXPECT_EQ(error, "drucker_prager tension 'x': the tensile strength must be a number (Pa), >= 0");
}

// Uniaxial and biaxial plane-strain stretching of a cohesive soil, explicit steps + return: the
// mean stress never exceeds the tension cut-off T, reaches it and stays there; the shear stays
// within the cone at that mean stress. For phi = 20 with and without 'tension', and phi = 0 with it.
TEST(DruckerPrager, StretchingNeverExceedsTheTensionCutOff)
{
  const double c = 1.0e4, dt = 1.0e-5;
  const double spin[3] = {0.0, 0.0, 0.0};
  for (double phi : {20.0, 0.0})
    for (double tension : {std::numeric_limits<double>::infinity(), 2.0e3}) {
      if (phi == 0.0 && tension == std::numeric_limits<double>::infinity()) continue;
      DruckerPragerParameters p = soil(phi, 0.0, c, 1.5e6, 0.3, DruckerPragerFit::exact);
      p.tension = tension;
      const DruckerPrager model(p);
      const double cutoff = model.tensile_strength();
      for (int biaxial = 0; biaxial < 2; biaxial++) {
        SCOPED_TRACE("phi " + std::to_string(phi) + " T " + std::to_string(tension) +
                     (biaxial ? " biaxial" : " uniaxial"));
        const double strain_rate[6] = {1.0, biaxial ? 1.0 : 0.0, 0.0, 0.0, 0.0, 0.0};
        double stress[6] = {0.0, 0.0, 0.0, 0.0, 0.0, 0.0};
        double largest_mean = -1.0e300;
        for (int n = 0; n < 5000; n++) {    // strain 0.05, far past the cut-off (~0.001)
          double rate[6];
          model.stress_rate(stress, strain_rate, spin, rate);
          for (int k = 0; k < 6; k++) stress[k] += dt * rate[k];
          model.return_to_admissible(stress);
          largest_mean = std::max(largest_mean, mean_stress(stress));
          ASSERT_LE(model.yield_function(stress), 1.0e-9 * c);
        }
        EXPECT_LE(largest_mean, cutoff * (1.0 + 1.0e-12));
        EXPECT_NEAR(mean_stress(stress), cutoff, 1.0e-9 * c);
        EXPECT_TRUE(model.on_yield_surface(stress));
        EXPECT_LE(sqrt_j2(stress), model.k_c() - model.alpha_phi() * 3.0 * cutoff + 1.0e-9 * c);
      }
    }
}
