/* ----------------------------------------------------------------------
   SPH_SOIL package for LAMMPS: fix SPH_SOIL_WALLS (internal; see the header)
------------------------------------------------------------------------- */

#include "fix_sph_soil_walls.h"

#include "atom.h"
#include "memory.h"
#include "soil_wall_friction.h"
#include "sph_soil_fixes.h"
#include "update.h"

using namespace LAMMPS_NS;
using namespace FixConst;

/* ---------------------------------------------------------------------- */

FixSPHSoilWalls::FixSPHSoilWalls(LAMMPS *lmp, int narg, char **arg) :
    Fix(lmp, narg, arg), accelerations(nullptr), pressures(nullptr)
{
  SPHSoilFixes::keep_per_atom(this, atom);
}

FixSPHSoilWalls::~FixSPHSoilWalls()
{
  SPHSoilFixes::keep_per_atom_end(this, atom);
  memory->destroy(accelerations);
  memory->destroy(pressures);
}

int FixSPHSoilWalls::setmask()
{
  return POST_INTEGRATE | POST_FORCE;
}

/* ----------------------------------------------------------------------
   the start of a run: the force evaluation of its set-up reads the walls' velocities
------------------------------------------------------------------------- */

void FixSPHSoilWalls::init()
{
  velocities_to_estimate(true);
}

/* ----------------------------------------------------------------------
   after every other force of the step (the forces of the set-up's evaluation too)
------------------------------------------------------------------------- */

void FixSPHSoilWalls::setup(int vflag)
{
  post_force(vflag);
}

void FixSPHSoilWalls::post_force(int /*vflag*/)
{
  if (after_forces) after_forces();
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
  memory->grow(pressures, nmax, "SPH_SOIL_WALLS:interface_pressures");
}

void FixSPHSoilWalls::copy_arrays(int i, int j, int /*delflag*/)
{
  for (int k = 0; k < 3; k++) accelerations[j][k] = accelerations[i][k];
  pressures[j] = pressures[i];
}

// a new atom: at rest, no contact yet
void FixSPHSoilWalls::set_arrays(int i)
{
  for (int k = 0; k < 3; k++) accelerations[i][k] = 0.0;
  pressures[i] = SPHSoil::NO_CONTACT;
}

int FixSPHSoilWalls::pack_exchange(int i, double *buf)
{
  for (int k = 0; k < 3; k++) buf[k] = accelerations[i][k];
  buf[3] = pressures[i];
  return 4;
}

int FixSPHSoilWalls::unpack_exchange(int nlocal, double *buf)
{
  for (int k = 0; k < 3; k++) accelerations[nlocal][k] = buf[k];
  pressures[nlocal] = buf[3];
  return 4;
}

// restart files: the interface pressure (the accelerations start at 0 in every run)
int FixSPHSoilWalls::pack_restart(int i, double *buf)
{
  buf[0] = 2;
  buf[1] = pressures[i];
  return 2;
}

void FixSPHSoilWalls::unpack_restart(int nlocal, int nth)
{
  double **extra = atom->extra;
  int m = 0;
  for (int i = 0; i < nth; i++) m += static_cast<int>(extra[nlocal][m]);
  pressures[nlocal] = extra[nlocal][m + 1];
}

int FixSPHSoilWalls::maxsize_restart()
{
  return 2;
}

int FixSPHSoilWalls::size_restart(int /*nlocal*/)
{
  return 2;
}

double FixSPHSoilWalls::memory_usage()
{
  return (double) atom->nmax * 4 * sizeof(double);
}
