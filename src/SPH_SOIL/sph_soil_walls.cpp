/* ----------------------------------------------------------------------
   SPH_SOIL package for LAMMPS: the walls of pair_style sph/soil (see the header)
------------------------------------------------------------------------- */

#include "sph_soil_walls.h"

#include "atom.h"
#include "atom_vec_sph_soil.h"
#include "comm.h"
#include "error.h"
#include "fix_sph_soil_walls.h"
#include "force.h"
#include "group.h"
#include "memory.h"
#include "modify.h"
#include "neighbor.h"
#include "pair.h"
#include "soil_packed_rows.h"
#include "soil_wall_images.h"
#include "sph_soil_compat.h"
#include "sph_soil_fixes.h"
#include "sph_soil_offenders.h"
#include "sph_soil_wall_friction.h"
#include "update.h"

#include <algorithm>
#include <cmath>
#include <cstring>

using namespace LAMMPS_NS;
using namespace SPHSoil;

/* ---------------------------------------------------------------------- */

SPHSoilWalls::SPHSoilWalls(LAMMPS *lmp, Pair *owner_) :
    Pointers(lmp), owner(owner_), avec(nullptr), has_mirror(false), has_extrapolated(false),
    has_friction(false), has_drained_mirror(false), friction(nullptr),
    exchange(Exchange::EXTRAPOLATION), may_turn(false),
    kinematics(nullptr), nmax(0), sums(nullptr), state(nullptr)
{
  // one ID for every instance of the pair style, so that the fix finds its per-atom state
  // (the interface pressures) in a restart file whatever pair style instance wrote it
  kinematics_id = "SPH_SOIL_WALLS";
}

// out-of-class definition: C++11/14 need it when the constant is bound to a reference
constexpr double SPHSoilWalls::NO_FRONT;

SPHSoilWalls::~SPHSoilWalls()
{
  delete friction;
  memory->destroy(sums);
  memory->destroy(state);
  if (modify && modify->find_fix(kinematics_id) >= 0) modify->delete_fix(kinematics_id);
}

/* ----------------------------------------------------------------------
   per type: the kind (soil or a wall's boundary), a mirror wall's slip and friction
------------------------------------------------------------------------- */

void SPHSoilWalls::classify(const std::vector<SoilMaterial> &materials,
                            const std::vector<int> &has_material, bool free_slip)
{
  const int ntypes = (int) materials.size() - 1;
  kind_of_type.assign(ntypes + 1, NEIGHBOUR_SOIL);
  slip_of_type.assign(ntypes + 1, SLIP_NONE);
  friction_of_type.assign(ntypes + 1, 0.0);
  adhesion_of_type.assign(ntypes + 1, 0.0);
  drained_mirror_of_type.assign(ntypes + 1, 0);
  has_mirror = has_extrapolated = has_friction = has_drained_mirror = false;
  for (int t = 1; t <= ntypes; t++) {
    const SoilMaterial &m = materials[t];
    if (!has_material[t] || !m.is_wall()) continue;
    const WallSlip slip = m.slip == WallSlip::pair_default
        ? (free_slip ? WallSlip::freeslip : WallSlip::noslip)
        : m.slip;
    const bool extrapolated = m.boundary == WallBoundary::extrapolate;
    kind_of_type[t] = extrapolated ? NEIGHBOUR_EXTRAPOLATED_WALL : NEIGHBOUR_MIRROR_WALL;
    has_extrapolated = has_extrapolated || extrapolated;
    has_mirror = has_mirror || !extrapolated;
    drained_mirror_of_type[t] = !extrapolated && m.drained;
    has_drained_mirror = has_drained_mirror || drained_mirror_of_type[t];
    // free slip and friction act across a plane; an extrapolated wall has none
    if (extrapolated && slip != WallSlip::noslip)
      SPHSoilCompat::error_all(
          lmp, FLERR,
          "Pair sph/soil: wall type {} has boundary extrapolate with {}: an "
          "extrapolated wall is no-slip (free slip and friction need the plane of "
          "'boundary mirror')",
          t, slip == WallSlip::freeslip ? "freeslip" : "friction");
    slip_of_type[t] = slip == WallSlip::noslip ? SLIP_NONE
        : slip == WallSlip::freeslip           ? SLIP_FREE
                                               : SLIP_FRICTION;
    friction_of_type[t] = m.friction;
    adhesion_of_type[t] = m.adhesion;
    has_friction = has_friction || slip == WallSlip::friction;
  }
  if (has_friction && !friction) friction = new SPHSoilWallFriction(lmp, owner);
  if (friction) {
    std::vector<double> speeds(ntypes + 1, 0.0);
    for (int t = 1; t <= ntypes; t++)
      if (has_material[t]) speeds[t] = materials[t].wave_speed();
    friction->set_wave_speeds(speeds);
  }
  if (!has_friction) {
    delete friction;
    friction = nullptr;
  }
}

int SPHSoilWalls::forward_size() const
{
  return WSTATE > SPHSoilWallFriction::FORWARD_SIZE ? WSTATE : SPHSoilWallFriction::FORWARD_SIZE;
}

int SPHSoilWalls::reverse_size() const
{
  return XSUMS > SPHSoilWallFriction::REVERSE_SIZE ? XSUMS : SPHSoilWallFriction::REVERSE_SIZE;
}

/* ----------------------------------------------------------------------
   mirror wall particles need their plane, and must lie behind it
------------------------------------------------------------------------- */

void SPHSoilWalls::check_particles() const
{
  using SPHSoilOffenders::find_offenders;
  auto soil_avec = dynamic_cast<AtomVecSPHSoil *>(atom->style_match("sph/soil"));
  const int *type = atom->type;
  double **x = atom->x;
  double **normal = soil_avec->wall_normal;
  const double *distance = soil_avec->wall_distance, *h = soil_avec->smoothing_length;
  auto mirror = [&](int i) { return kind_of_type[type[i]] == NEIGHBOUR_MIRROR_WALL; };

  const auto no_plane = find_offenders(
      lmp,
      [&](int i) {
        return mirror(i) &&
            normal[i][0] * normal[i][0] + normal[i][1] * normal[i][1] + normal[i][2] * normal[i][2] == 0.0;
      },
      [&](int i, double *values) {
        for (int a = 0; a < 3; a++) values[a] = x[i][a];
        values[3] = type[i];
      });
  if (no_plane)
    SPHSoilCompat::error_all(
        lmp, FLERR,
        "Pair sph/soil: {} wall particle(s) have no wall plane (atom {} of type {} at "
        "{} {} {}); set it with 'sph_soil/set <group> wall px py pz nx ny nz'",
        no_plane.count, no_plane.first, (int) no_plane.values[3], no_plane.values[0],
        no_plane.values[1], no_plane.values[2]);
  // behind the plane: distance >= 0 (a round-off margin for particles on the plane)
  const auto in_front = find_offenders(
      lmp, [&](int i) { return mirror(i) && distance[i] < -1.0e-9 * h[i]; },
      [&](int i, double *values) {
        values[0] = distance[i];
        for (int a = 0; a < 3; a++) values[1 + a] = normal[i][a];
      });
  if (in_front)
    SPHSoilCompat::error_all(
        lmp, FLERR,
        "Pair sph/soil: {} wall particle(s) lie in front of their wall plane (atom "
        "{}: distance {} along the normal {} {} {}); the normal given to "
        "'sph_soil/set <group> wall' must point into the soil, with the wall "
        "particles behind the plane",
        in_front.count, in_front.first, in_front.values[0], in_front.values[1], in_front.values[2],
        in_front.values[3]);
}

/* ----------------------------------------------------------------------
   the fixes the walls depend on, found by what they do (sph_soil_fixes.h): those that set a
   gravity vector (the soil's body force behind extrapolated walls), and those that move wall
   particles, which may turn them (fix rigid and its variants, fix move rotate with 'update
   dipole' turn mu): then the normals go to the ghosts every step
------------------------------------------------------------------------- */

void SPHSoilWalls::init()
{
  avec = dynamic_cast<AtomVecSPHSoil *>(atom->style_match("sph/soil"));
  gravity_fixes = SPHSoilFixes::gravity_fixes(lmp);
  may_turn = false;
  if (has_mirror) {
    const int *type = atom->type;
    may_turn = SPHSoilFixes::moved_by_other_fixes(
        lmp, [&](int i) { return kind_of_type[type[i]] == NEIGHBOUR_MIRROR_WALL; });
  }
  if (any()) create_kinematics();
}

// The kinematics fix, created once (pair_granular creates its history fix the same way). With
// frictional walls it applies the interface's forces at post_force, after every other fix's:
// it is created again at the end of the list of fixes if a fix that adds forces came after it.
void SPHSoilWalls::create_kinematics()
{
  int index = modify->find_fix(kinematics_id);
  if (index >= 0 && has_friction)
    for (int k = index + 1; k < modify->nfix; k++)
      if (modify->fmask[k] & FixConst::POST_FORCE) {
        modify->delete_fix(kinematics_id);
        index = -1;
        break;
      }
  if (index < 0) modify->add_fix(kinematics_id + " all SPH_SOIL_WALLS");
  kinematics = dynamic_cast<FixSPHSoilWalls *>(modify->fix[modify->find_fix(kinematics_id)]);
  if (!kinematics)
    SPHSoilCompat::error_all(lmp, FLERR, "Pair sph/soil: fix {} is not the walls' kinematics",
                             kinematics_id);
  if (kinematics->owner && kinematics->owner != this)
    SPHSoilCompat::error_all(
        lmp, FLERR,
        "Pair sph/soil: a second instance of pair style sph/soil with walls (e.g. "
        "under pair_style hybrid) is not supported: fix {} belongs to the first",
        kinematics_id);
  kinematics->owner = this;
  std::vector<int> wall_of_type(kind_of_type.size());
  for (size_t t = 0; t < kind_of_type.size(); t++) wall_of_type[t] = kind_of_type[t] != NEIGHBOUR_SOIL;
  kinematics->set_wall_types(wall_of_type);
  if (friction) {
    kinematics->set_after_forces([this]() {
      exchange = Exchange::FRICTION;
      friction->apply(avec->smoothing_length, kinematics->interface_pressures());
      exchange = Exchange::EXTRAPOLATION;
    });
  } else {
    kinematics->set_after_forces(nullptr);
  }
}

/* ---------------------------------------------------------------------- */

namespace {
struct Extrapolate {
  SPHSoilWalls *walls;
  double *packed;
  const NeighbourList &list;
  int dimension;
  template <class Kernel> void operator()() const
  {
    if (dimension == 2) walls->extrapolate<2, Kernel>(packed, list);
    else walls->extrapolate<3, Kernel>(packed, list);
  }
};
}    // namespace

void SPHSoilWalls::prepare(double *packed, const NeighbourList &list, KernelKind kernel, int dimension,
                           bool stress_itself)
{
  packed_stress_itself = stress_itself;
  if (may_turn) comm->forward_comm_array(4, atom->mu);
  if (friction) friction->begin_step();
  if (has_extrapolated) with_kernel(kernel, Extrapolate{this, packed, list, dimension});
  if (has_drained_mirror) {
    if (dimension == 2) follow_lifting_soil<2>(packed, list);
    else follow_lifting_soil<3>(packed, list);
  }
  // (after the drained walls have moved in their rows: the planes the pair loop sees)
  if (has_mirror) {
    if (dimension == 2) find_front_most<2>(packed, list);
    else find_front_most<3>(packed, list);
  }
}

/* ----------------------------------------------------------------------
   each soil particle's farthest distance in front of the plane of a mirror wall particle it
   pairs with (soil_wall_images.h's has_image()): over this rank's pairs, then the largest over
   every rank's to the owners, and back to the ghosts. (Skipping the exchanges where no rank has
   a soil particle behind a plane, at the price of a reduction of that flag every step, cost
   more instructions on 1 rank, with flat walls and with a footing: not done.)
------------------------------------------------------------------------- */

template <int DIMENSION>
void SPHSoilWalls::find_front_most(const double *packed, const NeighbourList &list)
{
  const int nlocal = atom->nlocal, nall = nlocal + atom->nghost;
  fronts.assign(nall, NO_FRONT);
  each_mirror_pair(list, nlocal, [&](int soil, int wall) {
    const double beyond =
        beyond_wall_plane<DIMENSION>(packed + (size_t) soil * PACKED, packed + (size_t) wall * PACKED,
                                     avec->wall_normal[wall], avec->wall_distance[wall]);
    if (beyond > fronts[soil]) fronts[soil] = beyond;
  });
  exchange = Exchange::FRONTS;
  if (force->newton_pair) SPHSoilCompat::reverse_comm_pair(comm, owner);
  SPHSoilCompat::forward_comm_pair(comm, owner);
  exchange = Exchange::EXTRAPOLATION;
}

SPHSoil::MirrorPlanes SPHSoilWalls::planes() const
{
  return {avec->wall_normal, avec->wall_distance, fronts.data()};
}

/* ----------------------------------------------------------------------
   soil lifting off a drained mirror wall (soil_wall_images.h, doc/theory.rst 7.3): each such
   wall particle's gap, the least of its soil partners' gaps to its plane (0 in contact or with
   no soil near), from the pairs on every rank; the wall particle then stands, in its packed
   row, where that soil would touch it, so that its images and its pore water's flow see the
   soil in contact with the water that fills the gap
------------------------------------------------------------------------- */

template <int DIMENSION> void SPHSoilWalls::follow_lifting_soil(double *packed, const NeighbourList &list)
{
  const int nlocal = atom->nlocal, nall = nlocal + atom->nghost;
  const int *type = atom->type;
  constexpr double NONE = 1.0e300;
  gaps.assign(nall, NONE);
  each_mirror_pair(list, atom->nlocal, [&](int soil, int wall) {
    if (!drained_mirror_of_type[type[wall]]) return;
    const double *ps = packed + (size_t) soil * PACKED, *pw = packed + (size_t) wall * PACKED;
    const double beyond =
        beyond_wall_plane<DIMENSION>(ps, pw, avec->wall_normal[wall], avec->wall_distance[wall]);
    const double gap = gap_to_wall<DIMENSION>(beyond, ps[P_VOLUME]);
    if (gap < gaps[wall]) gaps[wall] = gap;
  });
  // the least over every rank's pairs: to the owners, then back to the ghosts
  exchange = Exchange::GAPS;
  if (force->newton_pair) SPHSoilCompat::reverse_comm_pair(comm, owner);
  for (int i = 0; i < nlocal; i++)
    if (gaps[i] >= NONE || gaps[i] < 0.0) gaps[i] = 0.0;
  SPHSoilCompat::forward_comm_pair(comm, owner);
  exchange = Exchange::EXTRAPOLATION;
  // the wall follows the soil by at most half the neighbour skin: its pairs with the soil then
  // stay in the neighbour list (built at a distance of the cut-off plus the skin, rebuilt before
  // any particle has moved half the skin). A soil that lifts further leaves the wall behind.
  const double reach = 0.5 * neighbor->skin;
  double widest = 0.0;
  for (int i = 0; i < nall; i++) {
    if (!drained_mirror_of_type[type[i]]) continue;
    if (!(gaps[i] > 0.0) || gaps[i] >= NONE) {
      gaps[i] = 0.0;
      continue;
    }
    if (i < nlocal) widest = std::max(widest, gaps[i]);
    const double shift = std::min(gaps[i], reach);
    const double *n = avec->wall_normal[i];
    for (int a = 0; a < DIMENSION; a++) packed[(size_t) i * PACKED + P_X + a] += shift * n[a];
  }
  // once per run of LAMMPS: the soil has left a drained wall behind (looked for where LAMMPS
  // rebuilds its neighbour lists, at least once for every half skin that a particle moves: a
  // reduction over the ranks every step would cost more than the pass)
  if (!warned_reach && neighbor->ago == 0) {
    double widest_all = 0.0;
    MPI_Allreduce(&widest, &widest_all, 1, MPI_DOUBLE, MPI_MAX, world);
    if (widest_all > reach) {
      warned_reach = true;
      if (comm->me == 0)
        error->warning(FLERR,
                       "Pair sph/soil: soil has lifted {:.4g} off a drained wall at step {}, more "
                       "than half the neighbour skin ({:.4g}): the wall no longer follows it, "
                       "and its water pushes less as the gap widens (a larger skin, command "
                       "neighbor, follows further)",
                       widest_all, update->ntimestep, reach);
    }
  }
}

/* ----------------------------------------------------------------------
   walls with boundary extrapolate (Adami, Hu & Adams 2012, with the full stress; doc/theory.rst
   4.5): a wall particle w takes the soil's stress, density and velocity, interpolated to it
   with the kernel (Shepard: weights V_s W_ws over the soil particles s within its support),
     sigma_w = sum V W sigma_s / sum V W - (g - a_w) . sum V W rho_s (x_w - x_s) / sum V W  I
   (the weight of the soil between s and w, for soil under gravity g against a wall of
   acceleration a_w), and moves, as an image of the soil, with 2 v_w - v~ (no slip). The pair
   loop then treats it as a soil particle of that state. Its packed row is overwritten here.
------------------------------------------------------------------------- */

template <int DIMENSION, class Kernel>
void SPHSoilWalls::extrapolate(double *packed, const NeighbourList &list)
{
  const int nlocal = atom->nlocal, nall = nlocal + atom->nghost;
  if (atom->nmax > nmax) {
    nmax = atom->nmax;
    memory->destroy(sums);
    memory->destroy(state);
    memory->create(sums, nmax * XSUMS, "pair:extrapolation_sums");
    memory->create(state, nmax * WSTATE, "pair:extrapolated_state");
  }
  if (nall > 0) memset(sums, 0, sizeof(double) * XSUMS * nall);
  const int *type = atom->type;
  const int *kind = kind_of_type.data();
  const int newton_pair = force->newton_pair;
  double **stress = avec->stress;
  const double *pore_pressure = avec->pore_pressure;
  constexpr double SUPPORT2 = Kernel::SUPPORT * Kernel::SUPPORT;

  const int *partners = list.partner_data();
  for (int i = 0; i < nlocal; i++) {
    const bool wall_i = kind[type[i]] == NEIGHBOUR_EXTRAPOLATED_WALL;
    // the pairs of a soil particle and an extrapolated wall particle (soil_neighbours.h)
    for (int jj = list.extrapolated_begin(i); jj < list.plain_end(i); jj++) {
      const int j = partners[jj];
      const int wall = wall_i ? i : j, soil = wall_i ? j : i;
      if (!newton_pair && wall >= nlocal) continue;
      const double *ps = packed + (size_t) soil * PACKED, *pw = packed + (size_t) wall * PACKED;
      double r2 = 0.0, rw[3] = {0.0, 0.0, 0.0};
      for (int a = 0; a < DIMENSION; a++) {
        rw[a] = pw[P_X + a] - ps[P_X + a];
        r2 += rw[a] * rw[a];
      }
      const double hij = 0.5 * (ps[P_H] + pw[P_H]);
      if (r2 >= SUPPORT2 * hij * hij) continue;
      const double weight = ps[P_VOLUME] * Kernel::value(DIMENSION, sqrt(r2), hij);
      double *sum = sums + (size_t) wall * XSUMS;
      sum[X_WEIGHT] += weight;
      // (the total stress: a saturated soil's pore pressure pushes on the wall too)
      for (int k = 0; k < 3; k++) sum[X_STRESS + k] += weight * (stress[soil][k] - pore_pressure[soil]);
      for (int k = 3; k < 6; k++) sum[X_STRESS + k] += weight * stress[soil][k];
      sum[X_DENSITY] += weight * ps[P_RHO];
      for (int a = 0; a < DIMENSION; a++) {
        sum[X_HYDROSTATIC + a] += weight * ps[P_RHO] * rw[a];
        sum[X_VELOCITY + a] += weight * ps[P_V + a];
      }
    }
  }
  if (newton_pair) SPHSoilCompat::reverse_comm_pair(comm, owner);
  extrapolated_states<DIMENSION>(packed);
}

// each owned extrapolated wall particle's state from its sums; to the ghosts; into the rows
template <int DIMENSION> void SPHSoilWalls::extrapolated_states(double *packed)
{
  const int nlocal = atom->nlocal, nall = nlocal + atom->nghost;
  const int *type = atom->type;
  const int *kind = kind_of_type.data();
  double gravity[3];
  SPHSoilFixes::gravity_sum(gravity_fixes, gravity);
  const double *rho = atom->rho;
  for (int i = 0; i < nlocal; i++) {
    if (kind[type[i]] != NEIGHBOUR_EXTRAPOLATED_WALL) continue;
    const double *sum = sums + (size_t) i * XSUMS;
    const double *vw = packed + (size_t) i * PACKED + P_V;
    double *own = state + (size_t) i * WSTATE;
    if (!(sum[X_WEIGHT] > 0.0)) {
      // no soil near: the wall particle is nobody's partner
      for (int k = 0; k < 6; k++) own[W_STRESS + k] = 0.0;
      for (int a = 0; a < 3; a++) own[W_VELOCITY + a] = vw[a];
      own[W_DENSITY] = rho[i];
      continue;
    }
    const double inv_weight = 1.0 / sum[X_WEIGHT];
    const double *acceleration = kinematics->acceleration(i);
    double hydrostatic = 0.0;
    for (int a = 0; a < DIMENSION; a++)
      hydrostatic += (gravity[a] - acceleration[a]) * sum[X_HYDROSTATIC + a];
    hydrostatic *= inv_weight;
    const double density = sum[X_DENSITY] * inv_weight;
    const double inv_density2 = packed_stress_itself ? 1.0 : 1.0 / (density * density);
    for (int k = 0; k < 6; k++)
      own[W_STRESS + k] = (sum[X_STRESS + k] * inv_weight - (k < 3 ? hydrostatic : 0.0)) * inv_density2;
    for (int a = 0; a < 3; a++)
      own[W_VELOCITY + a] = 2.0 * vw[a] - (a < DIMENSION ? sum[X_VELOCITY + a] * inv_weight : vw[a]);
    own[W_DENSITY] = density;
  }
  SPHSoilCompat::forward_comm_pair(comm, owner);

  for (int i = 0; i < nall; i++) {
    if (kind[type[i]] != NEIGHBOUR_EXTRAPOLATED_WALL) continue;
    const double *own = state + (size_t) i * WSTATE;
    double *row = packed + (size_t) i * PACKED;
    for (int k = 0; k < 6; k++) row[P_STRESS + k] = own[W_STRESS + k];
    for (int a = 0; a < 3; a++) row[P_V + a] = own[W_VELOCITY + a];
    row[P_RHO] = own[W_DENSITY];
    row[P_VOLUME] = row[P_MASS] / own[W_DENSITY];
  }
}

/* ---------------------------------------------------------------------- */

int SPHSoilWalls::pack_reverse_comm(int n, int first, double *buf)
{
  if (exchange == Exchange::FRICTION) return friction->pack_reverse_comm(n, first, buf);
  int m = 0;
  if (exchange == Exchange::GAPS || exchange == Exchange::FRONTS) {
    const std::vector<double> &values = exchange == Exchange::GAPS ? gaps : fronts;
    for (int i = first; i < first + n; i++) buf[m++] = values[i];
    return m;
  }
  for (int i = first; i < first + n; i++)
    for (int k = 0; k < XSUMS; k++) buf[m++] = sums[(size_t) i * XSUMS + k];
  return m;
}

void SPHSoilWalls::unpack_reverse_comm(int n, int *list, double *buf)
{
  if (exchange == Exchange::FRICTION) {
    friction->unpack_reverse_comm(n, list, buf);
    return;
  }
  int m = 0;
  if (exchange == Exchange::GAPS) {
    for (int k = 0; k < n; k++) gaps[list[k]] = std::min(gaps[list[k]], buf[m++]);
    return;
  }
  if (exchange == Exchange::FRONTS) {
    for (int k = 0; k < n; k++) fronts[list[k]] = std::max(fronts[list[k]], buf[m++]);
    return;
  }
  for (int k = 0; k < n; k++)
    for (int c = 0; c < XSUMS; c++) sums[(size_t) list[k] * XSUMS + c] += buf[m++];
}

int SPHSoilWalls::pack_forward_comm(int n, int *list, double *buf)
{
  if (exchange == Exchange::FRICTION) return friction->pack_forward_comm(n, list, buf);
  int m = 0;
  if (exchange == Exchange::GAPS || exchange == Exchange::FRONTS) {
    const std::vector<double> &values = exchange == Exchange::GAPS ? gaps : fronts;
    for (int k = 0; k < n; k++) buf[m++] = values[list[k]];
    return m;
  }
  for (int k = 0; k < n; k++)
    for (int c = 0; c < WSTATE; c++) buf[m++] = state[(size_t) list[k] * WSTATE + c];
  return m;
}

void SPHSoilWalls::unpack_forward_comm(int n, int first, double *buf)
{
  if (exchange == Exchange::FRICTION) {
    friction->unpack_forward_comm(n, first, buf);
    return;
  }
  int m = 0;
  if (exchange == Exchange::GAPS || exchange == Exchange::FRONTS) {
    std::vector<double> &values = exchange == Exchange::GAPS ? gaps : fronts;
    for (int i = first; i < first + n; i++) values[i] = buf[m++];
    return;
  }
  for (int i = first; i < first + n; i++)
    for (int c = 0; c < WSTATE; c++) state[(size_t) i * WSTATE + c] = buf[m++];
}

double SPHSoilWalls::memory_usage() const
{
  return (double) nmax * (XSUMS + WSTATE) * sizeof(double) + (double) (gaps.capacity() + fronts.capacity()) * sizeof(double) +
      (friction ? friction->memory_usage() : 0.0);
}

/* ----------------------------------------------------------------------
   owned soil particles behind the plane of every mirror wall particle they paired with at the
   last pair loop, over every rank's pairs (find_front_most()): soil that crossed a wall. (Not
   one behind one plane and in front of another: it stands beside the other face of a body, past
   a convex corner.)
------------------------------------------------------------------------- */

bigint SPHSoilWalls::soil_behind_planes() const
{
  if (!has_mirror) return 0;
  const int nlocal = std::min(atom->nlocal, (int) fronts.size());
  bigint count = 0;
  for (int s = 0; s < nlocal; s++) count += fronts[s] > NO_FRONT && !(fronts[s] > 0.0);
  return count;
}
