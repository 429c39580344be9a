// Mohr-Coulomb soil model (doc/theory.rst section 3.10): the principal stresses, simple shear against
// the analytic strength, the return to the face, the two edges and the apex, objectivity, Tresca.
#include "soil_model_testing.h"
#include "soil_models.h"
#include "soil_mohr_coulomb.h"

#include "gtest/gtest.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <random>

using namespace SPHSoil;

namespace {

constexpr double PI = 3.14159265358979323846;

using SPHSoilTesting::frictional;

using SPHSoilTesting::random_rotation;
using SPHSoilTesting::rotate;

double max_abs(const double a[6])
{
  double m = 0.0;
  for (int k = 0; k < 6; k++) m = std::max(m, std::fabs(a[k]));
  return m;
}

}    // namespace

TEST(MohrCoulomb, PrincipalStressesAndVectors)
{
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int n = 0; n < 200; n++) {
    double stress[6];
    for (double &s : stress) s = u(rng);
    if (n % 2) stress[4] = stress[5] = 0.0;    // the plane-strain path
    double values[3], vectors[3][3];
    principal_stresses(stress, values, vectors);
    EXPECT_GE(values[0], values[1]);
    EXPECT_GE(values[1], values[2]);
    // sigma v = lambda v, |v| = 1
    const double m[3][3] = {{stress[0], stress[3], stress[4]},
                            {stress[3], stress[1], stress[5]},
                            {stress[4], stress[5], stress[2]}};
    for (int k = 0; k < 3; k++) {
      double length = 0.0;
      for (int a = 0; a < 3; a++) {
        double sv = 0.0;
        for (int b = 0; b < 3; b++) sv += m[a][b] * vectors[k][b];
        EXPECT_NEAR(sv, values[k] * vectors[k][a], 1e-14);
        length += vectors[k][a] * vectors[k][a];
      }
      EXPECT_NEAR(length, 1.0, 1e-14);
    }
    if (n % 2) {
      // z exactly an eigenvector: the plane stays a plane
      bool z_found = false;
      for (int k = 0; k < 3; k++)
        if (vectors[k][2] == 1.0 && vectors[k][0] == 0.0 && vectors[k][1] == 0.0) z_found = true;
      EXPECT_TRUE(z_found);
    }
  }
}

// Plane-strain simple shear from an isotropic stress without dilatancy: the return keeps the
// in-plane mean and sigma_zz, and the shear stress stops at Mohr-Coulomb's strength
// tau = c cos(phi) - sigma_m sin(phi) (tension positive), sigma_zz the intermediate stress.
TEST(MohrCoulomb, PlaneStrainSimpleShearReachesTheAnalyticStrength)
{
  const double p0 = 1.0e5;
  for (double phi : {0.0, 19.8, 30.0, 45.0})
    for (double c : {0.0, 5.0e3}) {
      if (phi == 0.0 && c == 0.0) continue;
      const MohrCoulomb model(frictional(phi, 0.0, c));
      double stress[6];
      SPHSoilTesting::simple_shear(model, p0, stress);
      ASSERT_TRUE(model.on_yield_surface(stress));
      const double mean = 0.5 * (stress[0] + stress[1]);
      EXPECT_NEAR(mean, -p0, 1.0e-10 * p0);
      EXPECT_EQ(stress[2], -p0);
      EXPECT_EQ(stress[4], 0.0);
      EXPECT_EQ(stress[5], 0.0);
      const double tau = SPHSoilTesting::in_plane_shear(stress);
      const double strength = SPHSoilTesting::mohr_coulomb_strength(c, phi, stress);
      EXPECT_NEAR(tau / strength, 1.0, 1.0e-10) << "phi " << phi << " c " << c;
    }
}

// Random trial stresses around the surface: every return ends on the surface; a face return
// moves the stress along D N (positive multiplier); an edge return along a positive
// combination of the D N of its two faces and leaves two principal stresses equal; the apex
// return ends at c cot(phi). All four kinds occur.
TEST(MohrCoulomb, ReturnToFaceEdgesAndApexIsConsistent)
{
  const double phi = 30.0, psi = 10.0, c = 1.0e4, bulk = 1.5e6, nu = 0.3;
  const MohrCoulomb model(frictional(phi, psi, c, bulk, nu));
  const double shear = model.shear_modulus(), lame = bulk - 2.0 * shear / 3.0;
  const double sin_psi = std::sin(psi * PI / 180.0);
  const double up = 2.0 * shear * (1.0 + sin_psi) + 2.0 * lame * sin_psi;
  const double vol = 2.0 * lame * sin_psi;
  const double down = 2.0 * shear * (-1.0 + sin_psi) + 2.0 * lame * sin_psi;
  const double apex = c / std::tan(phi * PI / 180.0);

  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::map<MohrCoulomb::Return, int> counts;
  for (int n = 0; n < 20000; n++) {
    double trial[3] = {6.0e4 * u(rng), 6.0e4 * u(rng), 6.0e4 * u(rng)};
    if (n % 4 == 0) trial[1] = trial[0];    // on an edge already: triaxial states
    std::sort(trial, trial + 3, [](double a, double b) { return a > b; });
    double r[3] = {trial[0], trial[1], trial[2]};
    const auto kind = model.return_principal(r);
    counts[kind]++;
    const double scale = std::fabs(trial[0]) + std::fabs(trial[2]) + c;
    const double f = (r[0] - r[2]) + (r[0] + r[2]) * std::sin(phi * PI / 180.0) -
        2.0 * c * std::cos(phi * PI / 180.0);
    EXPECT_GE(r[0], r[1]);
    EXPECT_GE(r[1], r[2]);
    const double d[3] = {trial[0] - r[0], trial[1] - r[1], trial[2] - r[2]};
    switch (kind) {
      case MohrCoulomb::Return::none:
        EXPECT_LE(f, 0.0);
        break;
      case MohrCoulomb::Return::face: {
        EXPECT_NEAR(f / scale, 0.0, 1e-13);
        const double gamma = d[0] / up;
        EXPECT_GT(gamma, 0.0);
        EXPECT_NEAR(d[1], gamma * vol, 1e-9 * scale);
        EXPECT_NEAR(d[2], gamma * down, 1e-9 * scale);
        break;
      }
      case MohrCoulomb::Return::edge_12:
      case MohrCoulomb::Return::edge_23: {
        EXPECT_NEAR(f / scale, 0.0, 1e-12);
        const bool top = kind == MohrCoulomb::Return::edge_12;
        EXPECT_EQ(top ? r[0] : r[1], top ? r[1] : r[2]);
        // faces (1,3) and (2,3): d = g (up, vol, down) + h (vol, up, down);
        // faces (1,3) and (1,2): d = g (up, vol, down) + h (up, down, vol)
        double g, h;
        if (top) {
          const double det = up * up - vol * vol;
          g = (d[0] * up - d[1] * vol) / det;
          h = (d[1] * up - d[0] * vol) / det;
          EXPECT_NEAR(d[2], (g + h) * down, 1e-9 * scale);
        } else {
          const double det = vol * vol - down * down;
          g = (d[1] * vol - d[2] * down) / det;
          h = (d[2] * vol - d[1] * down) / det;
          EXPECT_NEAR(d[0], (g + h) * up, 1e-9 * scale);
        }
        EXPECT_GE(g, -1e-12 * scale / shear);
        EXPECT_GE(h, -1e-12 * scale / shear);
        break;
      }
      case MohrCoulomb::Return::apex:
        for (double x : r) EXPECT_NEAR(x, apex, 1e-12 * apex);
        break;
    }
    // a second return leaves it where it is
    double again[3] = {r[0], r[1], r[2]};
    model.return_principal(again);
    for (int k = 0; k < 3; k++) EXPECT_NEAR(again[k], r[k], 1e-12 * scale);
  }
  for (auto kind : {MohrCoulomb::Return::none, MohrCoulomb::Return::face, MohrCoulomb::Return::edge_12,
                    MohrCoulomb::Return::edge_23, MohrCoulomb::Return::apex})
    EXPECT_GT(counts[kind], 100) << "return kind " << (int) kind;
}

// the return commutes with rotations (an isotropic model), and keeps plane strain plane
TEST(MohrCoulomb, ReturnIsObjectiveAndKeepsPlaneStrain)
{
  const MohrCoulomb model(frictional(35.0, 5.0, 2.0e4));
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  int returned = 0;
  for (int n = 0; n < 500; n++) {
    double stress[6];
    for (int k = 0; k < 6; k++) stress[k] = 1.0e5 * u(rng) - (k < 3 ? 3.0e4 : 0.0);
    double r[3][3];
    random_rotation(rng, r);
    double rotated[6], returned_then_rotated[6], a[6];
    rotate(r, stress, rotated);
    for (int k = 0; k < 6; k++) a[k] = stress[k];
    const bool changed = model.return_to_admissible(a);
    returned += changed;
    rotate(r, a, returned_then_rotated);
    EXPECT_EQ(model.return_to_admissible(rotated), changed);
    for (int k = 0; k < 6; k++) EXPECT_NEAR(rotated[k], returned_then_rotated[k], 1e-9 * max_abs(stress));
    EXPECT_LE(model.yield_function(a), 1e-10 * max_abs(stress));

    double plane[6] = {stress[0], stress[1], stress[2], stress[3], 0.0, 0.0};
    model.return_to_admissible(plane);
    EXPECT_EQ(plane[4], 0.0);
    EXPECT_EQ(plane[5], 0.0);
  }
  EXPECT_GT(returned, 100);
}

// phi = 0 is Tresca: maximum shear stress c, no apex, any pressure
TEST(MohrCoulomb, FrictionlessIsTresca)
{
  const double c = 5.0e3;
  const MohrCoulomb model(frictional(0.0, 0.0, c));
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int n = 0; n < 5000; n++) {
    double s[3] = {3.0e4 * u(rng), 3.0e4 * u(rng), 3.0e4 * u(rng)};
    if (n % 3 == 0) s[1] = s[0];
    std::sort(s, s + 3, [](double a, double b) { return a > b; });
    const double mean = (s[0] + s[1] + s[2]) / 3.0;
    const auto kind = model.return_principal(s);
    EXPECT_NE(kind, MohrCoulomb::Return::apex);
    EXPECT_LE(0.5 * (s[0] - s[2]), c * (1.0 + 1e-13));
    EXPECT_NEAR((s[0] + s[1] + s[2]) / 3.0, mean, 1e-9 * c);    // psi = 0: no volume change
  }
}

// the rate is Jaumann + Hooke everywhere (the plastic part is the return's); the surface's
// strength in uniaxial compression is 2 c cos(phi) / (1 - sin(phi))
TEST(MohrCoulomb, ElasticRateAndUniaxialStrength)
{
  const double bulk = 1.5e6, nu = 0.3, phi = 30.0, c = 1.0e4;
  const MohrCoulomb model(frictional(phi, 0.0, c, bulk, nu));
  const double shear = model.shear_modulus();
  const double stress[6] = {-1.0e4, -2.0e4, -1.5e4, 3.0e3, -1.0e3, 2.0e3};
  const double strain_rate[6] = {0.1, -0.2, 0.05, 0.3, -0.1, 0.2};
  const double spin[3] = {0.4, -0.3, 0.2};
  double rate[6], expected[6];
  model.stress_rate(stress, strain_rate, spin, rate);
  jaumann_terms(stress, spin, expected);
  const double trace = strain_rate[0] + strain_rate[1] + strain_rate[2];
  for (int k = 0; k < 6; k++)
    expected[k] += 2.0 * shear * (strain_rate[k] - (k < 3 ? trace / 3.0 : 0.0)) + (k < 3 ? bulk * trace : 0.0);
  for (int k = 0; k < 6; k++) EXPECT_NEAR(rate[k], expected[k], 1e-9 * std::fabs(expected[k]) + 1e-9);
  EXPECT_NEAR(model.wave_speed(2000.0), std::sqrt((bulk + 4.0 * shear / 3.0) / 2000.0), 1e-12);

  const double s = std::sin(phi * PI / 180.0);
  const double q = 2.0 * c * std::cos(phi * PI / 180.0) / (1.0 - s);
  const double uniaxial[6] = {0.0, -q, 0.0, 0.0, 0.0, 0.0};
  EXPECT_NEAR(model.yield_function(uniaxial) / q, 0.0, 1e-15);
  EXPECT_TRUE(model.on_yield_surface(uniaxial));
  const double weaker[6] = {0.0, -0.99 * q, 0.0, 0.0, 0.0, 0.0};
  EXPECT_FALSE(model.on_yield_surface(weaker));
}

TEST(MohrCoulomb, RegistryNamesTheModelAndItsParameter)
{
  std::string error;
  const auto model = make_model("mohr_coulomb", {"1e7", "0.25", "35", "5", "1e4"}, error);
  ASSERT_TRUE(model) << error;
  EXPECT_STREQ(model->keyword(), "mohr_coulomb");
  EXPECT_FALSE(make_model("mohr_coulomb", {"1e7", "0.25", "95", "5", "1e4"}, error));
  EXPECT_EQ(error, "mohr_coulomb friction angle phi = 95 must be in [0, 90) degrees");
  EXPECT_FALSE(make_model("mohr_coulomb", {"1e7", "0.25", "35", "5", "-1"}, error));
  EXPECT_EQ(error, "mohr_coulomb cohesion c = -1 must be finite and >= 0");
  EXPECT_EQ(model_keywords(), "drucker_prager, mohr_coulomb");
}

// The tension cut-off: no principal stress above T after the return; the others kept (in plane
// strain and 3D); the cut-off lowers tensile_strength() to T, and T above the apex is refused.
TEST(MohrCoulomb, TensionCutOffCapsEveryPrincipalStress)
{
  std::string error;
  const auto no_cutoff = make_model("mohr_coulomb", {"1e7", "0.25", "30", "0", "1e4"}, error);
  const auto model = make_model("mohr_coulomb", {"1e7", "0.25", "30", "0", "1e4", "tension", "0"}, error);
  ASSERT_TRUE(model) << error;
  const double apex = 1e4 / std::tan(30 * PI / 180);
  EXPECT_NEAR(no_cutoff->tensile_strength(), apex, 1e-9 * apex);
  EXPECT_EQ(model->tensile_strength(), 0.0);
  // uniaxial tension of 5 kPa: inside Mohr-Coulomb (its apex is 17 kPa), beyond the cut-off
  double stress[6] = {5000.0, -2000.0, -1000.0, 0.0, 0.0, 0.0};
  double unchanged[6];
  std::copy(stress, stress + 6, unchanged);
  EXPECT_FALSE(no_cutoff->return_to_admissible(unchanged));
  EXPECT_GT(model->yield_function(stress), 0.0);
  ASSERT_TRUE(model->return_to_admissible(stress));
  EXPECT_EQ(stress[0], 0.0);
  EXPECT_NEAR(stress[1], -2000.0, 1e-9);
  EXPECT_NEAR(stress[2], -1000.0, 1e-9);
  EXPECT_TRUE(model->on_yield_surface(stress));
  EXPECT_LE(model->yield_function(stress), 1e-9);
  // a rotated biaxial tension: both tensile principal stresses capped, objectively
  double rotated[6] = {3000.0, 1000.0, -500.0, 1500.0, 0.0, 0.0};
  ASSERT_TRUE(model->return_to_admissible(rotated));
  double values[3], vectors[3][3];
  principal_stresses(rotated, values, vectors);
  EXPECT_NEAR(values[0], 0.0, 1e-9);
  EXPECT_LE(values[1], 1e-9);
  // T above the apex
  EXPECT_FALSE(make_model("mohr_coulomb", {"1e7", "0.25", "30", "0", "1e4", "tension", "2e4"}, error));
  EXPECT_EQ(error, "mohr_coulomb tension = 20000: the tensile strength must be in [0, 17320.5] Pa, "
                   "the apex c cot(phi) of this phi and c (the apex limits the tension already)");
  EXPECT_FALSE(make_model("mohr_coulomb", {"1e7", "0.25", "30", "0", "1e4", "dilation", "2"}, error));
  EXPECT_EQ(error, "mohr_coulomb: unknown option 'dilation' (allowed: tension)");
}
