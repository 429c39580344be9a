// Material files of pair_style sph/soil: parsing, and the messages for bad entries.
#include "soil_constitutive.h"
#include "soil_material.h"

#include "gmock/gmock.h"
#include "gtest/gtest.h"

#include <fstream>
#include <sstream>

using namespace SPHSoil;
using ::testing::HasSubstr;

TEST(MaterialFile, ParsesSoilAndWallEntriesWithComments)
{
  std::vector<SoilMaterial> list;
  std::string error;
  ASSERT_TRUE(parse_material_file("# comment\n\nbars soil 2650 0.7e6 0.3 19.8 0 0  # trailing\n"
                                  "floor wall\n",
                                  list, error))
      << error;
  ASSERT_EQ(list.size(), 2u);
  EXPECT_EQ(list[0].name, "bars");
  EXPECT_FALSE(list[0].wall);
  EXPECT_EQ(list[0].density, 2650.0);
  EXPECT_EQ(list[0].bulk_modulus, 0.7e6);
  EXPECT_EQ(list[0].friction_angle, 19.8);
  EXPECT_TRUE(list[1].wall);
  // the shipped file reads, with the paper's materials
  std::ifstream shipped(SPH_SOIL_TEST_POTENTIALS "/bui2008.soil");
  std::stringstream text;
  text << shipped.rdbuf();
  ASSERT_TRUE(parse_material_file(text.str(), list, error)) << error;
  ASSERT_EQ(list.size(), 3u);
  EXPECT_EQ(list[1].name, "sand");
  EXPECT_EQ(list[1].friction_angle, 45.0);
  EXPECT_NEAR(list[0].wave_speed(), 20.66, 0.01);
}

TEST(MaterialFile, RejectsBadEntriesNamingLineAndParameter)
{
  std::vector<SoilMaterial> list;
  std::string error;
  EXPECT_FALSE(parse_material_file("a soil 2650 0.7e6 0.3 19.8 0\n", list, error));
  EXPECT_THAT(error, HasSubstr("line 1: material a: 'soil' needs 6 parameters"));
  EXPECT_FALSE(parse_material_file("\na soil 2650 0.7e6 0.7 19.8 0 0\n", list, error));
  EXPECT_THAT(error, HasSubstr("line 2: material a: Poisson ratio nu = 0.7 must be in (-1, 0.5)"));
  EXPECT_FALSE(parse_material_file("a soil 2650 0.7e6 0.3 19.8 25 0\n", list, error));
  EXPECT_THAT(error, HasSubstr("dilatancy angle psi = 25 must be in [0, phi = 19.8]"));
  EXPECT_FALSE(parse_material_file("a soil -1 0.7e6 0.3 19.8 0 0\n", list, error));
  EXPECT_THAT(error, HasSubstr("density rho0 = -1 must be finite and > 0"));
  EXPECT_FALSE(parse_material_file("a soil 2650 abc 0.3 19.8 0 0\n", list, error));
  EXPECT_THAT(error, HasSubstr("'abc' is not a finite number"));
  EXPECT_FALSE(parse_material_file("a rock 1 2 3\n", list, error));
  EXPECT_THAT(error, HasSubstr("unknown kind 'rock' (allowed: soil, wall)"));
  EXPECT_FALSE(parse_material_file("w wall\nw wall\n", list, error));
  EXPECT_THAT(error, HasSubstr("line 2: material w is defined twice"));
  EXPECT_FALSE(parse_material_file("# nothing\n", list, error));
  EXPECT_THAT(error, HasSubstr("no material defined"));
}

TEST(MaterialFile, FactoryBuildsTheModelOfASoil)
{
  SoilMaterial bars;
  std::string error;
  ASSERT_TRUE(material_from_words("bars", {"soil", "2650", "0.7e6", "0.3", "19.8", "0", "0"}, bars, error));
  auto model = make_constitutive_model(bars);
  ASSERT_NE(model, nullptr);
  EXPECT_NEAR(model->wave_speed(bars.density), bars.wave_speed(), 1e-12);
  SoilMaterial wall;
  ASSERT_TRUE(material_from_words("w", {"wall"}, wall, error));
  EXPECT_EQ(make_constitutive_model(wall), nullptr);
}
