/* ----------------------------------------------------------------------
   SPH_SOIL package for LAMMPS: fix SPH_SOIL_SKIN (internal; see the header)
------------------------------------------------------------------------- */

#include "fix_sph_soil_skin.h"

#include "atom.h"
#include "soil_neighbours.h"
#include "update.h"

using namespace LAMMPS_NS;
using namespace FixConst;

FixSPHSoilSkin::FixSPHSoilSkin(LAMMPS *lmp, int narg, char **arg) :
    Fix(lmp, narg, arg), list(nullptr), needed(false)
{
  force_reneighbor = 1;
  next_reneighbor = -1;
}

int FixSPHSoilSkin::setmask()
{
  return POST_INTEGRATE;
}

void FixSPHSoilSkin::watch(const SPHSoil::NeighbourList *watched, bool watch_needed)
{
  list = watched;
  needed = watch_needed;
}

void FixSPHSoilSkin::post_integrate()
{
  if (!needed || !list) return;
  const int outdated = list->moved_beyond_skin(atom->x, atom->nlocal) ? 1 : 0;
  int anywhere = 0;
  MPI_Allreduce(&outdated, &anywhere, 1, MPI_INT, MPI_MAX, world);
  if (anywhere) next_reneighbor = update->ntimestep;
}
