/* -*- c++ -*- ----------------------------------------------------------
   SPH_SOIL package for LAMMPS: merging (derefinement) for fix sph/soil/refine.
   doc/theory.rst section 5.11; the fix holds the per-atom history
   (RefineHistory) and hands its communication callbacks to the merger.

   Siblings (the 4 or 8 daughters of one split) merge back into one particle
   when all of them have been quiet for the hold time, are complete, lie within
   their parent's smoothing length of their centre of mass, and no particle
   finer than they are lies within the merged particle's reach (the 2:1 balance
   holds). The owner of daughter 0 decides and writes the merged particle into
   daughter 0's slot; the others' owners delete them. A quiet member that does
   not find all its siblings within the parent's smoothing length (the flow
   tore the family apart, or a sibling is gone) becomes an orphan; orphans
   merge in clusters of as many by proximity (soil_refine_clusters.h), the
   cluster's leader deciding as daughter 0 does.
------------------------------------------------------------------------- */

#ifndef LMP_SPH_SOIL_REFINE_MERGER_H
#define LMP_SPH_SOIL_REFINE_MERGER_H

#include "pointers.h"
#include "sph_soil_refine_criterion.h"

#include <cstdint>
#include <vector>

namespace LAMMPS_NS {

class SPHSoilRefineMerger : protected Pointers {
 public:
  SPHSoilRefineMerger(LAMMPS *lmp, double hold_time, class SPHSoilRefineBalance &balance,
                      class SPHSoilRefineSplitter &splitter) :
      Pointers(lmp), merge_time(hold_time), balance(balance), splitter(splitter)
  {
  }
  ~SPHSoilRefineMerger() override;

  // the values a merge mass-averages per atom, and the row each atom sends to the ghosts
  static constexpr int MERGE_VALUES = 6 + 6 + 6 + 6 + 3 + 1 + 2;
  static constexpr int MERGE_ROW = 12 + MERGE_VALUES;
  // the family of an orphan at its level (0: none known, > 0: the parent's ID)
  static constexpr double ORPHAN = -1.0;

  // Merge the families of `groupbit` that may, at a check of a fix every `nevery` steps whose
  // communication callbacks call this object's; the ghosts must be current. Returns the
  // merges on all ranks (families and clusters of orphans); if any, the ghosts are gone (the
  // caller reneighbours). Collective.
  bigint merge(class Fix *fix, const RefineHistory &history, int groupbit, int maxlevel, int nevery);
  // whether a particle quiet since `quiet_since` (< 0: not quiet) has been quiet for the hold
  // time at time `now`: it may merge, and the criterion does not split it
  bool held_quiet(double quiet_since, double now) const
  {
    return quiet_since >= 0.0 && now - quiet_since >= merge_time * (1.0 - 1.0e-12);
  }

  int pack_forward_comm(int n, int *list, double *buf);
  void unpack_forward_comm(int n, int first, double *buf);
  int pack_reverse_comm(int n, int first, double *buf);
  void unpack_reverse_comm(int n, int *list, double *buf);
  bigint clusters_merged() const { return last_clusters; }    // of the last merge()
  double memory_usage() const { return (double) merge_rows * MERGE_ROW * sizeof(double); }

 private:
  double merge_time;
  SPHSoilRefineBalance &balance;
  SPHSoilRefineSplitter &splitter;
  RefineHistory state;
  double **merge_buffer = nullptr;    // the rows of owned atoms and ghosts
  int merge_rows = 0;
  bigint last_clusters = 0;
  void merge_values(int i, double *values) const;
  void find_clusters(class Fix *fix, const std::vector<char> &orphan, uint64_t look);
  bool merge_into(int i, const std::vector<int> &members, double now);
};

}    // namespace LAMMPS_NS

#endif
