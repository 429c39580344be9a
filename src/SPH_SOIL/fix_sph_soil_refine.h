/* -*- c++ -*- ----------------------------------------------------------
   SPH_SOIL package for LAMMPS: fix sph/soil/refine

   Dynamic particle refinement (doc/theory.rst section 5): every N steps, each
   particle of the group that its criterion selects (by default: whose
   accumulated strain measure eps_xx^2 + eps_yy^2 + eps_zz^2 exceeds a
   threshold), and whose level is below maxlevel, is split into 4 (2D) or 8
   (3D) daughters.
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
  void write_restart(FILE *) override;
  void restart(char *) override;

 protected:
  int maxlevel;          // particles at this level are not split again
  std::unique_ptr<class SPHSoilRefineSelection> selection;    // criterion, region
  std::unique_ptr<class SPHSoilRefineSplitter> splitter;
  class FixSPHSoil *integrator;
  bool parameters_reported;
  double bytes_per_particle, node_bytes;    // at set-up: a split that would not fit stops

  bigint last_split;          // particles split at the last refinement step
  bigint last_split_step;     // that step
  bigint total_split;         // since the fix was defined (kept in restart files)

  void reneighbour();
  void report_parameters();
  void report_capacity();
};

}    // namespace LAMMPS_NS

#endif
#endif
