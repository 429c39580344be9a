/* ----------------------------------------------------------------------
   SPH_SOIL package for LAMMPS: the particles a refinement splits
------------------------------------------------------------------------- */

#include "sph_soil_refine_selection.h"

#include "atom.h"
#include "atom_vec_sph_soil.h"
#include "domain.h"
#include "error.h"
#include "region.h"
#include "sph_soil_compat.h"
#include "sph_soil_refine_criteria.h"
#include "utils.h"

using namespace LAMMPS_NS;

std::string SPHSoilRefineSelection::keywords()
{
  const std::string own = refine_criterion_keywords();
  return "criterion, region" + (own.empty() ? "" : ", " + own);
}

/* ---------------------------------------------------------------------- */

SPHSoilRefineSelection::SPHSoilRefineSelection(LAMMPS *lmp, const std::string &command,
                                               const std::string &default_criterion) :
    Pointers(lmp), command(command), criterion_word(default_criterion),
    criterion(make_refine_criterion(lmp, command, default_criterion)), region(nullptr)
{
}

bool SPHSoilRefineSelection::parse_keyword(const std::string &keyword, const char *value)
{
  if (keyword == "criterion") {
    if (!criterion_keyword.empty() && criterion_word != value)
      error->all(FLERR, "Illegal {} criterion {}: give it before {}, a keyword of criterion {}",
                 command, value, criterion_keyword, criterion_word);
    criterion = make_refine_criterion(lmp, command, value);
    criterion_word = value;
  } else if (keyword == "region") {
    region_id = value;
    if (!SPHSoilCompat::find_region(domain, region_id))
      error->all(FLERR, "{} region {} does not exist", command, region_id);
  } else if (criterion->parse_keyword(command, keyword, value)) {
    criterion_keyword = keyword;
  } else {
    // a keyword of another criterion: say whose
    for (const auto &c : refine_criteria())
      for (const auto &own : utils::split_words(c.keywords))
        if (own == keyword)
          error->all(FLERR, "Illegal {} {}: a keyword of criterion {}, not of criterion {}", command,
                     keyword, c.word, criterion_word);
    return false;
  }
  return true;
}

void SPHSoilRefineSelection::init()
{
  region = nullptr;
  if (!region_id.empty()) {
    region = SPHSoilCompat::find_region(domain, region_id);
    if (!region) error->all(FLERR, "{} region {} does not exist", command, region_id);
  }
  criterion->init(command);
}

std::vector<int> SPHSoilRefineSelection::parents(int groupbit, int maxlevel, const RefineHistory &history,
                                                 std::vector<char> *may_split)
{
  auto avec = static_cast<AtomVecSPHSoil *>(atom->style_match("sph/soil"));
  criterion->prepare(history);
  if (region) region->prematch();
  if (may_split) may_split->assign(atom->nlocal, 0);
  std::vector<int> selected;
  double **x = atom->x;
  for (int i = 0; i < atom->nlocal; i++) {
    if (!(atom->mask[i] & groupbit)) continue;
    if (maxlevel > 0 && avec->level[i] >= maxlevel) continue;
    if (region && !region->match(x[i][0], x[i][1], x[i][2])) continue;
    if (may_split) (*may_split)[i] = 1;
    if (criterion->wants(i)) selected.push_back(i);
  }
  return selected;
}

std::string SPHSoilRefineSelection::describe() const
{
  return criterion->describe() + (region_id.empty() ? "" : ", in region " + region_id);
}
