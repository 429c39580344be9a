/* ----------------------------------------------------------------------
   SPH_SOIL package for LAMMPS: the registry of refinement criteria
------------------------------------------------------------------------- */

#include "sph_soil_refine_criteria.h"

#include "sph_soil_compat.h"
#include "sph_soil_refine_criterion_all.h"
#include "sph_soil_refine_criterion_strain.h"
#include "sph_soil_refine_criterion_variable.h"
#include "utils.h"

using namespace LAMMPS_NS;

namespace {

// the registry: one line per criterion
std::vector<RefineCriterionEntry> &registry()
{
  static std::vector<RefineCriterionEntry> criteria = {
      refine_criterion_entry<SPHSoilRefineCriterionStrain>(),
      refine_criterion_entry<SPHSoilRefineCriterionAll>(),
      refine_criterion_entry<SPHSoilRefineCriterionVariable>(),
  };
  return criteria;
}

bool matches(const RefineCriterionEntry &c, const std::string &word)
{
  const std::string w = c.word;
  if (w.back() == '_') return word.size() > w.size() && word.compare(0, w.size(), w) == 0;
  return word == w;
}

std::string joined(const char *RefineCriterionEntry::*field)
{
  std::string list;
  for (const auto &c : refine_criteria())
    for (const auto &word : utils::split_words(c.*field)) list += (list.empty() ? "" : ", ") + word;
  return list;
}

}    // namespace

const std::vector<RefineCriterionEntry> &LAMMPS_NS::refine_criteria()
{
  return registry();
}

void LAMMPS_NS::register_refine_criterion(const RefineCriterionEntry &entry)
{
  registry().push_back(entry);
}

std::string LAMMPS_NS::refine_criterion_names()
{
  return joined(&RefineCriterionEntry::shown);
}

std::string LAMMPS_NS::refine_criterion_keywords()
{
  return joined(&RefineCriterionEntry::keywords);
}

std::unique_ptr<SPHSoilRefineCriterion> LAMMPS_NS::make_refine_criterion(LAMMPS *lmp,
                                                                         const std::string &command,
                                                                         const std::string &word)
{
  for (const auto &c : refine_criteria())
    if (matches(c, word)) return std::unique_ptr<SPHSoilRefineCriterion>(c.make(lmp, word));
  SPHSoilCompat::error_all(lmp, FLERR, "Illegal {} criterion {} (allowed: {})", command, word,
                           refine_criterion_names());
  return nullptr;
}

