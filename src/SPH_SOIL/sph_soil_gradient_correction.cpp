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
#include "sph_soil_compat.h"

#include <algorithm>

using namespace LAMMPS_NS;
using namespace SPHSoil;

SPHSoilGradientCorrection::SPHSoilGradientCorrection(LAMMPS *lmp, Pair *owner) :
    Pointers(lmp), owner(owner), exchange(NONE)
{
}

/* ---------------------------------------------------------------------- */

namespace {
struct Moments {
  SPHSoilGradientCorrection *correction;
  const double *packed;
  const NeighbourList &list;
  const int *wall_kind;
  int dimension;
  template <class Kernel> void operator()() const
  {
    if (dimension == 2) correction->moment_sums<2, Kernel>(packed, list, wall_kind);
    else correction->moment_sums<3, Kernel>(packed, list, wall_kind);
  }
};
}    // namespace

void SPHSoilGradientCorrection::correct(double *packed, const NeighbourList &list,
                                        const int *wall_kind, KernelKind kernel, int dimension)
{
  const int nlocal = atom->nlocal, nall = nlocal + atom->nghost;
  const int *type = atom->type;
  with_kernel(kernel, Moments{this, packed, list, wall_kind, dimension});
  if (force->newton_pair) {
    exchange = MOMENT;
    SPHSoilCompat::reverse_comm_pair(comm, owner);
    exchange = NONE;
  }
  factors.assign(nall, 1.0);
  for (int i = 0; i < nlocal; i++) {
    moments[i] /= dimension;
    if (wall_kind[type[i]] == NEIGHBOUR_SOIL) factors[i] = gradient_correction(moments[i]);
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
   each pair once: a plain pair's shares to both (each the other's volume); a soil particle
   and a mirror wall particle: the soil's, with the wall particle's own volume (the space its
   image fills)
------------------------------------------------------------------------- */

template <int DIMENSION, class Kernel>
void SPHSoilGradientCorrection::moment_sums(const double *packed, const NeighbourList &list,
                                            const int *wall_kind)
{
  const int nlocal = atom->nlocal, nall = nlocal + atom->nghost;
  const int newton_pair = force->newton_pair;
  const int *type = atom->type;
  moments.assign(newton_pair ? nall : nlocal, 0.0);
  const int *partners = list.partner_data();
  for (int i = 0; i < nlocal; i++) {
    const double *pi = packed + (size_t) i * PACKED;
    const int plain_end = list.plain_end(i);
    for (int jj = list.first(i); jj < plain_end; jj++) {
      const int j = partners[jj];
      const double *pj = packed + (size_t) j * PACKED;
      PairGeometry g;
      if (!pair_geometry<DIMENSION, Kernel>(pi + P_X, pi[P_H], pj, g)) continue;
      moments[i] += first_moment_term(pj[P_VOLUME], g.factor, g.r2);
      if (newton_pair || j < nlocal) moments[j] += first_moment_term(pi[P_VOLUME], g.factor, g.r2);
    }
    const bool wall_i = wall_kind[type[i]] == NEIGHBOUR_MIRROR_WALL;
    for (int jj = plain_end; jj < list.end(i); jj++) {
      const int j = partners[jj];
      const double *pj = packed + (size_t) j * PACKED;
      PairGeometry g;
      if (!pair_geometry<DIMENSION, Kernel>(pi + P_X, pi[P_H], pj, g)) continue;
      const int soil = wall_i ? j : i;
      const double *pw = wall_i ? pi : pj;
      if (newton_pair || soil < nlocal)
        moments[soil] += first_moment_term(pw[P_VOLUME], g.factor, g.r2);
    }
  }
}

/* ---------------------------------------------------------------------- */

int SPHSoilGradientCorrection::pack_forward_comm(int n, int *list, double *buf)
{
  for (int k = 0; k < n; k++) buf[k] = factors[list[k]];
  return n;
}

void SPHSoilGradientCorrection::unpack_forward_comm(int n, int first, double *buf)
{
  for (int k = 0; k < n; k++) factors[first + k] = buf[k];
}

int SPHSoilGradientCorrection::pack_reverse_comm(int n, int first, double *buf)
{
  for (int k = 0; k < n; k++) buf[k] = moments[first + k];
  return n;
}

void SPHSoilGradientCorrection::unpack_reverse_comm(int n, int *list, double *buf)
{
  for (int k = 0; k < n; k++) moments[list[k]] += buf[k];
}
