/* ----------------------------------------------------------------------
   SPH_SOIL package: free water (pure, no LAMMPS)
------------------------------------------------------------------------- */

#include "soil_water.h"

#include "soil_numbers.h"

using namespace SPHSoil;

constexpr const char *FreeWater::KEYWORD;

std::unique_ptr<FreeWater> FreeWater::from_words(const std::vector<std::string> &words,
                                                 std::string &error)
{
  if (words.empty()) {
    error = "water needs its bulk modulus K_w (Pa) after its density, got 0 value(s)";
    return nullptr;
  }
  if (words.size() > 1) {
    std::string given;
    for (const auto &word : words) given += " " + word;
    error = "water takes one value after its density, its bulk modulus K_w (Pa) ('water rho_w "
            "K_w'), got " + std::to_string(words.size()) + ":" + given;
    return nullptr;
  }
  double modulus = 0.0;
  if (!parse_finite_number(words[0], modulus) || !(modulus > 0.0)) {
    error = "water bulk modulus K_w = " + words[0] + " must be finite and > 0 (Pa)";
    return nullptr;
  }
  return std::unique_ptr<FreeWater>(new FreeWater(modulus));
}
