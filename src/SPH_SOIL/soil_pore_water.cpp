/* ----------------------------------------------------------------------
   SPH_SOIL package: the pore water of a saturated soil (pure, no LAMMPS)
------------------------------------------------------------------------- */

#include "soil_pore_water.h"

#include "soil_numbers.h"

#include <cmath>

using namespace SPHSoil;

constexpr double PoreWater::DEFAULT_DENSITY;
constexpr double PoreWater::DEFAULT_MODULUS;

namespace {

struct Keyword {
  const char *name;
  double PoreWater::*field;
  double low;        // the allowed range: (low, high) or [low, high) as low_open says
  bool low_open;
  double high;       // < 0: no upper bound
  const char *range;
};

const Keyword KEYWORD_TABLE[] = {
    {"porosity", &PoreWater::porosity, 0.0, true, 1.0, "in (0, 1)"},
    {"permeability", &PoreWater::conductivity, 0.0, false, -1.0, ">= 0 (hydraulic conductivity, m/s)"},
    {"water_density", &PoreWater::water_density, 0.0, true, -1.0, "> 0 (kg/m^3)"},
    {"water_modulus", &PoreWater::water_modulus, 0.0, true, -1.0, "> 0 (Pa)"},
};
constexpr int NKEYWORDS = sizeof(KEYWORD_TABLE) / sizeof(KEYWORD_TABLE[0]);

// the permeability laws by name (the keyword's values)
struct Law {
  const char *name;
  PermeabilityLaw law;
};
const Law LAW_TABLE[] = {
    {"constant", PermeabilityLaw::CONSTANT},
    {"kozeny_carman", PermeabilityLaw::KOZENY_CARMAN},
};
const char *const LAW_KEYWORD = "permeability_law";

}    // namespace

std::string PoreWater::law_names()
{
  std::string names;
  for (const Law &law : LAW_TABLE) names += (names.empty() ? "" : ", ") + std::string(law.name);
  return names;
}

std::string PoreWater::keyword_names()
{
  std::string names;
  for (const Keyword &keyword : KEYWORD_TABLE) names += std::string(keyword.name) + ", ";
  return names + LAW_KEYWORD;
}

namespace {

// the value of 'permeability_law' into `water`; false with the reason in `error`
bool read_law(const std::vector<std::string> &words, size_t &k, PoreWater &water, std::string &error)
{
  if (k + 1 >= words.size()) {
    error = std::string("pore water ") + LAW_KEYWORD + " needs a value: one of " + PoreWater::law_names();
    return false;
  }
  const std::string &text = words[++k];
  for (const Law &law : LAW_TABLE)
    if (text == law.name) {
      water.law = law.law;
      return true;
    }
  error = std::string("pore water ") + LAW_KEYWORD + " " + text + " is unknown: must be one of " +
      PoreWater::law_names();
  return false;
}

}    // namespace

bool PoreWater::from_words(std::vector<std::string> &words, PoreWater &water, bool &found,
                           std::string &error)
{
  water = PoreWater();
  found = false;
  bool given[NKEYWORDS] = {}, given_law = false;
  std::vector<std::string> rest;
  for (size_t k = 0; k < words.size(); k++) {
    if (words[k] == LAW_KEYWORD) {
      found = true;
      if (given_law) {
        error = std::string("pore water ") + LAW_KEYWORD + " given twice";
        return false;
      }
      given_law = true;
      if (!read_law(words, k, water, error)) return false;
      continue;
    }
    int which = -1;
    for (int w = 0; w < NKEYWORDS; w++)
      if (words[k] == KEYWORD_TABLE[w].name) which = w;
    if (which < 0) {
      rest.push_back(words[k]);
      continue;
    }
    const Keyword &keyword = KEYWORD_TABLE[which];
    found = true;
    if (given[which]) {
      error = std::string("pore water ") + keyword.name + " given twice";
      return false;
    }
    given[which] = true;
    if (k + 1 >= words.size()) {
      error = std::string("pore water ") + keyword.name + " needs a value " + keyword.range;
      return false;
    }
    const std::string &text = words[++k];
    double value = 0.0;
    if (!parse_finite_number(text, value) ||
        !(keyword.low_open ? value > keyword.low : value >= keyword.low) ||
        (keyword.high >= 0.0 && !(value < keyword.high))) {
      error = std::string("pore water ") + keyword.name + " = " + text + " must be finite and " +
          keyword.range;
      return false;
    }
    water.*(keyword.field) = value;
  }
  // (the table's first two: porosity and permeability, both needed)
  if (found && !(given[0] && given[1])) {
    error = std::string("a saturated soil needs both porosity and permeability (missing: ") +
        (given[0] ? "permeability" : given[1] ? "porosity" : "porosity and permeability") + ")";
    return false;
  }
  words = rest;
  return true;
}

std::string PoreWater::check_density(double saturated_density) const
{
  // (grains of positive mass)
  if (grain_density(saturated_density) > 0.0) return "";
  return "the saturated density rho0 = " + format_number(saturated_density) +
      " must exceed porosity * water_density = " + format_number(porosity * water_density) +
      " (rho0 of a saturated soil is the mass of grains and water per volume)";
}
