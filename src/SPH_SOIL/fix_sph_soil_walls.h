/* -*- c++ -*- ----------------------------------------------------------
   SPH_SOIL package for LAMMPS: fix SPH_SOIL_WALLS, internal.

   The wall particles' kinematics between steps, for pair_style sph/soil
   (whose walls unit, sph_soil_walls.h, creates this fix; users do not):
   after the fixes that move walls (move, rigid, ...) have run, each wall
   particle's velocity goes to vest, the field that the pair loop reads for
   every particle and that travels to the ghosts every step, and its
   acceleration over the last step, (v(t) - v(t - dt)) / dt, is kept for the
   walls that extrapolate the soil's stress (the inertia of a moving wall);
   0 at the start of a run. The acceleration travels with the atom.
------------------------------------------------------------------------- */

#ifdef FIX_CLASS
// clang-format off
FixStyle(SPH_SOIL_WALLS,FixSPHSoilWalls);
// clang-format on
#else

#ifndef LMP_FIX_SPH_SOIL_WALLS_H
#define LMP_FIX_SPH_SOIL_WALLS_H

#include "fix.h"

#include <vector>

namespace LAMMPS_NS {

class FixSPHSoilWalls : public Fix {
 public:
  FixSPHSoilWalls(class LAMMPS *, int, char **);
  ~FixSPHSoilWalls() override;
  int setmask() override;
  void init() override;
  void post_integrate() override;

  // which atom types are walls (non-zero), index 0..ntypes
  void set_wall_types(const std::vector<int> &wall_of_type) { is_wall_type = wall_of_type; }
  // the acceleration of owned wall particle i over the last step
  const double *acceleration(int i) const { return accelerations[i]; }

  void grow_arrays(int) override;
  void copy_arrays(int, int, int) override;
  int pack_exchange(int, double *) override;
  int unpack_exchange(int, double *) override;
  double memory_usage() override;

 private:
  std::vector<int> is_wall_type;
  double **accelerations;
  void velocities_to_estimate(bool start);
};

}    // namespace LAMMPS_NS

#endif
#endif
