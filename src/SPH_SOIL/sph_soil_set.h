/* -*- c++ -*- ----------------------------------------------------------
   SPH_SOIL package for LAMMPS: command sph_soil/set
   Sets the per-atom state of atom_style sph/soil for a group of atoms. The
   keywords are a table in the .cpp (keyword, count of values, what it sets).
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
#include "sph_soil_input.h"

#include <string>
#include <vector>

namespace LAMMPS_NS {

class SPHSoilSet : public Command {
 public:
  SPHSoilSet(class LAMMPS *lmp) : Command(lmp), avec(nullptr), groupbit(0) {}
  void command(int, char **) override;

 private:
  class AtomVecSPHSoil *avec;
  int groupbit;
  // the keywords: each reads its `count` values from args and returns how many more words it
  // took (optional ones)
  struct Keyword {
    const char *name;
    int count;
    int (SPHSoilSet::*apply)(const std::string &keyword, char **args, int available);
  };
  static const std::vector<Keyword> &keywords();
  int set_positive(const std::string &keyword, char **args, int available);
  int set_level(const std::string &keyword, char **args, int available);
  int set_tensor(const std::string &keyword, char **args, int available);
  int set_geostatic(const std::string &keyword, char **args, int available);
  int set_pore_pressure(const std::string &keyword, char **args, int available);
  int set_wall(const std::string &keyword, char **args, int available);
  int set_nowall(const std::string &keyword, char **args, int available);

  // A per-atom value given as a number or as v_name (equal- or atom-style variable): per_atom()
  // reads it, evaluates it for the owned atoms and checks those of the group against `range`
  // (the one statement of what the keyword allows, in both of its errors)
  struct Value {
    double constant = 0.0;
    std::string variable;
  };
  std::vector<double> per_atom(const std::string &keyword, const char *arg,
                               const SPHSoilInput::Range &range);
  Value parse_value(const std::string &keyword, const char *arg, const SPHSoilInput::Range &range);
  std::vector<double> evaluate(const Value &value);
  void check_range(const std::string &keyword, const std::vector<double> &values,
                   const SPHSoilInput::Range &range);
  bool in_group(int i) const;
};

}    // namespace LAMMPS_NS

#endif
#endif
