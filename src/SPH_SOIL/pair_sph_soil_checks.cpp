/* ----------------------------------------------------------------------
   SPH_SOIL package for LAMMPS: pair_style sph/soil: the set-up checks of the particles
------------------------------------------------------------------------- */

#include "pair_sph_soil.h"

#include "atom.h"
#include "atom_vec_sph_soil.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "math_const.h"
#include "modify.h"
#include "neighbor.h"
#include "soil_kernels.h"
#include "sph_soil_compat.h"
#include "sph_soil_fixes.h"
#include "sph_soil_memory.h"
#include "sph_soil_offenders.h"
#include "sph_soil_walls.h"

#include <algorithm>
#include <cmath>

using namespace LAMMPS_NS;
using MathConst::MY_PI;
using SPHSoilOffenders::find_offenders;

/* ----------------------------------------------------------------------
   the particles' state against their materials: wall particles need what their kind needs (an
   error otherwise, sph_soil_walls.h); a density far from the material's, an h far from the
   spacing that mass and density give, or soil in a rigid body are legal but most likely set-up
   mistakes (a warning, once)
------------------------------------------------------------------------- */

void PairSPHSoil::check_particles()
{
  walls->check_particles();
  warn_density();
  warn_spacing();
  warn_soil_in_rigid_bodies();
  warn_geostatic_across_gravity();
  if (avec->geostatic_unchecked_group && warn_geostatic_yield(avec->geostatic_unchecked_group, avec->geostatic_k0))
    avec->geostatic_unchecked_group = 0;
}

// A geostatic state on the yield surface is not at rest: its particles yield at the first step
// and the soil creeps towards another state (a consolidation with nu / (1 - nu) at phi = 30
// settled 4% ahead of Terzaghi while its pore pressure lagged). Zero stress (above the surface)
// is the apex of a cohesionless soil, on the surface whatever K0: not counted.
bool PairSPHSoil::warn_geostatic_yield(int groupbit, double k0)
{
  const int *type = atom->type, *mask = atom->mask;
  // (called by sph_soil/set before init_style() has found the atom style)
  auto *style = dynamic_cast<AtomVecSPHSoil *>(atom->style_match("sph/soil"));
  if (!style) return false;
  double **stress = style->stress;
  int missing = 0;
  for (int i = 0; i < atom->nlocal; i++)
    if ((mask[i] & groupbit) && !materials.has(type[i])) missing = 1;
  int any_missing = 0;
  MPI_Allreduce(&missing, &any_missing, 1, MPI_INT, MPI_MAX, world);
  if (any_missing) return false;
  const auto outside = find_offenders(
      lmp,
      [&](int i) {
        const SPHSoil::ConstitutiveModel *model = materials.model(type[i]);
        if (!(mask[i] & groupbit) || !model || materials.of(type[i]).water) return false;
        double size = 0.0;
        for (int k = 0; k < 6; k++) size = std::max(size, std::fabs(stress[i][k]));
        return size > 0.0 && model->on_yield_surface(stress[i]);
      },
      [&](int i, double *values) {
        values[0] = type[i];
        values[1] = stress[i][0];
        values[2] = stress[i][1];
        values[3] = stress[i][2];
      });
  if (outside && comm->me == 0)
    error->warning(FLERR,
                   "sph_soil/set geostatic: K0 = {} puts {} particle(s) on or outside their "
                   "material's yield surface (atom {} of type {}: stress {:.6g} {:.6g} {:.6g}): they yield at "
                   "the first step instead of resting; a K0 nearer 1 starts them inside (Jaky's "
                   "1 - sin(phi) does below phi = 39 degrees, for Drucker-Prager's default fit)",
                   k0, outside.count, outside.first, (int) outside.values[0], outside.values[1],
                   outside.values[2], outside.values[3]);
  return true;
}

// sph_soil/set geostatic puts the overburden along y in 2D and z in 3D unless told otherwise
// ('vertical'); a gravity that points along another axis makes that stress wrong
void PairSPHSoil::warn_geostatic_across_gravity()
{
  const int vertical = avec->geostatic_vertical;
  if (vertical < 0 || comm->me != 0) return;
  double g[3];
  SPHSoilFixes::gravity_sum(SPHSoilFixes::gravity_fixes(lmp), g);
  int along = 0;
  for (int a = 1; a < 3; a++)
    if (std::fabs(g[a]) > std::fabs(g[along])) along = a;
  if (g[along] != 0.0 && along != vertical)
    error->warning(FLERR, "Pair sph/soil: sph_soil/set geostatic put the overburden along {} but "
                          "gravity points along {} ({} {} {}): add 'vertical {}' to geostatic",
                   "xyz"[vertical], "xyz"[along], g[0], g[1], g[2], "xyz"[along]);
}

// Density within 10% of rho0: compression under soil's own weight changes it by p/K, well below 1%.
void PairSPHSoil::warn_density()
{
  if (warned_density) return;
  warned_density = true;
  const int *type = atom->type;
  const double *rho = atom->rho;
  const auto off = find_offenders(
      lmp,
      [&](int i) {
        return materials.has(type[i]) && !walls->is_wall(type[i]) &&
            std::fabs(rho[i] / materials.of(type[i]).density - 1.0) > 0.1;
      },
      [&](int i, double *values) {
        values[0] = rho[i];
        values[1] = materials.of(type[i]).density;
      });
  if (off && comm->me == 0)
    error->warning(FLERR, "Pair sph/soil: {} soil particle(s) have a density more than 10% away "
                          "from their material's rho0 (atom {}: {} against {}); is "
                          "'sph_soil/set <group> density' missing?", off.count, off.first,
                   off.values[0], off.values[1]);
}

// h/d within [0.9, 3], d = (m/rho)^(1/D) the spacing that mass and density give: below, a
// particle has too few neighbours for SPH (none below 0.5), above, the kernel smears over many
// spacings; runs use 1.2 to 2.
void PairSPHSoil::warn_spacing()
{
  if (warned_spacing) return;
  warned_spacing = true;
  const int *type = atom->type;
  const double *h = avec->smoothing_length, *rho = atom->rho, *rmass = atom->rmass;
  const int dimension = domain->dimension;
  auto ratio = [&](int i) { return h[i] / SPHSoil::volume_spacing(rmass[i] / rho[i], dimension); };
  const auto off = find_offenders(
      lmp,
      [&](int i) {
        if (!materials.has(type[i])) return false;
        const double r = ratio(i);
        return !(r >= 0.9 && r <= 3.0);
      },
      [&](int i, double *values) {
        values[0] = ratio(i);
        values[1] = h[i];
        values[2] = rmass[i];
        values[3] = rho[i];
      });
  if (off && comm->me == 0)
    error->warning(FLERR, "Pair sph/soil: {} particle(s) have h/d outside [0.9, 3], with d = "
                          "(m/rho)^(1/{}) the spacing that their mass and density give (atom {}: "
                          "h/d = {:.3g} from h {}, m {}, rho {}); usual is 1.2 to 2: check "
                          "'sph_soil/set ... mass ... density ... h'", off.count, dimension,
                   off.first, off.values[0], off.values[1], off.values[2], off.values[3]);
}

// A rigid body of soil particles that no fix sph/soil integrates (fix rigid and its variants)
// moves them as a block whose stress and density never change: structures are wall particles.
// (Soil that fix sph/soil integrates too is that fix's error, or allowed by its 'others allow'.)
void PairSPHSoil::warn_soil_in_rigid_bodies()
{
  const int *type = atom->type, *mask = atom->mask;
  int integrated = 0;    // the groups of the fixes sph/soil
  for (int f = 0; f < modify->nfix; f++)
    if (SPHSoilFixes::is_sph_soil_integrator(modify->fix[f])) integrated |= modify->fix[f]->groupbit;
  Fix *rigid = SPHSoilFixes::first_fix_holding(
      lmp, [](Fix *fix) { return fix->rigid_flag != 0; },
      [&](int i) { return materials.model(type[i]) != nullptr && !(mask[i] & integrated); });
  if (rigid && comm->me == 0)
    error->warning(FLERR, "Fix {} ({}) moves soil particles that no fix sph/soil integrates as a "
                          "rigid body, whose stress and density never change: a structure is made "
                          "of wall particles (pair_coeff I I wall), soil particles are integrated "
                          "by fix sph/soil", rigid->id, rigid->style);
}

/* ----------------------------------------------------------------------
   the pair list's size from the largest h/d: each particle lists about half of those within
   its support (2 h_ij + skin), about (pi or 4 pi / 3) / 2 ((support h + skin) / d)^D of them,
   4 bytes each. An h far beyond the spacing whose list cannot fit in what the ranks and nodes
   may have (sph_soil_memory.h) stops here, naming h, rather than in an allocation failure in
   the list's build.
------------------------------------------------------------------------- */

void PairSPHSoil::check_list_fits()
{
  const int *type = atom->type;
  const double *h = avec->smoothing_length, *rho = atom->rho, *rmass = atom->rmass;
  const int dimension = domain->dimension;
  double worst = 0.0, worst_all = 0.0;
  for (int i = 0; i < atom->nlocal; i++)
    if (materials.has(type[i]))
      worst = MAX(worst, h[i] / SPHSoil::volume_spacing(rmass[i] / rho[i], dimension));
  MPI_Allreduce(&worst, &worst_all, 1, MPI_DOUBLE, MPI_MAX, world);
  const double reach = SPHSoil::kernel_support(kernel) * worst_all * (1.0 + neighbor->skin / max_h);
  const double partners =
      0.5 * (dimension == 3 ? 4.0 / 3.0 * MY_PI * reach * reach * reach : MY_PI * reach * reach);
  const double bytes = (double) atom->natoms * partners * sizeof(int);
  const auto verdict = SPHSoilMemory::check(world, (double) atom->nlocal * partners * sizeof(int));
  if (!verdict.fits)
    SPHSoilCompat::error_all(
        lmp, FLERR,
        "Pair sph/soil: h/d up to {:.3g} gives each particle about {:.3g} neighbours, "
        "{:.3g} GB for the pair list of {} particles, more than {}; h is usually 1.2 to 2 "
        "times the spacing d = (m/rho)^(1/{})",
        worst_all, 2.0 * partners, bytes / 1e9, atom->natoms, verdict.limit, dimension);
}

/* ----------------------------------------------------------------------
   particles at the same place (created twice, or read twice): legal, the sums stay finite
   (the kernel gradient vanishes at r = 0), but most likely a mistake; warned once, at the
   first force evaluation, when the neighbour list exists
------------------------------------------------------------------------- */

void PairSPHSoil::warn_coinciding()
{
  warned_coinciding = true;
  double **x = atom->x;
  const double *h = avec->smoothing_length;
  const tagint *tag = atom->tag;
  bigint pairs = 0;
  int first = -1, partner = -1;
  const int *partners = neighbours.partner_data();
  for (int i = 0; i < atom->nlocal; i++) {
    const double tolerance = 1.0e-6 * h[i];
    for (int jj = neighbours.first(i); jj < neighbours.end(i); jj++) {
      const int j = partners[jj];
      // (in 2D the pair sums see x and y only: particles apart in z alone coincide for them)
      const double dx = x[i][0] - x[j][0], dy = x[i][1] - x[j][1],
                   dz = domain->dimension == 3 ? x[i][2] - x[j][2] : 0.0;
      if (dx * dx + dy * dy + dz * dz >= tolerance * tolerance) continue;
      pairs++;
      if (first < 0 || tag[i] < tag[first]) {
        first = i;
        partner = j;
      }
    }
  }
  const auto at_same_place = SPHSoilOffenders::reduce_offenders(
      lmp, pairs, first, [&](int i, double *values) {
        values[0] = tag[partner];
        for (int a = 0; a < 3; a++) values[1 + a] = x[i][a];
      });
  if (at_same_place && comm->me == 0)
    error->warning(FLERR, "Pair sph/soil: {} pair(s) of particles closer than 1e-6 h (atoms {} and "
                          "{} at {} {} {}): particles at the same place, created or read twice?",
                   at_same_place.count, at_same_place.first, (tagint) at_same_place.values[0],
                   at_same_place.values[1], at_same_place.values[2], at_same_place.values[3]);
}

/* ---------------------------------------------------------------------- */

bigint PairSPHSoil::soil_behind_walls() const
{
  const bigint mine = walls->soil_behind_planes();
  bigint all = 0;
  MPI_Allreduce(&mine, &all, 1, MPI_LMP_BIGINT, MPI_SUM, world);
  return all;
}
