/* ----------------------------------------------------------------------
   SPH_SOIL package for LAMMPS: the stress diffusion of pair_style sph/soil (see the header)
------------------------------------------------------------------------- */

#include "sph_soil_stress_diffusion.h"

#include "atom.h"
#include "atom_vec_sph_soil.h"
#include "comm.h"
#include "force.h"
#include "pair.h"
#include "soil_packed_rows.h"
#include "soil_stress_diffusion.h"
#include "sph_soil_compat.h"

#include <algorithm>

using namespace LAMMPS_NS;
using namespace SPHSoil;

constexpr int SPHSoilStressDiffusion::COMM_SIZE;
constexpr double SPHSoilStressDiffusion::SMALLEST_DETERMINANT;

SPHSoilStressDiffusion::SPHSoilStressDiffusion(LAMMPS *lmp, Pair *owner) :
    Pointers(lmp), owner(owner), avec(nullptr), exchange(NONE), gradient_width(0), moment(0), components(0)
{
  static_assert(gradient_size<3>() <= COMM_SIZE, "the exchanges' size");
}

void SPHSoilStressDiffusion::init(const std::vector<double> &coefficient_of_type)
{
  avec = dynamic_cast<AtomVecSPHSoil *>(atom->style_match("sph/soil"));
  coefficient = coefficient_of_type;
}

/* ---------------------------------------------------------------------- */

namespace {
struct Diffuse {
  SPHSoilStressDiffusion *diffusion;
  const double *packed;
  const NeighbourList &list;
  int dimension;
  template <class Kernel> void operator()() const
  {
    if (dimension == 2) diffusion->diffuse_sums<2, Kernel>(packed, list);
    else diffusion->diffuse_sums<3, Kernel>(packed, list);
  }
};
}    // namespace

void SPHSoilStressDiffusion::diffuse(const double *packed, const NeighbourList &list,
                                     KernelKind kernel, int dimension)
{
  gradient_width = dimension == 2 ? gradient_size<2>() : gradient_size<3>();
  moment = dimension == 2 ? moment_size<2>() : moment_size<3>();
  components = dimension == 2 ? diffused_components<2>() : diffused_components<3>();
  with_kernel(kernel, Diffuse{this, packed, list, dimension});
}

/* ----------------------------------------------------------------------
   the two passes (see the header); each pair once from the half list, its shares to both
------------------------------------------------------------------------- */

template <int DIMENSION, class Kernel>
void SPHSoilStressDiffusion::diffuse_sums(const double *packed, const NeighbourList &list)
{
  constexpr int D = DIMENSION, N = gradient_size<D>(), M = moment_size<D>();
  constexpr int C = diffused_components<D>();
  const int nlocal = atom->nlocal, nall = nlocal + atom->nghost;
  const int newton_pair = force->newton_pair;
  const int *type = atom->type;
  double **stress = avec->stress;
  const int *partners = list.partner_data();
  const double *coefficient_of_type = coefficient.data();

  // 1. M and g of every atom; the diffused pairs kept (partner, separation, factor, r^2, h)
  //    for the second pass, which then needs neither the list nor the kernel again
  gradients.assign((size_t) nall * N, 0.0);
  pairs.clear();
  pair_start.assign(nlocal + 1, 0);
  for (int i = 0; i < nlocal; i++) {
    pair_start[i] = (int) pairs.size();
    const int itype = type[i];
    if (coefficient_of_type[itype] <= 0.0) continue;
    const double *pi = packed + (size_t) i * PACKED;
    const double *si = stress[i];
    double *gi = &gradients[(size_t) i * N];
    const double vi = pi[P_VOLUME];
    for (int jj = list.first(i); jj < list.end(i); jj++) {
      const int j = partners[jj];
      if (type[j] != itype) continue;
      const double *pj = packed + (size_t) j * PACKED;
      PairGeometry g;
      if (!pair_geometry<D, Kernel>(pi + P_X, pi[P_H], pj, g)) continue;
      DiffusedPair pair;
      pair.partner = j;
      for (int a = 0; a < D; a++) pair.dx[a] = g.dx[a];
      pair.r2 = g.r2;
      pair.h = g.hij;
      pair.factor = g.factor;
      pairs.push_back(pair);
      const double *sj = stress[j];
      double difference[C], pair_sums[N];
      for (int k = 0; k < C; k++) difference[k] = sj[k] - si[k];
      for (int k = 0; k < N; k++) pair_sums[k] = 0.0;
      gradient_pair_sums<D>(g.dx, g.factor, difference, pair_sums);
      const double vj = pj[P_VOLUME];
      for (int k = 0; k < N; k++) gi[k] += vj * pair_sums[k];
      if (newton_pair || j < nlocal) {
        double *gj = &gradients[(size_t) j * N];
        for (int k = 0; k < N; k++) gj[k] += vi * pair_sums[k];
      }
    }
  }
  pair_start[nlocal] = (int) pairs.size();
  if (newton_pair) {
    exchange = SUMS;
    SPHSoilCompat::reverse_comm_pair(comm, owner);
    exchange = NONE;
  }
  valid.assign(nall, 0.0);
  for (int i = 0; i < nlocal; i++)
    if (coefficient_of_type[type[i]] > 0.0)
      valid[i] = renormalised_gradient<D>(&gradients[(size_t) i * N], SMALLEST_DETERMINANT) ? 1.0 : 0.0;
  exchange = GRADIENTS;
  SPHSoilCompat::forward_comm_pair(comm, owner);
  exchange = NONE;

  // 2. the rates, over the kept pairs
  rates.assign((size_t) (newton_pair ? nall : nlocal) * VOIGT, 0.0);
  for (int i = 0; i < nlocal; i++) {
    if (valid[i] == 0.0) continue;
    const double *gi = &gradients[(size_t) i * N + M];
    double *ri = &rates[(size_t) i * VOIGT];
    const double coefficient_i = coefficient_of_type[type[i]];
    const double vi = packed[(size_t) i * PACKED + P_VOLUME];
    for (int n = pair_start[i]; n < pair_start[i + 1]; n++) {
      const DiffusedPair &pair = pairs[n];
      const int j = pair.partner;
      if (valid[j] == 0.0) continue;
      double rate[C];
      stress_diffusion_pair<D>(stress[i], stress[j], gi, &gradients[(size_t) j * N + M], pair.dx,
                               pair.r2, pair.h, pair.factor, coefficient_i * pair.h, rate);
      const double vj = packed[(size_t) j * PACKED + P_VOLUME];
      for (int k = 0; k < C; k++) ri[k] += vj * rate[k];
      if (newton_pair || j < nlocal) {
        double *rj = &rates[(size_t) j * VOIGT];
        for (int k = 0; k < C; k++) rj[k] -= vi * rate[k];
      }
    }
  }
  if (newton_pair) {
    exchange = RATES;
    SPHSoilCompat::reverse_comm_pair(comm, owner);
    exchange = NONE;
  }
}

/* ----------------------------------------------------------------------
   the exchanges: the sums and the rates go back to the owners, the gradients (and whether they
   are trusted) to the ghosts
------------------------------------------------------------------------- */

int SPHSoilStressDiffusion::pack_forward_comm(int n, int *list, double *buf)
{
  const int m = gradient_width - moment;
  int k = 0;
  for (int i = 0; i < n; i++) {
    const double *g = &gradients[(size_t) list[i] * gradient_width + moment];
    for (int c = 0; c < m; c++) buf[k++] = g[c];
    buf[k++] = valid[list[i]];
  }
  return k;
}

void SPHSoilStressDiffusion::unpack_forward_comm(int n, int first, double *buf)
{
  const int m = gradient_width - moment;
  int k = 0;
  for (int i = first; i < first + n; i++) {
    double *g = &gradients[(size_t) i * gradient_width + moment];
    for (int c = 0; c < m; c++) g[c] = buf[k++];
    valid[i] = buf[k++];
  }
}

int SPHSoilStressDiffusion::pack_reverse_comm(int n, int first, double *buf)
{
  const bool sums = exchange == SUMS;
  const int width = sums ? gradient_width : components;
  int k = 0;
  for (int i = first; i < first + n; i++) {
    const double *from = sums ? &gradients[(size_t) i * gradient_width] : &rates[(size_t) i * VOIGT];
    for (int c = 0; c < width; c++) buf[k++] = from[c];
  }
  return k;
}

void SPHSoilStressDiffusion::unpack_reverse_comm(int n, int *list, double *buf)
{
  const bool sums = exchange == SUMS;
  const int width = sums ? gradient_width : components;
  int k = 0;
  for (int i = 0; i < n; i++) {
    double *to = sums ? &gradients[(size_t) list[i] * gradient_width] : &rates[(size_t) list[i] * VOIGT];
    for (int c = 0; c < width; c++) to[c] += buf[k++];
  }
}
