/* -*- c++ -*- ----------------------------------------------------------
   SPH_SOIL refinement criterion `v_name`: split where the atom-style
   variable `name` is non-zero, the LAMMPS way of letting a user write a
   criterion of their own (from per-atom properties, computes, positions).
------------------------------------------------------------------------- */

#ifndef LMP_SPH_SOIL_REFINE_CRITERION_VARIABLE_H
#define LMP_SPH_SOIL_REFINE_CRITERION_VARIABLE_H

#include "atom.h"
#include "input.h"
#include "sph_soil_compat.h"
#include "sph_soil_refine_criterion.h"
#include "variable.h"

namespace LAMMPS_NS {

class SPHSoilRefineCriterionVariable : public SPHSoilRefineCriterion {
 public:
  static constexpr const char *WORD = "v_", *SHOWN = "v_name", *KEYWORDS = "";
  // `word` is v_name
  SPHSoilRefineCriterionVariable(LAMMPS *lmp, const std::string &word) :
      SPHSoilRefineCriterion(lmp), name(word.substr(2)), ivar(-1)
  {
  }

  void init(const std::string &command) override
  {
    ivar = input->variable->find(name.c_str());
    if (ivar < 0)
      SPHSoilCompat::error_all(lmp, FLERR, "{} criterion v_{}: variable {} does not exist", command,
                               name, name);
    if (!input->variable->atomstyle(ivar))
      SPHSoilCompat::error_all(lmp, FLERR, "{} criterion v_{}: variable {} must be atom-style",
                               command, name, name);
  }
  void prepare(const RefineHistory &) override
  {
    values.assign(atom->nlocal > 0 ? atom->nlocal : 1, 0.0);
    input->variable->compute_atom(ivar, 0, values.data(), 1, 0);
  }
  bool wants(int i) const override { return values[i] != 0.0; }
  std::string describe() const override { return "v_" + name + " non-zero"; }

 private:
  std::string name;
  int ivar;
  std::vector<double> values;
};

}    // namespace LAMMPS_NS

#endif
