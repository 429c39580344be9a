// Material files of pair_style sph/soil: parsing, and the messages for bad entries.
#include "soil_drucker_prager.h"
#include "soil_mohr_coulomb.h"
#include "soil_material.h"

#include "gmock/gmock.h"
#include "gtest/gtest.h"

#include <fstream>
#include <sstream>

using namespace SPHSoil;
using ::testing::HasSubstr;

namespace {
const DruckerPragerParameters &drucker_prager(const SoilMaterial &material)
{
  return dynamic_cast<const DruckerPrager &>(*material.model).parameters();
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

TEST(MaterialFile, RejectsBadEntriesNamingLineModelAndParameter)
{
  std::vector<SoilMaterial> list;
  std::string error;
  auto rejects = [&](const std::string &text, const std::string &message) {
    EXPECT_FALSE(parse_material_file(text, list, error)) << text;
    EXPECT_EQ(error, message);
  };
  rejects("a soil 2650 0.7e6 0.3 19.8 0\n",
          "line 1: material a: drucker_prager needs 5 parameters (K nu phi psi c), got 4");
  rejects("\na soil 2650 0.7e6 0.7 19.8 0 0\n",
          "line 2: material a: drucker_prager Poisson ratio nu = 0.7 must be in (-1, 0.5)");
  rejects("a soil 2650 mohr_coulomb 0.7e6 0.3 19.8 25 0\n",
          "line 1: material a: mohr_coulomb dilatancy angle psi = 25 must be in [0, phi = 19.8] degrees");
  rejects("a soil 2650 mohr_coulomb 0.7e6 0.3 19.8 0 0 fit associated\n",
          "line 1: material a: mohr_coulomb: unknown option 'fit' (allowed: tension)");
  rejects("a soil 2650 mohr_coulomb 0.7e6 0.3\n",
          "line 1: material a: mohr_coulomb needs 5 parameters (K nu phi psi c), got 2");
  rejects("a soil -1 0.7e6 0.3 19.8 0 0\n", "line 1: material a: density rho0 = -1 must be finite and > 0");
  rejects("a soil 2650 drucker_prager 1e400 0.3 19.8 0 0\n",
          "line 1: material a: drucker_prager parameter K: '1e400' is not a finite number");
  rejects("a soil 2650 abc 0.3 19.8 0 0\n",
          "line 1: material a: unknown model 'abc' (allowed: drucker_prager, mohr_coulomb)");
  rejects("a soil\n", "line 1: material a: 'soil' needs rho0 and a model with its parameters");
  rejects("a rock 1 2 3\n", "line 1: material a: unknown kind 'rock' (allowed: soil, wall)");
  rejects("w wall\nw wall\n", "line 2: material w is defined twice");
  rejects("w wall sticky\n", "line 1: material w: unknown wall option 'sticky' (allowed: noslip, "
                             "freeslip, friction <mu>, delta <degrees>, adhesion <c_a>, "
                             "boundary mirror|extrapolate)");
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
