/* -*- c++ -*- ----------------------------------------------------------
   SPH_SOIL package for LAMMPS: the Coulomb interface of frictional walls.

   Part of the walls unit (sph_soil_walls.h owns it). Per step:
   - the pair loop adds each soil-wall pair of a frictional wall whose image pushes the soil
     (normal force N_ab > 0) to its soil particle's contact sums and keeps the pair;
   - after all forces of the step (the pair's and every fix's: the walls' internal fix calls
     apply() at post_force, as the last fix that adds forces), each owned soil particle with a
     contact gets the friction force of soil_wall_friction.h, and each kept pair's wall particle
     the opposite share, ratio * N_ab (Newton's third law: the walls carry the friction, so
     compute reduce on a wall group gives its normal and shear force).
   Communication (through the pair style's, as the extrapolated walls'): the contact sums of
   ghosts to their owners (newton on), the ratio T / N to the ghosts, the walls' shares of
   ghosts to their owners (newton on).
------------------------------------------------------------------------- */

#ifndef LMP_SPH_SOIL_WALL_FRICTION_H
#define LMP_SPH_SOIL_WALL_FRICTION_H

#include "pointers.h"
#include "soil_wall_friction.h"

#include <vector>

namespace LAMMPS_NS {

class SPHSoilWallFriction : protected Pointers {
 public:
  SPHSoilWallFriction(class LAMMPS *, class Pair *owner);
  ~SPHSoilWallFriction() override;

  // before the pair loop: the sums of owned and ghost atoms zeroed, no pairs kept
  void begin_step();
  // a pair of soil particle `soil` and wall particle `wall` (owned or ghost) whose image pushes
  // the soil with N_ab = normal_force > 0 along the wall's normal n; the wall's friction
  // coefficient mu, velocity, adhesion and the pair's contact area (SPHSoil::contact_area()).
  // `to_soil`, `to_wall`: whether this rank adds the pair's terms to the soil particle and to
  // the wall particle (newton off: owned atoms only).
  void add_pair(int soil, int wall, double normal_force, double mu, const double *n,
                const double *wall_velocity, double adhesion, double area, bool to_soil,
                bool to_wall)
  {
    if (to_soil)
      SPHSoil::add_contact(contact + (size_t) soil * SPHSoil::CONTACT_SUMS, normal_force, mu, n,
                           wall_velocity, adhesion, area);
    if (to_wall) pairs.push_back({soil, wall, normal_force});
  }
  // the P-wave speed of each atom type (index 0..ntypes; 0 for walls)
  void set_wave_speeds(const std::vector<double> &speeds) { wave_speed_of_type = speeds; }
  // after every force of the step: the friction forces on the soil and the walls, with the
  // atoms' smoothing lengths; `pressures` the owned atoms' interface pressures (the state of the
  // regularization, soil_wall_friction.h), updated
  void apply(const double *h, double *pressures);
  // stepping per level: the pair style's signed periods of this step's atoms (soil_level_steps.h;
  // nullptr with one global step). A particle that does not end a step has no pair with a wall
  // this step: its interface keeps its state, and one that does relaxes over its own step
  void set_step_periods(const double *periods) { step_periods = periods; }

  // the communication of apply(), handed on by the walls unit
  enum Exchange { CONTACTS, RATIOS, REACTIONS };
  static constexpr int FORWARD_SIZE = 3;
  static constexpr int REVERSE_SIZE = SPHSoil::CONTACT_SUMS;
  int pack_forward_comm(int n, int *list, double *buf);
  void unpack_forward_comm(int n, int first, double *buf);
  int pack_reverse_comm(int n, int first, double *buf);
  void unpack_reverse_comm(int n, int *list, double *buf);
  double memory_usage() const;

 private:
  class Pair *owner;
  struct KeptPair {
    int soil, wall;
    double normal_force;
  };
  std::vector<KeptPair> pairs;
  std::vector<double> wave_speed_of_type;
  int nmax;
  double *contact;     // per atom, SPHSoil::CONTACT_SUMS
  double *ratio;       // per atom, friction force / normal force (3)
  double *reaction;    // per atom, the walls' shares (3)
  const double *step_periods;
  Exchange exchange;
};

}    // namespace LAMMPS_NS

#endif
