// Material files of pair_style sph/soil: parsing, and the messages for bad entries.
#include "soil_drucker_prager.h"
#include "soil_mohr_coulomb.h"
#include "soil_material.h"
#include "soil_pore_water.h"
#include "soil_water.h"

#include "gmock/gmock.h"
#include "gtest/gtest.h"

#include <cmath>
#include <fstream>
#include <sstream>

using namespace SPHSoil;
using ::testing::HasSubstr;

namespace {
const DruckerPragerParameters &drucker_prager(const SoilMaterial &material)
{
  return dynamic_cast<const DruckerPrager &>(*material.model).parameters();
}

// a material file's text that must not parse, and the exact message
void rejects(const std::string &text, const std::string &message)
{
  std::vector<SoilMaterial> list;
  std::string error;
  EXPECT_FALSE(parse_material_file(text, list, error)) << text;
  EXPECT_EQ(error, message);
}
}    // namespace

TEST(MaterialFile, ParsesSoilAndWallEntriesWithComments)
{
  std::vector<SoilMaterial> list;
  std::string error;
  ASSERT_TRUE(parse_material_file("# comment\n\nbars soil 2650 drucker_prager 0.7e6 0.3 19.8 0 0  # trailing\n"
                                  "floor wall\n"
                                  "rock soil 2000 mohr_coulomb 1e7 0.25 35 5 1e4\n"
                                  "bars_bui soil 2650 drucker_prager 0.7e6 0.3 19.8 0 0 fit associated\n",
                                  list, error))
      << error;
  ASSERT_EQ(list.size(), 4u);
  EXPECT_EQ(list[0].name, "bars");
  EXPECT_FALSE(list[0].is_wall());
  EXPECT_EQ(list[0].density, 2650.0);
  EXPECT_STREQ(list[0].model->keyword(), "drucker_prager");
  EXPECT_EQ(drucker_prager(list[0]).bulk_modulus, 0.7e6);
  EXPECT_EQ(drucker_prager(list[0]).friction_angle, 19.8);
  EXPECT_TRUE(drucker_prager(list[0]).fit == DruckerPragerFit::exact);
  EXPECT_TRUE(list[1].is_wall());
  EXPECT_EQ(list[1].wave_speed(), 0.0);
  EXPECT_STREQ(list[2].model->keyword(), "mohr_coulomb");
  EXPECT_EQ(dynamic_cast<const MohrCoulomb &>(*list[2].model).parameters().dilatancy_angle, 5.0);
  EXPECT_TRUE(drucker_prager(list[3]).fit == DruckerPragerFit::associated);
  // the shipped file reads, with the paper's materials
  std::ifstream shipped(SPH_SOIL_TEST_POTENTIALS "/bui2008.soil");
  std::stringstream text;
  text << shipped.rdbuf();
  ASSERT_TRUE(parse_material_file(text.str(), list, error)) << error;
  ASSERT_GE(list.size(), 3u);
  EXPECT_EQ(list[1].name, "sand");
  EXPECT_EQ(drucker_prager(list[1]).friction_angle, 45.0);
  EXPECT_NEAR(list[0].wave_speed(), 20.66, 0.01);
}

// a wall's slip and boundary words, in any order; without them, the pair style's slip
TEST(MaterialFile, WallOptions)
{
  std::vector<SoilMaterial> list;
  std::string error;
  ASSERT_TRUE(parse_material_file("plain wall\n"
                                  "smooth wall freeslip\n"
                                  "rough wall friction 0.35 boundary mirror\n"
                                  "box wall boundary extrapolate noslip\n",
                                  list, error))
      << error;
  ASSERT_EQ(list.size(), 4u);
  EXPECT_TRUE(list[0].slip == WallSlip::pair_default);
  EXPECT_TRUE(list[0].boundary == WallBoundary::mirror);
  EXPECT_TRUE(list[1].slip == WallSlip::freeslip);
  EXPECT_TRUE(list[2].slip == WallSlip::friction);
  EXPECT_EQ(list[2].friction, 0.35);
  EXPECT_TRUE(list[3].slip == WallSlip::noslip);
  EXPECT_TRUE(list[3].boundary == WallBoundary::extrapolate);
  for (const auto &wall : list) EXPECT_TRUE(wall.is_wall());
}

// a line written before models had keywords (seven words) reads as Drucker-Prager, default fit
TEST(MaterialFile, LineWithoutModelWordIsDruckerPrager)
{
  SoilMaterial old_line, new_line;
  std::string error;
  ASSERT_TRUE(material_from_words("bars", {"soil", "2650", "0.7e6", "0.3", "19.8", "0", "0"}, old_line, error))
      << error;
  ASSERT_TRUE(material_from_words("bars", {"soil", "2650", "drucker_prager", "0.7e6", "0.3", "19.8", "0", "0"},
                                  new_line, error))
      << error;
  EXPECT_STREQ(old_line.model->keyword(), "drucker_prager");
  const auto &a = dynamic_cast<const DruckerPrager &>(*old_line.model);
  const auto &b = dynamic_cast<const DruckerPrager &>(*new_line.model);
  EXPECT_EQ(a.alpha_phi(), b.alpha_phi());
  EXPECT_EQ(a.k_c(), b.k_c());
  EXPECT_EQ(old_line.wave_speed(), new_line.wave_speed());
  EXPECT_EQ(old_line.wave_speed(), a.wave_speed(2650.0));
}

// a model's usage is the one statement of its words: its parameters, then its options
TEST(MaterialFile, ModelUsagesStateParametersAndOptions)
{
  EXPECT_EQ(usage_parameter_count(DruckerPrager::USAGE), 5);
  EXPECT_EQ(usage_options(DruckerPrager::USAGE), "fit, tension");
  EXPECT_TRUE(usage_has_option(DruckerPrager::USAGE, "fit"));
  EXPECT_FALSE(usage_has_option(DruckerPrager::USAGE, "exact"));
  EXPECT_EQ(usage_parameter_count(MohrCoulomb::USAGE), 5);
  EXPECT_EQ(usage_options(MohrCoulomb::USAGE), "tension");
  EXPECT_EQ(usage_options("K nu phi psi c"), "");
  EXPECT_EQ(PoreWater::keyword_names(),
            "porosity, permeability, water_density, water_modulus, permeability_law");
}

TEST(MaterialFile, RejectsBadEntriesNamingLineModelAndParameter)
{
  rejects("a soil 2650 0.7e6 0.3 19.8 0\n",
          "line 1: material a: drucker_prager needs 5 parameters (K nu phi psi c), got 4");
  rejects("\na soil 2650 0.7e6 0.7 19.8 0 0\n",
          "line 2: material a: drucker_prager Poisson ratio nu = 0.7 must be in (-1, 0.5)");
  rejects("a soil 2650 mohr_coulomb 0.7e6 0.3 19.8 25 0\n",
          "line 1: material a: mohr_coulomb dilatancy angle psi = 25 must be in [0, phi = 19.8] degrees");
  rejects("a soil 2650 mohr_coulomb 0.7e6 0.3 19.8 0 0 fit associated\n",
          "line 1: material a: mohr_coulomb: unknown option 'fit' (allowed on a soil line after the "
          "model's parameters: tension; for a saturated soil: porosity, permeability, water_density, "
          "water_modulus, permeability_law)");
  // a wall's word on a soil line: every word a soil line takes, and where the word belongs
  rejects("a soil 2650 drucker_prager 0.7e6 0.3 19.8 0 0 tension 0 drained\n",
          "line 1: material a: drucker_prager: unknown option 'drained' (allowed on a soil line after "
          "the model's parameters: fit, tension; for a saturated soil: porosity, permeability, "
          "water_density, water_modulus, permeability_law); 'drained' is a word of a wall ('wall ... "
          "drained')");
  rejects("a soil 2650 mohr_coulomb 0.7e6 0.3\n",
          "line 1: material a: mohr_coulomb needs 5 parameters (K nu phi psi c), got 2");
  rejects("a soil -1 0.7e6 0.3 19.8 0 0\n", "line 1: material a: density rho0 = -1 must be finite and > 0");
  rejects("a soil 2650 drucker_prager 1e400 0.3 19.8 0 0\n",
          "line 1: material a: drucker_prager parameter K: '1e400' is not a finite number");
  rejects("a soil 2650 abc 0.3 19.8 0 0\n",
          "line 1: material a: unknown model 'abc' (allowed: drucker_prager, mohr_coulomb)");
  rejects("a soil\n", "line 1: material a: 'soil' needs rho0 and a model with its parameters");
  rejects("a rock 1 2 3\n", "line 1: material a: unknown kind 'rock' (allowed: soil, wall, water)");
  rejects("w wall\nw wall\n", "line 2: material w is defined twice");
  rejects("w wall sticky\n", "line 1: material w: unknown wall option 'sticky' (allowed: noslip, "
                             "freeslip, friction <mu>, delta <degrees>, adhesion <c_a>, "
                             "boundary mirror|extrapolate, drained)");
  rejects("w wall friction\n", "line 1: material w: wall friction needs a coefficient mu >= 0");
  rejects("w wall friction -0.1\n",
          "line 1: material w: wall friction coefficient mu = -0.1 must be finite and >= 0");
  rejects("w wall delta 90\n",
          "line 1: material w: wall delta friction angle (degrees) = 90 must be finite and in [0, 90)");
  rejects("w wall delta nan\n",
          "line 1: material w: wall delta friction angle (degrees) = nan must be finite and in [0, 90)");
  rejects("w wall friction 0.3 adhesion -5\n",
          "line 1: material w: wall adhesion value c_a (stress units) = -5 must be finite and >= 0");
  rejects("w wall friction 0.3 adhesion\n",
          "line 1: material w: wall adhesion needs a value c_a (stress units) >= 0");
  rejects("w wall noslip adhesion 100\n",
          "line 1: material w: wall adhesion needs a frictional wall ('friction <mu>' or 'delta "
          "<degrees>' before or after it)");
  rejects("w wall noslip freeslip\n", "line 1: material w: wall slip given twice ('freeslip')");
  rejects("w wall boundary\n",
          "line 1: material w: wall boundary needs a value (mirror or extrapolate)");
  rejects("w wall boundary curved\n",
          "line 1: material w: wall boundary 'curved' (allowed: mirror, extrapolate)");
  rejects("# nothing\n", "no material defined");
}

// What editors and users write: a UTF-8 byte-order mark at the start (skipped), 'nan' or 'inf'
// for a number (a parameter that is not finite, not an unknown model), and the words that
// defined a material, kept for restart files
TEST(MaterialFile, ByteOrderMarkNotANumberAndTheDefiningWords)
{
  std::vector<SoilMaterial> list;
  std::string error;
  ASSERT_TRUE(parse_material_file("\xEF\xBB\xBFsand soil 1850 1.5e6 0.3 45 0 0\n", list, error)) << error;
  ASSERT_EQ(list.size(), 1u);
  EXPECT_EQ(list[0].name, "sand");
  EXPECT_EQ(list[0].words, (std::vector<std::string>{"soil", "1850", "1.5e6", "0.3", "45", "0", "0"}));
  SoilMaterial again;
  ASSERT_TRUE(material_from_words(list[0].name, list[0].words, again, error));
  EXPECT_EQ(drucker_prager(again).friction_angle, 45.0);
  EXPECT_FALSE(parse_material_file("sand soil 1850 nan 0.3 45 0 0\n", list, error));
  EXPECT_EQ(error, "line 1: material sand: drucker_prager parameter K: 'nan' is not a finite number");
  EXPECT_FALSE(parse_material_file("sand soil 1850 mohr_coulomb inf 0.3 45 0 0\n", list, error));
  EXPECT_EQ(error, "line 1: material sand: mohr_coulomb parameter K: 'inf' is not a finite number");
}

// A saturated soil: the model's words with the pore water's in any order after them; its wave
// speed undrained. Free water and a drained wall.
TEST(MaterialFile, SaturatedSoilFreeWaterAndDrainedWall)
{
  std::vector<SoilMaterial> list;
  std::string error;
  ASSERT_TRUE(parse_material_file(
                  "clay soil 2000 drucker_prager 1.5e6 0.3 30 0 0 porosity 0.4 permeability 1e-5\n"
                  "silt soil 1900 mohr_coulomb 2e6 0.3 30 0 1e3 water_modulus 2e7 porosity 0.35 "
                  "tension 500 permeability 0 water_density 1020\n"
                  "sea water 1025 2.0e7\n"
                  "filter wall freeslip drained\n",
                  list, error))
      << error;
  ASSERT_EQ(list.size(), 4u);
  EXPECT_TRUE(list[0].saturated);
  EXPECT_EQ(list[0].pore_water.porosity, 0.4);
  EXPECT_EQ(list[0].pore_water.conductivity, 1e-5);
  EXPECT_EQ(list[0].pore_water.water_density, 1000.0);
  EXPECT_EQ(list[0].pore_water.water_modulus, 2.2e9);
  EXPECT_DOUBLE_EQ(list[0].pore_water.mobility(), 1e-5 / (1000.0 * 9.80665));
  EXPECT_DOUBLE_EQ(list[0].pore_water.storage_modulus(), 2.2e9 / 0.4);
  // undrained: sqrt((K + 4G/3 + K_w/n) / rho_sat)
  const double g = 3 * 1.5e6 * 0.4 / (2 * 1.3);
  EXPECT_DOUBLE_EQ(list[0].wave_speed(), std::sqrt((1.5e6 + 4 * g / 3 + 2.2e9 / 0.4) / 2000));
  EXPECT_TRUE(list[1].saturated);
  EXPECT_EQ(list[1].pore_water.water_modulus, 2e7);
  EXPECT_EQ(list[1].pore_water.water_density, 1020.0);
  EXPECT_EQ(list[1].pore_water.conductivity, 0.0);
  EXPECT_EQ(list[1].model->tensile_strength(), 500.0);
  EXPECT_DOUBLE_EQ(list[1].pore_water.grain_density(1900), (1900 - 0.35 * 1020) / 0.65);
  EXPECT_TRUE(list[2].water);
  EXPECT_FALSE(list[2].is_wall());
  EXPECT_FALSE(list[2].saturated);
  EXPECT_EQ(list[2].density, 1025.0);
  EXPECT_DOUBLE_EQ(list[2].wave_speed(), std::sqrt(2.0e7 / 1025));
  EXPECT_EQ(list[2].model->tensile_strength(), 0.0);
  EXPECT_TRUE(list[3].is_wall());
  EXPECT_TRUE(list[3].drained);
  EXPECT_TRUE(list[3].slip == WallSlip::freeslip);
  EXPECT_FALSE(list[0].drained);
  // the linear equation of state and its inverse
  EXPECT_NEAR(FreeWater::pressure(1001.0, 1000.0, 2e7), 2e4, 1e-6);
  EXPECT_DOUBLE_EQ(FreeWater::density(2e4, 1000.0, 2e7), 1001.0);
}

TEST(MaterialFile, RejectsBadPoreWaterAndWater)
{
  const std::string soil = "a soil 2000 drucker_prager 1.5e6 0.3 30 0 0 ";
  rejects(soil + "porosity 0.4\n", "line 1: material a: a saturated soil needs both porosity and "
                                   "permeability (missing: permeability)");
  rejects(soil + "permeability 1e-4\n", "line 1: material a: a saturated soil needs both porosity "
                                        "and permeability (missing: porosity)");
  rejects(soil + "porosity 1 permeability 1e-4\n",
          "line 1: material a: pore water porosity = 1 must be finite and in (0, 1)");
  rejects(soil + "porosity 0 permeability 1e-4\n",
          "line 1: material a: pore water porosity = 0 must be finite and in (0, 1)");
  rejects(soil + "porosity 0.4 permeability -1e-4\n",
          "line 1: material a: pore water permeability = -1e-4 must be finite and >= 0 (hydraulic "
          "conductivity, m/s)");
  rejects(soil + "porosity 0.4 permeability inf\n",
          "line 1: material a: pore water permeability = inf must be finite and >= 0 (hydraulic "
          "conductivity, m/s)");
  rejects(soil + "porosity 0.4 permeability 1e-4 water_density 0\n",
          "line 1: material a: pore water water_density = 0 must be finite and > 0 (kg/m^3)");
  rejects(soil + "porosity 0.4 permeability 1e-4 water_modulus -2e7\n",
          "line 1: material a: pore water water_modulus = -2e7 must be finite and > 0 (Pa)");
  rejects(soil + "porosity 0.4 permeability 1e-4 porosity 0.3\n",
          "line 1: material a: pore water porosity given twice");
  rejects(soil + "porosity 0.4 permeability\n",
          "line 1: material a: pore water permeability needs a value >= 0 (hydraulic "
          "conductivity, m/s)");
  rejects("a soil 300 drucker_prager 1.5e6 0.3 30 0 0 porosity 0.4 permeability 1e-4\n",
          "line 1: material a: the saturated density rho0 = 300 must exceed porosity * "
          "water_density = 400 (rho0 of a saturated soil is the mass of grains and water per volume)");
  rejects(soil + "porosity 0.4 permeability 1e-4 permeability_law\n",
          "line 1: material a: pore water permeability_law needs a value: one of constant, kozeny_carman");
  rejects(soil + "porosity 0.4 permeability 1e-4 permeability_law ergun\n",
          "line 1: material a: pore water permeability_law ergun is unknown: must be one of "
          "constant, kozeny_carman");
  rejects(soil + "porosity 0.4 permeability 1e-4 permeability_law constant permeability_law kozeny_carman\n",
          "line 1: material a: pore water permeability_law given twice");
  rejects(soil + "permeability_law kozeny_carman\n",
          "line 1: material a: a saturated soil needs both porosity and permeability (missing: "
          "porosity and permeability)");
  rejects("w water\n", "line 1: material w: water needs its density rho_w, finite and > 0");
  rejects("w water -1000 2e7\n", "line 1: material w: water needs its density rho_w, finite and > 0, got -1000");
  rejects("w water 1000\n",
          "line 1: material w: water needs its bulk modulus K_w (Pa) after its density, got 0 value(s)");
  rejects("w water 1000 0\n", "line 1: material w: water bulk modulus K_w = 0 must be finite and > 0 (Pa)");
  rejects("w water 1000 2e7 3\n",
          "line 1: material w: water takes one value after its density, its bulk modulus K_w (Pa) "
          "('water rho_w K_w'), got 2: 2e7 3");
  // a saturated soil's word on water, wherever it stands: where it belongs, not K_w blamed
  rejects("w water 1000 porosity 0.4\n",
          "line 1: material w: water takes no 'porosity' (free water is 'water rho_w K_w'); porosity "
          "is a word of a saturated soil: 'soil rho0 model parameters porosity n permeability k'");
  rejects("w water 1000 2e7 water_modulus 2e7\n",
          "line 1: material w: water takes no 'water_modulus' (free water is 'water rho_w K_w'); "
          "water_modulus is a word of a saturated soil: 'soil rho0 model parameters porosity n "
          "permeability k'");
  rejects("w wall drained drained\n", "line 1: material w: wall drained given twice");
}

// Kozeny-Carman (soil_pore_water.h): k at the reference density unchanged; the porosity from the
// density with the grains kept; k(n) / k(n0) = n^3 (1 - n0)^2 / (n0^3 (1 - n)^2); a constant k
// ignores the density
TEST(PoreWater, KozenyCarmanFollowsThePorosity)
{
  std::vector<SoilMaterial> list;
  std::string error;
  ASSERT_TRUE(parse_material_file("a soil 2000 drucker_prager 1.5e6 0.3 30 0 0 porosity 0.4 "
                                  "permeability 1e-4 permeability_law kozeny_carman\n"
                                  "b soil 2000 drucker_prager 1.5e6 0.3 30 0 0 porosity 0.4 "
                                  "permeability 1e-4 permeability_law constant\n",
                                  list, error))
      << error;
  const PoreWater &kc = list[0].pore_water, &constant = list[1].pore_water;
  EXPECT_TRUE(kc.variable_conductivity());
  EXPECT_FALSE(constant.variable_conductivity());
  EXPECT_EQ(kc.conductivity, 1e-4);
  EXPECT_DOUBLE_EQ(kc.conductivity_factor(1.0), 1.0);
  // 5% less dense: the grains (0.6 of the volume) now fill 0.57
  EXPECT_DOUBLE_EQ(kc.porosity_at(0.95), 1.0 - 0.6 * 0.95);
  const double n = 0.43, expected = n * n * n / (0.4 * 0.4 * 0.4) * (0.6 * 0.6) / (0.57 * 0.57);
  EXPECT_NEAR(kc.conductivity_factor(0.95), expected, 1e-12);
  EXPECT_GT(kc.conductivity_factor(0.95), 1.3);    // a dilating soil drains faster
  EXPECT_LT(kc.conductivity_factor(1.05), 0.8);    // a contracting one slower
  EXPECT_EQ(kc.conductivity_factor(1.0 / 0.6), 0.0);    // the pores closed
  EXPECT_EQ(constant.conductivity_factor(0.95), 1.0);
}

// The pore water's pair term (soil_pore_water.h): no flow in a hydrostatic state (the head
// p - rho_w g.x is uniform), and Brookshaw's Laplacian of a quadratic head: 2 lambda (phi_a -
// phi_b) x.grad W / (r^2 + eta^2) summed over a lattice is lambda times its Laplacian (the sign:
// div(lambda grad phi) < 0 where phi is higher than around)
TEST(PoreWater, PairTermIsZeroInHydrostaticsAndALaplacian)
{
  const double gravity[3] = {0.0, -9.81, 0.0};
  // hydrostatic: p = rho_w g (L - y), a at y = 0.1, b 3 mm above it
  const double dx[3] = {0.001, -0.003, 0.0};    // x_a - x_b
  const double pa = 1000 * 9.81 * (0.5 - 0.1), pb = 1000 * 9.81 * (0.5 - 0.1 - 0.003);
  const double r2 = dx[0] * dx[0] + dx[1] * dx[1];
  EXPECT_NEAR(pore_flow<2>(pa, pb, 1000.0, gravity, dx, r2, 0.005, -1e5, 1e-8), 0.0, 1e-12);
  // 1 Pa more at a: it flows out of a (a negative share of the divergence... of the flow into a)
  EXPECT_LT(pore_flow<2>(pa + 1.0, pb, 1000.0, gravity, dx, r2, 0.005, -1e5, 1e-8), 0.0);
  // the harmonic mean: conductances in series; 0 with an impermeable partner
  EXPECT_DOUBLE_EQ(harmonic_mobility(1.0, 3.0), 1.5);
  EXPECT_EQ(harmonic_mobility(0.0, 3.0), 0.0);
  EXPECT_EQ(harmonic_mobility(0.0, 0.0), 0.0);
  // with a cubic spline of h = 1.2 d over a square lattice, around the origin: head phi = x^2 +
  // y^2 (no gravity), Laplacian 4; mobility 1
  const double d = 0.01, h = 1.2 * d, norm = 10.0 / (7.0 * 3.14159265358979 * h * h);
  const double zero[3] = {0.0, 0.0, 0.0};
  double sum = 0.0;
  for (int i = -3; i <= 3; i++)
    for (int j = -3; j <= 3; j++) {
      if (i == 0 && j == 0) continue;
      const double x[3] = {-i * d, -j * d, 0.0};    // x_a - x_b, a at the origin
      const double rr = x[0] * x[0] + x[1] * x[1], r = std::sqrt(rr), q = r / h;
      if (q >= 2.0) continue;
      const double dw = q < 1.0 ? norm * (-3.0 * q + 2.25 * q * q) / h : -norm * 0.75 * (2 - q) * (2 - q) / h;
      const double factor = dw / r;    // grad W = factor x_ab
      const double phi_b = (i * d) * (i * d) + (j * d) * (j * d);
      sum += d * d * pore_flow<2>(0.0, phi_b, 0.0, zero, x, rr, h, factor, 1.0);
    }
  // the lattice sum is the kernel's first moment C = 0.9908 times the Laplacian (before eta^2
  // fell from 0.01 h^2, 2% low: 3.92), which pair_style sph/soil's gradient correction divides out
  EXPECT_NEAR(sum, 4.0 * 0.9908, 0.002);
}
