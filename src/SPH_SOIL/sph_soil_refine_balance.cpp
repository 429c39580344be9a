/* ----------------------------------------------------------------------
   SPH_SOIL package for LAMMPS: the 2:1 level balance of refinement
------------------------------------------------------------------------- */

#include "sph_soil_refine_balance.h"

#include "atom.h"
#include "atom_vec_sph_soil.h"
#include "comm.h"
#include "domain.h"
#include "memory.h"
#include "soil_neighbours.h"
#include "soil_refine_balance.h"

#include <functional>

using namespace LAMMPS_NS;

SPHSoilRefineBalance::~SPHSoilRefineBalance()
{
  memory->destroy(shared);
}

/* ---------------------------------------------------------------------- */

void SPHSoilRefineBalance::prepare(int groupbit, double support, double scale)
{
  auto avec = static_cast<AtomVecSPHSoil *>(atom->style_match("sph/soil"));
  const int nlocal = atom->nlocal, nall = nlocal + atom->nghost;
  const int *mask = atom->mask;
  const double *h = avec->smoothing_length;

  // the ghosts' levels (the level does not travel with the ghosts' borders)
  level.assign(nall, 0);
  new_level.assign(nall, 0);
  for (int i = 0; i < nlocal; i++) level[i] = new_level[i] = avec->level[i];
  share(level);
  new_level = level;

  std::vector<int> members;
  for (int j = 0; j < nall; j++)
    if (mask[j] & groupbit) members.push_back(j);
  const int dimension = domain->dimension;
  SPHSoil::SmoothingClassGrids near;
  near.build(atom->x, h, members, dimension, BUFFER * support);
  offsets.assign(nlocal + 1, 0);
  support_offsets.assign(nlocal + 1, 0);
  partners.clear();
  support_partners.clear();
  double **x = atom->x;
  for (int i = 0; i < nlocal; i++) {
    if (mask[i] & groupbit)
      near.for_each_within(x[i], BUFFER * support * scale * h[i], [&](int j) {
        if (j == i) return;
        partners.push_back(j);
        double r2 = 0.0;
        for (int a = 0; a < dimension; a++) r2 += (x[i][a] - x[j][a]) * (x[i][a] - x[j][a]);
        const double reach = support * MAX(h[i], h[j]);
        if (r2 < reach * reach) support_partners.push_back(j);
      });
    offsets[i + 1] = (int) partners.size();
    support_offsets[i + 1] = (int) support_partners.size();
  }
}

/* ---------------------------------------------------------------------- */

bigint SPHSoilRefineBalance::unbalanced()
{
  const SPHSoil::LevelGraph graph{atom->nlocal, support_offsets.data(), support_partners.data()};
  bigint mine = SPHSoil::count_unbalanced(graph, level.data()), all = 0;
  MPI_Allreduce(&mine, &all, 1, MPI_LMP_BIGINT, MPI_SUM, world);
  return all;
}

/* ---------------------------------------------------------------------- */

std::vector<int> SPHSoilRefineBalance::parents(const std::vector<int> &wanted,
                                               const std::vector<char> &may_split)
{
  const int nlocal = atom->nlocal;
  const SPHSoil::LevelGraph graph{nlocal, offsets.data(), partners.data()};
  // each pass changes what the ghosts must see: repeat it until no rank changes anything
  auto until_settled = [&](std::vector<int> &values, const std::function<int()> &pass) {
    for (;;) {
      share(values);
      const int changed = pass();
      int any = 0;
      MPI_Allreduce(&changed, &any, 1, MPI_INT, MPI_MAX, world);
      if (!any) break;
    }
  };
  // 1. the deepest level each can reach
  std::vector<int> deepest(level);
  for (int i = 0; i < nlocal; i++) deepest[i] = level[i] + (may_split[i] ? 1 : 0);
  until_settled(deepest, [&]() { return SPHSoil::limit_new_levels(graph, level.data(), deepest.data()); });
  // 2. the criterion's splits that it allows; 3. the coarse neighbours that must follow
  for (int i : wanted)
    if (deepest[i] > level[i]) new_level[i] = level[i] + 1;
  until_settled(new_level, [&]() {
    return SPHSoil::raise_coarse_neighbours(graph, level.data(), new_level.data(), may_split.data());
  });
  std::vector<int> result;
  for (int i = 0; i < nlocal; i++)
    if (new_level[i] > level[i]) result.push_back(i);
  return result;
}

/* ---------------------------------------------------------------------- */

void SPHSoilRefineBalance::share(std::vector<int> &values)
{
  const int nlocal = atom->nlocal, nall = nlocal + atom->nghost;
  if (atom->nmax > shared_rows) {
    shared_rows = atom->nmax;
    memory->destroy(shared);
    memory->create(shared, shared_rows, 1, "sph/soil/refine:shared_levels");
  }
  for (int i = 0; i < nlocal; i++) shared[i][0] = values[i];
  comm->forward_comm_array(1, shared);
  for (int i = nlocal; i < nall; i++) values[i] = (int) shared[i][0];
}
