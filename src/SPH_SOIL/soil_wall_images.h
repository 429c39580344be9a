/* -*- c++ -*- ----------------------------------------------------------
   SPH_SOIL package: the image of a mirror wall particle (pure, inline).

   Morris-type wall particles with Bui's treatment (Bui 2008; doc/theory.rst
   4.3, 4.4): for a soil particle s, a wall particle w on its side of a plane
   (unit normal n into the soil, w at distance d_w behind it) stands for the
   image of s: relative to the wall it moves with -(d_w/d_s) (v_s - v_w),
   limited so that v_s - v_image = beta (v_s - v_w), beta = min(1.5,
   1 + d_w/d_s), and it has the density of s and its stress (no slip), the
   stress's mirror image in the plane (free slip and Coulomb friction: the
   normal part of the velocity only; the pair then pushes along the normal
   only, and a frictional wall's tangential force is soil_wall_friction.h's).
   What the pair exchanges is soil_pair_terms.h's.
------------------------------------------------------------------------- */

#ifndef LMP_SOIL_WALL_IMAGES_H
#define LMP_SOIL_WALL_IMAGES_H

#include "soil_packed_rows.h"
#include "soil_tensor.h"

#include <cmath>

namespace SPHSoil {

// how a wall holds the soil along its surface, per wall type
enum WallSlipCode { SLIP_NONE = 0, SLIP_FREE = 1, SLIP_FRICTION = 2 };

// sigma + R sigma R with R = I - 2 n n^T: the stress sum of a soil particle and its image behind
// a smooth (free-slip) wall. R sigma R, the mirror image of a stress in the plane of unit normal
// n, keeps the normal stresses and flips the shear between the normal and the plane, so the wall
// carries no shear traction, as the mirrored velocity v - 2 (v.n) n has no tangential slip
// relative to the soil. Voigt order xx yy zz xy xz yz.
inline void mirrored_stress_sum(const double stress[6], const double n[3], double sum[6])
{
  double sn[3];    // sigma n
  for (int a = 0; a < 3; a++)
    sn[a] = stress[voigt_index(a, 0)] * n[0] + stress[voigt_index(a, 1)] * n[1] +
        stress[voigt_index(a, 2)] * n[2];
  const double nsn = n[0] * sn[0] + n[1] * sn[1] + n[2] * sn[2];
  for (int k = 0; k < 6; k++) {
    const int a = VOIGT_ROW[k], b = VOIGT_COL[k];
    const double mirrored = stress[k] - 2.0 * (n[a] * sn[b] + sn[a] * n[b]) + 4.0 * n[a] * n[b] * nsn;
    sum[k] = stress[k] + mirrored;
  }
}

// a soil particle's distance beyond the plane of a mirror wall particle: its separation from
// the particle (x_s - x_w) along the normal less the particle's own distance behind the plane
template <int DIMENSION>
inline double beyond_wall_plane(const double separation[3], const double n[3], double wall_distance)
{
  double beyond = -wall_distance;
  for (int a = 0; a < DIMENSION; a++) beyond += separation[a] * n[a];
  return beyond;
}

// The image of mirror wall particle w for soil particle s, from their packed rows
// (soil_packed_rows.h): the velocity difference dv = v_s - v_image, the stress sum
// sigma_s / rho_s^2 + sigma_image / rho_s^2, the approach dv . x_sw and the separation along the
// normal (x_s - x_w) . n. `separation` = x_s - x_w.
// Behind a frictional wall (SLIP_FRICTION) the image is the free-slip one: the pair pushes
// along the normal only (pushing_part()), and the tangential force is the Coulomb interface's
// (soil_wall_friction.h), so that nothing else, not even the artificial viscosity, drags the
// soil along the wall (with the sticking velocity it did: a rough gate lifted at 1 m/s got
// 6.7 times the at-rest force in its first step).
struct MirrorImage {
  double dv[3];
  double stress_sum[6];
  double approach, normal_separation;
};

// What a smooth or frictional wall's image pair keeps of its force on the soil: the part along
// the wall's unit normal n if it pushes the soil away from the wall, else nothing (an interface
// carries no tension). Returns the push f . n (0 if none).
template <int DIMENSION> inline double pushing_part(double force[DIMENSION], const double n[3])
{
  double fn = 0.0;
  for (int a = 0; a < DIMENSION; a++) fn += force[a] * n[a];
  fn = fn > 0.0 ? fn : 0.0;
  for (int a = 0; a < DIMENSION; a++) force[a] = fn * n[a];
  return fn;
}

template <int DIMENSION>
inline void mirror_image(const double *ps, const double *pw, const double normal[3],
                         double wall_distance, const double separation[3], int slip,
                         MirrorImage &image)
{
  constexpr int D = DIMENSION;
  // the soil particle's distance beyond the wall plane
  const double ds = beyond_wall_plane<D>(separation, normal, wall_distance);
  image.normal_separation = ds + wall_distance;
  const double beta = ds > 0.0 ? std::fmin(1.5, 1.0 + wall_distance / ds) : 1.5;
  // the image's stress: the soil particle's (no slip), or its mirror image (free slip and
  // friction: no shear traction); its velocity: the whole relative velocity (no slip), else
  // the normal part
  const double *ss = ps + P_STRESS;
  double *stress_sum = image.stress_sum;
  for (int k = 0; k < 6; k++) stress_sum[k] = 0.0;
  const bool no_slip = slip == SLIP_NONE;
  if (no_slip) {
    for (int a = 0; a < D; a++)
      for (int b = a; b < D; b++) stress_sum[voigt_index(a, b)] = 2.0 * ss[voigt_index(a, b)];
  } else {
    mirrored_stress_sum(ss, normal, stress_sum);
  }
  double relative[3], vn = 0.0;
  for (int a = 0; a < D; a++) {
    relative[a] = beta * (ps[P_V + a] - pw[P_V + a]);
    vn += relative[a] * normal[a];
  }
  double approach = 0.0;
  for (int a = 0; a < 3; a++) image.dv[a] = 0.0;
  for (int a = 0; a < D; a++) {
    image.dv[a] = no_slip ? relative[a] : vn * normal[a];
    approach += image.dv[a] * separation[a];
  }
  image.approach = approach;
}

}    // namespace SPHSoil

#endif
