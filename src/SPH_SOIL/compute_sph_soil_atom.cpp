/* ----------------------------------------------------------------------
   SPH_SOIL package for LAMMPS: compute sph/soil/atom
------------------------------------------------------------------------- */

#include "compute_sph_soil_atom.h"

#include "atom.h"
#include "atom_vec_sph_soil.h"
#include "force.h"
#include "memory.h"
#include "pair_sph_soil.h"
#include "soil_constitutive.h"
#include "sph_soil_compat.h"
#include "sph_soil_fixes.h"
#include "update.h"

using namespace LAMMPS_NS;

namespace {
using Source = ComputeSPHSoilAtom::Source;
const char *const MATERIALS = "its materials", *const LIST = "its list";

double stress_component(const Source &s, int i, int k)
{
  return s.avec->stress[i][k];
}
double total_normal_stress(const Source &s, int i, int k)
{
  return s.avec->stress[i][k] - s.avec->pore_pressure[i];
}
}    // namespace

/* ----------------------------------------------------------------------
   the values: one line each
------------------------------------------------------------------------- */

const std::vector<ComputeSPHSoilAtom::Value> &ComputeSPHSoilAtom::values()
{
  static const std::vector<Value> table = {
      {{"sxx"}, nullptr, [](const Source &s, int i) { return stress_component(s, i, 0); }},
      {{"syy"}, nullptr, [](const Source &s, int i) { return stress_component(s, i, 1); }},
      {{"szz"}, nullptr, [](const Source &s, int i) { return stress_component(s, i, 2); }},
      {{"sxy"}, nullptr, [](const Source &s, int i) { return stress_component(s, i, 3); }},
      {{"sxz"}, nullptr, [](const Source &s, int i) { return stress_component(s, i, 4); }},
      {{"syz"}, nullptr, [](const Source &s, int i) { return stress_component(s, i, 5); }},
      {{"pressure"}, nullptr, [](const Source &s, int i) { return SPHSoil::pressure(s.avec->stress[i]); }},
      // a saturated soil's pore pressure (0 for dry soil), and the total stress: the stress above
      // is the effective stress (the soil skeleton's), the total stress that less the pore pressure
      {{"pore_pressure"}, nullptr, [](const Source &s, int i) { return s.avec->pore_pressure[i]; }},
      {{"total_sxx"}, nullptr, [](const Source &s, int i) { return total_normal_stress(s, i, 0); }},
      {{"total_syy"}, nullptr, [](const Source &s, int i) { return total_normal_stress(s, i, 1); }},
      {{"total_szz"}, nullptr, [](const Source &s, int i) { return total_normal_stress(s, i, 2); }},
      // the pore water it took in from drained walls and free water at the last step (m^3/s; m^2/s
      // per unit depth in 2D): compute reduce sum over a boundary's soil gives the flux through it
      {{"drained_inflow"}, LIST, [](const Source &s, int i) { return s.pair->drained_inflow(i); }},
      {{"sqrtJ2"}, nullptr, [](const Source &s, int i) { return SPHSoil::sqrt_j2(s.avec->stress[i]); }},
      {{"strain"}, nullptr,
       [](const Source &s, int i) { return SPHSoil::strain_measure(s.avec->total_strain[i]); }},
      {{"yielded"}, MATERIALS,
       [](const Source &s, int i) {
         const auto model = s.pair->model(s.atom->type[i]);
         return model && model->on_yield_surface(s.avec->stress[i]) ? 1.0 : 0.0;
       }},
      {{"density", "rho"}, nullptr, [](const Source &s, int i) { return s.atom->rho[i]; }},
      {{"h"}, nullptr, [](const Source &s, int i) { return s.avec->smoothing_length[i]; }},
      {{"level"}, nullptr, [](const Source &s, int i) { return (double) s.avec->level[i]; }},
      {{"neighbours", "neighbors"}, LIST,
       [](const Source &s, int i) { return (double) s.pair->listed_partners(i); }},
      {{"shear_strain"}, nullptr,
       [](const Source &s, int i) { return SPHSoil::shear_strain(s.avec->total_strain[i]); }},
      {{"shear_strain_rate"}, nullptr,
       [](const Source &s, int i) { return SPHSoil::shear_strain(s.avec->strain_rate[i]); }},
      // the particle's own time step in LAMMPS steps (fix sph/soil stepping level; 1 with one
      // global step); 0 for wall particles, which have none
      {{"step_period"}, MATERIALS,
       [](const Source &s, int i) {
         if (s.pair->is_wall_type(s.atom->type[i])) return 0.0;
         if (!s.schedule || !s.schedule->per_level) return 1.0;
         return (double) SPHSoil::step_period(s.avec->smoothing_length[i], s.schedule->finest_h);
       }},
  };
  return table;
}

std::string ComputeSPHSoilAtom::value_names()
{
  std::string list;
  for (const auto &v : values()) list += (list.empty() ? "" : " ") + v.names[0];
  return list;
}

/* ---------------------------------------------------------------------- */

ComputeSPHSoilAtom::ComputeSPHSoilAtom(LAMMPS *lmp, int narg, char **arg) :
    Compute(lmp, narg, arg), nmax(0), vector(nullptr), array(nullptr), pair(nullptr),
    schedule(nullptr)
{
  if (!atom->style_match("sph/soil"))
    SPHSoilCompat::error_all(lmp, FLERR, "Compute sph/soil/atom requires atom_style sph/soil");
  auto find = [&](const std::string &name) -> const Value * {
    for (const auto &v : values())
      for (const auto &n : v.names)
        if (n == name) return &v;
    return nullptr;
  };
  for (int iarg = 3; iarg < narg; iarg++) {
    const Value *value = find(arg[iarg]);
    if (!value)
      SPHSoilCompat::error_all(lmp, FLERR, "Illegal compute sph/soil/atom value {} (allowed: {})",
                               arg[iarg], value_names());
    chosen.push_back(value);
  }
  if (chosen.empty())
    for (const char *name : {"strain", "pressure", "sqrtJ2", "yielded", "density", "h", "level"})
      chosen.push_back(find(name));

  peratom_flag = 1;
  size_peratom_cols = chosen.size() == 1 ? 0 : chosen.size();
}

ComputeSPHSoilAtom::~ComputeSPHSoilAtom()
{
  memory->destroy(vector);
  memory->destroy(array);
}

/* ---------------------------------------------------------------------- */

void ComputeSPHSoilAtom::init()
{
  pair = dynamic_cast<PairSPHSoil *>(force->pair_match("sph/soil", 1));
  schedule = SPHSoilFixes::step_schedule(lmp);
  for (const Value *v : chosen)
    if (v->needs_pair && !pair)
      SPHSoilCompat::error_all(lmp, FLERR,
                               "Compute sph/soil/atom {} needs pair_style sph/soil ({})",
                               v->names[0], v->needs_pair);
}

/* ---------------------------------------------------------------------- */

void ComputeSPHSoilAtom::compute_peratom()
{
  invoked_peratom = update->ntimestep;
  if (atom->nmax > nmax) {
    nmax = atom->nmax;
    if (size_peratom_cols == 0) {
      memory->destroy(vector);
      memory->create(vector, nmax, "sph/soil/atom:vector");
      vector_atom = vector;
    } else {
      memory->destroy(array);
      memory->create(array, nmax, size_peratom_cols, "sph/soil/atom:array");
      array_atom = array;
    }
  }
  const Source source{dynamic_cast<AtomVecSPHSoil *>(atom->style_match("sph/soil")), atom, pair,
                      schedule};
  const int nlocal = atom->nlocal;
  const int *mask = atom->mask;
  const int n = chosen.size();
  for (int i = 0; i < nlocal; i++) {
    const bool in_group = mask[i] & groupbit;
    for (int k = 0; k < n; k++) {
      const double value = in_group ? chosen[k]->of(source, i) : 0.0;
      if (size_peratom_cols == 0) vector[i] = value;
      else array[i][k] = value;
    }
  }
}

double ComputeSPHSoilAtom::memory_usage()
{
  return (double) nmax * chosen.size() * sizeof(double);
}
