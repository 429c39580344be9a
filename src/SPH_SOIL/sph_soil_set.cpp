/* ----------------------------------------------------------------------
   SPH_SOIL package for LAMMPS: command sph_soil/set
------------------------------------------------------------------------- */

#include "sph_soil_set.h"

#include "atom.h"
#include "atom_vec_sph_soil.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "group.h"
#include "input.h"
#include "soil_refine_split.h"
#include "sph_soil_input.h"
#include "sph_soil_offenders.h"
#include "utils.h"
#include "variable.h"

#include <cmath>
#include <cstring>

using namespace LAMMPS_NS;

/* ---------------------------------------------------------------------- */

void SPHSoilSet::command(int narg, char **arg)
{
  if (domain->box_exist == 0)
    error->all(FLERR, "sph_soil/set command before simulation box is defined");
  if (narg < 2) error->all(FLERR, "Illegal sph_soil/set command: expected 'sph_soil/set group-ID keyword value ...'");
  auto avec = dynamic_cast<AtomVecSPHSoil *>(atom->style_match("sph/soil"));
  if (!avec) error->all(FLERR, "sph_soil/set command requires atom_style sph/soil");

  const int igroup = group->find(arg[0]);
  if (igroup == -1) error->all(FLERR, "Could not find sph_soil/set group ID {}", arg[0]);
  const int groupbit = group->bitmask[igroup];

  if (comm->me == 0) utils::logmesg(lmp, "Setting sph/soil atom values ...\n");

  int iarg = 1;
  while (iarg < narg) {
    const std::string keyword = arg[iarg];
    auto need = [&](int n) {
      if (iarg + n >= narg)
        error->all(FLERR, "Illegal sph_soil/set command: keyword {} needs {} value(s)", keyword, n);
    };
    const int nlocal = atom->nlocal;
    const int *mask = atom->mask;
    bigint count = 0;
    for (int i = 0; i < nlocal; i++)
      if (mask[i] & groupbit) count++;

    if (keyword == "mass" || keyword == "h" || keyword == "density") {
      need(1);
      auto values = evaluate(parse_value(keyword, arg[iarg + 1]));
      check_range(keyword, values, 0.0, true, "> 0", groupbit);
      double *target = keyword == "mass" ? atom->rmass
          : keyword == "h"              ? avec->smoothing_length
                                        : atom->rho;
      for (int i = 0; i < nlocal; i++)
        if (mask[i] & groupbit) target[i] = values[i];
      iarg += 2;
    } else if (keyword == "level") {
      need(1);
      const int value = SPHSoilInput::integer(FLERR, lmp, "sph_soil/set level", arg[iarg + 1], 0,
                                              SPHSoil::MAX_LEVEL);
      for (int i = 0; i < nlocal; i++)
        if (mask[i] & groupbit) avec->level[i] = value;
      iarg += 2;
    } else if (keyword == "stress" || keyword == "strain") {
      need(AtomVecSPHSoil::NVOIGT);
      double **target = keyword == "stress" ? avec->stress : avec->total_strain;
      for (int k = 0; k < AtomVecSPHSoil::NVOIGT; k++) {
        auto values = evaluate(parse_value(keyword, arg[iarg + 1 + k]));
        check_range(keyword, values, -HUGE_VAL, true, "finite", groupbit);
        // plane strain: no xz, yz shear (the pair sums never produce the rates that would
        // change them, so a value set here would stay, unbalanced)
        if (domain->dimension == 2 && k >= 4) {
          const auto shear = SPHSoilOffenders::find_offenders(
              lmp, [&](int i) { return (mask[i] & groupbit) && values[i] != 0.0; },
              [&](int i, double *out) { out[0] = values[i]; });
          if (shear)
            error->all(FLERR, "Illegal sph_soil/set {}: the {} component must be 0 in 2D (plane "
                              "strain), got {} for atom {}", keyword, k == 4 ? "xz" : "yz",
                       shear.values[0], shear.first);
        }
        for (int i = 0; i < nlocal; i++)
          if (mask[i] & groupbit) target[i][k] = values[i];
      }
      iarg += 1 + AtomVecSPHSoil::NVOIGT;
    } else if (keyword == "geostatic") {
      // sigma_v = rho0 g (v - v_surface) below the surface (0 above), sigma_h = K0 sigma_v;
      // v is y in 2D and z in 3D
      need(4);
      using namespace SPHSoilInput;
      const double surface = number(FLERR, lmp, "sph_soil/set geostatic surface", arg[iarg + 1]);
      const double density = number(FLERR, lmp, "sph_soil/set geostatic density", arg[iarg + 2], above(0.0));
      const double gravity = number(FLERR, lmp, "sph_soil/set geostatic gravity", arg[iarg + 3], at_least(0.0));
      const double k0 = number(FLERR, lmp, "sph_soil/set geostatic K0", arg[iarg + 4],
                               between(0.0, 10.0, false, false));
      const int vertical = domain->dimension == 2 ? 1 : 2;
      double **x = atom->x;
      for (int i = 0; i < nlocal; i++) {
        if (!(mask[i] & groupbit)) continue;
        const double sv = density * gravity * MIN(x[i][vertical] - surface, 0.0);
        double *stress = avec->stress[i];
        for (int k = 0; k < 3; k++) stress[k] = k == vertical ? sv : k0 * sv;
        for (int k = 3; k < 6; k++) stress[k] = 0.0;
      }
      iarg += 5;
    } else if (keyword == "wall") {
      need(6);
      double point[3], normal[3];
      for (int k = 0; k < 3; k++) {
        point[k] = SPHSoilInput::number(FLERR, lmp, "sph_soil/set wall point", arg[iarg + 1 + k]);
        normal[k] = SPHSoilInput::number(FLERR, lmp, "sph_soil/set wall normal", arg[iarg + 4 + k]);
      }
      const double norm = sqrt(normal[0] * normal[0] + normal[1] * normal[1] + normal[2] * normal[2]);
      if (!(norm > 0.0))
        error->all(FLERR, "Illegal sph_soil/set wall: the normal ({} {} {}) must be non-zero",
                   normal[0], normal[1], normal[2]);
      if (domain->dimension == 2 && normal[2] != 0.0)
        error->all(FLERR, "Illegal sph_soil/set wall: the normal must lie in the xy plane in 2D");
      for (int k = 0; k < 3; k++) normal[k] /= norm;
      double **x = atom->x;
      for (int i = 0; i < nlocal; i++) {
        if (!(mask[i] & groupbit)) continue;
        double behind = 0.0;
        for (int k = 0; k < 3; k++) {
          avec->wall_normal[i][k] = normal[k];
          behind += (point[k] - x[i][k]) * normal[k];
        }
        avec->wall_normal[i][3] = 1.0;    // the length of mu: fixes turn mu only when > 0
        avec->wall_distance[i] = behind;
      }
      iarg += 7;
    } else if (keyword == "nowall") {
      for (int i = 0; i < nlocal; i++) {
        if (!(mask[i] & groupbit)) continue;
        for (int k = 0; k < 4; k++) avec->wall_normal[i][k] = 0.0;
        avec->wall_distance[i] = 0.0;
      }
      iarg += 1;
    } else {
      error->all(FLERR,
                 "Illegal sph_soil/set command: unknown keyword {} (allowed: mass, h, density, "
                 "level, stress, strain, geostatic, wall, nowall)",
                 keyword);
    }

    bigint total = 0;
    MPI_Allreduce(&count, &total, 1, MPI_LMP_BIGINT, MPI_SUM, world);
    if (comm->me == 0) utils::logmesg(lmp, "  {} settings made for {}\n", total, keyword);
  }
}

/* ---------------------------------------------------------------------- */

SPHSoilSet::Value SPHSoilSet::parse_value(const std::string &keyword, const char *arg)
{
  Value value;
  if (strncmp(arg, "v_", 2) == 0) {
    value.variable = arg + 2;
    const int ivar = input->variable->find(value.variable.c_str());
    if (ivar < 0)
      error->all(FLERR, "Variable name {} for sph_soil/set {} does not exist", value.variable, keyword);
    if (!input->variable->equalstyle(ivar) && !input->variable->atomstyle(ivar))
      error->all(FLERR, "Variable {} for sph_soil/set {} must be equal-style or atom-style",
                 value.variable, keyword);
  } else {
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
                             double lo, bool lo_open, const char *allowed, int groupbit)
{
  const int *mask = atom->mask;
  const auto bad = SPHSoilOffenders::find_offenders(
      lmp,
      [&](int i) {
        const double v = values[i];
        return (mask[i] & groupbit) && !(std::isfinite(v) && (lo_open ? v > lo : v >= lo));
      },
      [&](int i, double *out) { out[0] = values[i]; });
  if (bad)
    error->all(FLERR, "Illegal sph_soil/set {} value {} for atom {}: must be {}", keyword,
               bad.values[0], bad.first, allowed);
}
