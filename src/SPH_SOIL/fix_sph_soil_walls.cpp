/* ----------------------------------------------------------------------
   SPH_SOIL package for LAMMPS: fix SPH_SOIL_WALLS (internal; see the header)
------------------------------------------------------------------------- */

#include "fix_sph_soil_walls.h"

#include "atom.h"
#include "memory.h"
#include "update.h"

using namespace LAMMPS_NS;
using namespace FixConst;

/* ---------------------------------------------------------------------- */

FixSPHSoilWalls::FixSPHSoilWalls(LAMMPS *lmp, int narg, char **arg) :
    Fix(lmp, narg, arg), accelerations(nullptr)
{
  grow_arrays(atom->nmax);
  atom->add_callback(Atom::GROW);
}

FixSPHSoilWalls::~FixSPHSoilWalls()
{
  atom->delete_callback(id, Atom::GROW);
  memory->destroy(accelerations);
}

int FixSPHSoilWalls::setmask()
{
  return POST_INTEGRATE;
}

/* ----------------------------------------------------------------------
   the start of a run: the force evaluation of its set-up reads the walls' velocities
------------------------------------------------------------------------- */

void FixSPHSoilWalls::init()
{
  velocities_to_estimate(true);
}

/* ----------------------------------------------------------------------
   after every fix has moved its atoms (initial_integrate), whatever the order of the fixes
------------------------------------------------------------------------- */

void FixSPHSoilWalls::post_integrate()
{
  velocities_to_estimate(false);
}

// vest holds the wall's velocity of the step before: the difference is its acceleration
void FixSPHSoilWalls::velocities_to_estimate(bool start)
{
  double **v = atom->v, **vest = atom->vest;
  const int *type = atom->type;
  const int nlocal = atom->nlocal;
  const int ntypes = (int) is_wall_type.size();
  const double inv_dt = 1.0 / update->dt;
  for (int i = 0; i < nlocal; i++)
    if (type[i] < ntypes && is_wall_type[type[i]])
      for (int k = 0; k < 3; k++) {
        accelerations[i][k] = start ? 0.0 : (v[i][k] - vest[i][k]) * inv_dt;
        vest[i][k] = v[i][k];
      }
}

/* ---------------------------------------------------------------------- */

void FixSPHSoilWalls::grow_arrays(int nmax)
{
  memory->grow(accelerations, nmax, 3, "SPH_SOIL_WALLS:accelerations");
}

void FixSPHSoilWalls::copy_arrays(int i, int j, int /*delflag*/)
{
  for (int k = 0; k < 3; k++) accelerations[j][k] = accelerations[i][k];
}

int FixSPHSoilWalls::pack_exchange(int i, double *buf)
{
  for (int k = 0; k < 3; k++) buf[k] = accelerations[i][k];
  return 3;
}

int FixSPHSoilWalls::unpack_exchange(int nlocal, double *buf)
{
  for (int k = 0; k < 3; k++) accelerations[nlocal][k] = buf[k];
  return 3;
}

double FixSPHSoilWalls::memory_usage()
{
  return (double) atom->nmax * 3 * sizeof(double);
}
