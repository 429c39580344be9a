/* -*- c++ -*- ----------------------------------------------------------
   SPH_SOIL package for LAMMPS: command sph_soil/refine
   Static refinement: splits every particle of a group once, with the same
   code as fix sph/soil/refine (the paper's "fine discretization").
   See doc/sph_soil_refine.rst.
------------------------------------------------------------------------- */

#ifdef COMMAND_CLASS
// clang-format off
CommandStyle(sph_soil/refine,SPHSoilRefine);
// clang-format on
#else

#ifndef LMP_SPH_SOIL_REFINE_H
#define LMP_SPH_SOIL_REFINE_H

#include "command.h"

namespace LAMMPS_NS {

class SPHSoilRefine : public Command {
 public:
  SPHSoilRefine(class LAMMPS *lmp) : Command(lmp) {}
  void command(int, char **) override;
};

}    // namespace LAMMPS_NS

#endif
#endif
