/* -*- c++ -*- ----------------------------------------------------------
   SPH_SOIL package for LAMMPS: fix sph/soil

   Time integration of the soil state: velocity Verlet for positions and
   velocities, a Heun predictor-corrector for density, accumulated strain
   and stress (doc/theory.rst section 4.1), each stress update followed by
   the constitutive model's return to the admissible set. Optional adaptive
   time step from the CFL condition. Wall particles are never integrated.
   See doc/fix_sph_soil.rst.
------------------------------------------------------------------------- */

#ifdef FIX_CLASS
// clang-format off
FixStyle(sph/soil,FixSPHSoil);
// clang-format on
#else

#ifndef LMP_FIX_SPH_SOIL_H
#define LMP_FIX_SPH_SOIL_H

#include "atom.h"
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
  void setup(int) override;
  void initial_integrate(int) override;
  void post_integrate() override;
  void final_integrate() override;
  void end_of_step() override;
  void reset_dt() override;
  void post_run() override;
  double compute_vector(int) override;

  // the acceleration of wall particle i (owned) over the last step, (v(t) - v(t - dt)) / dt,
  // for walls that extrapolate the soil's stress (pair_style sph/soil: the inertia of a
  // moving wall); 0 at the start of a run
  const double *wall_acceleration(int i) const { return integrator_state[i] + WALL_ACCELERATION; }

  // after particles were split (smaller h): adapt the time step (cfl), or stop with an error
  // if the user's fixed step is now above the stability limit
  void particles_refined(const char *who);

  // the rates of the last step travel with the atoms, into restart files and the next run
  void grow_arrays(int) override;
  void copy_arrays(int, int, int) override;
  int pack_exchange(int, double *) override;
  int unpack_exchange(int, double *) override;
  void write_restart(FILE *) override;
  void restart(char *) override;
  int pack_restart(int, double *) override;
  void unpack_restart(int, int) override;
  int maxsize_restart() override;
  int size_restart(int) override;
  double memory_usage() override;

 protected:
  double dtv, dtf;
  double cfl;           // adaptive time step dt = cfl * min h / c_p (0: fixed time step)
  double stable_cfl;    // largest cfl accepted for a user-fixed time step
  double max_dt;        // upper bound of the adaptive step (0: none)
  class AtomVecSPHSoil *avec;
  class PairSPHSoil *pair;
  std::vector<const SPHSoil::ConstitutiveModel *> model_of_type;    // owned by the pair style
  std::vector<int> wall_type;    // per type: 1 for the pair style's wall types
  bool first_integrator;   // the first fix sph/soil does it for all walls, and the skin check
  void walls_velocity_to_estimate(bool start);
  void reneighbour_if_skin_used();
  bigint yielded_count;

  // The integrator's own per-atom state, one row per atom (the current rates live in the atom
  // style, where the pair style writes them):
  //  - at the start of each step, the density rate and strain rate, for the Heun corrector;
  //  - the rates of the last step (acceleration, density rate, strain rate, stress rate), saved
  //    at the end of a run and in restart files, and used by the first half step of the next
  //    run instead of the rates that setup recomputes from the full-step state: so a
  //    restarted or continued run is identical to an uninterrupted one. SAVED is 1 when they
  //    are there to be restored.
  // Atoms migrate between the predictor and the corrector: the row travels with them.
  // A wall particle's row holds its acceleration (the first 3 values) and nothing else.
  enum {
    WALL_ACCELERATION = 0,      // 3, wall particles only
    HEUN_DRHO = 0,
    HEUN_STRAIN_RATE = 1,       // 6
    SAVED = 7,                  // the saved block: flag, then NSAVED rates
    SAVED_ACCELERATION = 8,     // 3
    SAVED_DRHO = 11,
    SAVED_STRAIN_RATE = 12,     // 6
    SAVED_STRESS_RATE = 18,     // 6
    NSTATE = 24,
    NSAVED = NSTATE - SAVED - 1
  };
  double **integrator_state;
  int allocated_rows;
  bool restore_pending;
  void save_rates(int i, double *block) const;
  void restore_rates(int i);

  bool integrated(int i) const
  {
    const int type = atom->type[i];
    return (atom->mask[i] & groupbit) && type < (int) model_of_type.size() && model_of_type[type];
  }
  bool unstable(int i) const;
  // whether atom i has a lower ID than atom j (any, if j < 0)
  bool lower_id(int i, int j) const { return j < 0 || atom->tag[i] < atom->tag[j]; }
  void stop_if_unstable(int first_unstable);
  double stable_timestep();
  void adapt_timestep();
};

}    // namespace LAMMPS_NS

#endif
#endif
