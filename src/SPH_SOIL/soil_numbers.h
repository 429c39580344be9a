/* -*- c++ -*- ----------------------------------------------------------
   SPH_SOIL package: numbers in the words of material lines and in messages
   (pure, no LAMMPS).
------------------------------------------------------------------------- */

#ifndef LMP_SOIL_NUMBERS_H
#define LMP_SOIL_NUMBERS_H

#include <string>

namespace SPHSoil {

// the decimal form of a number for messages: 19.8, not 19.800000
std::string format_number(double value);
// a whole word as a finite number (the words of material lines); false if it is not one
bool parse_finite_number(const std::string &word, double &value);
// a whole word as a number, finite or not (nan, inf); false if it is not one
bool parse_number(const std::string &word, double &value);

}    // namespace SPHSoil

#endif
