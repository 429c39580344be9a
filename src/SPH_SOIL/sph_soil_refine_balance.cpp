/* ----------------------------------------------------------------------
   SPH_SOIL package for LAMMPS: the 2:1 level balance of refinement
------------------------------------------------------------------------- */

#include "sph_soil_refine_balance.h"

#include "atom.h"
#include "atom_vec_sph_soil.h"
#include "domain.h"
#include "soil_neighbours.h"
#include "soil_refine_balance.h"

#include <functional>

using namespace LAMMPS_NS;

/* ---------------------------------------------------------------------- */

void SPHSoilRefineBalance::prepare(int groupbit, double support, double scale,
                                   const std::vector<char> *only)
{
  auto avec = static_cast<AtomVecSPHSoil *>(atom->style_match("sph/soil"));
  const int nlocal = atom->nlocal, nall = nlocal + atom->nghost;
  const int *mask = atom->mask;
  const double *h = avec->smoothing_length;

  // the ghosts' levels (the level does not travel with the ghosts' borders)
  level.assign(nall, 0);
  for (int i = 0; i < nlocal; i++) level[i] = avec->level[i];
  share(level);
  new_level = level;

  // Only refined particles search (and, for the merge, the particles `only` names): a pair of
  // level-0 particles can be neither unbalanced nor limit nor force anything, so a level-0
  // particle needs its refined neighbours only, which find it. The cost follows the refined
  // zone, not the whole group.
  // The splits' balance needs the pairs of different levels only (a pair of one level
  // constrains nothing, soil_refine_balance.h): the particles are binned by level and each
  // searches the other levels' bins, so that inside a refined zone a particle visits few. The
  // merge's search (`only`) keeps every level, in one bin.
  std::vector<std::vector<int>> by_level(1);
  for (int j = 0; j < nall; j++) {
    if (!(mask[j] & groupbit)) continue;
    const int bin = only ? 0 : level[j];
    if (bin >= (int) by_level.size()) by_level.resize(bin + 1);
    by_level[bin].push_back(j);
  }
  const int dimension = domain->dimension;
  std::vector<SPHSoil::SmoothingClassGrids> near(by_level.size());
  for (size_t bin = 0; bin < by_level.size(); bin++)
    near[bin].build(atom->x, h, by_level[bin], dimension, BUFFER * support);
  struct Edge {
    int i, j;
    bool within_support;
  };
  std::vector<Edge> edges;
  edges.reserve(previous_edges + previous_edges / 8);
  double **x = atom->x;
  for (const auto &members : by_level) {
    for (int j : members) {
      if (only ? j >= nlocal || !(*only)[j] : level[j] < 1) continue;
      const auto visit = [&](int k, double r2) {
        if (k == j) return;
        const double reach = support * MAX(h[j], h[k]);
        const bool within = r2 < reach * reach;
        if (j < nlocal) edges.push_back({j, k, within});
        if (!only && k < nlocal && level[k] < 1) edges.push_back({k, j, within});
      };
      for (size_t bin = 0; bin < by_level.size(); bin++)
        if (only || (int) bin != level[j]) near[bin].for_each_within(x[j], BUFFER * support * scale * h[j], visit);
    }
  }
  previous_edges = edges.size();
  // the owned particles' lists (a counting sort of the edges)
  offsets.assign(nlocal + 1, 0);
  support_offsets.assign(nlocal + 1, 0);
  for (const auto &e : edges) {
    offsets[e.i + 1]++;
    if (e.within_support) support_offsets[e.i + 1]++;
  }
  for (int i = 0; i < nlocal; i++) {
    offsets[i + 1] += offsets[i];
    support_offsets[i + 1] += support_offsets[i];
  }
  partners.resize(edges.size());
  support_partners.resize(support_offsets[nlocal]);
  std::vector<int> fill(offsets.begin(), offsets.end() - 1),
      support_fill(support_offsets.begin(), support_offsets.end() - 1);
  for (const auto &e : edges) {
    partners[fill[e.i]++] = e.j;
    if (e.within_support) support_partners[support_fill[e.i]++] = e.j;
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
  double **rows = shared.owned();
  for (int i = 0; i < nlocal; i++) rows[i][0] = values[i];
  shared.forward();
  for (int i = nlocal; i < nall; i++) values[i] = (int) rows[i][0];
}
