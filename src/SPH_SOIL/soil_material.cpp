/* ----------------------------------------------------------------------
   SPH_SOIL package: materials of pair_style sph/soil (pure, no LAMMPS)
------------------------------------------------------------------------- */

#include "soil_material.h"

#include "soil_constitutive.h"

#include <cmath>
#include <cstdlib>
#include <sstream>

using namespace SPHSoil;

namespace {

bool to_number(const std::string &word, double &value)
{
  char *end = nullptr;
  value = std::strtod(word.c_str(), &end);
  return end && *end == '\0' && !word.empty() && std::isfinite(value);
}

std::string format(double value)
{
  std::ostringstream out;
  out << value;
  return out.str();
}

}    // namespace

std::string SoilMaterial::check() const
{
  if (wall) return "";
  if (!(density > 0.0) || !std::isfinite(density))
    return "density rho0 = " + format(density) + " must be finite and > 0";
  // the elastic-plastic parameters are the constitutive model's to judge
  DruckerPragerParameters parameters;
  parameters.bulk_modulus = bulk_modulus;
  parameters.poisson_ratio = poisson_ratio;
  parameters.friction_angle = friction_angle;
  parameters.dilatancy_angle = dilatancy_angle;
  parameters.cohesion = cohesion;
  return DruckerPrager::check(parameters);
}

double SoilMaterial::wave_speed() const
{
  if (wall || density <= 0.0) return 0.0;
  return std::sqrt((bulk_modulus + 4.0 * shear_modulus() / 3.0) / density);
}

bool SPHSoil::material_from_words(const std::string &name, const std::vector<std::string> &words,
                                  SoilMaterial &material, std::string &error)
{
  material = SoilMaterial();
  material.name = name;
  if (words.empty()) {
    error = "material " + name + ": expected 'soil rho0 K nu phi psi c' or 'wall'";
    return false;
  }
  if (words[0] == "wall") {
    if (words.size() != 1) {
      error = "material " + name + ": 'wall' takes no parameters, got " + std::to_string(words.size() - 1);
      return false;
    }
    material.wall = true;
    return true;
  }
  if (words[0] != "soil") {
    error = "material " + name + ": unknown kind '" + words[0] + "' (allowed: soil, wall)";
    return false;
  }
  if (words.size() != 7) {
    error = "material " + name + ": 'soil' needs 6 parameters (rho0 K nu phi psi c), got " +
        std::to_string(words.size() - 1);
    return false;
  }
  double values[6];
  for (int k = 0; k < 6; k++)
    if (!to_number(words[k + 1], values[k])) {
      error = "material " + name + ": '" + words[k + 1] + "' is not a finite number";
      return false;
    }
  material.density = values[0];
  material.bulk_modulus = values[1];
  material.poisson_ratio = values[2];
  material.friction_angle = values[3];
  material.dilatancy_angle = values[4];
  material.cohesion = values[5];
  const std::string problem = material.check();
  if (!problem.empty()) {
    error = "material " + name + ": " + problem;
    return false;
  }
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
