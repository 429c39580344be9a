/* ----------------------------------------------------------------------
   SPH_SOIL package: materials of pair_style sph/soil (pure, no LAMMPS)
------------------------------------------------------------------------- */

#include "soil_material.h"

#include "soil_models.h"

#include <cctype>
#include <sstream>

using namespace SPHSoil;

bool SPHSoil::material_from_words(const std::string &name, const std::vector<std::string> &words,
                                  SoilMaterial &material, std::string &error)
{
  material = SoilMaterial();
  material.name = name;
  if (words.empty()) {
    error = "material " + name + ": expected 'soil rho0 model parameters' (models: " +
        model_keywords() + ") or 'wall'";
    return false;
  }
  if (words[0] == "wall") {
    if (words.size() != 1) {
      error = "material " + name + ": 'wall' takes no parameters, got " + std::to_string(words.size() - 1);
      return false;
    }
    return true;
  }
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
  // a number where the model word goes: a line from before models had keywords
  const bool named = words.size() > 2 && std::isalpha((unsigned char) words[2][0]);
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
  std::istringstream lines(text);
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
