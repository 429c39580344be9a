/* -*- c++ -*- ----------------------------------------------------------
   SPH_SOIL package: clusters of orphans for merging (pure, no LAMMPS).
   doc/theory.rst section 5.11.

   A family that the flow has torn apart (or that lost a sibling) never merges
   as a family; after it has been quiet for twice the hold time its members
   become orphans, and orphans of one level merge in clusters of as many as a
   family has (4 in 2D, 8 in 3D), chosen by proximity in three rounds that each
   rank takes for its owned orphans from its own and the ghosts' values, so
   that the outcome does not depend on the ranks:
   1. a leader is an orphan with no orphan of its level within its reach (the
      parent's smoothing length) of a smaller priority, a scrambling of the ID
      (IDs run along the lattice and through families, so that the smallest ID
      within reach falls at the edge of a zone and the clusters would grow
      from there, a few per look; scrambled, leaders are spread over the zone);
   2. every other orphan joins the nearest leader within its reach (the
      smaller ID at a tie), or none;
   3. a leader with at least count - 1 members takes the count - 1 nearest (the
      smaller ID at a tie) and merges with them; the others wait for a later
      look, where the leaders have changed: the priority is salted with the
      look (with fixed priorities an orphan that leads a cluster too small to
      merge would lead it at every look, and its members would wait for ever).
   Every orphan joins at most one leader and leaders join none, so no particle
   goes into two merges.
------------------------------------------------------------------------- */

#ifndef LMP_SOIL_REFINE_CLUSTERS_H
#define LMP_SOIL_REFINE_CLUSTERS_H

#include <algorithm>
#include <cstdint>
#include <vector>

namespace SPHSoil {

// an orphan of the same level near the one deciding: its ID and squared distance, and which
// particle it is (an index of the caller's)
struct NearOrphan {
  double tag;
  double distance2;
  int index;
};

// the priority of a leader at a look (a count of the looks, the same on every rank): a
// bijection of the 64-bit integers for each look (the ID salted with the look, then
// splitmix64's finalizer), so that distinct IDs never tie
inline uint64_t cluster_priority(double tag, uint64_t look = 0)
{
  uint64_t z = ((uint64_t) tag ^ (look * 0xd1b54a32d192ed03ULL)) + 0x9e3779b97f4a7c15ULL;
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

// round 1: `tag` leads if no orphan within reach has a smaller priority at this look
inline bool leads_cluster(double tag, const std::vector<NearOrphan> &within_reach, uint64_t look = 0)
{
  const uint64_t own = cluster_priority(tag, look);
  for (const auto &o : within_reach)
    if (cluster_priority(o.tag, look) < own) return false;
  return true;
}

// round 2: the ID of the leader an orphan joins among the leaders within its reach, 0 if none
inline double joined_leader(const std::vector<NearOrphan> &leaders_within_reach)
{
  const NearOrphan *best = nullptr;
  for (const auto &o : leaders_within_reach)
    if (!best || o.distance2 < best->distance2 || (o.distance2 == best->distance2 && o.tag < best->tag))
      best = &o;
  return best ? best->tag : 0.0;
}

// round 3: the `wanted` nearest of the orphans that joined a leader (the smaller ID at a
// tie), or none if fewer joined
inline std::vector<NearOrphan> cluster_members(std::vector<NearOrphan> joined, int wanted)
{
  if ((int) joined.size() < wanted) return {};
  std::sort(joined.begin(), joined.end(), [](const NearOrphan &a, const NearOrphan &b) {
    return a.distance2 < b.distance2 || (a.distance2 == b.distance2 && a.tag < b.tag);
  });
  joined.resize(wanted);
  return joined;
}

}    // namespace SPHSoil

#endif
