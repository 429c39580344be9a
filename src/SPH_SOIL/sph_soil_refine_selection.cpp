/* ----------------------------------------------------------------------
   SPH_SOIL package for LAMMPS: the particles a refinement splits
------------------------------------------------------------------------- */

#include "sph_soil_refine_selection.h"

#include "atom.h"
#include "atom_vec_sph_soil.h"
#include "domain.h"
#include "error.h"
#include "region.h"
#include "soil_neighbours.h"
#include "sph_soil_compat.h"
#include "sph_soil_input.h"
#include "sph_soil_refine_criteria.h"
#include "utils.h"

using namespace LAMMPS_NS;

std::string SPHSoilRefineSelection::keywords()
{
  const std::string own = refine_criterion_keywords();
  return "criterion, region, buffer" + (own.empty() ? "" : ", " + own);
}

/* ---------------------------------------------------------------------- */

SPHSoilRefineSelection::SPHSoilRefineSelection(LAMMPS *lmp, const std::string &command,
                                               const std::string &default_criterion) :
    Pointers(lmp), command(command), criterion_word(default_criterion),
    criterion(make_refine_criterion(lmp, command, default_criterion)), region(nullptr),
    shared(lmp, 2, "sph/soil/refine:buffer")
{
}

bool SPHSoilRefineSelection::parse_keyword(const std::string &keyword, const char *value)
{
  if (keyword == "criterion") {
    if (!criterion_keyword.empty() && criterion_word != value)
      SPHSoilCompat::error_all(
          lmp, FLERR, "Illegal {} criterion {}: give it before {}, a keyword of criterion {}",
          command, value, criterion_keyword, criterion_word);
    criterion = make_refine_criterion(lmp, command, value);
    criterion_word = value;
  } else if (keyword == "region") {
    region_id = value;
    if (!SPHSoilCompat::find_region(domain, region_id))
      SPHSoilCompat::error_all(lmp, FLERR, "{} region {} does not exist", command, region_id);
  } else if (keyword == "buffer") {
    // up to one support: a wanted ghost is then within the ghost cut-off (the neighbour
    // list's, at least the support of the largest h) of the owned particles it buffers
    buffer = SPHSoilInput::number(FLERR, lmp, command + " buffer", value,
                                  SPHSoilInput::between(0.0, 1.0, false, false));
  } else if (criterion->parse_keyword(command, keyword, value)) {
    criterion_keyword = keyword;
  } else {
    // a keyword of another criterion: say whose
    for (const auto &c : refine_criteria())
      for (const auto &own : utils::split_words(c.keywords))
        if (own == keyword)
          SPHSoilCompat::error_all(lmp, FLERR,
                                   "Illegal {} {}: a keyword of criterion {}, not of criterion {}",
                                   command, keyword, c.word, criterion_word);
    return false;
  }
  return true;
}

void SPHSoilRefineSelection::init(double kernel_support, double ratio)
{
  support = kernel_support;
  smoothing_ratio = ratio;
  region = nullptr;
  if (!region_id.empty()) {
    region = SPHSoilCompat::find_region(domain, region_id);
    if (!region)
      SPHSoilCompat::error_all(lmp, FLERR, "{} region {} does not exist", command, region_id);
  }
  criterion->init(command);
}

std::vector<int> SPHSoilRefineSelection::parents(int groupbit, int maxlevel, const RefineHistory &history,
                                                 std::vector<char> *may_split)
{
  auto avec = static_cast<AtomVecSPHSoil *>(atom->style_match("sph/soil"));
  criterion->prepare(history);
  if (region) region->prematch();
  std::vector<char> own_may_split;
  std::vector<char> &allowed = may_split ? *may_split : own_may_split;
  allowed.assign(atom->nlocal, 0);
  std::vector<int> selected;
  std::vector<char> wanted(buffer > 0.0 ? atom->nlocal : 0, 0);
  double **x = atom->x;
  for (int i = 0; i < atom->nlocal; i++) {
    if (!(atom->mask[i] & groupbit)) continue;
    if (region && !region->match(x[i][0], x[i][1], x[i][2])) continue;
    allowed[i] = maxlevel <= 0 || avec->level[i] < maxlevel;
    // (the criterion is asked at maxlevel too only where a buffer needs the answer)
    if (buffer > 0.0) {
      wanted[i] = criterion->wants(i);
      if (allowed[i] && wanted[i]) selected.push_back(i);
    } else if (allowed[i] && criterion->wants(i)) {
      selected.push_back(i);
    }
  }
  in_buffer.clear();
  parent_in_buffer.clear();
  if (buffer > 0.0) widen(groupbit, wanted, allowed, selected);
  return selected;
}

/* ----------------------------------------------------------------------
   the buffer: the wanted particles' flags and levels to the ghosts, then each wanted particle j
   (owned or ghost) marks the owned particles k of the group whose b support h_k reaches it and
   that are not finer than j; those that may split and are not selected yet join `selected`.
   And the refined particles whose parent (h_k / alpha_r, a level coarser) would be so: they do
   not merge. (The ghosts reach the support of the largest h, and a merge needs its parent's
   reach among them anyway: sph_soil_refine_balance.h.)
------------------------------------------------------------------------- */

void SPHSoilRefineSelection::widen(int groupbit, const std::vector<char> &wanted,
                                   const std::vector<char> &may_split, std::vector<int> &selected)
{
  auto avec = static_cast<AtomVecSPHSoil *>(atom->style_match("sph/soil"));
  const int nlocal = atom->nlocal, nall = nlocal + atom->nghost;
  double **rows = shared.owned();
  for (int i = 0; i < nlocal; i++) {
    rows[i][0] = wanted[i];
    rows[i][1] = avec->level[i];
  }
  shared.forward();

  std::vector<int> members;
  for (int i = 0; i < nlocal; i++)
    if (atom->mask[i] & groupbit) members.push_back(i);
  const double *h = avec->smoothing_length;
  SPHSoil::SmoothingClassGrids near;
  const double reach = buffer * support, parent = 1.0 / smoothing_ratio;
  // (binned by the reach of their parent: a search from a point finds the members whose parent
  // would reach it, each class of h in cells of its own size)
  near.build(atom->x, h, members, domain->dimension, reach * MAX(1.0, parent));
  in_buffer.assign(nlocal, 0);
  parent_in_buffer.assign(nlocal, 0);
  double **x = atom->x;
  for (int j = 0; j < nall; j++) {
    if (rows[j][0] == 0.0) continue;
    const int level_j = (int) rows[j][1];
    // the members whose b support h_k (or their parent's) reaches x_j
    near.for_each_within(x[j], 0.0, [&](int k, double r2) {
      if (k == j) return;
      const int level_k = avec->level[k];
      if (level_k <= level_j && r2 < reach * reach * h[k] * h[k]) in_buffer[k] = 1;
      if (level_k >= 1 && level_k - 1 <= level_j && r2 < reach * reach * parent * parent * h[k] * h[k])
        parent_in_buffer[k] = 1;
    });
  }
  std::vector<char> chosen(nlocal, 0);
  for (int i : selected) chosen[i] = 1;
  for (int k = 0; k < nlocal; k++)
    if (in_buffer[k] && may_split[k] && !chosen[k]) selected.push_back(k);
}

std::string SPHSoilRefineSelection::describe() const
{
  return criterion->describe() + (region_id.empty() ? "" : ", in region " + region_id) +
      (buffer > 0.0 ? fmt::format(", and those whose kernel ({} of its support) reaches one", buffer) : "");
}
