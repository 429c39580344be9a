/* ----------------------------------------------------------------------
   SPH_SOIL package: materials of pair_style sph/soil (pure, no LAMMPS)
------------------------------------------------------------------------- */

#include "soil_material.h"

#include "soil_models.h"

#include <cctype>
#include <sstream>

using namespace SPHSoil;

// wall [noslip | freeslip | friction mu] [boundary mirror | extrapolate], in any order
static bool wall_from_words(const std::string &name, const std::vector<std::string> &words,
                            SoilMaterial &material, std::string &error)
{
  const std::string usage =
      "(allowed: noslip, freeslip, friction <mu>, boundary mirror|extrapolate)";
  bool slip_given = false, boundary_given = false;
  for (size_t k = 1; k < words.size(); k++) {
    const std::string &word = words[k];
    if (word == "noslip" || word == "freeslip" || word == "friction") {
      if (slip_given) {
        error = "material " + name + ": wall slip given twice ('" + word + "')";
        return false;
      }
      slip_given = true;
      material.slip = word == "noslip" ? WallSlip::noslip
          : word == "freeslip"         ? WallSlip::freeslip
                                       : WallSlip::friction;
      if (material.slip != WallSlip::friction) continue;
      if (k + 1 >= words.size()) {
        error = "material " + name + ": wall friction needs a coefficient mu >= 0";
        return false;
      }
      const std::string &value = words[++k];
      if (!parse_finite_number(value, material.friction) || material.friction < 0.0) {
        error = "material " + name + ": wall friction coefficient mu = " + value +
            " must be finite and >= 0";
        return false;
      }
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
  return true;
}

bool SPHSoil::material_from_words(const std::string &name, const std::vector<std::string> &words,
                                  SoilMaterial &material, std::string &error)
{
  material = SoilMaterial();
  material.name = name;
  material.words = words;
  if (words.empty()) {
    error = "material " + name + ": expected 'soil rho0 model parameters' (models: " +
        model_keywords() + ") or 'wall'";
    return false;
  }
  if (words[0] == "wall") return wall_from_words(name, words, material, error);
  if (words[0] != "soil") {
    error = "material " + name + ": unknown kind '" + words[0] + "' (allowed: soil, wall)";
    return false;
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
  const std::vector<std::string> parameters(words.begin() + (named ? 3 : 2), words.end());
  std::unique_ptr<ConstitutiveModel> model = make_model(keyword, parameters, error);
  if (!model) {
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
