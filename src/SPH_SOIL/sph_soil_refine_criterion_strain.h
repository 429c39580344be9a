/* -*- c++ -*- ----------------------------------------------------------
   SPH_SOIL refinement criterion `strain` (the default of fix sph/soil/refine):
   split where the strain measure eps_xx^2 + eps_yy^2 + eps_zz^2 exceeds
   `threshold` (doc/theory.rst section 5.1), of the strain since the particle's
   birth (`since split`, the default: a daughter is judged on what it has done
   itself, so that it does not split again at the next check on its parent's
   strain), with merging since it was last quiet (5.11), or of the whole
   accumulated strain (`since start`, the paper's).
------------------------------------------------------------------------- */

#ifndef LMP_SPH_SOIL_REFINE_CRITERION_STRAIN_H
#define LMP_SPH_SOIL_REFINE_CRITERION_STRAIN_H

#include "atom.h"
#include "atom_vec_sph_soil.h"
#include "soil_tensor.h"
#include "sph_soil_compat.h"
#include "sph_soil_input.h"
#include "sph_soil_refine_criterion.h"

namespace LAMMPS_NS {

class SPHSoilRefineCriterionStrain : public SPHSoilRefineCriterion {
 public:
  static constexpr const char *WORD = "strain", *SHOWN = "strain", *KEYWORDS = "threshold since";
  SPHSoilRefineCriterionStrain(LAMMPS *lmp, const std::string &) :
      SPHSoilRefineCriterion(lmp), threshold(0.05), since_split(true), avec(nullptr)
  {
  }

  bool parse_keyword(const std::string &command, const std::string &keyword, const char *value) override
  {
    if (keyword == "threshold") {
      threshold = SPHSoilInput::number(FLERR, lmp, command + " threshold", value, SPHSoilInput::at_least(0.0));
    } else if (keyword == "since") {
      const std::string word = value;
      if (word != "split" && word != "start")
        SPHSoilCompat::error_all(lmp, FLERR, "Illegal {} since {}: must be split or start", command,
                                 word);
      since_split = word == "split";
    } else {
      return false;
    }
    return true;
  }
  void prepare(const RefineHistory &history) override
  {
    avec = static_cast<AtomVecSPHSoil *>(atom->style_match("sph/soil"));
    strain_reference = since_split ? history.strain_reference : nullptr;
  }
  bool wants(int i) const override
  {
    double strain[6];
    for (int k = 0; k < 6; k++)
      strain[k] = avec->total_strain[i][k] - (strain_reference ? strain_reference[i][k] : 0.0);
    return SPHSoil::strain_measure(strain) > threshold;
  }
  // quiet: at its present strain rate it would take more than twice the hold time to reach
  // the threshold (the measure is a square: a quarter of it in the hold time)
  bool quiet(int i, double hold_time) const override
  {
    double strain[6];
    for (int k = 0; k < 6; k++) strain[k] = avec->strain_rate[i][k] * hold_time;
    return SPHSoil::strain_measure(strain) < 0.25 * threshold;
  }
  void rest(int i) override
  {
    if (strain_reference)
      for (int k = 0; k < 6; k++) strain_reference[i][k] = avec->total_strain[i][k];
  }
  std::string describe() const override
  {
    return fmt::format("strain measure > {} (of the strain since {})", threshold,
                       since_split ? "the particle's split" : "the start");
  }

 private:
  double threshold;
  bool since_split;
  AtomVecSPHSoil *avec;
  double **strain_reference = nullptr;
};

}    // namespace LAMMPS_NS

#endif
