/* -*- c++ -*- ----------------------------------------------------------
   SPH_SOIL package: the pair loop's packed rows (pure, no LAMMPS).

   pair_style sph/soil copies the per-atom inputs of its sums once per step into
   one row of PACKED doubles per owned and ghost atom, so that a neighbour costs
   two cache lines instead of a load from each of eight arrays: position,
   velocity (a soil particle's estimate of v(t + dt); a wall particle's own, or
   for an extrapolated wall its image's), stress / rho^2 (Voigt), volume m / rho,
   mass, density, h. The walls' code reads and writes the same rows. The stress
   is the total stress: a saturated soil's effective stress less its pore pressure.
------------------------------------------------------------------------- */

#ifndef LMP_SOIL_PACKED_ROWS_H
#define LMP_SOIL_PACKED_ROWS_H

#include <algorithm>
#include <cfloat>
#include <cmath>

namespace SPHSoil {

enum PackedRow { P_X = 0, P_V = 3, P_STRESS = 6, P_VOLUME = 12, P_MASS = 13, P_RHO = 14, P_H = 15,
                 PACKED = 16 };

struct PairGeometry {
  double dx[3], r2, r, inv_h, hij, factor;
};

/* ----------------------------------------------------------------------
   a pair's separation dx = x_i - x_j, r, h_ij and gradient factor (grad W = factor dx), from
   i's position and h and j's packed row; false beyond the support (the list has a skin)
------------------------------------------------------------------------- */

template <int DIMENSION, class Kernel>
inline bool pair_geometry(const double *xi, double hi, const double *pj, PairGeometry &g)
{
  g.dx[0] = xi[0] - pj[P_X];
  g.dx[1] = xi[1] - pj[P_X + 1];
  g.dx[2] = DIMENSION == 3 ? xi[2] - pj[P_X + 2] : 0.0;
  g.r2 = g.dx[0] * g.dx[0] + g.dx[1] * g.dx[1] + g.dx[2] * g.dx[2];
  g.hij = 0.5 * (hi + pj[P_H]);
  constexpr double SUPPORT2 = Kernel::SUPPORT * Kernel::SUPPORT;
  if (g.r2 >= SUPPORT2 * g.hij * g.hij) return false;
  // the square root and the two divisions are independent of each other, so that the
  // processor overlaps them; at r = 0 (coinciding particles) q = 0 takes the kernel's inner
  // piece, and 1/max(r^2, DBL_MIN) keeps the unused h/r finite (0) without a branch
  g.r = std::sqrt(g.r2);
  g.inv_h = 1.0 / g.hij;
  const double inv_r2 = 1.0 / std::max(g.r2, DBL_MIN);
  g.factor = Kernel::template gradient_factor_inside<DIMENSION>(g.r, g.inv_h, g.hij * g.r * inv_r2);
  return true;
}

}    // namespace SPHSoil

#endif
