/* -*- c++ -*- ----------------------------------------------------------
   SPH_SOIL package for LAMMPS: command sph_soil/set
   Sets the per-atom state of atom_style sph/soil for a group of atoms.
   See doc/sph_soil_set.rst.
------------------------------------------------------------------------- */

#ifdef COMMAND_CLASS
// clang-format off
CommandStyle(sph_soil/set,SPHSoilSet);
// clang-format on
#else

#ifndef LMP_SPH_SOIL_SET_H
#define LMP_SPH_SOIL_SET_H

#include "command.h"

#include <string>
#include <vector>

namespace LAMMPS_NS {

class SPHSoilSet : public Command {
 public:
  SPHSoilSet(class LAMMPS *lmp) : Command(lmp) {}
  void command(int, char **) override;

 private:
  // A per-atom value given as a number or as v_name (equal- or atom-style variable).
  struct Value {
    double constant = 0.0;
    std::string variable;
  };
  Value parse_value(const std::string &keyword, const char *arg);
  std::vector<double> evaluate(const Value &value);
  void check_range(const std::string &keyword, const std::vector<double> &values, double lo,
                   bool lo_open, const char *allowed, int groupbit);
};

}    // namespace LAMMPS_NS

#endif
#endif
