/* -*- c++ -*- ----------------------------------------------------------
   SPH_SOIL package for LAMMPS: fix sph/soil

   Time integration of the soil state: velocity Verlet for positions and
   velocities, a Heun predictor-corrector for density, accumulated strain
   and stress (doc/theory.rst section 4.1), each stress update followed by
   the constitutive model's return to the admissible set. Optional adaptive
   time step from the CFL condition, for every fix; optionally a time step
   per level (stepping level: soil_level_steps.h, doc/theory.rst 5.12). Wall
   particles are never integrated (their kinematics are the pair style's:
   sph_soil_walls.h).
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
#include "soil_level_steps.h"

#include <string>
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
  void final_integrate() override;
  void end_of_step() override;
  void reset_dt() override;
  void post_run() override;
  double compute_vector(int) override;
  // extract("sph_soil_integrator") (SPHSoilFixes::INTEGRATOR): this fix, for the package's code
  // that finds fixes by what they do
  void *extract(const char *, int &) override;

  // after particles were split (smaller h): adapt the time step (cfl), or stop with an error
  // if the user's fixed step is now above the stability limit
  void particles_refined(const char *who);
  // the time-step hierarchy (one global step unless 'stepping level')
  const SPHSoil::StepSchedule &step_schedule() const { return schedule; }

  // the Heun predictor's rates travel with the atoms (they migrate between the predictor and
  // the corrector)
  void grow_arrays(int) override;
  void copy_arrays(int, int, int) override;
  void set_arrays(int) override;
  // with stepping level, each particle's own step (mid-step too) goes into restart files
  int pack_restart(int, double *) override;
  void unpack_restart(int, int) override;
  int maxsize_restart() override;
  int size_restart(int) override;
  int pack_exchange(int, double *) override;
  int unpack_exchange(int, double *) override;
  // the elapsed time, with a format number (see write_restart())
  void write_restart(FILE *) override;
  void restart(char *) override;
  static constexpr int RESTART_FORMAT = 2;
  double memory_usage() override;

 protected:
  double dtv, dtf;
  double cfl;           // adaptive time step dt = cfl * min h / c_p (0: fixed time step)
  double stable_cfl;    // largest cfl accepted for a user-fixed time step
  double max_dt;        // upper bound of the adaptive step (0: none)
  // 'others allow': other fixes (fix rigid, fix move, fix nve, ...) may move particles this fix
  // integrates; by default a run stops (check_integrators())
  bool others_allowed = false;
  // the pore pressure's largest diffusivity (soil_pore_water.h; 0 without saturated soil) and
  // the bound it puts on the step, dt <= DIFFUSION_NUMBER h^2 / D
  double max_diffusivity;
  // whether it changes with the densities (a permeability law): found at every step
  bool variable_diffusivity = false;
  static constexpr double DIFFUSION_NUMBER = 0.1;
  double viscosity_factor = 1.0;    // pair sph/soil's viscosity_step_factor() at min(h), last
  bool diffusion_bound;    // whether the last stable_timestep() was the diffusion's
  std::string stability_bound() const;
  SPHSoil::StepSchedule schedule;    // the time step per level (stepping level), or off
  class AtomVecSPHSoil *avec;
  class PairSPHSoil *pair;
  // the pair style's stress diffusion, whose rates the corrector adds, or nullptr
  const class SPHSoilStressDiffusion *diffusion = nullptr;
  std::vector<const SPHSoil::ConstitutiveModel *> model_of_type;    // owned by the pair style
  std::vector<double> density_floor_of_type;    // SPHSoil::DENSITY_FLOOR of the material's rho0
  // K_w / n of a saturated soil type (soil_pore_water.h), 0 for a dry one: dp/dt = K_w / n
  // (-div v + the pair style's pore flow)
  std::vector<double> storage_of_type;
  double pore_pressure_rate(int i) const;
  // K_w of a free water type (soil_water.h), 0 otherwise: its pressure follows its density
  std::vector<double> water_modulus_of_type;
  // whether a type exchanges water with its partners (a saturated soil's pores, free water):
  // the water brings its mass and momentum (exchange_water())
  std::vector<int> exchanges_of_type;
  void exchange_water(int i, double step) const;
  void water_pressure(int i) const;
  bigint yielded_count;

  // The integrator's own per-atom state, one row per atom (the current rates live in the atom
  // style, where the pair style writes them): at the start of each step, the density's
  // logarithmic rate (drho / rho), the strain rate and the pore pressure's rate, for the Heun
  // corrector. (The rates of
  // the last step of a run, which the next run starts from, are the atom style's saved_rates.)
  // Stepping per level adds the particle's own step: the LAMMPS steps it began and ends at, its
  // duration (s), the increments of its density, stress and pore pressure per time step (from
  // the start to the predictor's state at the end) and that end state, its velocity at the start
  // and the
  // mean acceleration of its last step (the velocity partners see of it between its steps' ends).
  enum {
    HEUN_LOG_DRHO = 0,
    HEUN_STRAIN_RATE = 1,
    HEUN_PORE_RATE = 7,
    NSTATE_GLOBAL = 8,
    STEP_BEGIN = 8,
    STEP_END = 9,
    STEP_DURATION = 10,
    RHO_INCREMENT = 11,
    STRESS_INCREMENT = 12,
    END_RHO = 18,
    END_STRESS = 19,
    BEGIN_VELOCITY = 25,
    MEAN_ACCELERATION = 28,
    PORE_INCREMENT = 31,
    END_PORE = 32,
    NSTATE_LEVELS = 33
  };
  int nstate;
  double **integrator_state;
  // the Heun predictor over a step of `step` (a full step with the rates of its start, which
  // the corrector keeps), and the corrector with half that step; true if the corrected stress
  // was returned to the yield surface
  // (PRESSURES: some type is a saturated soil or free water, whose pressures the integrator steps
  // or sets; the loops of runs without are compiled without those branches)
  template <bool PRESSURES> void predict(int i, double step);
  template <bool PRESSURES> bool correct(int i, double half_step);
  template <bool PRESSURES> void initial_integrate_global();
  template <bool PRESSURES> void initial_integrate_levels();
  template <bool LEVELS, bool PRESSURES> void kick_and_correct();
  bool pressures;
  // the hierarchy from the smallest and largest h (collective)
  void update_schedule(double min_h, double max_h);
  bool restore_pending;    // at the first step of a run: restore the saved rates
  void save_rates(int i) const;
  void restore_rates(int i);

  void check_integrators();
  bool integrated(int i) const
  {
    const int type = atom->type[i];
    return (atom->mask[i] & groupbit) && type < (int) model_of_type.size() && model_of_type[type];
  }
  template <bool PRESSURES> bool unstable(int i) const;
  // whether atom i has a lower ID than atom j (any, if j < 0)
  bool lower_id(int i, int j) const { return j < 0 || atom->tag[i] < atom->tag[j]; }
  void stop_if_unstable(int first_unstable);
  void box_limits(double lo[3], double hi[3]) const;
  // a position beyond the box's fixed faces (or not finite): the lowest ID of each kind
  void check_position(int i, const double lo[3], const double hi[3], int &first_unstable,
                      int &first_outside) const;
  void stop_if_left_box(int first_outside);
  std::string likely_causes(double density, double reference_density);
  double stable_timestep();
  void smoothing_length_range(double &min_h, double &max_h);
  void adapt_timestep();
};

}    // namespace LAMMPS_NS

#endif
#endif
