/* -*- c++ -*- ----------------------------------------------------------
   SPH_SOIL refinement criterion `all` (the default of sph_soil/refine):
   every particle of the group (and region) splits.
------------------------------------------------------------------------- */

#ifndef LMP_SPH_SOIL_REFINE_CRITERION_ALL_H
#define LMP_SPH_SOIL_REFINE_CRITERION_ALL_H

#include "sph_soil_refine_criterion.h"

namespace LAMMPS_NS {

class SPHSoilRefineCriterionAll : public SPHSoilRefineCriterion {
 public:
  static constexpr const char *WORD = "all", *SHOWN = "all", *KEYWORDS = "";
  SPHSoilRefineCriterionAll(LAMMPS *lmp, const std::string &) : SPHSoilRefineCriterion(lmp) {}
  bool wants(int) const override { return true; }
  std::string describe() const override { return "all"; }
};

}    // namespace LAMMPS_NS

#endif
