/* ----------------------------------------------------------------------
   SPH_SOIL package for LAMMPS: fix sph/soil
------------------------------------------------------------------------- */

#include "fix_sph_soil.h"

#include "atom.h"
#include "atom_vec_sph_soil.h"
#include "comm.h"
#include "error.h"
#include "memory.h"
#include "force.h"
#include "group.h"
#include "modify.h"
#include "pair_sph_soil.h"
#include "soil_constitutive.h"
#include "sph_soil_input.h"
#include "sph_soil_offenders.h"
#include "update.h"
#include "utils.h"

#include <cmath>
#include <cstring>

using namespace LAMMPS_NS;
using namespace FixConst;

namespace {
constexpr double BIG = 1.0e30;
}

/* ---------------------------------------------------------------------- */

FixSPHSoil::FixSPHSoil(LAMMPS *lmp, int narg, char **arg) :
    Fix(lmp, narg, arg), cfl(0.0), stable_cfl(0.2), max_dt(0.0), avec(nullptr), pair(nullptr),
    yielded_count(0), integrator_state(nullptr), allocated_rows(0), restore_pending(false)
{
  time_integrate = 1;
  // the pair style's skins follow h (reneighbour_if_skin_used())
  force_reneighbor = 1;
  next_reneighbor = -1;
  restart_global = 1;
  restart_peratom = 1;
  vector_flag = 1;
  size_vector = 3;
  global_freq = 1;
  extvector = 0;

  for (int iarg = 3; iarg < narg; iarg += 2) {
    if (iarg + 1 >= narg)
      error->all(FLERR, "Illegal fix sph/soil command: keyword {} needs a value", arg[iarg]);
    if (strcmp(arg[iarg], "cfl") == 0) {
      cfl = SphSoilInput::number(FLERR, lmp, "fix sph/soil cfl", arg[iarg + 1],
                                 SphSoilInput::between(0.0, 1.0, true, false));
    } else if (strcmp(arg[iarg], "dtmax") == 0) {
      max_dt = SphSoilInput::number(FLERR, lmp, "fix sph/soil dtmax", arg[iarg + 1],
                                    SphSoilInput::above(0.0));
    } else {
      error->all(FLERR, "Illegal fix sph/soil keyword {} (allowed: cfl, dtmax)", arg[iarg]);
    }
  }
  avec = dynamic_cast<AtomVecSPHSoil *>(atom->style_match("sph/soil"));
  if (!avec) error->all(FLERR, "Fix sph/soil requires atom_style sph/soil");
  if (max_dt > 0.0 && cfl == 0.0)
    error->all(FLERR, "Illegal fix sph/soil dtmax {}: it bounds the adaptive time step, which needs "
                      "'cfl C' too", max_dt);
  // the largest C_cfl measured stable with a fixed step (see setup()): the documented range
  // of cfl goes higher for a smooth, slow flow, but most runs will not survive it
  if (cfl > stable_cfl && comm->me == 0)
    error->warning(FLERR, "Fix sph/soil cfl {}: above {}, the largest value measured stable (a "
                          "geostatic column); expect the run to go unstable, 0.1 to 0.2 is usual",
                   cfl, stable_cfl);

  grow_arrays(atom->nmax);
  atom->add_callback(Atom::GROW);
  atom->add_callback(Atom::RESTART);
}

/* ---------------------------------------------------------------------- */

FixSPHSoil::~FixSPHSoil()
{
  atom->delete_callback(id, Atom::GROW);
  atom->delete_callback(id, Atom::RESTART);
  memory->destroy(integrator_state);
}

/* ---------------------------------------------------------------------- */

int FixSPHSoil::setmask()
{
  return INITIAL_INTEGRATE | POST_INTEGRATE | FINAL_INTEGRATE | END_OF_STEP;
}

/* ---------------------------------------------------------------------- */

void FixSPHSoil::init()
{
  pair = dynamic_cast<PairSPHSoil *>(force->pair_match("sph/soil", 1));
  if (!pair) error->all(FLERR, "Fix sph/soil requires pair_style sph/soil");
  avec = dynamic_cast<AtomVecSPHSoil *>(atom->style_match("sph/soil"));

  model_of_type.assign(atom->ntypes + 1, nullptr);
  wall_type.assign(atom->ntypes + 1, 0);
  for (int type = 1; type <= atom->ntypes; type++) {
    model_of_type[type] = pair->model(type);
    wall_type[type] = pair->is_wall_type(type) ? 1 : 0;
  }

  // one integrator per particle: two fixes sph/soil over the same particles would each
  // advance them, a step of 2 dt
  const int *mask = atom->mask;
  // the first fix sph/soil passes the walls' velocities on (a second would see vest = v and
  // take the walls' acceleration for 0)
  first_integrator = true;
  const int me = modify->find_fix(id);
  for (int ifix = 0; ifix < modify->nfix; ifix++) {
    const Fix *other = modify->fix[ifix];
    if (other == this || strcmp(other->style, "sph/soil") != 0) continue;
    if (ifix < me) first_integrator = false;
    const int otherbit = other->groupbit;
    const auto twice = SphSoilOffenders::find_offenders(
        lmp, [&](int i) { return (mask[i] & groupbit) && (mask[i] & otherbit); },
        [](int, double *) {});
    if (twice)
      error->all(FLERR, "Fix sph/soil {} and {} both integrate {} particle(s) (e.g. atom {}); "
                        "integrate each particle with one fix", id, other->id, twice.count,
                 twice.first);
  }
  // a group without soil particles is integrated by no one (wall particles never move)
  bigint soil = 0, all_soil = 0;
  for (int i = 0; i < atom->nlocal; i++)
    if (integrated(i)) soil++;
  MPI_Allreduce(&soil, &all_soil, 1, MPI_LMP_BIGINT, MPI_SUM, world);
  if (all_soil == 0 && comm->me == 0)
    error->warning(FLERR, "Fix sph/soil {}: group {} holds no soil particle (wall particles are "
                          "never integrated): this fix moves nothing", id, group->names[igroup]);

  // the rates of the first force evaluation use vest: start it at v (ghosts, made later
  // at setup, take it from their owners)
  const int nlocal = atom->nlocal;
  for (int i = 0; i < nlocal; i++)
    if (integrated(i))
      for (int k = 0; k < 3; k++) atom->vest[i][k] = atom->v[i][k];
  walls_velocity_to_estimate(true);

  if (cfl > 0.0) {
    const double dt = stable_timestep();
    if (dt != update->dt) {
      update->update_time();
      update->dt = dt;
      update->dt_default = 0;
    }
  }
  reset_dt();
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
  const int nlocal = atom->nlocal;
  for (int i = 0; i < nlocal; i++)
    if (integrated(i))
      model_of_type[atom->type[i]]->stress_rate(avec->stress[i], avec->strain_rate[i], avec->spin[i],
                                                avec->stress_rate[i]);
  if (cfl == 0.0) {
    // measured: a geostatic column with the paper's viscosity (alpha = 0.1) stays at rest
    // up to 0.195 h/c_p; the usual C_cfl range is 0.1 to 0.2 (doc/theory.rst section 4)
    const double limit = stable_timestep();
    if (update->dt > limit)
      error->all(FLERR, "Fix sph/soil: timestep {:.6g} exceeds the stability limit {:.6g} = "
                        "{} * min(h) / c_p; use a smaller timestep or 'cfl 0.1'",
                 update->dt, limit, stable_cfl);
  }
}

/* ---------------------------------------------------------------------- */

void FixSPHSoil::initial_integrate(int /*vflag*/)
{
  double **x = atom->x, **v = atom->v, **f = atom->f, **vest = atom->vest;
  double *rho = atom->rho, *drho = atom->drho, *rmass = atom->rmass;
  const int nlocal = atom->nlocal;

  if (restore_pending) {
    for (int i = 0; i < nlocal; i++)
      if (integrator_state[i][SAVED] != 0.0) {
        if (integrated(i)) restore_rates(i);
        integrator_state[i][SAVED] = 0.0;
      }
    restore_pending = false;
  }

  int first_unstable = -1;
  for (int i = 0; i < nlocal; i++) {
    if (!integrated(i)) continue;
    // velocity Verlet for x, v; vest estimates v(t + dt) for the rates
    const double dtfm = dtf / rmass[i];
    for (int a = 0; a < 3; a++) {
      vest[i][a] = v[i][a] + 2.0 * dtfm * f[i][a];
      v[i][a] += dtfm * f[i][a];
      x[i][a] += dtv * v[i][a];
    }
    // Heun predictor for density, strain and stress: a full step with the old rates,
    // so that the force evaluation sees the state at t + dt (a half step would make the
    // scheme first order); the old rates are kept for the corrector
    double *old = integrator_state[i];
    old[HEUN_DRHO] = drho[i];
    rho[i] += dtv * drho[i];
    for (int k = 0; k < 6; k++) {
      old[HEUN_STRAIN_RATE + k] = avec->strain_rate[i][k];
      avec->total_strain[i][k] += dtv * avec->strain_rate[i][k];
      avec->stress[i][k] += dtv * avec->stress_rate[i][k];
    }
    model_of_type[atom->type[i]]->return_to_admissible(avec->stress[i]);
    // the positions only (a non-finite velocity makes them non-finite): what LAMMPS checks
    // before the next neighbour list; the whole state is checked after the corrector
    if (!std::isfinite(x[i][0] + x[i][1] + x[i][2]) && lower_id(i, first_unstable))
      first_unstable = i;
  }
  stop_if_unstable(first_unstable);
}

/* ----------------------------------------------------------------------
   The pair style reads every particle's velocity from vest (the field that travels to
   ghosts every step). A wall particle's is its own velocity, which a fix that moves walls
   (move, rigid, ...) has set by now, whatever the order of the fixes; 0 for a wall at rest.
   The first fix sph/soil does it for all wall particles: walls belong to no soil group.
------------------------------------------------------------------------- */

void FixSPHSoil::post_integrate()
{
  walls_velocity_to_estimate(false);
  reneighbour_if_skin_used();
}

/* ----------------------------------------------------------------------
   The pair style's list gives a particle of smaller h a smaller skin, which LAMMPS's check
   (one skin, the largest particles') does not know: LAMMPS reneighbours at this step if some
   particle (soil or wall, moved by any fix) has moved half its own skin. The first fix
   sph/soil does it, after every fix has moved its atoms and before Neighbor::decide(); not
   while every particle has the largest h (then LAMMPS's check is this one).
------------------------------------------------------------------------- */

void FixSPHSoil::reneighbour_if_skin_used()
{
  if (!first_integrator || !pair->skin_check_needed()) return;
  const int outdated = pair->neighbours_outdated() ? 1 : 0;
  int anywhere = 0;
  MPI_Allreduce(&outdated, &anywhere, 1, MPI_INT, MPI_MAX, world);
  if (anywhere) next_reneighbor = update->ntimestep;
}

// vest holds the wall's velocity of the step before: the difference is its acceleration
void FixSPHSoil::walls_velocity_to_estimate(bool start)
{
  if (!first_integrator) return;
  double **v = atom->v, **vest = atom->vest;
  const int *type = atom->type;
  const int nlocal = atom->nlocal;
  const double inv_dt = 1.0 / update->dt;
  for (int i = 0; i < nlocal; i++)
    if (wall_type[type[i]])
      for (int k = 0; k < 3; k++) {
        integrator_state[i][WALL_ACCELERATION + k] = start ? 0.0 : (v[i][k] - vest[i][k]) * inv_dt;
        vest[i][k] = v[i][k];
      }
}

/* ----------------------------------------------------------------------
   second velocity half kick; Heun corrector: y(t+dt) = y(t) + dt/2 (rate(t) + rate(t+dt))
------------------------------------------------------------------------- */

void FixSPHSoil::final_integrate()
{
  double **v = atom->v, **f = atom->f;
  double *rho = atom->rho, *drho = atom->drho, *rmass = atom->rmass;
  const int nlocal = atom->nlocal;
  bigint yielded = 0;
  int first_unstable = -1;

  for (int i = 0; i < nlocal; i++) {
    if (!integrated(i)) continue;
    const double dtfm = dtf / rmass[i];
    for (int a = 0; a < 3; a++) v[i][a] += dtfm * f[i][a];
    const double *old = integrator_state[i];
    rho[i] += dtf * (drho[i] - old[HEUN_DRHO]);
    for (int k = 0; k < 6; k++)
      avec->total_strain[i][k] += dtf * (avec->strain_rate[i][k] - old[HEUN_STRAIN_RATE + k]);

    const auto model = model_of_type[atom->type[i]];
    double *stress = avec->stress[i];
    double *stress_rate = avec->stress_rate[i];
    double new_rate[6];
    model->stress_rate(stress, avec->strain_rate[i], avec->spin[i], new_rate);
    for (int k = 0; k < 6; k++) {
      stress[k] += dtf * (new_rate[k] - stress_rate[k]);
      stress_rate[k] = new_rate[k];
    }
    if (model->return_to_admissible(stress)) yielded++;
    if (unstable(i) && lower_id(i, first_unstable)) first_unstable = i;
  }
  yielded_count = yielded;
  stop_if_unstable(first_unstable);
}

/* ----------------------------------------------------------------------
   a run that goes unstable stops, naming the particle and the step
------------------------------------------------------------------------- */

bool FixSPHSoil::unstable(int i) const
{
  // one test for all: a NaN or an infinity anywhere makes the sum non-finite
  double sum = atom->rho[i];
  for (int a = 0; a < 3; a++) sum += atom->v[i][a] + atom->x[i][a];
  for (int k = 0; k < 6; k++) sum += avec->stress[i][k];
  return !(std::isfinite(sum) && atom->rho[i] > 0.0);
}

// Collective (every rank raises the error, which so reaches the screen and the log, whichever
// rank owns the particle). Called after the predictor, before LAMMPS's own checks of the
// coordinates at the next neighbour-list build, and after the corrector.
void FixSPHSoil::stop_if_unstable(int first_unstable)
{
  const auto unstable = SphSoilOffenders::reduce_offenders(
      lmp, first_unstable >= 0 ? 1 : 0, first_unstable, [&](int i, double *values) {
        values[0] = atom->rho[i];
        for (int a = 0; a < 3; a++) values[1 + a] = atom->v[i][a];
        values[4] = avec->stress[i][0];
      });
  if (!unstable) return;
  const double *s = unstable.values;
  error->all(FLERR,
             "Fix sph/soil: particle {} became unstable at step {} (density {}, velocity {} {} "
             "{}, stress xx {}); reduce the timestep (or the cfl value)",
             unstable.first, update->ntimestep, s[0], s[1], s[2], s[3], s[4]);
}

/* ---------------------------------------------------------------------- */

double FixSPHSoil::stable_timestep()
{
  const int nlocal = atom->nlocal;
  double local_min_h = BIG;
  for (int i = 0; i < nlocal; i++)
    if (integrated(i)) local_min_h = MIN(local_min_h, avec->smoothing_length[i]);
  double min_h;
  MPI_Allreduce(&local_min_h, &min_h, 1, MPI_DOUBLE, MPI_MIN, world);
  const double c = pair->max_wave_speed();
  if (min_h >= BIG || c <= 0.0) return update->dt;
  double dt = (cfl > 0.0 ? cfl : stable_cfl) * min_h / c;
  if (cfl > 0.0 && max_dt > 0.0) dt = MIN(dt, max_dt);
  return dt;
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
  const double limit = stable_timestep();
  if (update->dt > limit)
    error->all(FLERR, "{}: after splitting at step {} the timestep {:.6g} exceeds the stability "
                      "limit {:.6g} = {} * min(h) / c_p; use 'cfl 0.1' in fix sph/soil (adaptive "
                      "step) or a timestep <= {:.6g}", who, update->ntimestep, update->dt, limit,
               stable_cfl, limit);
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
   keep the rates of the last step for the next run (see the header)
------------------------------------------------------------------------- */

void FixSPHSoil::post_run()
{
  const int nlocal = atom->nlocal;
  for (int i = 0; i < nlocal; i++) {
    if (integrated(i)) save_rates(i, integrator_state[i] + SAVED);
    else integrator_state[i][SAVED] = 0.0;
  }
  restore_pending = true;
}

/* ---------------------------------------------------------------------- */

// into a saved block (the row's, or a restart buffer's): block[0] = flag, then the rates at
// the offsets they have in the row
void FixSPHSoil::save_rates(int i, double *block) const
{
  block[0] = 1.0;
  const double inv_mass = 1.0 / atom->rmass[i];
  for (int a = 0; a < 3; a++) block[SAVED_ACCELERATION - SAVED + a] = atom->f[i][a] * inv_mass;
  block[SAVED_DRHO - SAVED] = atom->drho[i];
  for (int k = 0; k < 6; k++) {
    block[SAVED_STRAIN_RATE - SAVED + k] = avec->strain_rate[i][k];
    block[SAVED_STRESS_RATE - SAVED + k] = avec->stress_rate[i][k];
  }
}

void FixSPHSoil::restore_rates(int i)
{
  const double *row = integrator_state[i];
  for (int a = 0; a < 3; a++) atom->f[i][a] = row[SAVED_ACCELERATION + a] * atom->rmass[i];
  atom->drho[i] = row[SAVED_DRHO];
  for (int k = 0; k < 6; k++) {
    avec->strain_rate[i][k] = row[SAVED_STRAIN_RATE + k];
    avec->stress_rate[i][k] = row[SAVED_STRESS_RATE + k];
  }
}

/* ---------------------------------------------------------------------- */

void FixSPHSoil::grow_arrays(int nmax)
{
  memory->grow(integrator_state, nmax, NSTATE, "sph/soil:integrator_state");
  // new rows hold nothing to restore (atoms made later by create_atoms etc.)
  for (int i = allocated_rows; i < nmax; i++) integrator_state[i][SAVED] = 0.0;
  allocated_rows = nmax;
}

void FixSPHSoil::copy_arrays(int i, int j, int /*delflag*/)
{
  for (int k = 0; k < NSTATE; k++) integrator_state[j][k] = integrator_state[i][k];
}

// the saved block only when it holds something
int FixSPHSoil::pack_exchange(int i, double *buf)
{
  const int n = integrator_state[i][SAVED] != 0.0 ? NSTATE : SAVED + 1;
  for (int k = 0; k < n; k++) buf[k] = integrator_state[i][k];
  return n;
}

int FixSPHSoil::unpack_exchange(int nlocal, double *buf)
{
  const int n = buf[SAVED] != 0.0 ? NSTATE : SAVED + 1;
  for (int k = 0; k < n; k++) integrator_state[nlocal][k] = buf[k];
  if (n == NSTATE) restore_pending = true;
  return n;
}

/* ----------------------------------------------------------------------
   the elapsed time: restart files of LAMMPS 29Sep2021 do not keep it, which would then take
   step * (current dt) and misplace time-based output and stop conditions; stored here for
   every version
------------------------------------------------------------------------- */

void FixSPHSoil::write_restart(FILE *fp)
{
  double list[2] = {update->atime + (update->ntimestep - update->atimestep) * update->dt,
                    (double) update->ntimestep};
  if (comm->me == 0) {
    int size = sizeof(list);
    fwrite(&size, sizeof(int), 1, fp);
    fwrite(list, sizeof(double), 2, fp);
  }
}

void FixSPHSoil::restart(char *buf)
{
  const auto *list = reinterpret_cast<const double *>(buf);
  // a reset_timestep since the restart file was read starts the clock anew
  if ((bigint) list[1] != update->ntimestep) return;
  update->atime = list[0];
  update->atimestep = update->ntimestep;
}

/* ----------------------------------------------------------------------
   restart files: the current rates (between runs they are those of the last step)
------------------------------------------------------------------------- */

int FixSPHSoil::pack_restart(int i, double *buf)
{
  // buf[0] is the count of values including itself, the way other fixes read it; then the
  // saved block (flag and rates), the current rates
  buf[0] = NSAVED + 2;
  save_rates(i, &buf[1]);
  if (!integrated(i)) buf[1] = 0.0;
  return NSAVED + 2;
}

void FixSPHSoil::unpack_restart(int nlocal, int nth)
{
  double **extra = atom->extra;
  int m = 0;
  for (int i = 0; i < nth; i++) m += static_cast<int>(extra[nlocal][m]);
  m++;
  for (int k = 0; k <= NSAVED; k++) integrator_state[nlocal][SAVED + k] = extra[nlocal][m++];
  if (integrator_state[nlocal][SAVED] != 0.0) restore_pending = true;
}

int FixSPHSoil::maxsize_restart()
{
  return NSAVED + 2;
}

int FixSPHSoil::size_restart(int /*nlocal*/)
{
  return NSAVED + 2;
}

double FixSPHSoil::memory_usage()
{
  return (double) atom->nmax * NSTATE * sizeof(double);
}

/* ----------------------------------------------------------------------
   1: time step, 2: smallest h, 3: particles returned to the yield surface this step
------------------------------------------------------------------------- */

double FixSPHSoil::compute_vector(int n)
{
  if (n == 0) return update->dt;
  if (n == 1) {
    double local_min_h = BIG, min_h;
    for (int i = 0; i < atom->nlocal; i++)
      if (integrated(i)) local_min_h = MIN(local_min_h, avec->smoothing_length[i]);
    MPI_Allreduce(&local_min_h, &min_h, 1, MPI_DOUBLE, MPI_MIN, world);
    return min_h;
  }
  bigint total = 0;
  MPI_Allreduce(&yielded_count, &total, 1, MPI_LMP_BIGINT, MPI_SUM, world);
  return (double) total;
}
