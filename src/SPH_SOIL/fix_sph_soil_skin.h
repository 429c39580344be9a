/* -*- c++ -*- ----------------------------------------------------------
   SPH_SOIL package for LAMMPS: fix SPH_SOIL_SKIN, internal.

   pair_style sph/soil's own neighbour list gives a particle of smaller h a
   smaller skin (soil_neighbours.h; doc/theory.rst 5.8), which LAMMPS's check
   (one skin, the largest particles') does not know. This fix, which the pair
   style creates, makes LAMMPS reneighbour at a step where some particle (soil
   or wall, moved by any fix) has moved half its own skin: after every fix has
   moved its atoms and before Neighbor::decide(). It has nothing to do while
   every particle has the largest h (then LAMMPS's check is this one).
------------------------------------------------------------------------- */

#ifdef FIX_CLASS
// clang-format off
FixStyle(SPH_SOIL_SKIN,FixSPHSoilSkin);
// clang-format on
#else

#ifndef LMP_FIX_SPH_SOIL_SKIN_H
#define LMP_FIX_SPH_SOIL_SKIN_H

#include "fix.h"

namespace SPHSoil {
class NeighbourList;
}

namespace LAMMPS_NS {

class FixSPHSoilSkin : public Fix {
 public:
  FixSPHSoilSkin(class LAMMPS *, int, char **);
  int setmask() override;
  void post_integrate() override;

  // the list to watch, and whether it needs watching (the same on every rank)
  void watch(const SPHSoil::NeighbourList *list, bool needed);

 private:
  const SPHSoil::NeighbourList *list;
  bool needed;
};

}    // namespace LAMMPS_NS

#endif
#endif
