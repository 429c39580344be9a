/* ----------------------------------------------------------------------
   SPH_SOIL package for LAMMPS: the pore water of pair_style sph/soil (see the header)
------------------------------------------------------------------------- */

#include "sph_soil_pore_water.h"

#include "atom.h"
#include "atom_vec_sph_soil.h"
#include "comm.h"
#include "force.h"
#include "pair.h"
#include "soil_packed_rows.h"
#include "soil_pore_water.h"
#include "sph_soil_gradient_correction.h"
#include "sph_soil_compat.h"
#include "sph_soil_fixes.h"
#include "sph_soil_offenders.h"
#include "update.h"

#include <algorithm>
#include <cmath>
#include <cstring>

using namespace LAMMPS_NS;
using namespace SPHSoil;

constexpr double SPHSoilPoreWater::DRAINED;

SPHSoilPoreWater::SPHSoilPoreWater(LAMMPS *lmp, Pair *owner) :
    Pointers(lmp), owner(owner), avec(nullptr), saturated(false), water(false), variable(false), exchange(NONE)
{
}

/* ---------------------------------------------------------------------- */

void SPHSoilPoreWater::init(const std::vector<SoilMaterial> &materials,
                            const std::vector<int> &has_material, double density_diffusion)
{
  avec = dynamic_cast<AtomVecSPHSoil *>(atom->style_match("sph/soil"));
  const int ntypes = (int) materials.size() - 1;
  mobility_of_type.assign(ntypes + 1, 0.0);
  water_of_type.assign(ntypes + 1, PoreWater());
  density_of_type.assign(ntypes + 1, 0.0);
  free_water_of_type.assign(ntypes + 1, FreeWaterType());
  saturated = water = variable = false;
  diffuses_water = false;
  int first_saturated = 0;
  for (int t = 1; t <= ntypes; t++) {
    if (!has_material[t]) continue;
    const SoilMaterial &m = materials[t];
    // a drained wall and free water: the pressure of the water the soil drains into
    if (m.is_wall() || m.water) {
      if (m.drained || m.water) mobility_of_type[t] = DRAINED;
      if (m.water) {
        // (its P-wave modulus is K_w, soil_water.h)
        const double modulus = m.model->p_wave_modulus();
        FreeWaterType &w = free_water_of_type[t];
        w.density = m.density;
        w.compliance = m.density / modulus;
        w.diffusion_speed = density_diffusion * std::sqrt(modulus / m.density);
        water = true;
        diffuses_water = diffuses_water || w.diffusion_speed > 0.0;
      }
      continue;
    }
    if (!m.saturated) continue;
    mobility_of_type[t] = m.pore_water.mobility();
    water_of_type[t] = m.pore_water;
    density_of_type[t] = m.density;
    variable = variable || m.pore_water.variable_conductivity();
    if (!saturated) first_saturated = t;
    saturated = true;
    // two saturated soils hold two waters: legal (layers of other fluids), most likely a typo
    if (m.pore_water.water_density != water_of_type[first_saturated].water_density && comm->me == 0)
      error->warning(FLERR,
                     "Pair sph/soil: the saturated soils of types {} and {} have pore water of "
                     "densities {} and {}; the flow between them takes their mean",
                     first_saturated, t, water_of_type[first_saturated].water_density,
                     m.pore_water.water_density);
  }
  // a hydraulic conductivity is measured under the standard gravity g_n = 9.80665 m/s^2
  if (saturated && strcmp(update->unit_style, "si") != 0)
    SPHSoilCompat::error_all(lmp, FLERR,
                             "Pair sph/soil: the saturated soil of type {} needs 'units si' (its "
                             "permeability is a hydraulic conductivity in m/s, measured under the "
                             "standard gravity 9.80665 m/s^2), got units {}",
                             first_saturated, update->unit_style);
  gravity_fixes = SPHSoilFixes::gravity_fixes(lmp);

  // a pore pressure on dry soil would enter its total stress and never change
  const int *type = atom->type;
  const double *pressure = avec->pore_pressure;
  const auto dry = SPHSoilOffenders::find_offenders(
      lmp,
      [&](int i) {
        const int t = type[i];
        return has_material[t] && !materials[t].is_wall() && !materials[t].saturated &&
            !materials[t].water && pressure[i] != 0.0;
      },
      [&](int i, double *values) {
        values[0] = pressure[i];
        values[1] = type[i];
      });
  if (dry)
    SPHSoilCompat::error_all(lmp, FLERR,
                             "Pair sph/soil: {} particle(s) of dry soil carry a pore pressure (atom "
                             "{} of type {}: {}); only a saturated soil (a material with porosity "
                             "and permeability) or a drained wall has one: set it to 0 with "
                             "'sph_soil/set <group> pore_pressure 0'",
                             dry.count, dry.first, (int) dry.values[1], dry.values[0]);
}

/* ---------------------------------------------------------------------- */

void SPHSoilPoreWater::share_pressures()
{
  exchange = PRESSURE;
  SPHSoilCompat::forward_comm_pair(comm, owner);
  exchange = NONE;
}

/* ---------------------------------------------------------------------- */

namespace {
struct Flow {
  SPHSoilPoreWater *water;
  const double *packed;
  const NeighbourList &list;
  int dimension;
  const SPHSoilGradientCorrection *correction;
  template <class Kernel> void operator()() const
  {
    const bool per_atom = water->variable_conductivity();
    if (dimension == 2) {
      if (per_atom) water->flow_sums<2, Kernel, true>(packed, list, correction);
      else water->flow_sums<2, Kernel, false>(packed, list, correction);
    } else {
      if (per_atom) water->flow_sums<3, Kernel, true>(packed, list, correction);
      else water->flow_sums<3, Kernel, false>(packed, list, correction);
    }
  }
};
}    // namespace

void SPHSoilPoreWater::flow(const double *packed, const NeighbourList &list, KernelKind kernel,
                            int dimension, const SPHSoilGradientCorrection *correction)
{
  with_kernel(kernel, Flow{this, packed, list, dimension, correction});
  if (force->newton_pair) {
    exchange = FLOW;
    SPHSoilCompat::reverse_comm_pair(comm, owner);
    exchange = NONE;
  }
}

/* ----------------------------------------------------------------------
   every pair of a saturated soil particle and a saturated soil or drained partner (a drained
   wall, free water: the soil's conductance alone, soil_pore_water.h), with
   the partners' volumes (soil_pore_water.h): each pair once, its shares to both (the water
   volume leaving one enters the other). Mirror and extrapolated walls alike: a drained wall
   particle holds the pressure of the water behind it, the others no water.
------------------------------------------------------------------------- */

template <int DIMENSION, class Kernel, bool PER_ATOM>
void SPHSoilPoreWater::flow_sums(const double *packed, const NeighbourList &list,
                                 const SPHSoilGradientCorrection *correction)
{
  const int nlocal = atom->nlocal, nall = nlocal + atom->nghost;
  const int newton_pair = force->newton_pair;
  const int *type = atom->type;
  const double *pressure = avec->pore_pressure;
  double *flow = avec->pore_flow;
  double *drho = atom->drho;
  // (flow, zeroed by the pair style before its loop, holds the soil-water pairs' divergence:
  // this sum adds to it, PairSPHSoil::eval())
  inflow.assign(nlocal, 0.0);
  moved.assign((size_t) (newton_pair ? nall : nlocal) * MOVED, 0.0);
  // each atom's mobility: its type's, or (PER_ATOM) at its density where k follows the porosity
  if (PER_ATOM) {
    atom_mobility.resize(nall);
    for (int i = 0; i < nall; i++)
      atom_mobility[i] = mobility_at(type[i], packed[(size_t) i * PACKED + P_RHO]);
  }
  const double *mobility = PER_ATOM ? atom_mobility.data() : mobility_of_type.data();
  const PoreWater *pore = water_of_type.data();
  const FreeWaterType *free_water = free_water_of_type.data();
  double gravity[3];
  SPHSoilFixes::gravity_sum(gravity_fixes, gravity);
  const int *partners = list.partner_data();

  for (int i = 0; i < nlocal; i++) {
    const double lambda_i = mobility[PER_ATOM ? i : type[i]];
    if (lambda_i == 0.0) continue;
    const double *pi = packed + (size_t) i * PACKED;
    const FreeWaterType &water_i = free_water[type[i]];
    for (int jj = list.first(i); jj < list.end(i); jj++) {
      const int j = partners[jj];
      const double lambda_j = mobility[PER_ATOM ? j : type[j]];
      if (lambda_j == 0.0 || (lambda_i == DRAINED && lambda_j == DRAINED && !diffuses_water)) continue;
      const double *pj = packed + (size_t) j * PACKED;
      const FreeWaterType &water_j = free_water[type[j]];
      const bool update_j = newton_pair || j < nlocal;
      PairGeometry g;
      if (!pair_geometry<DIMENSION, Kernel>(pi + P_X, pi[P_H], pj, g)) continue;

      if (lambda_i == DRAINED && lambda_j == DRAINED) {
        // two free water particles (drained walls hold no free water): delta-SPH's density
        // diffusion, in the head's form (soil_water.h)
        if (!water_i.is_water() || !water_j.is_water()) continue;
        const double speed = 0.5 * (water_i.diffusion_speed + water_j.diffusion_speed);
        const double rho_w = 0.5 * (water_i.density + water_j.density);
        const double term = pore_flow<DIMENSION>(pressure[i], pressure[j], rho_w, gravity, g.dx,
                                                 g.r2, g.hij, g.factor, speed * g.hij);
        drho[i] += water_i.compliance * pj[P_VOLUME] * term;
        if (update_j) drho[j] -= water_j.compliance * pi[P_VOLUME] * term;
        continue;
      }

      // the pore water's flow: between two saturated soil particles the harmonic mean of their
      // mobilities, to a drained partner (a drained wall, free water) the soil's conductance alone
      double lambda_ij, rho_w;
      if (lambda_i > 0.0 && lambda_j > 0.0) {
        lambda_ij = harmonic_mobility(lambda_i, lambda_j);
        rho_w = 0.5 * (pore[type[i]].water_density + pore[type[j]].water_density);
      } else if (lambda_i > 0.0) {
        lambda_ij = 2.0 * lambda_i;
        rho_w = pore[type[i]].water_density;
      } else {
        lambda_ij = 2.0 * lambda_j;
        rho_w = pore[type[j]].water_density;
      }
      // (the Laplacian of a quadratic head is the kernel's moment C times its own: the
      // correction's 1 / C, the pair's mean, keeps the flow conserved pair by pair)
      if (correction) lambda_ij *= 0.5 * (correction->factor(i) + correction->factor(j));
      const double term = pore_flow<DIMENSION>(pressure[i], pressure[j], rho_w, gravity, g.dx, g.r2,
                                               g.hij, g.factor, lambda_ij);
      if (lambda_i > 0.0) flow[i] += pj[P_VOLUME] * term;
      if (lambda_j > 0.0 && update_j) flow[j] -= pi[P_VOLUME] * term;
      // the water taken from a drained partner: each side's owner counts its own
      const double volume = pi[P_VOLUME] * pj[P_VOLUME] * term;    // into i, per unit time
      if (lambda_j == DRAINED) inflow[i] += volume;
      else if (lambda_i == DRAINED && j < nlocal) inflow[j] -= volume;
      // the water brings its mass and the momentum it has with the particle that gives it
      // (a soil particle or free water; a drained wall is a reservoir, whose own are not
      // counted): fix sph/soil moves them (doc/theory.rst 7.4)
      const double mass = rho_w * volume;
      const double *giver = (volume > 0.0 ? pj : pi) + P_V;
      const bool exchanges_i = lambda_i > 0.0 || water_i.is_water();
      const bool exchanges_j = (lambda_j > 0.0 || water_j.is_water()) && update_j;
      if (exchanges_i) {
        double *to = &moved[(size_t) i * MOVED];
        to[0] += mass;
        for (int a = 0; a < DIMENSION; a++) to[1 + a] += mass * giver[a];
      }
      if (exchanges_j) {
        double *to = &moved[(size_t) j * MOVED];
        to[0] -= mass;
        for (int a = 0; a < DIMENSION; a++) to[1 + a] -= mass * giver[a];
      }
    }
  }
}

/* ---------------------------------------------------------------------- */

double SPHSoilPoreWater::largest_diffusivity(int groupbit) const
{
  const int *type = atom->type, *mask = atom->mask;
  const double *rho = atom->rho;
  double largest = 0.0;
  for (int i = 0; i < atom->nlocal; i++) {
    const int t = type[i];
    if (!(mask[i] & groupbit) || mobility_of_type[t] <= 0.0) continue;
    largest = std::max(largest, mobility_at(t, rho[i]) * water_of_type[t].storage_modulus());
  }
  return largest;
}

/* ---------------------------------------------------------------------- */

// the pore pressure, and the mass, which the exchange of water changes at every step (the atom
// style sends it at reneighbouring only, so that dry runs do not carry it)
int SPHSoilPoreWater::pack_forward_comm(int n, int *list, double *buf)
{
  int m = 0;
  for (int k = 0; k < n; k++) {
    buf[m++] = avec->pore_pressure[list[k]];
    buf[m++] = atom->rmass[list[k]];
  }
  return m;
}

void SPHSoilPoreWater::unpack_forward_comm(int n, int first, double *buf)
{
  int m = 0;
  for (int k = first; k < first + n; k++) {
    avec->pore_pressure[k] = buf[m++];
    atom->rmass[k] = buf[m++];
  }
}

int SPHSoilPoreWater::pack_reverse_comm(int n, int first, double *buf)
{
  int m = 0;
  for (int k = first; k < first + n; k++) {
    buf[m++] = avec->pore_flow[k];
    for (int c = 0; c < MOVED; c++) buf[m++] = moved[(size_t) k * MOVED + c];
  }
  return m;
}

void SPHSoilPoreWater::unpack_reverse_comm(int n, int *list, double *buf)
{
  int m = 0;
  for (int k = 0; k < n; k++) {
    avec->pore_flow[list[k]] += buf[m++];
    for (int c = 0; c < MOVED; c++) moved[(size_t) list[k] * MOVED + c] += buf[m++];
  }
}
