/* -*- c++ -*- ----------------------------------------------------------
   SPH_SOIL package for LAMMPS: fix sph/soil/refine

   Dynamic particle refinement (doc/theory.rst section 5): every N steps, each
   particle of the group that its criterion selects (by default: whose
   accumulated strain measure eps_xx^2 + eps_yy^2 + eps_zz^2 exceeds a
   threshold), and whose level is below maxlevel, is split into 4 (2D) or 8
   (3D) daughters, keeping neighbours within one level of each other (2:1
   balance, sph_soil_refine_balance.h), and with `merge T` merges siblings
   that have been quiet for a time T back into their parent, and particles of
   families torn apart in clusters (sph_soil_refine_merger.h). Per atom it keeps the total strain at each
   particle's birth (a criterion judges a daughter on what it has done since),
   since when it has been quiet, and its ancestors' IDs (its families).
   See doc/fix_sph_soil_refine.rst.
------------------------------------------------------------------------- */

#ifdef FIX_CLASS
// clang-format off
FixStyle(sph/soil/refine,FixSPHSoilRefine);
// clang-format on
#else

#ifndef LMP_FIX_SPH_SOIL_REFINE_H
#define LMP_FIX_SPH_SOIL_REFINE_H

#include "fix.h"
#include "soil_level_steps.h"
#include "sph_soil_refine_criterion.h"

#include <memory>
#include <string>
#include <vector>

namespace LAMMPS_NS {

class FixSPHSoilRefine : public Fix {
 public:
  FixSPHSoilRefine(class LAMMPS *, int, char **);
  ~FixSPHSoilRefine() override;
  int setmask() override;
  void init() override;
  void setup(int) override;
  void post_integrate() override;
  void end_of_step() override;
  double compute_vector(int) override;
  void post_run() override;
  void write_restart(FILE *) override;
  void restart(char *) override;

  // per-atom: the total strain at the particle's birth, quiet since, families, easing
  void grow_arrays(int) override;
  void copy_arrays(int, int, int) override;
  void set_arrays(int) override;
  int pack_exchange(int, double *) override;
  int unpack_exchange(int, double *) override;
  int pack_restart(int, double *) override;
  void unpack_restart(int, int) override;
  int maxsize_restart() override;
  int size_restart(int) override;
  double memory_usage() override;
  // the merge's communication: its flags and state to the ghosts, deletions to the owners; and
  // while daughters ease, their smoothing lengths to the ghosts
  int pack_forward_comm(int, int *, double *, int, int *) override;
  void unpack_forward_comm(int, int, double *) override;
  int pack_reverse_comm(int, int, double *) override;
  void unpack_reverse_comm(int, int *, double *) override;

 protected:
  int maxlevel;          // particles at this level are not split again
  std::unique_ptr<class SPHSoilRefineSelection> selection;    // criterion, region, buffer
  std::unique_ptr<class SPHSoilRefineSplitter> splitter;
  std::unique_ptr<class SPHSoilRefineBalance> balance;
  // per atom: the history of RefineHistory (sph_soil_refine_criterion.h)
  double **strain_reference, *quiet_since, **family;
  double merge_time;           // merge: siblings quiet for this time merge (0: no merging)
  // ease T: daughters are born with the smoothing ratio of the split's least stress defect
  // (birth_ratio) and their h goes linearly to alpha_r h_parent over the time T (0: no easing)
  double ease_time = 0.0, birth_ratio = 0.0;
  double *ease_since = nullptr, *ease_target = nullptr;    // per atom: birth (-1: done), final h
  double easing_until = -1.0;    // the time the last daughters finish easing (all ranks)
  bool forwarding_h = false;     // the forward communication in progress is ease()'s
  bigint total_merged;         // merges since the fix was defined (families and clusters)
  bigint total_clusters = 0;   // of them, clusters of orphans
  class FixSPHSoil *integrator;
  const SPHSoil::StepSchedule *schedule;    // fix sph/soil's time-step hierarchy
  bool parameters_reported;
  double bytes_per_particle;    // measured at each split: a split that would not fit stops

  bigint last_split;          // particles split at the last refinement step
  bigint last_split_step;     // that step
  bigint total_split;         // since the fix was defined (kept in restart files)
  bigint last_unbalanced;     // pairs more than one level apart at the last check, before its splits
  bigint run_unbalanced;      // the most at a check of this run
  bigint run_split, run_forced;    // split in this run; of them, split for the balance only

  int per_atom_columns() const { return 6 + 1 + maxlevel + 2; }
  RefineHistory history() const
  {
    RefineHistory h;    // (not an aggregate in C++11, where LAMMPS 29Sep2021 compiles)
    h.strain_reference = strain_reference;
    h.quiet_since = quiet_since;
    h.family = family;
    return h;
  }
  void born(const std::vector<int> &parents, int nlocal_before);
  void ease();
  void choose_birth_ratio(double ra);
  // an easing daughter's h: `remaining` (1 at birth, 0 at T) of the way from its final h to
  // birth_ratio / alpha_r times it
  double eased_smoothing_length(double final_h, double remaining) const;
  void mark_quiet();
  void merge();
  std::unique_ptr<class SPHSoilRefineMerger> merger;    // with merge T
  bigint run_merged = 0, run_clusters = 0;

  void reneighbour();
  void report_parameters();
  void report_capacity();
  void measure_bytes_per_particle();
  double growth_bytes(double owned) const;
};

}    // namespace LAMMPS_NS

#endif
#endif
