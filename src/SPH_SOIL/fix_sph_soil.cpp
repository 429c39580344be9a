/* ----------------------------------------------------------------------
   SPH_SOIL package for LAMMPS: fix sph/soil
------------------------------------------------------------------------- */

#include "fix_sph_soil.h"

#include "atom.h"
#include "atom_vec_sph_soil.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "force.h"
#include "group.h"
#include "memory.h"
#include "modify.h"
#include "output.h"
#include "pair_sph_soil.h"
#include "soil_constitutive.h"
#include "soil_density_step.h"
#include "soil_water.h"
#include "sph_soil_compat.h"
#include "sph_soil_fixes.h"
#include "sph_soil_input.h"
#include "sph_soil_offenders.h"
#include "sph_soil_pore_water.h"
#include "sph_soil_stress_diffusion.h"
#include "thermo.h"
#include "update.h"
#include "utils.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <functional>
#include <utility>
#include <vector>

using namespace LAMMPS_NS;
using namespace FixConst;

namespace {
constexpr double BIG = 1.0e30;
}

// the predictor and the corrector, inlined into each integration loop (as one function each
// they cost a call per particle and the loops' registers: +3% instructions per particle-step)
#if defined(__GNUC__)
#define SPH_SOIL_INLINE inline __attribute__((always_inline))
#else
#define SPH_SOIL_INLINE inline
#endif

/* ---------------------------------------------------------------------- */

FixSPHSoil::FixSPHSoil(LAMMPS *lmp, int narg, char **arg) :
    Fix(lmp, narg, arg), cfl(0.0), stable_cfl(0.2), max_dt(0.0), max_diffusivity(0.0),
    diffusion_bound(false), avec(nullptr), pair(nullptr),
    yielded_count(0), nstate(NSTATE_GLOBAL), integrator_state(nullptr), pressures(false),
    restore_pending(false)
{
  time_integrate = 1;
  restart_global = 1;
  vector_flag = 1;
  size_vector = 4;
  global_freq = 1;
  extvector = 0;

  // the keywords and how each reads its value: the one list of them, which the error shows
  using namespace SPHSoilInput;
  const std::vector<std::pair<std::string, std::function<void(const char *)>>> keywords = {
      {"cfl", [&](const char *value) {
         cfl = number(FLERR, lmp, "fix sph/soil cfl", value, between(0.0, 1.0, true, false));
       }},
      {"dtmax", [&](const char *value) {
         max_dt = number(FLERR, lmp, "fix sph/soil dtmax", value, above(0.0));
       }},
      {"stepping", [&](const char *value) {
         schedule.per_level = choice(FLERR, lmp, "fix sph/soil stepping", value, {"global", "level"}) == 1;
       }},
      {"others", [&](const char *value) {
         others_allowed = choice(FLERR, lmp, "fix sph/soil others", value, {"error", "allow"}) == 1;
       }},
  };
  for (int iarg = 3; iarg < narg; iarg += 2) {
    if (iarg + 1 >= narg)
      SPHSoilCompat::error_all(lmp, FLERR, "Illegal fix sph/soil command: keyword {} needs a value",
                               arg[iarg]);
    auto keyword = std::find_if(keywords.begin(), keywords.end(),
                                [&](const decltype(keywords[0]) &k) { return k.first == arg[iarg]; });
    if (keyword == keywords.end()) {
      std::string allowed;
      for (const auto &k : keywords) allowed += (allowed.empty() ? "" : ", ") + k.first;
      SPHSoilCompat::error_all(lmp, FLERR, "Illegal fix sph/soil keyword {} (allowed: {})", arg[iarg],
                               allowed);
    }
    keyword->second(arg[iarg + 1]);
  }
  if (schedule.per_level) nstate = NSTATE_LEVELS;
  avec = dynamic_cast<AtomVecSPHSoil *>(atom->style_match("sph/soil"));
  if (!avec) SPHSoilCompat::error_all(lmp, FLERR, "Fix sph/soil requires atom_style sph/soil");
  if (max_dt > 0.0 && cfl == 0.0)
    SPHSoilCompat::error_all(
        lmp, FLERR,
        "Illegal fix sph/soil dtmax {}: it bounds the adaptive time step, which needs "
        "'cfl C' too",
        max_dt);
  // the largest C_cfl measured stable with a fixed step (see setup()): the documented range
  // of cfl goes higher for a smooth, slow flow, but most runs will not survive it
  if (cfl > stable_cfl && comm->me == 0)
    error->warning(FLERR, "Fix sph/soil cfl {}: above {}, the largest value measured stable (a "
                          "geostatic column); expect the run to go unstable, 0.1 to 0.2 is usual",
                   cfl, stable_cfl);

  // (atoms created later get their rows from set_arrays())
  create_attribute = 1;
  grow_arrays(atom->nmax);
  for (int i = 0; i < atom->nmax; i++) set_arrays(i);
  atom->add_callback(Atom::GROW);
  // each particle's own step, in restart files: a run continues exactly at any step
  if (schedule.per_level) {
    restart_peratom = 1;
    atom->add_callback(Atom::RESTART);
  }
}

/* ---------------------------------------------------------------------- */

FixSPHSoil::~FixSPHSoil()
{
  atom->delete_callback(id, Atom::GROW);
  if (restart_peratom) atom->delete_callback(id, Atom::RESTART);
  memory->destroy(integrator_state);
}

/* ---------------------------------------------------------------------- */

int FixSPHSoil::setmask()
{
  return INITIAL_INTEGRATE | FINAL_INTEGRATE | END_OF_STEP;
}

/* ---------------------------------------------------------------------- */

void FixSPHSoil::init()
{
  pair = dynamic_cast<PairSPHSoil *>(force->pair_match("sph/soil", 1));
  if (!pair) SPHSoilCompat::error_all(lmp, FLERR, "Fix sph/soil requires pair_style sph/soil");
  avec = dynamic_cast<AtomVecSPHSoil *>(atom->style_match("sph/soil"));

  model_of_type.assign(atom->ntypes + 1, nullptr);
  density_floor_of_type.assign(atom->ntypes + 1, 0.0);
  storage_of_type.assign(atom->ntypes + 1, 0.0);
  water_modulus_of_type.assign(atom->ntypes + 1, 0.0);
  exchanges_of_type.assign(atom->ntypes + 1, 0);
  pressures = pair->carries_pressures();
  diffusion = pair->stress_diffusion_unit();
  variable_diffusivity = pair->pore_water_unit().variable_conductivity();
  max_diffusivity = 0.0;
  for (int type = 1; type <= atom->ntypes; type++) {
    model_of_type[type] = pair->model(type);
    if (!model_of_type[type]) continue;
    const auto &material = pair->material(type);
    density_floor_of_type[type] = SPHSoil::DENSITY_FLOOR * material.density;
    if (material.water) {
      water_modulus_of_type[type] = material.model->p_wave_modulus();
      exchanges_of_type[type] = 1;
    }
    if (material.saturated) {
      exchanges_of_type[type] = 1;
      storage_of_type[type] = material.pore_water.storage_modulus();
      max_diffusivity = MAX(max_diffusivity, material.pore_water.diffusivity());
    }
  }

  check_integrators();
  // a group without soil particles is integrated by no one (wall particles never move)
  bigint soil = 0, all_soil = 0;
  for (int i = 0; i < atom->nlocal; i++)
    if (integrated(i)) soil++;
  MPI_Allreduce(&soil, &all_soil, 1, MPI_LMP_BIGINT, MPI_SUM, world);
  if (all_soil == 0 && comm->me == 0)
    error->warning(FLERR, "Fix sph/soil {}: group {} holds no soil particle (wall particles are "
                          "never integrated): this fix moves nothing", id, group->names[igroup]);

  // the rates of the first force evaluation use vest: start it at v, and free water's pressure
  // at that of its density (ghosts, made later at setup, take them from their owners)
  const int nlocal = atom->nlocal;
  for (int i = 0; i < nlocal; i++)
    if (integrated(i)) {
      for (int k = 0; k < 3; k++) atom->vest[i][k] = atom->v[i][k];
      water_pressure(i);
    }

  // (stable_timestep() sets the hierarchy of stepping per level too)
  const double dt = stable_timestep();
  if (cfl > 0.0 && dt != update->dt) {
    update->update_time();
    update->dt = dt;
    update->dt_default = 0;
  }
  reset_dt();
}

/* ----------------------------------------------------------------------
   one integrator per particle. Two fixes sph/soil over the same particles would each advance
   them, a step of 2 dt. Another fix that moves atoms (fix rigid and its variants, fix move, fix
   nve, ...: SPHSoilFixes::moves_atoms) would move the soil and free water this fix integrates a
   second time each step, while their density and stress follow this fix alone: an error too,
   unless 'others allow' says the user means it. Wall particles are never integrated here, so
   structures of wall particles under those fixes stay legal. Collective.
------------------------------------------------------------------------- */

void FixSPHSoil::check_integrators()
{
  const int *mask = atom->mask;
  for (int ifix = 0; ifix < modify->nfix; ifix++) {
    Fix *other = modify->fix[ifix];
    if (other == this) continue;
    const bool integrator = dynamic_cast<FixSPHSoil *>(other) != nullptr;
    if (!integrator && (others_allowed || !SPHSoilFixes::moves_atoms(other))) continue;
    const int otherbit = other->groupbit;
    const auto both = SPHSoilOffenders::find_offenders(
        lmp, [&](int i) { return integrated(i) && (mask[i] & otherbit); },
        [&](int i, double *values) { values[0] = atom->type[i]; });
    if (!both) continue;
    if (integrator)
      SPHSoilCompat::error_all(
          lmp, FLERR,
          "Fix sph/soil {} and {} both integrate {} particle(s) (e.g. atom {}); "
          "integrate each particle with one fix",
          id, other->id, both.count, both.first);
    SPHSoilCompat::error_all(
        lmp, FLERR,
        "Fix sph/soil {} and fix {} ({}) both move {} particle(s) (e.g. atom {} of type {}): "
        "fix sph/soil integrates soil and free water, and a particle that two fixes move "
        "moves twice per step; make a structure of wall particles (pair_coeff I I wall), which "
        "fix sph/soil never moves, or add 'others allow' to fix sph/soil {} if fix {} is meant "
        "to move them too",
        id, other->id, other->style, both.count, both.first, (int) both.values[0], id, other->id);
  }
}

/* ---------------------------------------------------------------------- */

void FixSPHSoil::reset_dt()
{
  dtv = update->dt;
  dtf = 0.5 * update->dt;
}

/* ---------------------------------------------------------------------- */


/* ----------------------------------------------------------------------
   the first half step of the stress needs the rate at the start
------------------------------------------------------------------------- */

void FixSPHSoil::setup(int /*vflag*/)
{
  restore_pending = true;
  const int nlocal = atom->nlocal;
  // a density below the floor is not a state of the soil (doc/theory.rst 2.1): the steps would
  // lift it at once, so it is an input error (a density never set, most likely)
  const auto thin = SPHSoilOffenders::find_offenders(
      lmp, [&](int i) { return integrated(i) && atom->rho[i] < density_floor_of_type[atom->type[i]]; },
      [&](int i, double *values) {
        values[0] = atom->rho[i];
        values[1] = pair->material(atom->type[i]).density;
      });
  if (thin)
    SPHSoilCompat::error_all(
        lmp, FLERR,
        "Fix sph/soil: {} soil particle(s) have a density below exp(-1) = {:.3f} times "
        "their material's rho0, the least a soil particle can have (atom {}: {} "
        "against rho0 {}); set it with 'sph_soil/set <group> density'",
        thin.count, SPHSoil::DENSITY_FLOOR, thin.first, thin.values[0], thin.values[1]);
  for (int i = 0; i < nlocal; i++)
    if (integrated(i))
      model_of_type[atom->type[i]]->stress_rate(avec->stress[i], avec->strain_rate[i], avec->spin[i],
                                                avec->stress_rate[i]);
  if (cfl == 0.0) {
    // measured: a geostatic column with the paper's viscosity (alpha = 0.1) stays at rest
    // up to 0.195 h/c_p; the usual C_cfl range is 0.1 to 0.2 (doc/theory.rst section 4)
    const double limit = stable_timestep();
    if (update->dt > limit)
      SPHSoilCompat::error_all(lmp, FLERR,
                               "Fix sph/soil: timestep {:.6g} exceeds the stability limit {:.6g} = "
                               "{}; use a smaller timestep or 'cfl 0.1'",
                               update->dt, limit, stability_bound());
  }
}

/* ---------------------------------------------------------------------- */

void FixSPHSoil::initial_integrate(int /*vflag*/)
{
  double **x = atom->x, **v = atom->v, **f = atom->f, **vest = atom->vest;
  double *rmass = atom->rmass;
  const int nlocal = atom->nlocal;

  if (restore_pending) {
    for (int i = 0; i < nlocal; i++)
      if (integrated(i) && avec->saved_rates[i][AtomVecSPHSoil::SAVED_FLAG] != 0.0) restore_rates(i);
    restore_pending = false;
  }
  // (runs without pore water or free water: the loops without their branches)
  if (schedule.per_level) {
    if (pressures) return initial_integrate_levels<true>();
    return initial_integrate_levels<false>();
  }
  if (pressures) return initial_integrate_global<true>();
  initial_integrate_global<false>();
}

template <bool PRESSURES> void FixSPHSoil::initial_integrate_global()
{
  double **x = atom->x, **v = atom->v, **f = atom->f, **vest = atom->vest;
  double *rmass = atom->rmass;
  const int nlocal = atom->nlocal;
  int first_unstable = -1, first_outside = -1;
  double lo[3], hi[3];
  box_limits(lo, hi);
  for (int i = 0; i < nlocal; i++) {
    if (!integrated(i)) continue;
    // velocity Verlet for x, v; vest estimates v(t + dt) for the rates
    const double dtfm = dtf / rmass[i];
    for (int a = 0; a < 3; a++) {
      vest[i][a] = v[i][a] + 2.0 * dtfm * f[i][a];
      v[i][a] += dtfm * f[i][a];
      x[i][a] += dtv * v[i][a];
    }
    predict<PRESSURES>(i, dtv);
    if (PRESSURES) water_pressure(i);
    check_position(i, lo, hi, first_unstable, first_outside);
  }
  stop_if_unstable(first_unstable);
  stop_if_left_box(first_outside);
}

// The positions only (a non-finite velocity makes them non-finite): what LAMMPS checks before
// the next neighbour list; the whole state is checked after the corrector. The comparisons are
// false for a NaN too.
SPH_SOIL_INLINE void FixSPHSoil::check_position(int i, const double lo[3], const double hi[3],
                                                int &first_unstable, int &first_outside) const
{
  const double *x = atom->x[i];
  if (x[0] >= lo[0] && x[0] < hi[0] && x[1] >= lo[1] && x[1] < hi[1] && x[2] >= lo[2] && x[2] < hi[2])
    return;
  if (!std::isfinite(x[0] + x[1] + x[2])) {
    if (lower_id(i, first_unstable)) first_unstable = i;
  } else if (lower_id(i, first_outside)) {
    first_outside = i;
  }
}

/* ----------------------------------------------------------------------
   where the particles may go: within a fixed ('f') boundary of an orthogonal box, unless the
   run ignores lost atoms (thermo_modify lost ignore); unbounded elsewhere
------------------------------------------------------------------------- */

void FixSPHSoil::box_limits(double lo[3], double hi[3]) const
{
  const bool bounded = !domain->triclinic && output->thermo->lostflag != Thermo::IGNORE;
  for (int a = 0; a < 3; a++) {
    lo[a] = bounded && domain->boundary[a][0] == 1 ? domain->boxlo[a] : -INFINITY;
    hi[a] = bounded && domain->boundary[a][1] == 1 ? domain->boxhi[a] : INFINITY;
  }
}

// A particle beyond a fixed boundary would be lost at the next neighbour list, and LAMMPS's
// "Lost atoms" names none: the run stops here instead, naming it (collective).
void FixSPHSoil::stop_if_left_box(int first_outside)
{
  const auto outside = SPHSoilOffenders::reduce_offenders(
      lmp, first_outside >= 0 ? 1 : 0, first_outside, [&](int i, double *values) {
        for (int a = 0; a < 3; a++) {
          values[a] = atom->x[i][a];
          values[3 + a] = atom->v[i][a];
        }
      });
  if (!outside) return;
  const double *s = outside.values;
  SPHSoilCompat::error_all(
      lmp, FLERR,
      "Fix sph/soil: particle {} left the box through a fixed boundary at step {} "
      "(position {} {} {}, velocity {} {} {}); a larger box, or 'thermo_modify lost ignore' "
      "if particles may leave; if it flew off: {}",
      outside.first, update->ntimestep, s[0], s[1], s[2], s[3], s[4], s[5],
      likely_causes(1.0, 1.0));
}

/* ----------------------------------------------------------------------
   second velocity half kick; Heun corrector: y(t+dt) = y(t) + dt/2 (rate(t) + rate(t+dt))
------------------------------------------------------------------------- */

void FixSPHSoil::final_integrate()
{
  if (schedule.per_level)
    pressures ? kick_and_correct<true, true>() : kick_and_correct<true, false>();
  else
    pressures ? kick_and_correct<false, true>() : kick_and_correct<false, false>();
}

// the second kick for all; the corrector for every particle (one global step) or for those
// whose own step ends now (a time step per level, soil_level_steps.h)
template <bool LEVELS, bool PRESSURES> void FixSPHSoil::kick_and_correct()
{
  double **v = atom->v, **f = atom->f;
  const double *rmass = atom->rmass;
  const int nlocal = atom->nlocal;
  const double now = (double) update->ntimestep;
  bigint yielded = 0;
  int first_unstable = -1;

  for (int i = 0; i < nlocal; i++) {
    if (!integrated(i)) continue;
    const double dtfm = dtf / rmass[i];
    for (int a = 0; a < 3; a++) v[i][a] += dtfm * f[i][a];
    if (!LEVELS) {
      if (correct<PRESSURES>(i, dtf)) yielded++;
    } else {
      const double *s = integrator_state[i];
      if (now == s[STEP_END] && correct<PRESSURES>(i, 0.5 * (s[STEP_END] - s[STEP_BEGIN]) * dtv))
        yielded++;
    }
    if (PRESSURES) water_pressure(i);
    if (unstable<PRESSURES>(i) && lower_id(i, first_unstable)) first_unstable = i;
  }
  yielded_count = yielded;
  stop_if_unstable(first_unstable);
}

/* ----------------------------------------------------------------------
   Heun predictor for density, strain and stress: a full step with the old rates, so that the
   force evaluation sees the state at the step's end (a half step would make the scheme first
   order); the old rates are kept for the corrector. The density steps in its logarithm
   (doc/theory.rst 4.1): positive whatever the rate
------------------------------------------------------------------------- */

template <bool PRESSURES> SPH_SOIL_INLINE void FixSPHSoil::predict(int i, double step)
{
  double *rho = atom->rho;
  double *old = integrator_state[i];
  old[HEUN_LOG_DRHO] = atom->drho[i] / rho[i];
  rho[i] = std::max(rho[i] * SPHSoil::density_growth(step * old[HEUN_LOG_DRHO]),
                    density_floor_of_type[atom->type[i]]);
  for (int k = 0; k < 6; k++) {
    old[HEUN_STRAIN_RATE + k] = avec->strain_rate[i][k];
    avec->total_strain[i][k] += step * avec->strain_rate[i][k];
    avec->stress[i][k] += step * avec->stress_rate[i][k];
  }
  if (PRESSURES && storage_of_type[atom->type[i]] > 0.0) {
    old[HEUN_PORE_RATE] = pore_pressure_rate(i);
    avec->pore_pressure[i] += step * old[HEUN_PORE_RATE];
  }
  model_of_type[atom->type[i]]->return_to_admissible(avec->stress[i]);
}

// free water: the pressure of its density (soil_water.h), after each change of the density
SPH_SOIL_INLINE void FixSPHSoil::water_pressure(int i) const
{
  const int type = atom->type[i];
  if (water_modulus_of_type[type] > 0.0)
    avec->pore_pressure[i] = SPHSoil::FreeWater::pressure(
        atom->rho[i], pair->material(type).density, water_modulus_of_type[type]);
}

// The water a saturated soil particle's pores take in from its partners (or give them), and the
// water a free water particle takes from the pores (or gives them), brings its mass and
// momentum over the step (the pair style's moved_water()): the particle's mass and density grow
// alike, so that a soil particle's volume stays its skeleton's (the mixture's density follows
// its porosity: rho_w more per unit of water taken in), and a free water particle is
// compressed by what it takes in (its pressure does the work the pores receive) and then
// expands with it (doc/theory.rst 7.4). Each pair gives one what it takes from the other, so
// that with one time step for all mass and momentum are kept to round-off. (At the corrector,
// with the rates of the state the pair style saw: the exchange is slow.)
SPH_SOIL_INLINE void FixSPHSoil::exchange_water(int i, double step) const
{
  if (!exchanges_of_type[atom->type[i]]) return;
  const double *moved = pair->pore_water_unit().moved_water(i);
  const double mass = atom->rmass[i];
  // (a particle never gives more than a fraction of itself in one step; the floor guards the
  // sign against a wild rate, which the time step's diffusion bound rules out)
  const double after = std::max(mass + step * moved[0], 0.5 * mass);
  double *v = atom->v[i];
  for (int a = 0; a < 3; a++) v[a] = (mass * v[a] + step * moved[1 + a]) / after;
  atom->rho[i] *= after / mass;
  atom->rmass[i] = after;
}

// dp/dt = K_w / n (-div v + div(k / gamma_w grad(p - rho_w g.x))) (soil_pore_water.h), from
// the rates of the last force evaluation
SPH_SOIL_INLINE double FixSPHSoil::pore_pressure_rate(int i) const
{
  const double *strain_rate = avec->strain_rate[i];
  const double divergence = strain_rate[0] + strain_rate[1] + strain_rate[2];
  return storage_of_type[atom->type[i]] * (avec->pore_flow[i] - divergence);
}

// Heun corrector: y(t + dt) = y(t) + dt/2 (rate(t) + rate(t + dt)), the predictor having made
// the full step with rate(t)
template <bool PRESSURES> SPH_SOIL_INLINE bool FixSPHSoil::correct(int i, double half_step)
{
  // (first: the exchange's volumes are those of the state the pair style saw)
  if (PRESSURES) exchange_water(i, 2.0 * half_step);
  double *rho = atom->rho;
  const double *old = integrator_state[i];
  rho[i] = std::max(rho[i] * SPHSoil::density_growth(half_step * (atom->drho[i] / rho[i] - old[HEUN_LOG_DRHO])),
                    density_floor_of_type[atom->type[i]]);
  for (int k = 0; k < 6; k++)
    avec->total_strain[i][k] += half_step * (avec->strain_rate[i][k] - old[HEUN_STRAIN_RATE + k]);
  if (PRESSURES && storage_of_type[atom->type[i]] > 0.0)
    avec->pore_pressure[i] += half_step * (pore_pressure_rate(i) - old[HEUN_PORE_RATE]);

  const auto model = model_of_type[atom->type[i]];
  double *stress = avec->stress[i];
  double *stress_rate = avec->stress_rate[i];
  double new_rate[6];
  model->stress_rate(stress, avec->strain_rate[i], avec->spin[i], new_rate);
  for (int k = 0; k < 6; k++) {
    stress[k] += half_step * (new_rate[k] - stress_rate[k]);
    stress_rate[k] = new_rate[k];
  }
  // the stress diffusion (doc/theory.rst 2.8): over the whole step at the rate of the state the
  // predictor reached (a stabiliser, first order is enough), before the return
  if (diffusion) {
    const double *diffused = diffusion->rate(i);
    for (int k = 0; k < 6; k++) stress[k] += 2.0 * half_step * diffused[k];
  }
  return model->return_to_admissible(stress);
}

/* ----------------------------------------------------------------------
   a time step per level (soil_level_steps.h, doc/theory.rst 5.12). This LAMMPS step is a
   sub-step of dt that ends at step `now`. Every particle gets the kicks of the forces of the last
   evaluation (weighted by the pair style: impulses of each pair's own period, and the body
   forces of every step) and drifts; a particle whose own step begins now predicts its state
   for the step's end; the others show their partners the state interpolated to `now`.
------------------------------------------------------------------------- */

template <bool PRESSURES> void FixSPHSoil::initial_integrate_levels()
{
  double **x = atom->x, **v = atom->v, **f = atom->f, **vest = atom->vest;
  double **stress = avec->stress;
  double *rho = atom->rho, *pore = avec->pore_pressure;
  const double *rmass = atom->rmass, *h = avec->smoothing_length;
  const int nlocal = atom->nlocal;
  const int64_t now = update->ntimestep;
  const double begun = (double) (now - 1), ends = (double) now;

  int first_unstable = -1, first_outside = -1;
  double lo[3], hi[3];
  box_limits(lo, hi);
  for (int i = 0; i < nlocal; i++) {
    if (!integrated(i)) continue;
    const double dtfm = dtf / rmass[i];
    double v_start[3];
    for (int a = 0; a < 3; a++) {
      v_start[a] = v[i][a];
      v[i][a] += dtfm * f[i][a];
      x[i][a] += dtv * v[i][a];
    }
    double *s = integrator_state[i];
    // a new step: after the last one ended, and for a particle without one (new, or steps
    // renumbered by reset_timestep); one that begins off its period's multiples (a run's start)
    // is shortened to the next
    if (begun >= s[STEP_END] || begun < s[STEP_BEGIN]) {
      const int period = SPHSoil::step_period(h[i], schedule.finest_h);
      const bool continues = begun == s[STEP_END] && s[STEP_DURATION] > 0.0;
      s[STEP_BEGIN] = begun;
      s[STEP_END] = (double) SPHSoil::step_end(now - 1, period);
      const double length = s[STEP_END] - s[STEP_BEGIN], duration = length * dtv;
      if (length == 1.0) {
        // a step of one time step: the global scheme (its estimate of v(t + dt) included)
        s[STEP_DURATION] = duration;
        for (int a = 0; a < 3; a++) {
          s[BEGIN_VELOCITY + a] = v_start[a];
          vest[i][a] = v_start[a] + 2.0 * dtfm * f[i][a];
        }
        predict<PRESSURES>(i, duration);
      } else {
        // the mean acceleration of the step that ended now (the velocity's change over it,
        // every kick included); a particle without one: its forces of now, spread over its step
        for (int a = 0; a < 3; a++) {
          s[MEAN_ACCELERATION + a] = continues
              ? (v_start[a] - s[BEGIN_VELOCITY + a]) / s[STEP_DURATION]
              : 2.0 * dtfm * f[i][a] / duration;
          s[BEGIN_VELOCITY + a] = v_start[a];
          vest[i][a] = v_start[a] + dtv * s[MEAN_ACCELERATION + a];
        }
        s[STEP_DURATION] = duration;
        const double begin_rho = rho[i], begin_pore = PRESSURES ? pore[i] : 0.0;
        double begin_stress[6];
        for (int k = 0; k < 6; k++) begin_stress[k] = stress[i][k];
        predict<PRESSURES>(i, duration);
        // partners see the state interpolated between the start and the prediction
        s[END_RHO] = rho[i];
        s[RHO_INCREMENT] = (rho[i] - begin_rho) / length;
        rho[i] = begin_rho + s[RHO_INCREMENT];
        if (PRESSURES) {
          s[END_PORE] = pore[i];
          s[PORE_INCREMENT] = (pore[i] - begin_pore) / length;
          pore[i] = begin_pore + s[PORE_INCREMENT];
        }
        for (int k = 0; k < 6; k++) {
          s[END_STRESS + k] = stress[i][k];
          s[STRESS_INCREMENT + k] = (stress[i][k] - begin_stress[k]) / length;
          stress[i][k] = begin_stress[k] + s[STRESS_INCREMENT + k];
        }
      }
    } else if (ends == s[STEP_END]) {
      // the step's last time step: exactly the predictor's state, for the corrector
      rho[i] = s[END_RHO];
      if (PRESSURES) pore[i] = s[END_PORE];
      for (int k = 0; k < 6; k++) stress[i][k] = s[END_STRESS + k];
      for (int a = 0; a < 3; a++) vest[i][a] += dtv * s[MEAN_ACCELERATION + a];
    } else {
      rho[i] += s[RHO_INCREMENT];
      if (PRESSURES) pore[i] += s[PORE_INCREMENT];
      for (int k = 0; k < 6; k++) stress[i][k] += s[STRESS_INCREMENT + k];
      for (int a = 0; a < 3; a++) vest[i][a] += dtv * s[MEAN_ACCELERATION + a];
    }
    if (PRESSURES) water_pressure(i);
    check_position(i, lo, hi, first_unstable, first_outside);
  }
  stop_if_unstable(first_unstable);
  stop_if_left_box(first_outside);
}


/* ----------------------------------------------------------------------
   a run that goes unstable stops, naming the particle and the step
------------------------------------------------------------------------- */

template <bool PRESSURES> bool FixSPHSoil::unstable(int i) const
{
  // one test for all: a NaN or an infinity anywhere makes the sum non-finite
  double sum = atom->rho[i];
  for (int a = 0; a < 3; a++) sum += atom->v[i][a] + atom->x[i][a];
  for (int k = 0; k < 6; k++) sum += avec->stress[i][k];
  if (PRESSURES) sum += avec->pore_pressure[i];
  return !(std::isfinite(sum) && atom->rho[i] > 0.0);
}

// Collective (every rank raises the error, which so reaches the screen and the log, whichever
// rank owns the particle). Called after the predictor, before LAMMPS's own checks of the
// coordinates at the next neighbour-list build, and after the corrector.
void FixSPHSoil::stop_if_unstable(int first_unstable)
{
  const auto unstable = SPHSoilOffenders::reduce_offenders(
      lmp, first_unstable >= 0 ? 1 : 0, first_unstable, [&](int i, double *values) {
        values[0] = atom->rho[i];
        for (int a = 0; a < 3; a++) values[1 + a] = atom->v[i][a];
        values[4] = avec->stress[i][0];
        values[5] = pair->material(atom->type[i]).density;
      });
  if (!unstable) return;
  const double *s = unstable.values;
  SPHSoilCompat::error_all(
      lmp, FLERR,
      "Fix sph/soil: particle {} became unstable at step {} (density {}, velocity {} {} "
      "{}, stress xx {}); {}",
      unstable.first, update->ntimestep, s[0], s[1], s[2], s[3], s[4], likely_causes(s[0], s[5]));
}

/* ----------------------------------------------------------------------
   what the run shows of the usual causes of an instability, for the message (collective):
   soil in tension at the apex of its yield surface (SPH's tensile instability), the unstable
   particle's density far from its material's, soil behind a wall's plane (a wall crossed);
   else the time step
------------------------------------------------------------------------- */

std::string FixSPHSoil::likely_causes(double density, double reference_density)
{
  std::vector<std::string> causes;
  bigint at_apex = 0, all_at_apex = 0;
  for (int i = 0; i < atom->nlocal; i++) {
    if (!integrated(i)) continue;
    const auto model = model_of_type[atom->type[i]];
    const double strength = model->tensile_strength(), mean = SPHSoil::mean_stress(avec->stress[i]);
    if (strength > 0.0 && std::isfinite(strength) && mean >= 0.99 * strength) at_apex++;
  }
  MPI_Allreduce(&at_apex, &all_at_apex, 1, MPI_LMP_BIGINT, MPI_SUM, world);
  if (all_at_apex > 0)
    causes.push_back(fmt::format("{} soil particle(s) are in tension at the apex of their yield "
                                 "surface, where SPH is unstable: give the soil a tension cut-off "
                                 "('tension 0' of its model)", all_at_apex));
  if (std::isfinite(density) && !(density > 0.5 * reference_density && density < 2.0 * reference_density))
    causes.push_back(fmt::format("its density is {:.3g} times its material's rho0 (an expansion at a "
                                 "free surface, a leak through a wall, or a wrong 'sph_soil/set ... "
                                 "density'?)", density / reference_density));
  const bigint behind = pair->soil_behind_walls();
  if (behind > 0)
    causes.push_back(fmt::format("{} soil particle(s) are behind a wall's plane: the soil crossed "
                                 "a wall (thicker walls, or a smaller time step)", behind));
  if (causes.empty()) return "reduce the timestep (or the cfl value)";
  std::string text = "likely causes: ";
  for (size_t k = 0; k < causes.size(); k++) text += (k ? "; " : "") + causes[k];
  return text + "; else reduce the timestep (or the cfl value)";
}

/* ---------------------------------------------------------------------- */

// the smallest and the largest h of the integrated particles (BIG and -BIG without any)
void FixSPHSoil::smoothing_length_range(double &min_h, double &max_h)
{
  double local[2] = {BIG, BIG}, all[2];    // min h and -max h: one reduction
  for (int i = 0; i < atom->nlocal; i++)
    if (integrated(i)) {
      local[0] = MIN(local[0], avec->smoothing_length[i]);
      local[1] = MIN(local[1], -avec->smoothing_length[i]);
    }
  MPI_Allreduce(local, all, 2, MPI_DOUBLE, MPI_MIN, world);
  min_h = all[0];
  max_h = -all[1];
}

// the finest h steps every LAMMPS step; the hierarchy changes with it only where refinement
// changes it, at the steps where all levels are synchronised (fix sph/soil/refine)
void FixSPHSoil::update_schedule(double min_h, double max_h)
{
  if (!schedule.per_level) return;
  schedule.finest_h = min_h < BIG ? min_h : 0.0;
  schedule.largest_period = min_h < BIG ? SPHSoil::step_period(max_h, min_h) : 1;
}

double FixSPHSoil::stable_timestep()
{
  double min_h, max_h;
  smoothing_length_range(min_h, max_h);
  update_schedule(min_h, max_h);
  const double c = pair->max_wave_speed();
  if (min_h >= BIG || c <= 0.0) return update->dt;
  // (viscosity_h0 raises the artificial viscosity of particles finer than h0: soil_pair_terms.h)
  viscosity_factor = pair->viscosity_step_factor(min_h);
  double dt = (cfl > 0.0 ? cfl : stable_cfl) * min_h / (c * viscosity_factor);
  // the pore pressure's diffusion (explicit: dt D / h^2 bounded, doc/theory.rst 7.3)
  // (where k follows the porosity: the largest at the particles' densities now)
  if (variable_diffusivity) {
    const double local = pair->pore_water_unit().largest_diffusivity(groupbit);
    MPI_Allreduce(&local, &max_diffusivity, 1, MPI_DOUBLE, MPI_MAX, world);
  }
  const double diffusion_dt = max_diffusivity > 0.0 ? DIFFUSION_NUMBER * min_h * min_h / max_diffusivity : BIG;
  diffusion_bound = diffusion_dt < dt;
  dt = MIN(dt, diffusion_dt);
  if (cfl > 0.0 && max_dt > 0.0) dt = MIN(dt, max_dt);
  return dt;
}

// the formula of the bound stable_timestep() returned last, for messages
std::string FixSPHSoil::stability_bound() const
{
  if (diffusion_bound)
    return fmt::format("{} * min(h)^2 / D, D = {:.6g} the pore pressure's largest diffusivity "
                       "k K_w / (gamma_w n)", DIFFUSION_NUMBER, max_diffusivity);
  if (viscosity_factor > 1.0)
    return fmt::format("{} * min(h) / (c_p f), f = {:.6g} for viscosity_h0 at min(h)", stable_cfl,
                       viscosity_factor);
  return fmt::format("{} * min(h) / c_p", stable_cfl);
}

/* ----------------------------------------------------------------------
   adapt the time step to the smallest h (refinement lowers it)
------------------------------------------------------------------------- */

void FixSPHSoil::end_of_step()
{
  if (cfl > 0.0) adapt_timestep();
}

void FixSPHSoil::particles_refined(const char *who)
{
  if (cfl > 0.0) return adapt_timestep();
  const double limit = stable_timestep();    // (the hierarchy follows the new smallest h too)
  if (update->dt > limit)
    SPHSoilCompat::error_all(
        lmp, FLERR,
        "{}: after splitting at step {} the timestep {:.6g} exceeds the stability "
        "limit {:.6g} = {}; use 'cfl 0.1' in fix sph/soil (adaptive "
        "step) or a timestep <= {:.6g}",
        who, update->ntimestep, update->dt, limit, stability_bound(), limit);
}

void FixSPHSoil::adapt_timestep()
{
  const double dt = stable_timestep();
  if (dt == update->dt) return;
  update->update_time();
  update->dt = dt;
  update->dt_default = 0;
  if (force->pair) force->pair->reset_dt();
  for (int ifix = 0; ifix < modify->nfix; ifix++) modify->fix[ifix]->reset_dt();
}

/* ----------------------------------------------------------------------
   keep the rates of the last step for the next run (the atom style's saved_rates)
------------------------------------------------------------------------- */

void FixSPHSoil::post_run()
{
  for (int i = 0; i < atom->nlocal; i++)
    if (integrated(i)) save_rates(i);
}

void FixSPHSoil::save_rates(int i) const
{
  using A = AtomVecSPHSoil;
  double *saved = avec->saved_rates[i];
  saved[A::SAVED_FLAG] = 1.0;
  const double inv_mass = 1.0 / atom->rmass[i];
  for (int a = 0; a < 3; a++) saved[A::SAVED_ACCELERATION + a] = atom->f[i][a] * inv_mass;
  saved[A::SAVED_DRHO] = atom->drho[i];
  for (int k = 0; k < 6; k++) {
    saved[A::SAVED_STRAIN_RATE + k] = avec->strain_rate[i][k];
    saved[A::SAVED_STRESS_RATE + k] = avec->stress_rate[i][k];
  }
  saved[A::SAVED_PORE_FLOW] = avec->pore_flow[i];
}

// (used once: the flag goes back to 0)
void FixSPHSoil::restore_rates(int i)
{
  using A = AtomVecSPHSoil;
  double *saved = avec->saved_rates[i];
  for (int a = 0; a < 3; a++) atom->f[i][a] = saved[A::SAVED_ACCELERATION + a] * atom->rmass[i];
  atom->drho[i] = saved[A::SAVED_DRHO];
  for (int k = 0; k < 6; k++) {
    avec->strain_rate[i][k] = saved[A::SAVED_STRAIN_RATE + k];
    avec->stress_rate[i][k] = saved[A::SAVED_STRESS_RATE + k];
  }
  avec->pore_flow[i] = saved[A::SAVED_PORE_FLOW];
  saved[A::SAVED_FLAG] = 0.0;
}

/* ---------------------------------------------------------------------- */

void FixSPHSoil::grow_arrays(int nmax)
{
  memory->grow(integrator_state, nmax, nstate, "sph/soil:integrator_state");
}

void FixSPHSoil::copy_arrays(int i, int j, int /*delflag*/)
{
  for (int k = 0; k < nstate; k++) integrator_state[j][k] = integrator_state[i][k];
}

// a new particle has no step of its own yet (it begins one at its first sub-step)
void FixSPHSoil::set_arrays(int i)
{
  for (int k = 0; k < nstate; k++) integrator_state[i][k] = 0.0;
  if (nstate > STEP_END) integrator_state[i][STEP_BEGIN] = integrator_state[i][STEP_END] = -BIG;
}

// the row after its length (LAMMPS's layout of per-atom restart data)
int FixSPHSoil::pack_restart(int i, double *buf)
{
  buf[0] = nstate + 1;
  for (int k = 0; k < nstate; k++) buf[1 + k] = integrator_state[i][k];
  return nstate + 1;
}

// a row of another length (a file of another build) leaves the particle without a step of its
// own: it begins one at its first time step
void FixSPHSoil::unpack_restart(int nlocal, int nth)
{
  double **extra = atom->extra;
  int m = 0;
  for (int i = 0; i < nth; i++) m += static_cast<int>(extra[nlocal][m]);
  const double *buf = &extra[nlocal][m];
  if (static_cast<int>(buf[0]) != nstate + 1) return set_arrays(nlocal);
  for (int k = 0; k < nstate; k++) integrator_state[nlocal][k] = buf[1 + k];
}

int FixSPHSoil::maxsize_restart()
{
  return nstate + 1;
}

int FixSPHSoil::size_restart(int /*nlocal*/)
{
  return nstate + 1;
}

int FixSPHSoil::pack_exchange(int i, double *buf)
{
  for (int k = 0; k < nstate; k++) buf[k] = integrator_state[i][k];
  return nstate;
}

int FixSPHSoil::unpack_exchange(int nlocal, double *buf)
{
  for (int k = 0; k < nstate; k++) integrator_state[nlocal][k] = buf[k];
  return nstate;
}

/* ----------------------------------------------------------------------
   the elapsed time: restart files of LAMMPS 29Sep2021 do not keep it, which would then take
   step * (current dt) and misplace time-based output and stop conditions; stored here for
   every version
------------------------------------------------------------------------- */

// the record: -RESTART_FORMAT (an older record began with the elapsed time, >= 0), the elapsed
// time, the step. Called on every rank before the atoms are written: a restart file written
// during a run (the restart command) saves the rates of the last step with the atoms, as the end
// of a run does; one written between runs has those of the last run (or none before the first,
// when no force has been computed yet).
void FixSPHSoil::write_restart(FILE *fp)
{
  if (update->whichflag == 1)
    for (int i = 0; i < atom->nlocal; i++)
      if (integrated(i)) save_rates(i);
  double list[3] = {-(double) RESTART_FORMAT,
                    SPHSoilFixes::elapsed_time(update),
                    (double) update->ntimestep};
  if (comm->me == 0) {
    int size = sizeof(list);
    fwrite(&size, sizeof(int), 1, fp);
    fwrite(list, sizeof(double), 3, fp);
  }
}

void FixSPHSoil::restart(char *buf)
{
  const auto *list = reinterpret_cast<const double *>(buf);
  const int format = list[0] < 0.0 ? (int) -list[0] : 1;
  if (format != RESTART_FORMAT)
    SPHSoilCompat::error_all(
        lmp, FLERR,
        "Fix sph/soil {}: the restart file holds its data in format {}; this build of "
        "SPH_SOIL reads format {}",
        id, format, RESTART_FORMAT);
  // a reset_timestep since the restart file was read starts the clock anew
  if ((bigint) list[2] != update->ntimestep) return;
  update->atime = list[1];
  update->atimestep = update->ntimestep;
}

// (a definition for C++11, where LAMMPS 29Sep2021 compiles: the value is passed by reference)
constexpr int FixSPHSoil::RESTART_FORMAT;
constexpr double FixSPHSoil::DIFFUSION_NUMBER;

double FixSPHSoil::memory_usage()
{
  return (double) atom->nmax * nstate * sizeof(double);
}

void *FixSPHSoil::extract(const char *name, int &dim)
{
  dim = 0;
  if (strcmp(name, SPHSoilFixes::INTEGRATOR) == 0) return (void *) this;
  if (strcmp(name, SPHSoilFixes::SCHEDULE) == 0) return (void *) &schedule;
  return nullptr;
}

/* ----------------------------------------------------------------------
   1: time step, 2: smallest h, 3: particles returned to the yield surface this step, 4: the
   largest period in time steps (1 with one global step)
------------------------------------------------------------------------- */

double FixSPHSoil::compute_vector(int n)
{
  if (n == 0) return update->dt;
  if (n == 3) return schedule.per_level ? (double) schedule.largest_period : 1.0;
  if (n == 1) {
    double min_h, max_h;
    smoothing_length_range(min_h, max_h);
    return min_h;
  }
  bigint total = 0;
  MPI_Allreduce(&yielded_count, &total, 1, MPI_LMP_BIGINT, MPI_SUM, world);
  return (double) total;
}
