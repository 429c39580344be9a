/* ----------------------------------------------------------------------
   SPH_SOIL package for LAMMPS: particle splitting (see the header)
------------------------------------------------------------------------- */

#include "sph_soil_refine_splitter.h"

#include "sph_soil_fixes.h"
#include "sph_soil_input.h"
#include "sph_soil_offenders.h"

#include "atom.h"
#include "atom_vec_sph_soil.h"
#include "comm.h"
#include "domain.h"
#include "force.h"
#include "pair.h"
#include "soil_constitutive.h"
#include "soil_material.h"
#include "soil_neighbours.h"
#include "soil_refine_split.h"
#include "sph_soil_compat.h"
#include "sph_soil_materials.h"

#include <algorithm>
#include <cmath>

using namespace LAMMPS_NS;
using namespace SPHSoil;

// (a definition for C++11, where LAMMPS 29Sep2021 compiles: the value is used by reference)
constexpr int SPHSoilRefineSplitter::NSTATE;

/* ---------------------------------------------------------------------- */

SPHSoilRefineSplitter::SPHSoilRefineSplitter(LAMMPS *lmp, const std::string &who_) :
    Pointers(lmp), who(who_), avec(nullptr), materials(nullptr)
{
}

// (a definition for C++11, where LAMMPS 29Sep2021 compiles: the value is passed by reference)
constexpr const char *SPHSoilRefineSplitter::KEYWORDS;

/* ---------------------------------------------------------------------- */

SPHSoil::KernelKind SPHSoilRefineSplitter::kernel_kind() const
{
  return kernel;
}

/* ---------------------------------------------------------------------- */

bool SPHSoilRefineSplitter::parse_keyword(const std::string &command, const std::string &keyword,
                                    const char *value)
{
  using namespace SPHSoilInput;
  const std::string what = command + " " + keyword;
  if (keyword == "separation")
    separation = number(FLERR, lmp, what, value, between(0.0, 1.0, true, true));
  else if (keyword == "smoothing")
    smoothing_ratio = number(FLERR, lmp, what, value, between(0.0, 1.0, true, true));
  else if (keyword == "dref")
    reference_spacing = number(FLERR, lmp, what, value, above(0.0));
  else
    return false;
  return true;
}

/* ---------------------------------------------------------------------- */

void SPHSoilRefineSplitter::init()
{
  avec = dynamic_cast<AtomVecSPHSoil *>(atom->style_match("sph/soil"));
  if (!avec) SPHSoilCompat::error_all(lmp, FLERR, "{} requires atom_style sph/soil", who);
  Pair *pair = force->pair_match("sph/soil", 1);
  if (!pair) SPHSoilCompat::error_all(lmp, FLERR, "{} requires pair_style sph/soil", who);
  int dim;
  materials = static_cast<const SPHSoilMaterials *>(pair->extract("sph_soil_materials", dim));
  kernel = *static_cast<const SPHSoil::KernelKind *>(pair->extract("sph_soil_kernel", dim));
}

/* ---------------------------------------------------------------------- */

double SPHSoilRefineSplitter::smoothing_length(int i) const
{
  return avec->smoothing_length[i];
}

double SPHSoilRefineSplitter::spacing(int i) const
{
  if (reference_spacing > 0.0) return level_spacing(reference_spacing, avec->level[i]);
  const double density = materials->of(atom->type[i]).density;
  return volume_spacing(atom->rmass[i] / density, domain->dimension);
}

/* ----------------------------------------------------------------------
   CSPM average of the state at `position` over the atoms of the parent's type whose support
   reaches it (the parent's own included); `near` has the atoms of the parents' types binned
------------------------------------------------------------------------- */

void SPHSoilRefineSplitter::interpolate(int parent, const double *position,
                                        const SmoothingClassGrids &near, double *state) const
{
  const int dimension = domain->dimension;
  const double *rho = atom->rho, *rmass = atom->rmass, *h = avec->smoothing_length;
  const int *type = atom->type;
  const int itype = type[parent];

  CspmSum<NSTATE> sum(kernel);
  near.for_each_within(position, 0.0, [&](int j, double r2) {
    if (type[j] != itype) return;
    double f[NSTATE];
    f[0] = rho[j];
    for (int k = 0; k < 6; k++) {
      f[1 + k] = avec->stress[j][k];
      f[7 + k] = avec->total_strain[j][k];
    }
    f[13] = avec->pore_pressure[j];
    sum.add(dimension, rmass[j] / rho[j], std::sqrt(r2), h[j], f);
  });
  if (!sum.result(state)) {
    // no neighbour reaches the daughter (separation far beyond the support): keep the parent's
    state[0] = rho[parent];
    for (int k = 0; k < 6; k++) {
      state[1 + k] = avec->stress[parent][k];
      state[7 + k] = avec->total_strain[parent][k];
    }
    state[13] = avec->pore_pressure[parent];
  }
}

/* ----------------------------------------------------------------------
   the first new tag of each parent's daughters: after the largest ID, in the order of the
   parents' IDs, so that the result does not depend on how atoms are spread over ranks
------------------------------------------------------------------------- */

std::vector<tagint> SPHSoilRefineSplitter::first_new_tags(const std::vector<int> &parents, bigint &total)
{
  const int nprocs = comm->nprocs;
  const int mine = (int) parents.size();
  std::vector<int> counts(nprocs), offsets(nprocs, 0);
  MPI_Allgather(&mine, 1, MPI_INT, counts.data(), 1, MPI_INT, world);
  total = 0;
  for (int p = 0; p < nprocs; p++) {
    offsets[p] = (int) total;
    total += counts[p];
  }
  if (total > MAXSMALLINT)
    SPHSoilCompat::error_all(lmp, FLERR, "{}: too many particles split at once ({})", who, total);

  std::vector<tagint> local_tags(mine), all_tags(total > 0 ? total : 1);
  for (int n = 0; n < mine; n++) local_tags[n] = atom->tag[parents[n]];
  MPI_Allgatherv(local_tags.data(), mine, MPI_LMP_TAGINT, all_tags.data(), counts.data(),
                 offsets.data(), MPI_LMP_TAGINT, world);
  all_tags.resize(total);
  std::sort(all_tags.begin(), all_tags.end());

  tagint maxtag = 0, maxtag_all = 0;
  for (int i = 0; i < atom->nlocal; i++) maxtag = MAX(maxtag, atom->tag[i]);
  MPI_Allreduce(&maxtag, &maxtag_all, 1, MPI_LMP_TAGINT, MPI_MAX, world);

  const int new_per_parent = daughter_count(domain->dimension) - 1;
  if ((double) maxtag_all + (double) total * new_per_parent >= (double) MAXTAGINT)
    SPHSoilCompat::error_all(lmp, FLERR, "{}: new atom IDs would exceed the largest allowed ID",
                             who);

  std::vector<tagint> first(mine);
  for (int n = 0; n < mine; n++) {
    const auto rank = std::lower_bound(all_tags.begin(), all_tags.end(), local_tags[n]) - all_tags.begin();
    first[n] = maxtag_all + (tagint) rank * new_per_parent + 1;
  }
  return first;
}

/* ---------------------------------------------------------------------- */

bigint SPHSoilRefineSplitter::split(const std::vector<int> &parents)
{
  if (!atom->tag_enable) SPHSoilCompat::error_all(lmp, FLERR, "{} requires atom IDs", who);
  bigint total = 0;
  const std::vector<tagint> first_tag = first_new_tags(parents, total);
  if (total == 0) return 0;

  Daughters daughters;
  plan_daughters(parents, daughters);
  stop_if_outside_box(parents, daughters);
  add_daughters(parents, first_tag, daughters);

  SPHSoilFixes::recount_atoms(atom, world);
  return total;
}

/* ----------------------------------------------------------------------
   every daughter's position and interpolated state, before anything changes: from the owned
   and ghost atoms of the parents' types (the ghosts reach 2 max(h) + skin beyond the
   subdomain), binned by their own h so that a search costs what the atoms near a daughter
   need (walls, which never refine, and coarse soil elsewhere do not widen it), with the
   ghosts' state as of now (the strain does not travel every step)
------------------------------------------------------------------------- */

void SPHSoilRefineSplitter::plan_daughters(const std::vector<int> &parents, Daughters &daughters)
{
  comm->forward_comm();
  comm->forward_comm_array(AtomVecSPHSoil::NVOIGT, avec->total_strain);

  const int dimension = domain->dimension;
  const int count = daughter_count(dimension);
  const int nparents = (int) parents.size();
  const int nall = atom->nlocal + atom->nghost;
  std::vector<char> parent_type(atom->ntypes + 1, 0);
  for (int i : parents) parent_type[atom->type[i]] = 1;
  std::vector<int> members;
  for (int j = 0; j < nall; j++)
    if (parent_type[atom->type[j]]) members.push_back(j);
  SmoothingClassGrids near;
  near.build(atom->x, avec->smoothing_length, members, dimension, kernel_support(kernel));

  daughters.count = count;
  daughters.position.assign((size_t) nparents * count * 3, 0.0);
  daughters.state.assign((size_t) nparents * count * NSTATE, 0.0);
  for (int n = 0; n < nparents; n++) {
    const int i = parents[n];
    double offsets[MAX_DAUGHTERS][3];
    daughter_offsets(dimension, separation, spacing(i), offsets);
    for (int k = 0; k < count; k++) {
      double *xd = daughters.position_of(n, k);
      for (int a = 0; a < 3; a++) xd[a] = atom->x[i][a] + offsets[k][a];
      interpolate(i, xd, near, daughters.state_of(n, k));
    }
  }
}

// a daughter beyond a fixed ('f') boundary would be lost at the next reneighbouring
void SPHSoilRefineSplitter::stop_if_outside_box(const std::vector<int> &parents, Daughters &daughters)
{
  const int dimension = domain->dimension, count = daughters.count;
  std::vector<int> outside(atom->nlocal, -1);    // per parent: its first daughter outside
  for (int n = 0; n < (int) parents.size(); n++)
    for (int k = 0; k < count && outside[parents[n]] < 0; k++) {
      const double *xd = daughters.position_of(n, k);
      for (int a = 0; a < dimension; a++)
        if ((domain->boundary[a][0] == 1 && xd[a] < domain->boxlo[a]) ||
            (domain->boundary[a][1] == 1 && xd[a] >= domain->boxhi[a]))
          outside[parents[n]] = n * count + k;
    }
  const auto lost = SPHSoilOffenders::find_offenders(
      lmp, [&](int i) { return outside[i] >= 0; },
      [&](int i, double *values) {
        for (int a = 0; a < 3; a++) values[a] = daughters.position[(size_t) outside[i] * 3 + a];
      });
  if (lost)
    SPHSoilCompat::error_all(
        lmp, FLERR,
        "{}: splitting {} particle(s) would put daughters outside the box through a "
        "fixed boundary (atom {}: a daughter at {:.6g} {:.6g} {:.6g}); keep the split particles "
        "separation * d_p / 2 away from fixed boundaries (e.g. with a region), or "
        "make the boundary shrink-wrapped",
        who, lost.count, lost.first, lost.values[0], lost.values[1], lost.values[2]);
}

/* ----------------------------------------------------------------------
   the daughters: the parent's slot becomes daughter 0, the others are copies of the parent
   appended to the owned atoms (overwriting the ghosts, which are rebuilt later)
------------------------------------------------------------------------- */

void SPHSoilRefineSplitter::add_daughters(const std::vector<int> &parents,
                                          const std::vector<tagint> &first_tag, Daughters &daughters)
{
  atom->nghost = 0;
  const int count = daughters.count;
  for (int n = 0; n < (int) parents.size(); n++) {
    const int i = parents[n];
    Parent parent{avec->level[i], atom->rmass[i], avec->smoothing_length[i],
                  {atom->f[i][0], atom->f[i][1], atom->f[i][2]}};
    for (int k = 1; k < count; k++) {
      const int j = atom->nlocal;
      // through the atom style in use (under atom_style hybrid, the hybrid style): every
      // per-atom array moves with grow and is copied, the fixes' arrays with them
      if (j == atom->nmax) atom->avec->grow(0);
      atom->avec->copy(i, j, 0);
      atom->tag[j] = first_tag[n] + k - 1;
      atom->nlocal++;
      set_daughter(j, parent, daughters.position_of(n, k), daughters.state_of(n, k), count);
    }
    set_daughter(i, parent, daughters.position_of(n, 0), daughters.state_of(n, 0), count);
  }
}

void SPHSoilRefineSplitter::set_daughter(int j, const Parent &parent, const double *position,
                                         const double *state, int count)
{
  for (int a = 0; a < 3; a++) {
    atom->x[j][a] = position[a];
    atom->f[j][a] = parent.force[a] / count;    // the parent's acceleration
  }
  atom->rmass[j] = parent.mass / count;
  avec->smoothing_length[j] = smoothing_ratio * parent.h;
  avec->level[j] = parent.level + 1;
  atom->rho[j] = state[0];
  for (int c = 0; c < 6; c++) {
    avec->stress[j][c] = state[1 + c];
    avec->total_strain[j][c] = state[7 + c];
  }
  avec->pore_pressure[j] = state[13];
  // a CSPM average of admissible stresses is admissible for one convex yield surface; the
  // return guards against round-off
  return_to_admissible(j);
}

/* ---------------------------------------------------------------------- */

void SPHSoilRefineSplitter::return_to_admissible(int i) const
{
  const auto model = materials->model(atom->type[i]);
  if (model) model->return_to_admissible(avec->stress[i]);
}
