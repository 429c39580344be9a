/* -*- c++ -*- ----------------------------------------------------------
   SPH_SOIL package for LAMMPS: which particles a refinement splits.

   A criterion answers, for each owned particle, whether it wants to be
   split; fix sph/soil/refine and sph_soil/refine then apply their group,
   region and maxlevel on top (SPHSoilRefineSelection). Criteria are chosen
   by keyword (`criterion strain|all|v_name`) from the registry in
   sph_soil_refine_criterion.cpp: a new criterion is one header with its
   class and one line there.
------------------------------------------------------------------------- */

#ifndef LMP_SPH_SOIL_REFINE_CRITERION_H
#define LMP_SPH_SOIL_REFINE_CRITERION_H

#include "pointers.h"

#include <memory>
#include <string>
#include <vector>

namespace LAMMPS_NS {

class SPHSoilRefineCriterion : protected Pointers {
 public:
  explicit SPHSoilRefineCriterion(LAMMPS *lmp) : Pointers(lmp) {}
  virtual ~SPHSoilRefineCriterion() = default;

  // a keyword of this criterion (e.g. threshold) for `command`; false if not one of its own
  virtual bool parse_keyword(const std::string & /*command*/, const std::string & /*keyword*/,
                             const char * /*value*/)
  {
    return false;
  }
  // check what it needs, at init (e.g. that a variable exists)
  virtual void init(const std::string & /*command*/) {}
  // before each selection (e.g. evaluate a variable); collective
  virtual void prepare() {}
  // whether owned particle i wants to be split
  virtual bool wants(int i) const = 0;
  // what it selects, for the log: "strain measure > 0.05"
  virtual std::string describe() const = 0;
};

// The registry of criteria (sph_soil_refine_criterion.cpp): a criterion class names its word
// after the keyword `criterion` (WORD; a trailing '_' makes it a prefix: v_name), how the
// "allowed" lists show it (SHOWN) and its own keywords (KEYWORDS, space-separated), and is built
// from (lmp, the word as given). A new criterion is its header and one registry line.
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

// Group, region, level limit and criterion: the particles a refinement splits. One parser for
// the keywords that fix sph/soil/refine and sph_soil/refine share.
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
  // the criterion wants; collective (the criterion may evaluate a variable)
  std::vector<int> parents(int groupbit, int maxlevel);
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
