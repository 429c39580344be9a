/* ----------------------------------------------------------------------
   SPH_SOIL package for LAMMPS: fix sph/soil
------------------------------------------------------------------------- */

#include "fix_sph_soil.h"

#include "atom.h"
#include "atom_vec_sph_soil.h"
#include "comm.h"
#include "error.h"
#include "force.h"
#include "modify.h"
#include "pair_sph_soil.h"
#include "soil_constitutive.h"
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
    yielded_count(0)
{
  time_integrate = 1;
  vector_flag = 1;
  size_vector = 3;
  global_freq = 1;
  extvector = 0;

  for (int iarg = 3; iarg < narg; iarg += 2) {
    if (iarg + 1 >= narg)
      error->all(FLERR, "Illegal fix sph/soil command: keyword {} needs a value", arg[iarg]);
    if (strcmp(arg[iarg], "cfl") == 0) {
      cfl = utils::numeric(FLERR, arg[iarg + 1], false, lmp);
      if (!(cfl > 0.0 && cfl <= 1.0))
        error->all(FLERR, "Illegal fix sph/soil cfl {}: must be in (0, 1], typically 0.1 to 0.2", cfl);
    } else if (strcmp(arg[iarg], "dtmax") == 0) {
      max_dt = utils::numeric(FLERR, arg[iarg + 1], false, lmp);
      if (!(max_dt > 0.0)) error->all(FLERR, "Illegal fix sph/soil dtmax {}: must be > 0", max_dt);
    } else {
      error->all(FLERR, "Illegal fix sph/soil keyword {} (allowed: cfl, dtmax)", arg[iarg]);
    }
  }
  avec = dynamic_cast<AtomVecSPHSoil *>(atom->style_match("sph/soil"));
  if (!avec) error->all(FLERR, "Fix sph/soil requires atom_style sph/soil");
}

/* ---------------------------------------------------------------------- */

FixSPHSoil::~FixSPHSoil() = default;

/* ---------------------------------------------------------------------- */

int FixSPHSoil::setmask()
{
  return INITIAL_INTEGRATE | FINAL_INTEGRATE | END_OF_STEP;
}

/* ---------------------------------------------------------------------- */

void FixSPHSoil::init()
{
  pair = dynamic_cast<PairSPHSoil *>(force->pair_match("sph/soil", 1));
  if (!pair) error->all(FLERR, "Fix sph/soil requires pair_style sph/soil");
  avec = dynamic_cast<AtomVecSPHSoil *>(atom->style_match("sph/soil"));

  model_of_type.assign(atom->ntypes + 1, nullptr);
  for (int type = 1; type <= atom->ntypes; type++) model_of_type[type] = pair->model(type);
  reset_dt();
}

/* ---------------------------------------------------------------------- */

void FixSPHSoil::reset_dt()
{
  dtv = update->dt;
  dtf = 0.5 * update->dt;
}

/* ---------------------------------------------------------------------- */

bool FixSPHSoil::integrated(int i) const
{
  return (atom->mask[i] & groupbit) && model_of_type[atom->type[i]];
}

/* ----------------------------------------------------------------------
   the pair sums of the first force evaluation use vest: start it at v
------------------------------------------------------------------------- */

void FixSPHSoil::setup_pre_force(int /*vflag*/)
{
  const int nlocal = atom->nlocal;
  for (int i = 0; i < nlocal; i++)
    if (integrated(i))
      for (int k = 0; k < 3; k++) atom->vest[i][k] = atom->v[i][k];
  // ghosts were made before this: they need the new vest too (the atom style carries it)
  comm->forward_comm();
  if (cfl > 0.0) {
    const double dt = stable_timestep();
    if (dt != update->dt) {
      update->update_time();
      update->dt = dt;
      update->dt_default = 0;
      if (force->pair) force->pair->reset_dt();
      for (int ifix = 0; ifix < modify->nfix; ifix++) modify->fix[ifix]->reset_dt();
    }
  }
}

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
    // measured: with the paper's viscosity (alpha = 0.1) a geostatic column grows a
    // checkerboard mode at 0.15 h/c_p and stays at rest at 0.075 h/c_p
    const double limit = stable_timestep();
    if (update->dt > limit)
      error->all(FLERR, "Fix sph/soil: timestep {:.6g} exceeds the stability limit {:.6g} = "
                        "{} * min(h) / c_p; use a smaller timestep or 'cfl 0.1'",
                 update->dt, limit, stable_cfl);
    if (update->dt > 0.5 * limit && comm->me == 0)
      error->warning(FLERR, "Fix sph/soil: timestep {:.6g} is above 0.1 * min(h) / c_p = {:.6g}; "
                            "low artificial viscosity may then let a checkerboard mode grow",
                     update->dt, 0.5 * limit);
  }
}

/* ---------------------------------------------------------------------- */

void FixSPHSoil::initial_integrate(int /*vflag*/)
{
  double **x = atom->x, **v = atom->v, **f = atom->f, **vest = atom->vest;
  double *rho = atom->rho, *drho = atom->drho, *rmass = atom->rmass;
  const int nlocal = atom->nlocal;

  for (int i = 0; i < nlocal; i++) {
    if (!integrated(i)) continue;
    const double dtfm = dtf / rmass[i];
    for (int a = 0; a < 3; a++) {
      vest[i][a] = v[i][a] + 2.0 * dtfm * f[i][a];    // v(t + dt) estimate for the rates
      v[i][a] += dtfm * f[i][a];
      x[i][a] += dtv * v[i][a];
    }
    rho[i] += dtf * drho[i];
    for (int k = 0; k < 6; k++) {
      avec->total_strain[i][k] += dtf * avec->strain_rate[i][k];
      avec->stress[i][k] += dtf * avec->stress_rate[i][k];
    }
    model_of_type[atom->type[i]]->return_to_admissible(avec->stress[i]);
  }
}

/* ---------------------------------------------------------------------- */

void FixSPHSoil::final_integrate()
{
  double **v = atom->v, **f = atom->f;
  double *rho = atom->rho, *drho = atom->drho, *rmass = atom->rmass;
  const int nlocal = atom->nlocal;
  bigint yielded = 0;

  for (int i = 0; i < nlocal; i++) {
    if (!integrated(i)) continue;
    const double dtfm = dtf / rmass[i];
    for (int a = 0; a < 3; a++) v[i][a] += dtfm * f[i][a];
    rho[i] += dtf * drho[i];
    const auto model = model_of_type[atom->type[i]];
    double *stress = avec->stress[i];
    for (int k = 0; k < 6; k++) avec->total_strain[i][k] += dtf * avec->strain_rate[i][k];
    model->stress_rate(stress, avec->strain_rate[i], avec->spin[i], avec->stress_rate[i]);
    for (int k = 0; k < 6; k++) stress[k] += dtf * avec->stress_rate[i][k];
    if (model->return_to_admissible(stress)) yielded++;
    check_state(i);
  }
  yielded_count = yielded;
}

/* ----------------------------------------------------------------------
   stop a run that goes unstable, naming the particle and the step
------------------------------------------------------------------------- */

void FixSPHSoil::check_state(int i)
{
  bool finite = std::isfinite(atom->rho[i]) && atom->rho[i] > 0.0;
  for (int a = 0; a < 3; a++) finite = finite && std::isfinite(atom->v[i][a]) && std::isfinite(atom->x[i][a]);
  for (int k = 0; k < 6; k++) finite = finite && std::isfinite(avec->stress[i][k]);
  if (!finite)
    error->one(FLERR,
               "Fix sph/soil: particle {} became unstable at step {} (density {}, velocity {} {} "
               "{}, stress xx {}); reduce the timestep (or the cfl value)",
               atom->tag[i], update->ntimestep, atom->rho[i], atom->v[i][0], atom->v[i][1],
               atom->v[i][2], avec->stress[i][0]);
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
  if (cfl == 0.0) return;
  const double dt = stable_timestep();
  if (dt == update->dt) return;
  update->update_time();
  update->dt = dt;
  update->dt_default = 0;
  if (force->pair) force->pair->reset_dt();
  for (int ifix = 0; ifix < modify->nfix; ifix++) modify->fix[ifix]->reset_dt();
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
