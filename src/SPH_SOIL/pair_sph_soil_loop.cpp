/* ----------------------------------------------------------------------
   SPH_SOIL package for LAMMPS: pair_style sph/soil: the packed rows, the loop, the virial
------------------------------------------------------------------------- */

#include "pair_sph_soil.h"

#include "atom.h"
#include "atom_vec_sph_soil.h"
#include "domain.h"
#include "force.h"
#include "memory.h"
#include "neighbor.h"
#include "soil_artificial_stress.h"
#include "soil_gradient_correction.h"
#include "soil_packed_rows.h"
#include "soil_pair_terms.h"
#include "soil_kernels.h"
#include "soil_wall_images.h"
#include "sph_soil_gradient_correction.h"
#include "sph_soil_pore_water.h"
#include "sph_soil_stress_diffusion.h"
#include "sph_soil_wall_friction.h"
#include "sph_soil_walls.h"
#include "update.h"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstring>

using namespace LAMMPS_NS;
using SPHSoil::P_H;
using SPHSoil::P_MASS;
using SPHSoil::P_RHO;
using SPHSoil::P_STRESS;
using SPHSoil::P_V;
using SPHSoil::P_VOLUME;
using SPHSoil::P_X;
using SPHSoil::pair_geometry;
using SPHSoil::PairGeometry;

// kept out of line (GCC and Clang would inline it into the pair loop)
#if defined(__GNUC__)
#define SPH_SOIL_NOINLINE __attribute__((noinline))
#else
#define SPH_SOIL_NOINLINE
#endif

/* ----------------------------------------------------------------------
   LAMMPS has just reneighboured (set-up, or the skin was used up, or atoms were added): owned
   and ghost atoms are new, and so is our list. The virial: pair by pair when LAMMPS asks for it
   that way or per atom (compute stress/atom), else x . f over owned and ghost atoms
------------------------------------------------------------------------- */

void PairSPHSoil::compute(int eflag, int vflag)
{
  ev_init(eflag, vflag);
  if (neighbor->ago == 0) build_neighbours();
  if (!warned_coinciding) warn_coinciding();
  const bool levels = per_level();
  if (levels) pack_step_periods();
  if (walls->interface()) walls->interface()->set_step_periods(levels ? step_periods : nullptr);
  // the ghosts' pore pressure, for the total stress of the packed rows and the flow
  if (pore_water->pressures()) pore_water->share_pressures();
  SPHSoil::with_kernel(kernel, Evaluate{this, domain->dimension, has_artificial_stress,
                                        vflag_either != 0, levels, multiphase});
  if (vflag_fdotr) virial_fdotr_compute();
}

template <class Kernel> void PairSPHSoil::Evaluate::operator()() const
{
  // (a table of member-function pointers: one branch instead of a tree of them)
  using Eval = void (PairSPHSoil::*)();
  using P = PairSPHSoil;
#define SPH_SOIL_EVAL_PAIR(D, A, V, L) \
  {&P::eval<D, Kernel, A, V, L, false>, &P::eval<D, Kernel, A, V, L, true>}
#define SPH_SOIL_EVAL_LEVELS(D, A, V) \
  {SPH_SOIL_EVAL_PAIR(D, A, V, false), SPH_SOIL_EVAL_PAIR(D, A, V, true)}
#define SPH_SOIL_EVAL_VIRIAL(D, A) \
  {SPH_SOIL_EVAL_LEVELS(D, A, false), SPH_SOIL_EVAL_LEVELS(D, A, true)}
#define SPH_SOIL_EVAL_DIMENSION(D) \
  {SPH_SOIL_EVAL_VIRIAL(D, false), SPH_SOIL_EVAL_VIRIAL(D, true)}
  static const Eval table[2][2][2][2][2] = {SPH_SOIL_EVAL_DIMENSION(2), SPH_SOIL_EVAL_DIMENSION(3)};
#undef SPH_SOIL_EVAL_PAIR
#undef SPH_SOIL_EVAL_LEVELS
#undef SPH_SOIL_EVAL_VIRIAL
#undef SPH_SOIL_EVAL_DIMENSION
  (pair->*table[dimension == 3][artificial_stress][virial][levels][phases])();
}

/* ----------------------------------------------------------------------
   each owned and ghost atom's signed period at this evaluation (soil_level_steps.h): ghosts
   have their owners' h, and every rank the same schedule
------------------------------------------------------------------------- */

void PairSPHSoil::pack_step_periods()
{
  const int nall = atom->nlocal + atom->nghost;
  // the periods follow h and h_min, which change where LAMMPS reneighbours (splits, merges,
  // sph_soil/set) or where the hierarchy changes: kept between
  bool fresh = neighbor->ago == 0 || schedule->finest_h != periods_finest_h;
  if (atom->nmax > nmax_periods) {
    nmax_periods = atom->nmax;
    memory->destroy(step_periods);
    memory->destroy(atom_periods);
    memory->create(step_periods, nmax_periods, "pair:step_periods");
    memory->create(atom_periods, nmax_periods, "pair:atom_periods");
    fresh = true;
  }
  const int64_t now = update->ntimestep;
  if (fresh) {
    const int *type = atom->type;
    const int *const wall_kind = walls->kinds();
    const double *h = avec->smoothing_length;
    const double finest_h = schedule->finest_h;
    for (int i = 0; i < nall; i++)
      atom_periods[i] = wall_kind[type[i]] != SPHSoil::NEIGHBOUR_SOIL ? 0 : SPHSoil::step_period(h[i], finest_h);
    periods_finest_h = finest_h;
  }
  for (int i = 0; i < nall; i++) {
    const int period = atom_periods[i];
    step_periods[i] = period == 0 ? -INFINITY
                                  : (SPHSoil::ends_step(now, period) ? (double) period : -(double) period);
  }
}

/* ----------------------------------------------------------------------
   per-atom inputs of the pair sums, once per step for owned and ghost atoms,
   packed into one row of PACKED doubles per atom (see the header): a
   neighbour then costs two cache lines instead of a load from each of
   eight arrays; and the accumulators of the sums, set to zero
------------------------------------------------------------------------- */

template <int DIMENSION, bool PHASES, bool PRESSURES> void PairSPHSoil::pack_atoms()
{
  const int nall = atom->nlocal + atom->nghost;
  if (nall > nmax_packed) {
    nmax_packed = atom->nmax;
    memory->destroy(packed);
    memory->destroy(sums);
    memory->create(packed, nmax_packed * SPHSoil::PACKED, "pair:packed");
    memory->create(sums, nmax_packed * SUMS, "pair:sums");
  }
  double **x = atom->x, **vest = atom->vest, **stress = avec->stress;
  const double *rho = atom->rho, *rmass = atom->rmass, *h = avec->smoothing_length;
  const double *pore_pressure = avec->pore_pressure;
  for (int i = 0; i < nall; i++) {
    double *row = packed + (size_t) i * SPHSoil::PACKED;
    const double inv_rho = 1.0 / rho[i];
    // (the multiphase form sums the stress itself)
    const double inv_rho2 = PHASES ? 1.0 : inv_rho * inv_rho;
    // soil: fix sph/soil's estimate of v(t + dt); a wall: its velocity (the walls' fix
    // SPH_SOIL_WALLS copies it there after the fixes that move walls have run)
    for (int a = 0; a < 3; a++) {
      row[P_X + a] = x[i][a];
      row[P_V + a] = vest[i][a];
    }
    // the total stress: a saturated soil's effective stress less its pore pressure (0 for
    // dry soil; a drained wall's own is not the soil's, and no wall particle's stress is used)
    const double pore = PRESSURES ? pore_pressure[i] : 0.0;
    for (int k = 0; k < 3; k++) row[P_STRESS + k] = (stress[i][k] - pore) * inv_rho2;
    for (int k = 3; k < 6; k++) row[P_STRESS + k] = stress[i][k] * inv_rho2;
    row[P_VOLUME] = rmass[i] * inv_rho;
    row[P_MASS] = rmass[i];
    row[P_RHO] = rho[i];
    row[P_H] = h[i];
  }
  if (PHASES) {
    packed_pressure.assign(pore_pressure, pore_pressure + nall);
    // a soil particle's skeleton tension (the tensile part of its effective stress), 0 for
    // water and walls
    skeleton_tension.assign((size_t) nall * 6, 0.0);
    const int *type = atom->type;
    for (int i = 0; i < nall; i++)
      if (type_soil_by_water[type[i]])
        SPHSoil::artificial_stress<DIMENSION>(stress[i], 1.0, -1.0, &skeleton_tension[(size_t) i * 6]);
  }
  if (nall > 0) memset(sums, 0, sizeof(double) * SUM_ROW<DIMENSION>() * nall);
}

/* ----------------------------------------------------------------------
   the artificial stress R of every owned and ghost atom (soil_artificial_stress.h), 0 for
   the types without it, and 1 / w(d / h) for the pair's weight (see the header)
------------------------------------------------------------------------- */

template <int DIMENSION, class Kernel, bool PHASES> void PairSPHSoil::pack_artificial_stress()
{
  const int nall = atom->nlocal + atom->nghost;
  if (atom->nmax > nmax_artificial) {
    nmax_artificial = atom->nmax;
    memory->destroy(artificial);
    memory->create(artificial, nmax_artificial * ARTIFICIAL, "pair:artificial");
  }
  double **stress = avec->stress;
  const int *type = atom->type;
  const double *rho = atom->rho, *rmass = atom->rmass, *h = avec->smoothing_length;
  const double *pore_pressure = pore_water->pressures() ? avec->pore_pressure : nullptr;
  for (int i = 0; i < nall; i++) {
    double *row = artificial + (size_t) i * ARTIFICIAL;
    if (type_artificial_stress[type[i]]) {
      // from the skeleton's tension that the momentum sum sees: a saturated soil's effective
      // stress less its pore pressure where that compresses (an undrained block between plates
      // has its effective stress in tension where the total is not, and a repulsion from the
      // effective stress held it in a total tension that nothing else does); a suction is the
      // water's tension, not the skeleton's, and a repulsion from it dilates the soil, whose
      // suction grows: the undrained drawdown blew up that way (doc/theory.rst 2.5)
      double total[6];
      const double pore = pore_pressure ? std::max(pore_pressure[i], 0.0) : 0.0;
      for (int k = 0; k < 6; k++) total[k] = stress[i][k] - (k < 3 ? pore : 0.0);
      SPHSoil::artificial_stress<DIMENSION>(total, rho[i], artificial_stress_epsilon,
                                            row + A_STRESS);
      // (in the units of the packed stress: the multiphase form's is the stress itself)
      if (PHASES)
        for (int k = 0; k < 6; k++) row[A_STRESS + k] *= rho[i] * rho[i];
    } else {
      for (int k = 0; k < 6; k++) row[A_STRESS + k] = 0.0;
    }
    const double spacing = SPHSoil::volume_spacing(rmass[i] / rho[i], DIMENSION);
    row[A_INVERSE_SHAPE] = 1.0 / Kernel::shape(spacing / h[i]);
  }
}

/* ----------------------------------------------------------------------
   the sums into the atoms' arrays (owned and ghost: the atom style's reverse
   communication then brings the ghosts' shares to their owners)
------------------------------------------------------------------------- */

template <int DIMENSION, int CORRECTION, bool PHASES> void PairSPHSoil::unpack_sums()
{
  static_assert(S_ACROSS<DIMENSION>() < SUM_ROW<DIMENSION>(), "a sum row holds its columns");
  constexpr bool CORRECTED = CORRECTION != CORRECTION_NONE;
  constexpr bool FULL = CORRECTION == CORRECTION_FULL;
  // without Newton's third law for ghost pairs, ghost rows hold shares that their owners
  // compute themselves
  const int n = force->newton_pair ? atom->nlocal + atom->nghost : atom->nlocal;
  double **f = atom->f, **strain_rate = avec->strain_rate, **spin = avec->spin;
  double *drho = atom->drho, *pore_flow = avec->pore_flow;
  const double *rho = atom->rho;
  const bool volume_form = continuity_volume;
  constexpr int D = DIMENSION;
  for (int i = 0; i < n; i++) {
    const double *sum = sums + (size_t) i * SUM_ROW<D>();
    for (int a = 0; a < D; a++) f[i][a] += sum[S_FORCE + a];
    // i's own gradients over its kernel's first moment (a ghost's share with its owner's factor)
    const double scale = CORRECTED ? correction->factor(i) : 1.0;
    const double *g = sum + S_GRADIENT<D>();
    double corrected[D * D];
    if (FULL) {
      // by the moment tensors (soil_gradient_correction.h); the volume form's density rate
      // from the corrected trace
      const auto l = correction->velocity_correction(i);
      SPHSoil::corrected_velocity_gradient<D>(g, l.normal, l.full, l.plain, corrected);
      g = corrected;
    }
    // the volume form sums V_j (v_ij . grad W) = -div v: the rate is rho_i times it
    if (FULL && volume_form) {
      double divergence = 0.0;
      for (int a = 0; a < D; a++) divergence += g[a * D + a];
      drho[i] -= rho[i] * divergence;
    } else {
      drho[i] += (volume_form ? rho[i] : 1.0) * scale * sum[S_DRHO<D>()];
    }
    // strain rate (Voigt) and spin (xy xz yz): the symmetric and antisymmetric parts
    const double gradient_scale = FULL ? 1.0 : scale;    // (full: L holds it)
    // the soil-water pairs' divergence: water that crossed into (or out of) the soil's pores,
    // in the pore water's balance of volume (the pore water's flow adds its own later; with
    // the full correction, whose factor the ghosts do not hold, as summed)
    if (PHASES) pore_flow[i] -= gradient_scale * sum[S_ACROSS<D>()];
    for (int a = 0; a < D; a++) strain_rate[i][a] += gradient_scale * g[a * D + a];
    for (int a = 0; a < D; a++)
      for (int b = a + 1; b < D; b++) {
        strain_rate[i][SPHSoil::voigt_index(a, b)] +=
            0.5 * gradient_scale * (g[a * D + b] + g[b * D + a]);
        spin[i][a + b - 1] += 0.5 * gradient_scale * (g[a * D + b] - g[b * D + a]);
      }
  }
}

/* ----------------------------------------------------------------------
   soil particle s and the image of mirror wall particle w (soil_wall_images.h): s takes its
   share, w the opposite force (Newton's third law: the soil's force on the structure); a wall
   moved by a fix (move, rigid) brings its velocity, a wall at rest has v_w = 0 and the terms of
   a static wall. `sign` dx = x_s - x_w.
------------------------------------------------------------------------- */

template <int DIMENSION, bool VIRIAL, bool PHASES>
SPH_SOIL_NOINLINE void PairSPHSoil::mirror_wall_pair(int soil, int wall, double sign,
                                                     const double dx[3], double r2, double hij,
                                                     double factor, double c_ij, double weight)
{
  constexpr int D = DIMENSION;
  const int newton_pair = force->newton_pair, nlocal = atom->nlocal;
  const bool update_soil = newton_pair || soil < nlocal;
  const bool update_wall = newton_pair || wall < nlocal;
  const double *ps = packed + (size_t) soil * SPHSoil::PACKED;
  const double *pw = packed + (size_t) wall * SPHSoil::PACKED;
  const double *normal = avec->wall_normal[wall];
  const double wall_distance = avec->wall_distance[wall];
  const int wall_type = atom->type[wall];

  // seen from the soil particle: x_s - x_w; the image (soil_wall_images.h)
  double separation[3] = {0.0, 0.0, 0.0};
  for (int a = 0; a < D; a++) separation[a] = sign * dx[a];
  SPHSoil::MirrorImage image;
  const int slip = walls->slips()[wall_type];
  // (a soil particle beside another face of the wall's body has none: only the contact below
  // acts on it)
  const bool imaged = SPHSoil::mirror_image<D>(ps, pw, normal, wall_distance,
                                               walls->front_most(soil), separation, slip, image);
  const double rhos = ps[P_RHO];
  // soil lifting off a drained wall leaves a gap of the wall's water (soil_wall_images.h), its
  // pressure in the packed stress's units (the multiphase form's is the stress itself)
  if (imaged && walls->drained_mirror(wall_type)) {
    const double gap = walls->gap(wall);
    if (gap > 0.0) {
      const double wall_pressure =
          PHASES ? packed_pressure[wall] : avec->pore_pressure[wall] / (rhos * rhos);
      SPHSoil::drained_image<D>(ps + P_STRESS, wall_pressure,
                                SPHSoil::contact_share<D>(gap, ps[P_VOLUME]), normal, separation,
                                image);
    }
  }
  const double viscosity_h =
      SPHSoil::viscosity_length(viscosity_h0, SPHSoil::viscosity_h_weight(viscosity_h0), hij);
  SPHSoil::PairTerms<D> terms;
  // (the multiphase form: the mean density's place holds (rho_s + rho_s) / (2 rho_s rho_s))
  if (imaged)
    SPHSoil::pair_terms<D>(separation, r2, hij, viscosity_h, factor, image.dv, image.approach,
                           image.stress_sum, PHASES ? 1.0 / rhos : rhos, c_ij, viscosity_alpha,
                           viscosity_beta, terms);
  else
    SPHSoil::no_pair_terms<D>(terms);
  // the image's volume: the wall particle's mass at the soil's density (the paper's form, whose
  // sums weigh by mass); in the multiphase form, which weighs by volume, the wall particle's own,
  // so that a wall set up with the soil's mass holds free water at the water's pressure rather
  // than rho_soil / rho_water times it
  const double mw = pw[P_MASS], volume = PHASES ? pw[P_VOLUME] : mw / rhos;
  const double mass_product =
      weight * (PHASES ? ps[P_VOLUME] * volume : ps[P_MASS] * mw);
  // the wall particle's contact: a soil particle within its reach is pushed away whatever its
  // stress (soil_wall_images.h; a bound without roots first), a force per unit mass product as
  // the pair's
  if (SPHSoil::contact_possible<D>(r2, ps[P_VOLUME], pw[P_VOLUME])) {
    const double soil_spacing = SPHSoil::volume_spacing(ps[P_VOLUME], D);
    const double r = std::sqrt(r2);
    const double strain =
        SPHSoil::contact_strain(r, soil_spacing, SPHSoil::volume_spacing(pw[P_VOLUME], D));
    if (strain > 0.0) {
      double relative[3] = {0.0, 0.0, 0.0};
      for (int a = 0; a < D; a++) relative[a] = ps[P_V + a] - pw[P_V + a];
      SPHSoil::add_contact_force<D>(rhos * c_ij * c_ij, rhos * c_ij, soil_spacing, strain,
                                    separation, r, relative, weight / mass_product, terms.force);
    }
  }
  // a smooth or frictional wall pushes along its normal only, and never pulls (an interface
  // carries no tension: a soil in tension comes off it); a frictional wall's pushing pairs go
  // to the interface, which adds the friction after all forces of the step (doc/theory.rst 4.4)
  if (slip != SPHSoil::SLIP_NONE) {
    const double push = SPHSoil::pushing_part<D>(terms.force, normal);
    if (slip == SPHSoil::SLIP_FRICTION && push > 0.0) {
      const double area =
          SPHSoil::contact_area(ps[P_VOLUME], volume, factor, image.normal_separation);
      // (stepping per level: the impulse of the pair's period; the area in proportion, so that
      // the interface's pressure is the contact's)
      walls->interface()->add_pair(soil, wall, mass_product * push,
                                   walls->frictions()[wall_type], normal, pw + P_V,
                                   walls->adhesions()[wall_type], weight * area, update_soil,
                                   update_wall);
    }
  }

  if (VIRIAL)
    ev_tally_xyz(soil, wall, nlocal, newton_pair, 0.0, 0.0, mass_product * terms.force[0],
                 mass_product * terms.force[1], D == 3 ? mass_product * terms.force[2] : 0.0,
                 separation[0], separation[1], separation[2]);
  if (update_wall) {
    double *ow = sums + (size_t) wall * SUM_ROW<D>();
    for (int a = 0; a < D; a++) ow[S_FORCE + a] -= mass_product * terms.force[a];
  }
  if (!update_soil) return;
  double *os = sums + (size_t) soil * SUM_ROW<D>();
  os[S_DRHO<D>()] += (continuity_volume ? volume : mw) * terms.density_rate;
  // (the rates are the particle's own, used where it ends a step: never weighted)
  for (int a = 0; a < D; a++) os[S_FORCE + a] += mass_product * terms.force[a];
  for (int c = 0; c < D; c++)
    for (int d = 0; d < D; d++) os[S_GRADIENT<D>() + c * D + d] += volume * terms.gradient[c][d];
}

/* ----------------------------------------------------------------------
   the SPH sums of doc/theory.rst section 2 over a half neighbour list: every pair once,
   its contributions to both particles (Newton's third law: momentum is
   conserved exactly); ghosts' shares return to their owners by reverse
   communication (the atom style carries drho, strain rate and spin back)
------------------------------------------------------------------------- */

template <int DIMENSION, class Kernel, bool ARTIFICIAL_STRESS, bool VIRIAL, bool LEVELS, bool PHASES>
void PairSPHSoil::eval()
{
  using SPHSoil::voigt_index;
  constexpr int D = DIMENSION;
  const int *type = atom->type;
  const int nlocal = atom->nlocal;
  // members as locals: the stores to the sums (double *) could otherwise alias the double
  // members, which the compiler would then reload for every pair
  const double alpha = viscosity_alpha, beta_viscosity = viscosity_beta, h0 = viscosity_h0;
  const double h0_weight = SPHSoil::viscosity_h_weight(viscosity_h0);
  double *const *const c_type = sound_speed_ij;
  const int *const wall_kind = walls->kinds();
  const int newton_pair = force->newton_pair;

  // (re)allocates the packed rows: take their addresses after it. Free water carries a pressure
  if (PHASES || pore_water->pressures())
    pack_atoms<D, PHASES, true>();
  else
    pack_atoms<D, false, false>();
  walls->prepare(packed, neighbours, kernel, D, PHASES);
  // the stress of each atom over its kernel's first moment (after the walls have written theirs)
  if (correction) {
    correction->correct(packed, neighbours, wall_kind, walls->slips(), walls->planes(), kernel, D);
    if (PHASES)
      for (int i = 0; i < atom->nlocal + atom->nghost; i++) {
        packed_pressure[i] *= correction->factor(i);
        for (int k = 0; k < 6; k++) skeleton_tension[(size_t) i * 6 + k] *= correction->factor(i);
      }
  }
  const double *const pressure = PHASES ? packed_pressure.data() : nullptr;
  const double *const tension = PHASES ? skeleton_tension.data() : nullptr;
  const int *const free_water = type_free_water.data();
  if (ARTIFICIAL_STRESS) pack_artificial_stress<D, Kernel, PHASES>();
  const int *const artificial_type = type_artificial_stress.data();
  const double *const in = packed;
  double *const out = sums;
  constexpr int ROW = SUM_ROW<D>();
  constexpr int DRHO = S_DRHO<D>(), GRADIENT = S_GRADIENT<D>();
  const int *const partners = neighbours.partner_data();
  // stepping per level: each pair weighted by its period, skipped where neither ends a step
  const double *const periods = LEVELS ? step_periods : nullptr;
  // the continuity sum's weight of a partner: its volume, or its mass (the paper's form)
  const int weight_column = continuity_volume ? P_VOLUME : P_MASS;

  for (int i = 0; i < nlocal; i++) {
    const int itype = type[i];
    // i's inputs as local copies: the stores to j's sums (double *) could alias the packed
    // rows, and the compiler would reload them for every pair
    const double *pi = in + (size_t) i * SPHSoil::PACKED;
    double xi[3], vi[3], si[6];
    for (int a = 0; a < 3; a++) {
      xi[a] = pi[P_X + a];
      vi[a] = pi[P_V + a];
    }
    for (int k = 0; k < 6; k++) si[k] = pi[P_STRESS + k];
    const double hi = pi[P_H];
    const double mi = pi[P_MASS], rhoi = pi[P_RHO], volume_i = pi[P_VOLUME];
    // the momentum sum's factor of i: its mass, or its volume (the multiphase form)
    const double product_i = PHASES ? volume_i : mi;
    const double *c_i = c_type[itype];
    // the plain pairs to visit: all of i's, or, with stepping per level, where i does not end a
    // step, those whose partner does (collected here; none: nothing to do for i, most of the
    // coarse particles most of the time). Their weight is the finer period.
    const int plain_end = neighbours.plain_end(i);
    const int *plain_partners = partners + neighbours.first(i);
    int plain_count = plain_end - neighbours.first(i);
    const double period_i = LEVELS ? periods[i] : 1.0;
    const double unsigned_period_i = LEVELS ? std::fabs(period_i) : 1.0;
    if (LEVELS && period_i < 0.0) {
      if ((int) active_partners.size() < plain_count) active_partners.resize(plain_count);
      int count = 0;
      for (int k = 0; k < plain_count; k++)
        if (periods[plain_partners[k]] > 0.0) active_partners[count++] = plain_partners[k];
      bool mirror = false;
      for (int jj = plain_end; jj < neighbours.end(i) && !mirror; jj++) mirror = periods[partners[jj]] > 0.0;
      if (count == 0 && !mirror) continue;
      plain_partners = active_partners.data();
      plain_count = count;
    }

    // i's shares, accumulated here and stored once after the j loop
    double drho_i = 0.0, across_i = 0.0, force_i[D], gradient_i[D][D];
    for (int a = 0; a < D; a++) {
      force_i[a] = 0.0;
      for (int b = 0; b < D; b++) gradient_i[a][b] = 0.0;
    }

    // the plain pairs: soil-soil, or soil and an extrapolated wall particle (a partner like a
    // soil particle, with the soil's state extrapolated to it; its own rates are summed and
    // never used). Seen from i: grad = dW/dx_i; j gets the same terms with the opposite force
    // and dW/dx_j = -grad (Newton's third law). Without Newton's third law for ghost pairs,
    // a ghost j's row is written and never read (unpack_sums()).
    for (int k = 0; k < plain_count; k++) {
      const int j = plain_partners[k];
      double weight = 1.0;
      if (LEVELS) weight = SPHSoil::finer_period(unsigned_period_i, periods[j]);
      const double *pj = in + (size_t) j * SPHSoil::PACKED;
      PairGeometry g;
      if (!pair_geometry<D, Kernel>(xi, hi, pj, g)) continue;
      const int jtype = type[j];
      const double *sj = pj + P_STRESS;
      double dv[3], stress_sum[6];
      for (int a = 0; a < D; a++) {
        dv[a] = vi[a] - pj[P_V + a];
        for (int b = a; b < D; b++) {
          const int k = voigt_index(a, b);
          stress_sum[k] = si[k] + sj[k];
        }
      }
      // soil and free water: their pressures, and the skeleton's tension only (see the header)
      const bool across = PHASES && free_water[itype] != free_water[jtype];
      if (across) {
        const double both = -(pressure[i] + pressure[j]);
        const double *ti = tension + (size_t) i * 6, *tj = tension + (size_t) j * 6;
        for (int a = 0; a < D; a++)
          for (int b = a; b < D; b++) {
            const int k = voigt_index(a, b);
            stress_sum[k] = (a == b ? both : 0.0) + ti[k] + tj[k];
          }
      }
      if (ARTIFICIAL_STRESS && (artificial_type[itype] || artificial_type[jtype])) {
        // (R_i + R_j) (W(r) / W(spacing))^4
        const double *ai = artificial + (size_t) i * ARTIFICIAL;
        const double *aj = artificial + (size_t) j * ARTIFICIAL;
        const double weight = SPHSoil::artificial_stress_weight(
            Kernel::shape(g.r * g.inv_h) * 0.5 * (ai[A_INVERSE_SHAPE] + aj[A_INVERSE_SHAPE]));
        for (int a = 0; a < D; a++)
          for (int b = a; b < D; b++) {
            const int k = voigt_index(a, b);
            stress_sum[k] += weight * (ai[A_STRESS + k] + aj[A_STRESS + k]);
          }
      }
      double approach = 0.0;
      for (int a = 0; a < D; a++) approach += dv[a] * g.dx[a];
      SPHSoil::PairTerms<D> terms;
      const double viscosity_h = SPHSoil::viscosity_length(h0, h0_weight, g.hij);
      // the multiphase form: (rho_i + rho_j) / (2 rho_i rho_j) in the mean density's place, so
      // that V_i V_j Pi is m_i m_j Pi
      const double rhoj = pj[P_RHO];
      const double mean_density = PHASES ? 0.5 * (rhoi + rhoj) / (rhoi * rhoj) : 0.5 * (rhoi + rhoj);
      SPHSoil::pair_terms<D>(g.dx, g.r2, g.hij, viscosity_h, g.factor, dv, approach, stress_sum,
                             mean_density, c_i[jtype], alpha, beta_viscosity, terms);

      const double volume_j = pj[P_VOLUME];
      const double product_j = PHASES ? volume_j : pj[P_MASS];
      const double mass_product = LEVELS ? weight * product_i * product_j : product_i * product_j;
      if (VIRIAL)
        ev_tally_xyz(i, j, nlocal, newton_pair, 0.0, 0.0, mass_product * terms.force[0],
                     mass_product * terms.force[1], D == 3 ? mass_product * terms.force[2] : 0.0,
                     g.dx[0], g.dx[1], g.dx[2]);
      double *oj = out + (size_t) j * ROW;
      drho_i += pj[weight_column] * terms.density_rate;
      oj[DRHO] += pi[weight_column] * terms.density_rate;
      for (int a = 0; a < D; a++) {
        const double force = mass_product * terms.force[a];
        force_i[a] += force;
        oj[S_FORCE + a] -= force;
      }
      // soil and free water: their divergence goes to the volumes the pair's pressures work on
      // (the pore water's, the free water's), not to the skeleton's strain rate (its effective
      // stress does not act across the pair, so it must not deform with it; see the header)
      if (across) {
        double trace = 0.0;
        for (int c = 0; c < D; c++) trace += terms.gradient[c][c];
        across_i += volume_j * trace;
        oj[S_ACROSS<D>()] += volume_i * trace;
        continue;
      }
      // g_i += V_j (v_j - v_i) x grad, and g_j += V_i (v_i - v_j) x (-grad): the same tensor
      for (int c = 0; c < D; c++)
        for (int d = 0; d < D; d++) {
          gradient_i[c][d] += volume_j * terms.gradient[c][d];
          oj[GRADIENT + c * D + d] += volume_i * terms.gradient[c][d];
        }
    }

    double *oi = out + (size_t) i * ROW;
    if (PHASES) oi[S_ACROSS<D>()] += across_i;
    oi[DRHO] += drho_i;
    for (int a = 0; a < D; a++) oi[S_FORCE + a] += force_i[a];
    for (int c = 0; c < D; c++)
      for (int d = 0; d < D; d++) oi[GRADIENT + c * D + d] += gradient_i[c][d];

    // a soil particle and a mirror wall particle: out of line, so that the plain pair above
    // keeps its registers (inlined, the larger loop cost 15 instructions per pair)
    const bool wall_i = wall_kind[itype] == SPHSoil::NEIGHBOUR_MIRROR_WALL;
    for (int jj = plain_end; jj < neighbours.end(i); jj++) {
      const int j = partners[jj];
      double weight = 1.0;
      if (LEVELS) {
        weight = SPHSoil::pair_step_weight(period_i, periods[j]);
        if (weight == 0.0) continue;
      }
      PairGeometry g;
      if (!pair_geometry<D, Kernel>(xi, hi, in + (size_t) j * SPHSoil::PACKED, g)) continue;
      mirror_wall_pair<D, VIRIAL, PHASES>(wall_i ? j : i, wall_i ? i : j, wall_i ? -1.0 : 1.0, g.dx, g.r2, g.hij,
                          g.factor, c_i[type[j]], weight);
    }
  }

  // pore_flow, the pore water's balance of volume, is summed here from zero: the soil-water
  // pairs' divergence when unpacked, then the pore water's own flow (SPHSoilPoreWater::flow())
  if (pore_water->pressures()) memset(avec->pore_flow, 0, sizeof(double) * (atom->nlocal + atom->nghost));
  if (!correction)
    unpack_sums<D, CORRECTION_NONE, PHASES>();
  else if (correction->full())
    unpack_sums<D, CORRECTION_FULL, PHASES>();
  else
    unpack_sums<D, CORRECTION_SCALAR, PHASES>();
  // the pore water's flow and free water's density diffusion: a loop of their own, so that runs
  // of dry soil pay nothing for them; the stress diffusion likewise
  if (pore_water->flows()) pore_water->flow(packed, neighbours, kernel, D, correction.get());
  if (diffusion) diffusion->diffuse(packed, neighbours, kernel, D);
}

