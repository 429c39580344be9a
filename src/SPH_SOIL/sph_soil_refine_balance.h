/* -*- c++ -*- ----------------------------------------------------------
   SPH_SOIL package for LAMMPS: the 2:1 level balance of fix sph/soil/refine
   (soil_refine_balance.h has the rule): the neighbours of the group's owned
   particles, their ghosts' levels, and the passes repeated over all ranks.
------------------------------------------------------------------------- */

#ifndef LMP_SPH_SOIL_REFINE_BALANCE_H
#define LMP_SPH_SOIL_REFINE_BALANCE_H

#include "pointers.h"
#include "sph_soil_ghost_rows.h"

#include <vector>

namespace LAMMPS_NS {

class SPHSoilRefineBalance : protected Pointers {
 public:
  explicit SPHSoilRefineBalance(LAMMPS *lmp) :
      Pointers(lmp), shared(lmp, 1, "sph/soil/refine:shared_levels")
  {
  }

  // The neighbours among the owned and ghost particles of `groupbit`, and their levels; the
  // ghosts must be current. Collective. Neighbours for the balance lie within BUFFER times the
  // kernel's support (`support` h) of the coarser one: the daughters of a split lie up to a
  // quarter of a spacing from their parent (in 2D, 0.3 h at h = 1.2 d), where a coarse particle
  // just beyond its support would meet them, and motion between checks does the same.
  static constexpr double BUFFER = 1.5;
  // `scale` widens the owned particles' own reach (the merge: the reach of the particle that
  // siblings of smoothing length h would merge into, 2h, plus its offset from them); `only`
  // (the merge) lists the neighbours of these owned particles alone.
  void prepare(int groupbit, double support, double scale = 1.0, const std::vector<char> *only = nullptr);
  // pairs of the group within the support of the coarser one and more than one level apart
  // (after prepare(), all ranks)
  bigint unbalanced();
  // the owned particles to split: `wanted` and those the balance adds, less those it calls off;
  // may_split[i]: owned particle i may split at this check. Collective.
  std::vector<int> parents(const std::vector<int> &wanted, const std::vector<char> &may_split);
  // Owned particle i's neighbours: after the splits' prepare() (no `only`) those of other
  // levels only; after the merge's, those of every level.
  // the finest level among owned particle i's neighbours (its own level if it has none)
  int finest_neighbour(int i) const
  {
    int finest = level[i];
    for (int k = offsets[i]; k < offsets[i + 1]; k++) finest = level[partners[k]] > finest ? level[partners[k]] : finest;
    return finest;
  }
  // f(j) for owned particle i's neighbours j (owned or ghost)
  template <class F> void for_each_neighbour(int i, F &&f) const
  {
    for (int k = offsets[i]; k < offsets[i + 1]; k++) f(partners[k]);
  }

 private:
  std::vector<int> offsets, partners;
  std::vector<int> support_offsets, support_partners;    // the neighbours within the support
  size_t previous_edges = 0;                               // (to reserve)
  std::vector<int> level, new_level;    // owned and ghost particles
  SPHSoilGhostRows shared;              // levels to the ghosts
  void share(std::vector<int> &values);    // owned values to the ghosts
};

}    // namespace LAMMPS_NS

#endif
