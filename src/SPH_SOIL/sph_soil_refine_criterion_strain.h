/* -*- c++ -*- ----------------------------------------------------------
   SPH_SOIL refinement criterion `strain` (the default of fix sph/soil/refine):
   split where the accumulated strain measure eps_xx^2 + eps_yy^2 + eps_zz^2
   exceeds `threshold` (doc/theory.rst section 5.1).
------------------------------------------------------------------------- */

#ifndef LMP_SPH_SOIL_REFINE_CRITERION_STRAIN_H
#define LMP_SPH_SOIL_REFINE_CRITERION_STRAIN_H

#include "atom.h"
#include "atom_vec_sph_soil.h"
#include "soil_tensor.h"
#include "sph_soil_input.h"
#include "sph_soil_refine_criterion.h"

namespace LAMMPS_NS {

class SPHSoilRefineCriterionStrain : public SPHSoilRefineCriterion {
 public:
  static constexpr const char *WORD = "strain", *SHOWN = "strain", *KEYWORDS = "threshold";
  SPHSoilRefineCriterionStrain(LAMMPS *lmp, const std::string &) :
      SPHSoilRefineCriterion(lmp), threshold(0.05), avec(nullptr)
  {
  }

  bool parse_keyword(const std::string &command, const std::string &keyword, const char *value) override
  {
    if (keyword != "threshold") return false;
    threshold = SPHSoilInput::number(FLERR, lmp, command + " threshold", value, SPHSoilInput::at_least(0.0));
    return true;
  }
  void prepare() override { avec = static_cast<AtomVecSPHSoil *>(atom->style_match("sph/soil")); }
  bool wants(int i) const override { return SPHSoil::strain_measure(avec->total_strain[i]) > threshold; }
  std::string describe() const override { return fmt::format("strain measure > {}", threshold); }

 private:
  double threshold;
  AtomVecSPHSoil *avec;
};

}    // namespace LAMMPS_NS

#endif
