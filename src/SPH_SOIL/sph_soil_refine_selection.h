/* -*- c++ -*- ----------------------------------------------------------
   SPH_SOIL package for LAMMPS: the particles a refinement splits: group,
   region, level limit and criterion (sph_soil_refine_criteria.h), with one
   parser for the keywords that fix sph/soil/refine and sph_soil/refine share.
------------------------------------------------------------------------- */

#ifndef LMP_SPH_SOIL_REFINE_SELECTION_H
#define LMP_SPH_SOIL_REFINE_SELECTION_H

#include "sph_soil_refine_criterion.h"

#include <memory>
#include <string>
#include <vector>

namespace LAMMPS_NS {

class SPHSoilRefineSelection : protected Pointers {
 public:
  // `command` as the user types it ("fix sph/soil/refine"), `default_criterion` its default
  SPHSoilRefineSelection(LAMMPS *lmp, const std::string &command, const std::string &default_criterion);

  // criterion, region and the criterion's own keywords; false if `keyword` is none of them
  bool parse_keyword(const std::string &keyword, const char *value);
  // its keywords and every criterion's own, for messages: "criterion, region, threshold"
  static std::string keywords();
  // at init: the region (it may have been redefined) and the criterion's needs
  void init();
  // owned particles of `groupbit` below `maxlevel` (0: no limit) that the region contains and
  // the criterion wants; collective (the criterion may evaluate a variable). `may_split`, if
  // given, gets per owned particle whether it may split (group, level, region) whatever the
  // criterion says.
  std::vector<int> parents(int groupbit, int maxlevel, const RefineHistory &history = RefineHistory(),
                           std::vector<char> *may_split = nullptr);
  // whether owned particle i is quiet enough to merge (after parents(), which prepares the
  // criterion)
  bool quiet(int i, double hold_time) const { return criterion->quiet(i, hold_time); }
  std::string describe() const;

 private:
  std::string command;
  std::string criterion_word;       // as given to `criterion`
  std::string criterion_keyword;    // the last keyword of the criterion's own that was given
  std::unique_ptr<SPHSoilRefineCriterion> criterion;
  std::string region_id;
  class Region *region;
};

}    // namespace LAMMPS_NS

#endif
