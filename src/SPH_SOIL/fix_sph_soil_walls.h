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

   With frictional walls, the walls unit also hands it what must run after
   every force of the step (set_after_forces(): the Coulomb interface's
   friction forces), which it calls at post_force; the walls unit keeps it the
   last fix that adds forces.
------------------------------------------------------------------------- */

#ifdef FIX_CLASS
// clang-format off
FixStyle(SPH_SOIL_WALLS,FixSPHSoilWalls);
// clang-format on
#else

#ifndef LMP_FIX_SPH_SOIL_WALLS_H
#define LMP_FIX_SPH_SOIL_WALLS_H

#include "fix.h"

#include <functional>
#include <vector>

namespace LAMMPS_NS {

class FixSPHSoilWalls : public Fix {
 public:
  FixSPHSoilWalls(class LAMMPS *, int, char **);
  ~FixSPHSoilWalls() override;
  int setmask() override;
  void init() override;
  void post_integrate() override;
  void setup(int) override;
  void post_force(int) override;

  // the walls unit that created it (one per LAMMPS instance: its ID is fixed, see sph_soil_walls)
  const void *owner = nullptr;
  // which atom types are walls (non-zero), index 0..ntypes
  void set_wall_types(const std::vector<int> &wall_of_type) { is_wall_type = wall_of_type; }
  // what runs after every other force of the step (nothing if empty)
  void set_after_forces(std::function<void()> work) { after_forces = std::move(work); }
  // the acceleration of owned wall particle i over the last step
  const double *acceleration(int i) const { return accelerations[i]; }
  // per atom: the interface pressure of a frictional wall's contact (SPHSoil::NO_CONTACT: none)
  double *interface_pressures() { return pressures; }

  void grow_arrays(int) override;
  void copy_arrays(int, int, int) override;
  void set_arrays(int) override;
  int pack_exchange(int, double *) override;
  int unpack_exchange(int, double *) override;
  int pack_restart(int, double *) override;
  void unpack_restart(int, int) override;
  int maxsize_restart() override;
  int size_restart(int) override;
  double memory_usage() override;

 private:
  std::vector<int> is_wall_type;
  double **accelerations;
  double *pressures;
  std::function<void()> after_forces;
  void velocities_to_estimate(bool start);
};

}    // namespace LAMMPS_NS

#endif
#endif
