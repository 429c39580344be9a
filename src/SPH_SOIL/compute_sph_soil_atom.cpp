/* ----------------------------------------------------------------------
   SPH_SOIL package for LAMMPS: compute sph/soil/atom
------------------------------------------------------------------------- */

#include "compute_sph_soil_atom.h"

#include "atom.h"
#include "atom_vec_sph_soil.h"
#include "error.h"
#include "force.h"
#include "memory.h"
#include "pair_sph_soil.h"
#include "soil_constitutive.h"
#include "update.h"

#include <cstring>
#include <string>

using namespace LAMMPS_NS;

namespace {
struct Name {
  const char *name;
  int quantity;
};
// accepted names (a few aliases that users of other codes would type)
const Name names[] = {{"sxx", 0},     {"syy", 1},      {"szz", 2},      {"sxy", 3},     {"sxz", 4},
                      {"syz", 5},     {"pressure", 6}, {"sqrtJ2", 7},   {"strain", 8},  {"yielded", 9},
                      {"density", 10}, {"rho", 10},    {"h", 11},       {"level", 12},
                      {"neighbours", 13}, {"neighbors", 13}, {"shear_strain", 14},
                      {"shear_strain_rate", 15}};

// the names for an error message, without the aliases (each quantity's first name)
std::string allowed_names()
{
  std::string list;
  int last = -1;
  for (const auto &n : names)
    if (n.quantity > last) {
      list += (list.empty() ? "" : " ") + std::string(n.name);
      last = n.quantity;
    }
  return list;
}
}    // namespace

/* ---------------------------------------------------------------------- */

ComputeSPHSoilAtom::ComputeSPHSoilAtom(LAMMPS *lmp, int narg, char **arg) :
    Compute(lmp, narg, arg), nmax(0), values(nullptr), table(nullptr), pair(nullptr)
{
  if (!atom->style_match("sph/soil"))
    error->all(FLERR, "Compute sph/soil/atom requires atom_style sph/soil");
  for (int iarg = 3; iarg < narg; iarg++) {
    int found = -1;
    for (const auto &n : names)
      if (strcmp(arg[iarg], n.name) == 0) found = n.quantity;
    if (found < 0)
      error->all(FLERR, "Illegal compute sph/soil/atom value {} (allowed: {})", arg[iarg],
                 allowed_names());
    quantities.push_back((Quantity) found);
  }
  if (quantities.empty())
    quantities = {STRAIN, PRESSURE, SQRTJ2, YIELDED, DENSITY, H, LEVEL};

  peratom_flag = 1;
  size_peratom_cols = quantities.size() == 1 ? 0 : quantities.size();
}

/* ---------------------------------------------------------------------- */

ComputeSPHSoilAtom::~ComputeSPHSoilAtom()
{
  memory->destroy(values);
  memory->destroy(table);
}

/* ---------------------------------------------------------------------- */

void ComputeSPHSoilAtom::init()
{
  pair = dynamic_cast<PairSPHSoil *>(force->pair_match("sph/soil", 1));
  for (auto q : quantities)
    if (q == YIELDED && !pair)
      error->all(FLERR, "Compute sph/soil/atom yielded needs pair_style sph/soil (its materials)");
    else if (q == NEIGHBOURS && !pair)
      error->all(FLERR, "Compute sph/soil/atom neighbours needs pair_style sph/soil (its list)");
}

/* ---------------------------------------------------------------------- */

double ComputeSPHSoilAtom::evaluate(Quantity q, int i) const
{
  auto avec = static_cast<AtomVecSPHSoil *>(atom->style_match("sph/soil"));
  const double *s = avec->stress[i];
  switch (q) {
    case SXX: case SYY: case SZZ: case SXY: case SXZ: case SYZ: return s[q - SXX];
    case PRESSURE: return SPHSoil::pressure(s);
    case SQRTJ2: return SPHSoil::sqrt_j2(s);
    case STRAIN: return SPHSoil::strain_measure(avec->total_strain[i]);
    case YIELDED: {
      const auto model = pair ? pair->model(atom->type[i]) : nullptr;
      return model && model->on_yield_surface(s) ? 1.0 : 0.0;
    }
    case DENSITY: return atom->rho[i];
    case H: return avec->smoothing_length[i];
    case LEVEL: return avec->level[i];
    case NEIGHBOURS: return pair->listed_partners(i);
    case SHEAR_STRAIN: return SPHSoil::shear_strain(avec->total_strain[i]);
    case SHEAR_STRAIN_RATE: return SPHSoil::shear_strain(avec->strain_rate[i]);
  }
  return 0.0;
}

/* ---------------------------------------------------------------------- */

void ComputeSPHSoilAtom::compute_peratom()
{
  invoked_peratom = update->ntimestep;
  if (atom->nmax > nmax) {
    nmax = atom->nmax;
    if (size_peratom_cols == 0) {
      memory->destroy(values);
      memory->create(values, nmax, "sph/soil/atom:values");
      vector_atom = values;
    } else {
      memory->destroy(table);
      memory->create(table, nmax, size_peratom_cols, "sph/soil/atom:table");
      array_atom = table;
    }
  }
  const int nlocal = atom->nlocal;
  const int *mask = atom->mask;
  const int n = quantities.size();
  for (int i = 0; i < nlocal; i++) {
    const bool in_group = mask[i] & groupbit;
    for (int k = 0; k < n; k++) {
      const double value = in_group ? evaluate(quantities[k], i) : 0.0;
      if (size_peratom_cols == 0) values[i] = value;
      else table[i][k] = value;
    }
  }
}

/* ---------------------------------------------------------------------- */

double ComputeSPHSoilAtom::memory_usage()
{
  return (double) nmax * quantities.size() * sizeof(double);
}
