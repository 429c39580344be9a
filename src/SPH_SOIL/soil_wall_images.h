/* -*- c++ -*- ----------------------------------------------------------
   SPH_SOIL package: the image of a mirror wall particle (pure, inline).

   Morris-type wall particles with Bui's treatment (Bui 2008; doc/theory.rst
   4.3, 4.4): for a soil particle s, a wall particle w on its side of a plane
   (unit normal n into the soil, w at distance d_w behind it) stands for the
   image of s: relative to the wall it moves with -(d_w/d_s) (v_s - v_w),
   limited so that v_s - v_image = beta (v_s - v_w), beta = min(1.5,
   1 + d_w/d_s), and it has the density of s and its stress (no slip), the
   stress's mirror image in the plane (free slip: the normal part of the
   velocity only) or between the two (Coulomb friction). What the pair then
   exchanges is soil_pair_terms.h's.
------------------------------------------------------------------------- */

#ifndef LMP_SOIL_WALL_IMAGES_H
#define LMP_SOIL_WALL_IMAGES_H

#include "soil_packed_rows.h"
#include "soil_tensor.h"

#include <cmath>

namespace SPHSoil {

// how a wall holds the soil along its surface, per wall type
enum WallSlipCode { SLIP_NONE = 0, SLIP_FREE = 1, SLIP_FRICTION = 2 };

// R sigma R with R = I - 2 n n^T, the mirror image of a stress in the plane of unit normal n:
// it keeps the normal stresses and flips the shear between the normal and the plane. Also
// returns the traction's normal part n.sigma.n and its shear part |sigma n - (n.sigma.n) n|.
// Voigt order xx yy zz xy xz yz.
inline void mirror_stress(const double stress[6], const double n[3], double mirrored[6],
                          double &normal_traction, double &shear_traction)
{
  double sn[3];    // sigma n
  for (int a = 0; a < 3; a++)
    sn[a] = stress[voigt_index(a, 0)] * n[0] + stress[voigt_index(a, 1)] * n[1] +
        stress[voigt_index(a, 2)] * n[2];
  const double nsn = n[0] * sn[0] + n[1] * sn[1] + n[2] * sn[2];
  for (int k = 0; k < 6; k++) {
    const int a = VOIGT_ROW[k], b = VOIGT_COL[k];
    mirrored[k] = stress[k] - 2.0 * (n[a] * sn[b] + sn[a] * n[b]) + 4.0 * n[a] * n[b] * nsn;
  }
  double shear2 = 0.0;
  for (int a = 0; a < 3; a++) shear2 += (sn[a] - nsn * n[a]) * (sn[a] - nsn * n[a]);
  normal_traction = nsn;
  shear_traction = std::sqrt(shear2);
}

// sigma + R sigma R: the stress sum of a soil particle and its image behind a smooth
// (free-slip) wall. The wall carries no shear traction, as the mirrored velocity
// v - 2 (v.n) n has no tangential slip relative to the soil.
inline void mirrored_stress_sum(const double stress[6], const double n[3], double sum[6])
{
  double mirrored[6], normal_traction, shear_traction;
  mirror_stress(stress, n, mirrored, normal_traction, shear_traction);
  for (int k = 0; k < 6; k++) sum[k] = stress[k] + mirrored[k];
}

// Coulomb friction on a wall, between free slip and no slip (doc/theory.rst 4.4): the image's
// stress is the mirror image plus the share lambda of the soil particle's shear,
//   sum = sigma + R sigma R + lambda (sigma - R sigma R),
// lambda = min(1, mu (-sigma_nn) / |sigma_nt|), 0 when the soil pulls on the wall
// (sigma_nn >= 0); so the traction the wall transmits, lambda |sigma_nt|, never exceeds
// mu (-sigma_nn). lambda = 1 (the soil sticks) is the no-slip image's 2 sigma, mu = 0 the
// free-slip image. Returns lambda. (sigma may be scaled, e.g. sigma / rho^2: lambda is not.)
inline double frictional_stress_sum(const double stress[6], const double n[3], double mu,
                                    double sum[6])
{
  double mirrored[6], normal_traction, shear_traction;
  mirror_stress(stress, n, mirrored, normal_traction, shear_traction);
  const double limit = normal_traction < 0.0 ? -mu * normal_traction : 0.0;
  const double share = shear_traction <= limit ? 1.0 : limit / shear_traction;
  for (int k = 0; k < 6; k++)
    sum[k] = stress[k] + mirrored[k] + share * (stress[k] - mirrored[k]);
  return share;
}

// The image of mirror wall particle w for soil particle s, from their packed rows
// (soil_packed_rows.h): the velocity difference dv = v_s - v_image, the stress sum
// sigma_s / rho_s^2 + sigma_image / rho_s^2, the approach dv . x_sw and the part of it that the
// artificial viscosity sees (behind a frictional wall the normal part only: with the sticking
// velocity the viscosity would add a drag across the wall that mu does not bound; a rough gate
// lifted at 1 m/s got 6 times the at-rest force in its first step). `separation` = x_s - x_w.
struct MirrorImage {
  double dv[3];
  double stress_sum[6];
  double approach, viscous_approach;
};

template <int DIMENSION>
inline void mirror_image(const double *ps, const double *pw, const double normal[3],
                         double wall_distance, const double separation[3], int slip,
                         double friction, MirrorImage &image)
{
  constexpr int D = DIMENSION;
  // the soil particle's distance beyond the wall plane
  double ds = -wall_distance;
  for (int a = 0; a < D; a++) ds += separation[a] * normal[a];
  const double beta = ds > 0.0 ? std::fmin(1.5, 1.0 + wall_distance / ds) : 1.5;
  // the image's stress: the soil particle's (no slip), its mirror image (free slip: no shear
  // traction), or the mirror image plus the share of the shear that Coulomb's law allows
  // (friction); its velocity: the whole relative velocity while the soil sticks, else the
  // normal part
  const double *ss = ps + P_STRESS;
  double *stress_sum = image.stress_sum;
  for (int k = 0; k < 6; k++) stress_sum[k] = 0.0;
  double share = 1.0;    // of the tangential velocity
  if (slip == SLIP_NONE) {
    for (int a = 0; a < D; a++)
      for (int b = a; b < D; b++) stress_sum[voigt_index(a, b)] = 2.0 * ss[voigt_index(a, b)];
  } else if (slip == SLIP_FREE) {
    mirrored_stress_sum(ss, normal, stress_sum);
    share = 0.0;
  } else {
    share = frictional_stress_sum(ss, normal, friction, stress_sum);
  }
  double relative[3], vn = 0.0;
  for (int a = 0; a < D; a++) {
    relative[a] = beta * (ps[P_V + a] - pw[P_V + a]);
    vn += relative[a] * normal[a];
  }
  double approach = 0.0;
  for (int a = 0; a < 3; a++) image.dv[a] = 0.0;
  for (int a = 0; a < D; a++) {
    image.dv[a] = share == 1.0 ? relative[a] : vn * normal[a];
    approach += image.dv[a] * separation[a];
  }
  image.approach = approach;
  image.viscous_approach = approach;
  if (slip == SLIP_FRICTION) {
    double normal_distance = 0.0;
    for (int a = 0; a < D; a++) normal_distance += separation[a] * normal[a];
    image.viscous_approach = vn * normal_distance;
  }
}

}    // namespace SPHSoil

#endif
