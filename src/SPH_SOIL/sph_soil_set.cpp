/* ----------------------------------------------------------------------
   SPH_SOIL package for LAMMPS: command sph_soil/set
------------------------------------------------------------------------- */

#include "sph_soil_set.h"

#include "atom.h"
#include "atom_vec_sph_soil.h"
#include "comm.h"
#include "domain.h"
#include "force.h"
#include "pair_sph_soil.h"
#include "group.h"
#include "input.h"
#include "soil_refine_split.h"
#include "sph_soil_compat.h"
#include "sph_soil_input.h"
#include "sph_soil_offenders.h"
#include "utils.h"
#include "variable.h"

#include <cmath>
#include <cstring>

using namespace LAMMPS_NS;

/* ----------------------------------------------------------------------
   the keywords: one line each
------------------------------------------------------------------------- */

const std::vector<SPHSoilSet::Keyword> &SPHSoilSet::keywords()
{
  static const std::vector<Keyword> table = {
      {"mass", 1, &SPHSoilSet::set_positive},
      {"h", 1, &SPHSoilSet::set_positive},
      {"density", 1, &SPHSoilSet::set_positive},
      {"level", 1, &SPHSoilSet::set_level},
      {"stress", AtomVecSPHSoil::NVOIGT, &SPHSoilSet::set_tensor},
      {"strain", AtomVecSPHSoil::NVOIGT, &SPHSoilSet::set_tensor},
      {"geostatic", 4, &SPHSoilSet::set_geostatic},
      {"pore_pressure", 1, &SPHSoilSet::set_pore_pressure},
      {"wall", 6, &SPHSoilSet::set_wall},
      {"nowall", 0, &SPHSoilSet::set_nowall},
  };
  return table;
}

/* ---------------------------------------------------------------------- */

void SPHSoilSet::command(int narg, char **arg)
{
  if (domain->box_exist == 0)
    SPHSoilCompat::error_all(lmp, FLERR, "sph_soil/set command before simulation box is defined");
  if (narg < 2)
    SPHSoilCompat::error_all(
        lmp, FLERR,
        "Illegal sph_soil/set command: expected 'sph_soil/set group-ID keyword value ...'");
  avec = dynamic_cast<AtomVecSPHSoil *>(atom->style_match("sph/soil"));
  if (!avec)
    SPHSoilCompat::error_all(lmp, FLERR, "sph_soil/set command requires atom_style sph/soil");

  const int igroup = group->find(arg[0]);
  if (igroup == -1)
    SPHSoilCompat::error_all(lmp, FLERR, "Could not find sph_soil/set group ID {}", arg[0]);
  groupbit = group->bitmask[igroup];

  if (comm->me == 0) utils::logmesg(lmp, "Setting sph/soil atom values ...\n");

  bigint count = 0;
  for (int i = 0; i < atom->nlocal; i++)
    if (in_group(i)) count++;
  bigint total = 0;
  MPI_Allreduce(&count, &total, 1, MPI_LMP_BIGINT, MPI_SUM, world);

  int iarg = 1;
  while (iarg < narg) {
    const std::string keyword = arg[iarg];
    const Keyword *found = nullptr;
    for (const auto &k : keywords())
      if (keyword == k.name) found = &k;
    if (!found) {
      std::string allowed;
      for (const auto &k : keywords()) allowed += (allowed.empty() ? "" : ", ") + std::string(k.name);
      SPHSoilCompat::error_all(lmp, FLERR,
                               "Illegal sph_soil/set command: unknown keyword {} (allowed: {})",
                               keyword, allowed);
    }
    if (iarg + found->count >= narg)
      SPHSoilCompat::error_all(lmp, FLERR,
                               "Illegal sph_soil/set command: keyword {} needs {} value(s)",
                               keyword, found->count);
    const int extra = (this->*(found->apply))(keyword, arg + iarg + 1, narg - iarg - 1);
    iarg += 1 + found->count + extra;
    if (comm->me == 0) utils::logmesg(lmp, "  {} settings made for {}\n", total, keyword);
  }

  // the state changed: the rates saved at the end of the last run no longer belong to it
  for (int i = 0; i < atom->nlocal; i++)
    if (in_group(i)) avec->saved_rates[i][AtomVecSPHSoil::SAVED_FLAG] = 0.0;
}

bool SPHSoilSet::in_group(int i) const
{
  return atom->mask[i] & groupbit;
}

/* ----------------------------------------------------------------------
   mass, h, density: > 0
------------------------------------------------------------------------- */

int SPHSoilSet::set_positive(const std::string &keyword, char **args, int)
{
  const auto values = per_atom(keyword, args[0], SPHSoilInput::above(0.0));
  double *target = keyword == "mass" ? atom->rmass
      : keyword == "h"              ? avec->smoothing_length
                                    : atom->rho;
  for (int i = 0; i < atom->nlocal; i++)
    if (in_group(i)) target[i] = values[i];
  return 0;
}

int SPHSoilSet::set_level(const std::string &, char **args, int)
{
  const int value =
      SPHSoilInput::integer(FLERR, lmp, "sph_soil/set level", args[0], 0, SPHSoil::MAX_LEVEL);
  for (int i = 0; i < atom->nlocal; i++)
    if (in_group(i)) avec->level[i] = value;
  return 0;
}

/* ----------------------------------------------------------------------
   stress, strain: six Voigt components
------------------------------------------------------------------------- */

int SPHSoilSet::set_tensor(const std::string &keyword, char **args, int)
{
  double **target = keyword == "stress" ? avec->stress : avec->total_strain;
  for (int k = 0; k < AtomVecSPHSoil::NVOIGT; k++) {
    const auto values = per_atom(keyword, args[k], SPHSoilInput::any());
    // plane strain: no xz, yz shear (the pair sums never produce the rates that would
    // change them, so a value set here would stay, unbalanced)
    if (domain->dimension == 2 && k >= 4) {
      const auto shear = SPHSoilOffenders::find_offenders(
          lmp, [&](int i) { return in_group(i) && values[i] != 0.0; },
          [&](int i, double *out) { out[0] = values[i]; });
      if (shear)
        SPHSoilCompat::error_all(lmp, FLERR,
                                 "Illegal sph_soil/set {}: the {} component must be 0 in 2D (plane "
                                 "strain), got {} for atom {}",
                                 keyword, k == 4 ? "xz" : "yz", shear.values[0], shear.first);
    }
    for (int i = 0; i < atom->nlocal; i++)
      if (in_group(i)) target[i][k] = values[i];
  }
  return 0;
}

/* ----------------------------------------------------------------------
   pore_pressure p: a saturated soil's pore pressure, or a drained wall's (any finite value:
   suction is negative)
------------------------------------------------------------------------- */

int SPHSoilSet::set_pore_pressure(const std::string &keyword, char **args, int)
{
  const auto values = per_atom(keyword, args[0], SPHSoilInput::any());
  for (int i = 0; i < atom->nlocal; i++)
    if (in_group(i)) avec->pore_pressure[i] = values[i];
  return 0;
}

/* ----------------------------------------------------------------------
   geostatic surface rho0 g K0 [vertical x|y|z] [water level rho_w]: sigma_v = rho0 g (v -
   v_surface) below the surface (0 above), sigma_h = K0 sigma_v; v is y in 2D and z in 3D unless
   'vertical' says otherwise. With 'water', a water table at `level`: the pore pressure
   p = rho_w g (level - v) below it (0 above), the weight of free water above the surface added
   to the total stress, and the stress set is the effective stress, sigma'_v = sigma_v + p,
   sigma'_h = K0 sigma'_v (doc/theory.rst 7). The axis is kept
   (AtomVecSPHSoil::geostatic_vertical), so that pair_style sph/soil can tell when gravity
   points along another
------------------------------------------------------------------------- */

int SPHSoilSet::set_geostatic(const std::string &, char **args, int available)
{
  using namespace SPHSoilInput;
  const double surface = number(FLERR, lmp, "sph_soil/set geostatic surface", args[0]);
  const double density = number(FLERR, lmp, "sph_soil/set geostatic density", args[1], above(0.0));
  const double gravity = number(FLERR, lmp, "sph_soil/set geostatic gravity", args[2], at_least(0.0));
  const double k0 = number(FLERR, lmp, "sph_soil/set geostatic K0", args[3],
                           between(0.0, 10.0, false, false));
  int vertical = domain->dimension == 2 ? 1 : 2;
  bool water = false;
  double water_level = 0.0, water_density = 0.0;
  int extra = 0;
  // the options, each once, in any order
  while (available > 4 + extra) {
    const char *option = args[4 + extra];
    if (strcmp(option, "vertical") == 0) {
      if (available < 6 + extra)
        SPHSoilCompat::error_all(
            lmp, FLERR, "Illegal sph_soil/set geostatic vertical: needs an axis (x, y or z)");
      const std::string axis = args[5 + extra];
      vertical = axis == "x" ? 0 : axis == "y" ? 1 : axis == "z" ? 2 : -1;
      if (vertical < 0 || (domain->dimension == 2 && vertical == 2))
        SPHSoilCompat::error_all(
            lmp, FLERR,
            "Illegal sph_soil/set geostatic vertical {}: must be x or y in 2D, x, y "
            "or z in 3D",
            axis);
      extra += 2;
    } else if (strcmp(option, "water") == 0 && !water) {
      if (available < 7 + extra)
        SPHSoilCompat::error_all(lmp, FLERR,
                                 "Illegal sph_soil/set geostatic water: needs the water table's "
                                 "level and the water's density ('water level rho_w')");
      water = true;
      water_level = number(FLERR, lmp, "sph_soil/set geostatic water level", args[5 + extra]);
      water_density = number(FLERR, lmp, "sph_soil/set geostatic water density", args[6 + extra],
                             above(0.0));
      extra += 3;
    } else {
      break;
    }
  }
  avec->geostatic_vertical = vertical;
  // the state against the materials' yield surfaces: now if pair_style sph/soil knows them,
  // else at its init
  double **x = atom->x;
  // free water above the surface weighs on the soil
  const double water_above = water ? water_density * gravity * MAX(water_level - surface, 0.0) : 0.0;
  for (int i = 0; i < atom->nlocal; i++) {
    if (!in_group(i)) continue;
    const double v = x[i][vertical];
    const double below = MAX(surface - v, 0.0);
    const double pore = water ? water_density * gravity * MAX(water_level - v, 0.0) : 0.0;
    // the effective vertical stress (tension positive): the total stress plus the pore pressure
    // (0 above the surface, where only water, if any, bears on a particle)
    const double sv = below > 0.0 ? pore - (density * gravity * below + water_above) : 0.0;
    double *stress = avec->stress[i];
    for (int k = 0; k < 3; k++) stress[k] = k == vertical ? sv : k0 * sv;
    for (int k = 3; k < 6; k++) stress[k] = 0.0;
    if (water) avec->pore_pressure[i] = pore;
  }
  auto *pair = dynamic_cast<PairSPHSoil *>(force->pair_match("sph/soil", 1));
  const bool checked = pair && pair->allocated && pair->warn_geostatic_yield(groupbit, k0);
  avec->geostatic_unchecked_group = checked ? 0 : groupbit;
  avec->geostatic_k0 = k0;
  return extra;
}

/* ----------------------------------------------------------------------
   wall px py pz nx ny nz: the plane of mirror wall particles; nowall: none
------------------------------------------------------------------------- */

int SPHSoilSet::set_wall(const std::string &, char **args, int)
{
  double point[3], normal[3];
  for (int k = 0; k < 3; k++) {
    point[k] = SPHSoilInput::number(FLERR, lmp, "sph_soil/set wall point", args[k]);
    normal[k] = SPHSoilInput::number(FLERR, lmp, "sph_soil/set wall normal", args[3 + k]);
  }
  const double norm = sqrt(normal[0] * normal[0] + normal[1] * normal[1] + normal[2] * normal[2]);
  if (!(norm > 0.0))
    SPHSoilCompat::error_all(lmp, FLERR,
                             "Illegal sph_soil/set wall: the normal ({} {} {}) must be non-zero",
                             normal[0], normal[1], normal[2]);
  if (domain->dimension == 2 && normal[2] != 0.0)
    SPHSoilCompat::error_all(
        lmp, FLERR, "Illegal sph_soil/set wall: the normal must lie in the xy plane in 2D");
  for (int k = 0; k < 3; k++) normal[k] /= norm;
  double **x = atom->x;
  for (int i = 0; i < atom->nlocal; i++) {
    if (!in_group(i)) continue;
    double behind = 0.0;
    for (int k = 0; k < 3; k++) {
      avec->wall_normal[i][k] = normal[k];
      behind += (point[k] - x[i][k]) * normal[k];
    }
    avec->wall_normal[i][3] = 1.0;    // the length of mu: fixes turn mu only when > 0
    avec->wall_distance[i] = behind;
  }
  return 0;
}

int SPHSoilSet::set_nowall(const std::string &, char **, int)
{
  for (int i = 0; i < atom->nlocal; i++) {
    if (!in_group(i)) continue;
    for (int k = 0; k < 4; k++) avec->wall_normal[i][k] = 0.0;
    avec->wall_distance[i] = 0.0;
  }
  return 0;
}

/* ---------------------------------------------------------------------- */

std::vector<double> SPHSoilSet::per_atom(const std::string &keyword, const char *arg,
                                         const SPHSoilInput::Range &range)
{
  const auto values = evaluate(parse_value(keyword, arg, range));
  check_range(keyword, values, range);
  return values;
}

/* ----------------------------------------------------------------------
   a word that is neither v_name nor a number names both forms and the range; a number's range
   is checked per atom (check_range), with the variables' values
------------------------------------------------------------------------- */

SPHSoilSet::Value SPHSoilSet::parse_value(const std::string &keyword, const char *arg,
                                          const SPHSoilInput::Range &range)
{
  Value value;
  if (strncmp(arg, "v_", 2) == 0) {
    value.variable = arg + 2;
    const int ivar = input->variable->find(value.variable.c_str());
    if (ivar < 0)
      SPHSoilCompat::error_all(lmp, FLERR, "Variable name {} for sph_soil/set {} does not exist",
                               value.variable, keyword);
    if (!input->variable->equalstyle(ivar) && !input->variable->atomstyle(ivar))
      SPHSoilCompat::error_all(lmp, FLERR,
                               "Variable {} for sph_soil/set {} must be equal-style or atom-style",
                               value.variable, keyword);
  } else {
    if (SPHSoilInput::ascii(arg) && !utils::is_double(arg))
      SPHSoilCompat::error_all(lmp, FLERR,
                               "Illegal sph_soil/set {} {}: {} or v_name (an equal- or atom-style "
                               "variable)",
                               keyword, arg, SPHSoilInput::finite_number_in(range));
    value.constant = SPHSoilInput::number(FLERR, lmp, "sph_soil/set " + keyword, arg);
  }
  return value;
}

/* ---------------------------------------------------------------------- */

std::vector<double> SPHSoilSet::evaluate(const Value &value)
{
  const int nlocal = atom->nlocal;
  std::vector<double> values(nlocal > 0 ? nlocal : 1, value.constant);
  if (value.variable.empty()) return values;

  const int ivar = input->variable->find(value.variable.c_str());
  if (input->variable->atomstyle(ivar)) {
    input->variable->compute_atom(ivar, 0, values.data(), 1, 0);
  } else {
    const double v = input->variable->compute_equal(ivar);
    std::fill(values.begin(), values.end(), v);
  }
  return values;
}

/* ---------------------------------------------------------------------- */

void SPHSoilSet::check_range(const std::string &keyword, const std::vector<double> &values,
                             const SPHSoilInput::Range &range)
{
  const auto bad = SPHSoilOffenders::find_offenders(
      lmp, [&](int i) { return in_group(i) && !range.contains(values[i]); },
      [&](int i, double *out) { out[0] = values[i]; });
  const std::string allowed = range.describe();
  if (bad)
    SPHSoilCompat::error_all(lmp, FLERR, "Illegal sph_soil/set {} value {} for atom {}: must be {}",
                             keyword, bad.values[0], bad.first, allowed.empty() ? "finite" : allowed);
}
