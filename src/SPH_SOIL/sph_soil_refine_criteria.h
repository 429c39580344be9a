/* -*- c++ -*- ----------------------------------------------------------
   SPH_SOIL package for LAMMPS: the registry of refinement criteria, the one
   source of their words: a criterion class names its word after the keyword
   `criterion` (WORD; a trailing '_' makes it a prefix: v_name), how the
   "allowed" lists show it (SHOWN) and its own keywords (KEYWORDS,
   space-separated), and is built from (lmp, the word as given). A new
   criterion is its header and one line in sph_soil_refine_criteria.cpp.
------------------------------------------------------------------------- */

#ifndef LMP_SPH_SOIL_REFINE_CRITERIA_H
#define LMP_SPH_SOIL_REFINE_CRITERIA_H

#include "sph_soil_refine_criterion.h"

#include <memory>
#include <string>
#include <vector>

namespace LAMMPS_NS {

struct RefineCriterionEntry {
  const char *word, *shown, *keywords;
  SPHSoilRefineCriterion *(*make)(LAMMPS *lmp, const std::string &word);
};
template <class Criterion> RefineCriterionEntry refine_criterion_entry()
{
  return {Criterion::WORD, Criterion::SHOWN, Criterion::KEYWORDS,
          [](LAMMPS *lmp, const std::string &word) -> SPHSoilRefineCriterion * {
            return new Criterion(lmp, word);
          }};
}
const std::vector<RefineCriterionEntry> &refine_criteria();
// add a criterion to the registry (a criterion outside the package; the tests' dummy)
void register_refine_criterion(const RefineCriterionEntry &entry);
// "strain, all, v_name": the words the registry takes, for messages
std::string refine_criterion_names();
// every criterion's own keywords, comma-separated, for messages
std::string refine_criterion_keywords();

// The criterion of `word`, or an error naming `command` and the choices.
std::unique_ptr<SPHSoilRefineCriterion> make_refine_criterion(LAMMPS *lmp, const std::string &command,
                                                              const std::string &word);

}    // namespace LAMMPS_NS

#endif
