/* -*- c++ -*- ----------------------------------------------------------
   SPH_SOIL package: the 2:1 level balance of refinement (pure, no LAMMPS).
   doc/theory.rst section 5.9.

   At a split check every particle has a level L and a new level N (L, or L + 1
   if it splits at this check). Two particles are neighbours when one lies
   within the kernel support of the other's smoothing length (the coarser one's:
   a buffer of one coarse support around a refined zone). Balanced means no two
   neighbours' levels differ by more than one. A check keeps what is balanced
   balanced and mends what motion has unbalanced:
   1. limit: the deepest level C each particle can reach at this check, L + 1
      if it may split (group, region, maxlevel), else L, and at most one above
      any neighbour's C (never below L), repeated until nothing changes: a
      split that a neighbour could not follow (another group, outside the
      region, at maxlevel) is not made;
   2. N = L + 1 where the criterion wants a split and C allows it;
   3. raise: a particle that may split does so if a neighbour's N is more than
      one above its own (coarse neighbours split first), repeated until nothing
      changes. C guarantees that this mends every pair a split of step 2 would
      unbalance, and it mends pairs that motion has unbalanced where it can.
   A forced split never comes from a split that step 1 called off. Two
   neighbours of one level L never constrain each other (a neighbour's C is at
   least L, so it allows L + 1; N is at most L + 1, so it forces nothing; and
   they are balanced): a graph may leave such pairs out. The passes
   work on one rank's owned particles; the caller brings the ghosts' values up
   to date between passes and repeats until no rank changes anything.
------------------------------------------------------------------------- */

#ifndef LMP_SOIL_REFINE_BALANCE_H
#define LMP_SOIL_REFINE_BALANCE_H

namespace SPHSoil {

// owned particle i's neighbours are partners[offsets[i] .. offsets[i + 1]), indices into the
// level arrays (owned and ghost particles)
struct LevelGraph {
  int owned;
  const int *offsets, *partners;
};

// step 1: lower each owned particle's deepest reachable level to one above its neighbours'
// (never below its own level); the number changed
inline int limit_new_levels(const LevelGraph &g, const int *level, int *deepest)
{
  int changed = 0;
  for (int i = 0; i < g.owned; i++) {
    int c = deepest[i];
    for (int k = g.offsets[i]; k < g.offsets[i + 1]; k++) {
      const int above_neighbour = deepest[g.partners[k]] + 1;
      if (above_neighbour < c) c = above_neighbour;
    }
    if (c < level[i]) c = level[i];
    if (c < deepest[i]) {
      deepest[i] = c;
      changed++;
    }
  }
  return changed;
}

// step 3: owned particles that may split (may_split != 0) and do not yet, whose neighbour's
// new level is more than one above theirs, split; the number changed
inline int raise_coarse_neighbours(const LevelGraph &g, const int *level, int *new_level,
                                   const char *may_split)
{
  int changed = 0;
  for (int i = 0; i < g.owned; i++) {
    if (!may_split[i] || new_level[i] > level[i]) continue;
    for (int k = g.offsets[i]; k < g.offsets[i + 1]; k++)
      if (new_level[g.partners[k]] > new_level[i] + 1) {
        new_level[i] = level[i] + 1;
        changed++;
        break;
      }
  }
  return changed;
}

// pairs more than one level apart, each counted once: from its coarser particle's side, which
// must be owned (a pair of an owned fine and a ghost coarse particle is the coarse one's
// owner's to count)
inline long count_unbalanced(const LevelGraph &g, const int *level)
{
  long count = 0;
  for (int i = 0; i < g.owned; i++)
    for (int k = g.offsets[i]; k < g.offsets[i + 1]; k++)
      if (level[g.partners[k]] > level[i] + 1) count++;
  return count;
}

}    // namespace SPHSoil

#endif
