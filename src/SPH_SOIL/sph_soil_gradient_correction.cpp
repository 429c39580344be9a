/* ----------------------------------------------------------------------
   SPH_SOIL package for LAMMPS: the gradient correction of pair_style sph/soil (see the header)
------------------------------------------------------------------------- */

#include "sph_soil_gradient_correction.h"

#include "atom.h"
#include "comm.h"
#include "force.h"
#include "pair.h"
#include "soil_gradient_correction.h"
#include "soil_packed_rows.h"
#include "soil_wall_images.h"
#include "sph_soil_compat.h"

#include <algorithm>
#include <cmath>

using namespace LAMMPS_NS;
using namespace SPHSoil;

SPHSoilGradientCorrection::SPHSoilGradientCorrection(LAMMPS *lmp, Pair *owner, bool full) :
    Pointers(lmp), owner(owner), full_tensor(full), exchange(NONE)
{
}

/* ---------------------------------------------------------------------- */

namespace {
struct Moments {
  SPHSoilGradientCorrection *correction;
  const double *packed;
  const NeighbourList &list;
  const int *wall_kind, *slips;
  MirrorPlanes planes;
  int dimension;
  template <class Kernel> void operator()() const
  {
    // (the scalar correction's pass compiled without the tensors' sums)
    if (correction->full()) {
      if (dimension == 2) correction->moment_sums<2, Kernel, true>(packed, list, wall_kind, slips, planes);
      else correction->moment_sums<3, Kernel, true>(packed, list, wall_kind, slips, planes);
    } else {
      if (dimension == 2) correction->moment_sums<2, Kernel, false>(packed, list, wall_kind, slips, planes);
      else correction->moment_sums<3, Kernel, false>(packed, list, wall_kind, slips, planes);
    }
  }
};
}    // namespace

void SPHSoilGradientCorrection::correct(double *packed, const NeighbourList &list,
                                        const int *wall_kind, const int *slips,
                                        const MirrorPlanes &planes, KernelKind kernel,
                                        int dimension)
{
  const int nlocal = atom->nlocal, nall = nlocal + atom->nghost;
  const int *type = atom->type;
  with_kernel(kernel, Moments{this, packed, list, wall_kind, slips, planes, dimension});
  if (force->newton_pair) {
    exchange = MOMENT;
    SPHSoilCompat::reverse_comm_pair(comm, owner);
    exchange = NONE;
  }
  factors.assign(nall, 1.0);
  if (full_tensor) corrections.assign((size_t) nall * PER_ATOM, 0.0);
  for (int i = 0; i < nlocal; i++) {
    moments[i] /= dimension;
    const bool soil = wall_kind[type[i]] == NEIGHBOUR_SOIL;
    if (soil) factors[i] = gradient_correction(moments[i]);
    if (full_tensor) tensor_correction(i, soil, factors[i], dimension);
  }
  exchange = FACTOR;
  SPHSoilCompat::forward_comm_pair(comm, owner);
  exchange = NONE;
  for (int i = 0; i < nall; i++) {
    double *stress = packed + (size_t) i * PACKED + P_STRESS;
    for (int k = 0; k < 6; k++) stress[k] *= factors[i];
  }
}

/* ----------------------------------------------------------------------
   owned atom i's velocity gradient correction from its sums (a wall particle's: the identity,
   its rates are not used)
------------------------------------------------------------------------- */

void SPHSoilGradientCorrection::tensor_correction(int i, bool soil, double factor, int dimension)
{
  const double *sum = &tensors[(size_t) i * PER_ATOM];
  double *out = &corrections[(size_t) i * PER_ATOM];
  if (!soil) {
    for (int a = 0; a < dimension; a++) out[FULL_TENSOR + a] = out[IMAGE_TENSOR + a] = 1.0;
    return;
  }
  double plain[6];
  for (int k = 0; k < 6; k++) plain[k] = sum[FULL_TENSOR + k] - sum[IMAGE_TENSOR + k];
  double norm = 0.0;
  for (int a = 0; a < 3; a++) norm += sum[IMAGE_NORMAL + a] * sum[IMAGE_NORMAL + a];
  norm = std::sqrt(norm);
  if (dimension == 2) {
    velocity_gradient_correction<2>(sum + FULL_TENSOR, factor, out + FULL_TENSOR);
    velocity_gradient_correction<2>(plain, factor, out + IMAGE_TENSOR);
  } else {
    velocity_gradient_correction<3>(sum + FULL_TENSOR, factor, out + FULL_TENSOR);
    velocity_gradient_correction<3>(plain, factor, out + IMAGE_TENSOR);
  }
  // (without smooth wall images the plain tensor is the full one, and the normal 0)
  for (int a = 0; a < 3; a++) out[IMAGE_NORMAL + a] = norm > 0.0 ? sum[IMAGE_NORMAL + a] / norm : 0.0;
}

/* ----------------------------------------------------------------------
   each pair once: a plain pair's shares to both (each the other's volume); a soil particle
   and a mirror wall particle: the soil's, with the wall particle's own volume (the space its
   image fills)
------------------------------------------------------------------------- */

template <int DIMENSION, class Kernel, bool FULL>
void SPHSoilGradientCorrection::moment_sums(const double *packed, const NeighbourList &list,
                                            const int *wall_kind, const int *slips,
                                            const MirrorPlanes &planes)
{
  const int nlocal = atom->nlocal, nall = nlocal + atom->nghost;
  const int newton_pair = force->newton_pair;
  const int *type = atom->type;
  const int nsums = newton_pair ? nall : nlocal;
  moments.assign(nsums, 0.0);
  if (FULL) tensors.assign((size_t) nsums * PER_ATOM, 0.0);
  // a partner's share to i's sums (its volume); a smooth wall's image also to the image sums
  auto add = [&](int i, double volume, const PairGeometry &g, const double *smooth_normal) {
    const double share = first_moment_term(volume, g.factor, g.r2);
    moments[i] += share;
    if (!FULL) return;
    double *t = &tensors[(size_t) i * PER_ATOM];
    first_moment_tensor_term(volume, g.factor, g.dx, t + FULL_TENSOR);
    if (!smooth_normal) return;
    first_moment_tensor_term(volume, g.factor, g.dx, t + IMAGE_TENSOR);
    for (int a = 0; a < DIMENSION; a++) t[IMAGE_NORMAL + a] += share * smooth_normal[a];
  };
  const int *partners = list.partner_data();
  for (int i = 0; i < nlocal; i++) {
    const double *pi = packed + (size_t) i * PACKED;
    const int plain_end = list.plain_end(i);
    for (int jj = list.first(i); jj < plain_end; jj++) {
      const int j = partners[jj];
      const double *pj = packed + (size_t) j * PACKED;
      PairGeometry g;
      if (!pair_geometry<DIMENSION, Kernel>(pi + P_X, pi[P_H], pj, g)) continue;
      add(i, pj[P_VOLUME], g, nullptr);
      // (dx dx is the same seen from j)
      if (newton_pair || j < nlocal) add(j, pi[P_VOLUME], g, nullptr);
    }
    const bool wall_i = wall_kind[type[i]] == NEIGHBOUR_MIRROR_WALL;
    for (int jj = plain_end; jj < list.end(i); jj++) {
      const int j = partners[jj];
      const double *pj = packed + (size_t) j * PACKED;
      PairGeometry g;
      if (!pair_geometry<DIMENSION, Kernel>(pi + P_X, pi[P_H], pj, g)) continue;
      const int soil = wall_i ? j : i;
      const double *pw = wall_i ? pi : pj;
      const int wall = wall_i ? i : j;
      // (where the wall particle stands for no image of the soil particle, it adds nothing, as
      // in the pair loop: soil_wall_images.h)
      if (!has_image<DIMENSION>(wall_i ? pj : pi, pw, planes.normal[wall], planes.distance[wall],
                                planes.front_most[soil]))
        continue;
      const bool smooth = FULL && slips[type[wall]] != SLIP_NONE;
      if (newton_pair || soil < nlocal) add(soil, pw[P_VOLUME], g, smooth ? planes.normal[wall] : nullptr);
    }
  }
}

/* ---------------------------------------------------------------------- */

// per atom: the factor (and with full_tensor its PER_ATOM numbers) forward, the moment (and its
// sums) in reverse

int SPHSoilGradientCorrection::pack_forward_comm(int n, int *list, double *buf)
{
  int m = 0;
  for (int k = 0; k < n; k++) {
    buf[m++] = factors[list[k]];
    if (full_tensor)
      for (int c = 0; c < PER_ATOM; c++) buf[m++] = corrections[(size_t) list[k] * PER_ATOM + c];
  }
  return m;
}

void SPHSoilGradientCorrection::unpack_forward_comm(int n, int first, double *buf)
{
  int m = 0;
  for (int k = 0; k < n; k++) {
    factors[first + k] = buf[m++];
    if (full_tensor)
      for (int c = 0; c < PER_ATOM; c++) corrections[(size_t) (first + k) * PER_ATOM + c] = buf[m++];
  }
}

int SPHSoilGradientCorrection::pack_reverse_comm(int n, int first, double *buf)
{
  int m = 0;
  for (int k = 0; k < n; k++) {
    buf[m++] = moments[first + k];
    if (full_tensor)
      for (int c = 0; c < PER_ATOM; c++) buf[m++] = tensors[(size_t) (first + k) * PER_ATOM + c];
  }
  return m;
}

void SPHSoilGradientCorrection::unpack_reverse_comm(int n, int *list, double *buf)
{
  int m = 0;
  for (int k = 0; k < n; k++) {
    moments[list[k]] += buf[m++];
    if (full_tensor)
      for (int c = 0; c < PER_ATOM; c++) tensors[(size_t) list[k] * PER_ATOM + c] += buf[m++];
  }
}
