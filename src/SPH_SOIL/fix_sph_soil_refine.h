/* -*- c++ -*- ----------------------------------------------------------
   SPH_SOIL package for LAMMPS: fix sph/soil/refine

   Dynamic particle refinement (doc/theory.rst section 5): every N steps, each
   particle of the group that its criterion selects (by default: whose
   accumulated strain measure eps_xx^2 + eps_yy^2 + eps_zz^2 exceeds a
   threshold), and whose level is below maxlevel, is split into 4 (2D) or 8
   (3D) daughters, keeping neighbours within one level of each other (2:1
   balance, sph_soil_refine_balance.h). Per atom it keeps the total strain at
   each particle's birth, so that a criterion can judge a daughter on what it
   has done since.
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

#include <memory>
#include <string>

namespace LAMMPS_NS {

class FixSPHSoilRefine : public Fix {
 public:
  FixSPHSoilRefine(class LAMMPS *, int, char **);
  ~FixSPHSoilRefine() override;
  int setmask() override;
  void init() override;
  void setup(int) override;
  void end_of_step() override;
  double compute_vector(int) override;
  void post_run() override;
  void write_restart(FILE *) override;
  void restart(char *) override;

  // per-atom: the total strain at the particle's birth
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

 protected:
  int maxlevel;          // particles at this level are not split again
  std::unique_ptr<class SPHSoilRefineSelection> selection;    // criterion, region
  std::unique_ptr<class SPHSoilRefineSplitter> splitter;
  std::unique_ptr<class SPHSoilRefineBalance> balance;
  double **strain_at_birth;    // per atom, Voigt
  class FixSPHSoil *integrator;
  bool parameters_reported;
  double bytes_per_particle, node_bytes;    // at set-up: a split that would not fit stops

  bigint last_split;          // particles split at the last refinement step
  bigint last_split_step;     // that step
  bigint total_split;         // since the fix was defined (kept in restart files)
  bigint last_unbalanced;     // pairs more than one level apart at the last check, before its splits
  bigint run_unbalanced;      // the most at a check of this run
  bigint run_split, run_forced;    // split in this run; of them, split for the balance only

  void reneighbour();
  void report_parameters();
  void report_capacity();
};

}    // namespace LAMMPS_NS

#endif
#endif
