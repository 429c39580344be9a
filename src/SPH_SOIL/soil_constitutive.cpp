/* ----------------------------------------------------------------------
   SPH_SOIL package: what the constitutive models share (pure, no LAMMPS)
------------------------------------------------------------------------- */

#include "soil_constitutive.h"

#include <limits>

#include <cmath>
#include <cstdlib>
#include <utility>
#include <sstream>

using namespace SPHSoil;

/* ----------------------------------------------------------------------
   the negated comparisons also reject NaN
------------------------------------------------------------------------- */

std::string FrictionalParameters::check() const
{
  if (!(bulk_modulus > 0.0 && std::isfinite(bulk_modulus)))
    return "bulk modulus K = " + format_number(bulk_modulus) + " must be finite and > 0";
  if (!(poisson_ratio > -1.0 && poisson_ratio < 0.5))
    return "Poisson ratio nu = " + format_number(poisson_ratio) + " must be in (-1, 0.5)";
  if (!(friction_angle >= 0.0 && friction_angle < 90.0))
    return "friction angle phi = " + format_number(friction_angle) + " must be in [0, 90) degrees";
  if (!(dilatancy_angle >= 0.0 && dilatancy_angle <= friction_angle))
    return "dilatancy angle psi = " + format_number(dilatancy_angle) + " must be in [0, phi = " +
        format_number(friction_angle) + "] degrees";
  if (!(cohesion >= 0.0 && std::isfinite(cohesion)))
    return "cohesion c = " + format_number(cohesion) + " must be finite and >= 0";
  return "";
}

FrictionalParameters FrictionalParameters::from_young_modulus(double young_modulus,
                                                              double poisson_ratio,
                                                              double friction_angle,
                                                              double dilatancy_angle, double cohesion)
{
  FrictionalParameters parameters;
  parameters.bulk_modulus = young_modulus / (3.0 * (1.0 - 2.0 * poisson_ratio));
  parameters.poisson_ratio = poisson_ratio;
  parameters.friction_angle = friction_angle;
  parameters.dilatancy_angle = dilatancy_angle;
  parameters.cohesion = cohesion;
  return parameters;
}

std::string FrictionalParameters::check_young_modulus(double young_modulus, double poisson_ratio,
                                                      double friction_angle, double dilatancy_angle,
                                                      double cohesion)
{
  if (!(young_modulus > 0.0 && std::isfinite(young_modulus)))
    return "Young's modulus E = " + format_number(young_modulus) + " must be finite and > 0";
  // nu before K: a bad nu would otherwise show up as a puzzling K
  if (!(poisson_ratio > -1.0 && poisson_ratio < 0.5))
    return "Poisson ratio nu = " + format_number(poisson_ratio) + " must be in (-1, 0.5)";
  return from_young_modulus(young_modulus, poisson_ratio, friction_angle, dilatancy_angle, cohesion)
      .check();
}

namespace {
// the usage's words: (false, word) before the first '[', (true, option) for each '[option ...'
std::vector<std::pair<bool, std::string>> usage_words(const std::string &usage)
{
  std::vector<std::pair<bool, std::string>> words;
  std::istringstream in(usage);
  std::string word;
  bool options = false;
  while (in >> word) {
    if (word[0] == '[') {
      options = true;
      if (word.size() > 1) words.emplace_back(true, word.substr(1));
    } else if (!options) {
      words.emplace_back(false, word);
    }
  }
  return words;
}
}    // namespace

int SPHSoil::usage_parameter_count(const std::string &usage)
{
  int count = 0;
  for (const auto &word : usage_words(usage)) count += !word.first;
  return count;
}

std::string SPHSoil::usage_options(const std::string &usage)
{
  std::string list;
  for (const auto &word : usage_words(usage))
    if (word.first) list += (list.empty() ? "" : ", ") + word.second;
  return list;
}

bool SPHSoil::usage_has_option(const std::string &usage, const std::string &option)
{
  for (const auto &word : usage_words(usage))
    if (word.first && word.second == option) return true;
  return false;
}

bool FrictionalParameters::from_words(const std::string &model, const std::vector<std::string> &words,
                                      FrictionalParameters &parameters,
                                      std::vector<std::string> &options, std::string &error)
{
  static const char *const names[COUNT] = {"K", "nu", "phi", "psi", "c"};
  if ((int) words.size() < COUNT) {
    error = model + " needs " + std::to_string(COUNT) + " parameters (" + WORDS + "), got " +
        std::to_string(words.size());
    return false;
  }
  double values[COUNT];
  for (int k = 0; k < COUNT; k++) {
    if (!parse_finite_number(words[k], values[k])) {
      error = model + " parameter " + names[k] + ": '" + words[k] + "' is not a finite number";
      return false;
    }
  }
  parameters = FrictionalParameters();
  parameters.bulk_modulus = values[0];
  parameters.poisson_ratio = values[1];
  parameters.friction_angle = values[2];
  parameters.dilatancy_angle = values[3];
  parameters.cohesion = values[4];
  const std::string problem = parameters.check();
  if (!problem.empty()) {
    error = model + " " + problem;
    return false;
  }
  options.assign(words.begin() + COUNT, words.end());
  return true;
}

// out-of-class definitions: C++11/14 need them when the constants are bound to a reference
constexpr const char *FrictionalParameters::WORDS;
constexpr int FrictionalParameters::COUNT;

bool FrictionalParameters::tension_from_word(const std::string &model, const std::string &value,
                                             double &tension, std::string &error)
{
  if (parse_finite_number(value, tension)) return true;
  error = model + " tension '" + value + "': the tensile strength must be a number (Pa), >= 0";
  return false;
}

std::string FrictionalParameters::check_tension(double tension, double apex, const char *apex_name)
{
  if (!(tension >= 0.0))
    return "tension = " + format_number(tension) + ": the tensile strength must be >= 0 Pa";
  if (tension < std::numeric_limits<double>::infinity() && tension > apex)
    return "tension = " + format_number(tension) + ": the tensile strength must be in [0, " +
        format_number(apex) + "] Pa, " + apex_name + " of this phi and c (the apex limits the " +
        "tension already)";
  return "";
}
