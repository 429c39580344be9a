/* ----------------------------------------------------------------------
   SPH_SOIL package for LAMMPS: command sph_soil/refine
------------------------------------------------------------------------- */

#include "sph_soil_refine.h"

#include "atom.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "force.h"
#include "group.h"
#include "neighbor.h"
#include "pair_sph_soil.h"
#include "sph_soil_compat.h"
#include "sph_soil_refine_selection.h"
#include "sph_soil_refine_splitter.h"
#include "utils.h"

#include <string>
#include <vector>

using namespace LAMMPS_NS;

namespace {
const char *const STYLE = "sph_soil/refine";
}

/* ---------------------------------------------------------------------- */

void SPHSoilRefine::command(int narg, char **arg)
{
  if (domain->box_exist == 0)
    SPHSoilCompat::error_all(lmp, FLERR,
                             "sph_soil/refine command before simulation box is defined");
  if (narg < 1)
    SPHSoilCompat::error_all(
        lmp, FLERR,
        "Illegal sph_soil/refine command: expected 'sph_soil/refine group-ID keyword value ...'");
  if (!atom->style_match("sph/soil"))
    SPHSoilCompat::error_all(lmp, FLERR, "sph_soil/refine command requires atom_style sph/soil");
  const int igroup = group->find(arg[0]);
  if (igroup == -1)
    SPHSoilCompat::error_all(lmp, FLERR, "Could not find sph_soil/refine group ID {}", arg[0]);
  const int groupbit = group->bitmask[igroup];

  SPHSoilRefineSplitter splitter(lmp, STYLE);
  SPHSoilRefineSelection selection(lmp, STYLE, "all");
  for (int iarg = 1; iarg < narg; iarg += 2) {
    const std::string keyword = arg[iarg];
    if (iarg + 1 >= narg)
      SPHSoilCompat::error_all(
          lmp, FLERR, "Illegal sph_soil/refine command: keyword {} needs a value", keyword);
    const char *value = arg[iarg + 1];
    if (!selection.parse_keyword(keyword, value) && !splitter.parse_keyword(STYLE, keyword, value))
      SPHSoilCompat::error_all(lmp, FLERR, "Illegal sph_soil/refine keyword {} (allowed: {}, {})",
                               keyword, SPHSoilRefineSelection::keywords(),
                               SPHSoilRefineSplitter::KEYWORDS);
  }
  if (force->pair == nullptr || !force->pair_match("sph/soil", 1))
    SPHSoilCompat::error_all(lmp, FLERR, "sph_soil/refine command requires pair_style sph/soil");

  if (comm->me == 0) utils::logmesg(lmp, "System init for sph_soil/refine ...\n");
  lmp->init();
  splitter.init();
  selection.init(SPHSoil::kernel_support(splitter.kernel_kind()), splitter.smoothing_ratio);

  // wall particles carry the wall geometry; splitting them would break it
  auto pair = dynamic_cast<PairSPHSoil *>(force->pair_match("sph/soil", 1));
  bigint walls = 0, all_walls = 0;
  for (int i = 0; i < atom->nlocal; i++)
    if ((atom->mask[i] & groupbit) && pair->is_wall_type(atom->type[i])) walls++;
  MPI_Allreduce(&walls, &all_walls, 1, MPI_LMP_BIGINT, MPI_SUM, world);
  if (all_walls > 0)
    SPHSoilCompat::error_all(
        lmp, FLERR,
        "sph_soil/refine: group {} contains {} wall particles; refine soil particles only", arg[0],
        all_walls);

  // the ghosts, the way delete_atoms overlap sets them up
  if (domain->triclinic) domain->x2lamda(atom->nlocal);
  domain->pbc();
  domain->reset_box();
  comm->setup();
  if (neighbor->style) neighbor->setup_bins();
  comm->exchange();
  comm->borders();
  if (domain->triclinic) domain->lamda2x(atom->nlocal + atom->nghost);

  const std::vector<int> parents = selection.parents(groupbit, 0);
  const bigint before = atom->natoms;
  const bigint split = splitter.split(parents);
  if (comm->me == 0)
    utils::logmesg(lmp, "sph_soil/refine: split {} particles into {}: {} -> {} atoms\n", split,
                   split * (domain->dimension == 3 ? 8 : 4), before, atom->natoms);
}
