/* ----------------------------------------------------------------------
   SPH_SOIL package: materials of pair_style sph/soil (pure, no LAMMPS)
------------------------------------------------------------------------- */

#include "soil_material.h"

#include "soil_models.h"
#include "soil_pore_water.h"
#include "soil_tensor.h"
#include "soil_water.h"

#include <cctype>
#include <cmath>
#include <sstream>

using namespace SPHSoil;

// the value after words[k], "a <what>", as a finite number in [low, high) (high < 0: no upper
// bound)
static bool wall_number(const std::string &name, const std::vector<std::string> &words, size_t &k,
                        const char *what, double low, double high, double &value,
                        std::string &error)
{
  const std::string &word = words[k];
  const std::string range = high < 0.0 ? ">= " + format_number(low)
                                       : "in [" + format_number(low) + ", " + format_number(high) + ")";
  if (k + 1 >= words.size()) {
    error = "material " + name + ": wall " + word + " needs a " + what + " " + range;
    return false;
  }
  const std::string &text = words[++k];
  if (!parse_finite_number(text, value) || value < low || (high >= 0.0 && value >= high)) {
    error = "material " + name + ": wall " + word + " " + what + " = " + text +
        " must be finite and " + range;
    return false;
  }
  return true;
}

// wall [noslip | freeslip | friction mu | delta degrees] [adhesion c_a]
//      [boundary mirror | extrapolate] [drained], in any order
static bool wall_from_words(const std::string &name, const std::vector<std::string> &words,
                            SoilMaterial &material, std::string &error)
{
  const std::string usage = "(allowed: noslip, freeslip, friction <mu>, delta <degrees>, "
                            "adhesion <c_a>, boundary mirror|extrapolate, drained)";
  bool slip_given = false, boundary_given = false, adhesion_given = false;
  for (size_t k = 1; k < words.size(); k++) {
    const std::string &word = words[k];
    if (word == "noslip" || word == "freeslip" || word == "friction" || word == "delta") {
      if (slip_given) {
        error = "material " + name + ": wall slip given twice ('" + word + "')";
        return false;
      }
      slip_given = true;
      material.slip = word == "noslip" ? WallSlip::noslip
          : word == "freeslip"         ? WallSlip::freeslip
                                       : WallSlip::friction;
      if (word == "friction") {
        if (!wall_number(name, words, k, "coefficient mu", 0.0, -1.0, material.friction, error))
          return false;
      } else if (word == "delta") {
        double degrees = 0.0;
        if (!wall_number(name, words, k, "friction angle (degrees)", 0.0, 90.0, degrees, error))
          return false;
        material.friction = std::tan(degrees * DEG2RAD);
      }
    } else if (word == "drained") {
      if (material.drained) {
        error = "material " + name + ": wall drained given twice";
        return false;
      }
      material.drained = true;
    } else if (word == "adhesion") {
      adhesion_given = true;
      if (!wall_number(name, words, k, "value c_a (stress units)", 0.0, -1.0, material.adhesion, error))
        return false;
    } else if (word == "boundary") {
      if (boundary_given || k + 1 >= words.size()) {
        error = "material " + name + ": wall boundary " +
            (boundary_given ? "given twice" : "needs a value (mirror or extrapolate)");
        return false;
      }
      boundary_given = true;
      const std::string &value = words[++k];
      if (value == "mirror") material.boundary = WallBoundary::mirror;
      else if (value == "extrapolate") material.boundary = WallBoundary::extrapolate;
      else {
        error = "material " + name + ": wall boundary '" + value + "' (allowed: mirror, extrapolate)";
        return false;
      }
    } else {
      error = "material " + name + ": unknown wall option '" + word + "' " + usage;
      return false;
    }
  }
  if (adhesion_given && material.slip != WallSlip::friction) {
    error = "material " + name + ": wall adhesion needs a frictional wall ('friction <mu>' or "
                                 "'delta <degrees>' before or after it)";
    return false;
  }
  return true;
}

// whether `word` is a keyword of a saturated soil's pore water: its parser is asked (its words are
// listed in one place, soil_pore_water.cpp)
static bool pore_water_word(const std::string &word)
{
  std::vector<std::string> words = {word};
  PoreWater water;
  bool found = false;
  std::string error;
  PoreWater::from_words(words, water, found, error);
  return found;
}

// The first word after a model's parameters that is neither one of its options nor an option's
// value (its usage says which are which); false if there is none (then the model's own error,
// about a parameter or an option's value, stands)
static bool unknown_option(const std::string &usage, const std::vector<std::string> &words,
                           std::string &unknown)
{
  for (size_t k = usage_parameter_count(usage); k < words.size(); k++) {
    if (usage_has_option(usage, words[k])) {
      k++;    // (its value)
      continue;
    }
    unknown = words[k];
    return true;
  }
  return false;
}

// An unknown word on a soil line: every word the line takes after the model's parameters, the
// model's options (from its usage) and the pore water's keywords (from their table), and where
// a wall's word (one wall_from_words takes) belongs
static std::string unknown_soil_word(const std::string &model, const std::string &usage,
                                     const std::string &word)
{
  const std::string options = usage_options(usage);
  std::string text = model + ": unknown option '" + word + "' (allowed on a soil line after the " +
      "model's parameters: " + (options.empty() ? "" : options + "; ") + "for a saturated soil: " +
      PoreWater::keyword_names() + ")";
  SoilMaterial wall;
  std::string wall_error;
  if (wall_from_words("", {"wall", word}, wall, wall_error) ||
      wall_error.find("unknown wall option") == std::string::npos)
    text += "; '" + word + "' is a word of a wall ('wall ... " + word + "')";
  return text;
}

bool SPHSoil::material_from_words(const std::string &name, const std::vector<std::string> &words,
                                  SoilMaterial &material, std::string &error)
{
  material = SoilMaterial();
  material.name = name;
  material.words = words;
  if (words.empty()) {
    error = "material " + name + ": expected 'soil rho0 model parameters' (models: " +
        model_keywords() + "), 'wall' or 'water rho_w K_w'";
    return false;
  }
  if (words[0] == "wall") return wall_from_words(name, words, material, error);
  if (words[0] != "soil" && words[0] != "water") {
    error = "material " + name + ": unknown kind '" + words[0] + "' (allowed: soil, wall, water)";
    return false;
  }
  if (words[0] == "water") {
    if (words.size() < 2 || !parse_finite_number(words[1], material.density) ||
        !(material.density > 0.0)) {
      error = "material " + name + ": water needs its density rho_w, finite and > 0" +
          (words.size() < 2 ? std::string() : ", got " + words[1]);
      return false;
    }
    // a saturated soil's words on water: free water carries its own pressure, no pore water
    for (size_t k = 2; k < words.size(); k++)
      if (pore_water_word(words[k])) {
        error = "material " + name + ": water takes no '" + words[k] + "' (free water is 'water " +
            "rho_w K_w'); " + words[k] + " is a word of a saturated soil: 'soil rho0 model " +
            "parameters porosity n permeability k'";
        return false;
      }
    auto water = FreeWater::from_words({words.begin() + 2, words.end()}, error);
    if (!water) {
      error = "material " + name + ": " + error;
      return false;
    }
    material.model = std::move(water);
    material.water = true;
    return true;
  }
  if (words.size() < 2) {
    error = "material " + name + ": 'soil' needs rho0 and a model with its parameters";
    return false;
  }
  if (!parse_finite_number(words[1], material.density) || !(material.density > 0.0)) {
    error = "material " + name + ": density rho0 = " + words[1] + " must be finite and > 0";
    return false;
  }
  // a number where the model word goes: a line from before models had keywords ('nan' and
  // 'inf' are numbers, which the model then refuses as not finite, not unknown models)
  double number;
  const bool named = words.size() > 2 && std::isalpha((unsigned char) words[2][0]) &&
      !parse_number(words[2], number);
  const std::string keyword = named ? words[2] : DEFAULT_MODEL;
  std::vector<std::string> parameters(words.begin() + (named ? 3 : 2), words.end());
  // the pore water's words, wherever they stand after the model word (soil_pore_water.h)
  if (!PoreWater::from_words(parameters, material.pore_water, material.saturated, error)) {
    error = "material " + name + ": " + error;
    return false;
  }
  if (material.saturated) {
    const std::string problem = material.pore_water.check_density(material.density);
    if (!problem.empty()) {
      error = "material " + name + ": " + problem;
      return false;
    }
  }
  std::unique_ptr<ConstitutiveModel> model = make_model(keyword, parameters, error);
  if (!model) {
    const ModelEntry *entry = find_model(keyword);
    std::string unknown;
    if (entry && unknown_option(entry->usage, parameters, unknown))
      error = unknown_soil_word(keyword, entry->usage, unknown);
    error = "material " + name + ": " + error;
    return false;
  }
  material.model = std::move(model);
  return true;
}

bool SPHSoil::parse_material_file(const std::string &text, std::vector<SoilMaterial> &materials,
                                  std::string &error)
{
  materials.clear();
  // a UTF-8 byte-order mark, which some editors write at the start of a file
  const std::string bom = "\xEF\xBB\xBF";
  std::istringstream lines(text.compare(0, bom.size(), bom) == 0 ? text.substr(bom.size()) : text);
  std::string line;
  int number = 0;
  while (std::getline(lines, line)) {
    number++;
    const auto hash = line.find('#');
    if (hash != std::string::npos) line.erase(hash);
    std::istringstream wordstream(line);
    std::vector<std::string> words;
    std::string word;
    while (wordstream >> word) words.push_back(word);
    if (words.empty()) continue;
    SoilMaterial material;
    const std::string name = words[0];
    words.erase(words.begin());
    if (!material_from_words(name, words, material, error)) {
      error = "line " + std::to_string(number) + ": " + error;
      return false;
    }
    for (const auto &other : materials)
      if (other.name == name) {
        error = "line " + std::to_string(number) + ": material " + name + " is defined twice";
        return false;
      }
    materials.push_back(material);
  }
  if (materials.empty()) {
    error = "no material defined";
    return false;
  }
  return true;
}
