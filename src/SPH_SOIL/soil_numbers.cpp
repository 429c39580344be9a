/* ----------------------------------------------------------------------
   SPH_SOIL package: numbers in words and messages (pure, no LAMMPS)
------------------------------------------------------------------------- */

#include "soil_numbers.h"

#include <cmath>
#include <cstdlib>
#include <sstream>

using namespace SPHSoil;

std::string SPHSoil::format_number(double value)
{
  std::ostringstream out;
  out << value;
  return out.str();
}

bool SPHSoil::parse_number(const std::string &word, double &value)
{
  char *end = nullptr;
  value = std::strtod(word.c_str(), &end);
  return !word.empty() && end && *end == '\0';
}

bool SPHSoil::parse_finite_number(const std::string &word, double &value)
{
  return parse_number(word, value) && std::isfinite(value);
}
