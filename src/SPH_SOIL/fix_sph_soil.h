/* -*- c++ -*- ----------------------------------------------------------
   SPH_SOIL package for LAMMPS: fix sph/soil

   Time integration of the soil state (positions, velocities, density,
   stress, accumulated strain) with the kick-drift-kick scheme of fix sph,
   and the constitutive update (Drucker-Prager by default) after each
   stress half step, followed by the return to the admissible set.
   Optional adaptive time step from the CFL condition. Wall particles are
   never integrated. See doc/fix_sph_soil.rst.
------------------------------------------------------------------------- */

#ifdef FIX_CLASS
// clang-format off
FixStyle(sph/soil,FixSPHSoil);
// clang-format on
#else

#ifndef LMP_FIX_SPH_SOIL_H
#define LMP_FIX_SPH_SOIL_H

#include "fix.h"

#include <vector>

namespace SPHSoil {
class ConstitutiveModel;
}

namespace LAMMPS_NS {

class FixSPHSoil : public Fix {
 public:
  FixSPHSoil(class LAMMPS *, int, char **);
  ~FixSPHSoil() override;
  int setmask() override;
  void init() override;
  void setup_pre_force(int) override;
  void setup(int) override;
  void initial_integrate(int) override;
  void final_integrate() override;
  void end_of_step() override;
  void reset_dt() override;
  double compute_vector(int) override;

 protected:
  double dtv, dtf;
  double cfl;           // adaptive time step dt = cfl * min h / c_p (0: fixed time step)
  double stable_cfl;    // largest cfl accepted for a user-fixed time step
  double max_dt;        // upper bound of the adaptive step (0: none)
  class AtomVecSPHSoil *avec;
  class PairSPHSoil *pair;
  std::vector<const SPHSoil::ConstitutiveModel *> model_of_type;    // owned by the pair style
  bigint yielded_count;

  bool integrated(int i) const;
  void update_stress(int i);
  void check_state(int i);
  double stable_timestep();
};

}    // namespace LAMMPS_NS

#endif
#endif
