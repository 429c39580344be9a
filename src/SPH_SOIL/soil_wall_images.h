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

#include "soil_kernels.h"
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

// The mirror walls' planes, per atom: the unit normal into the soil, the wall particle's distance
// behind its plane, and for a soil particle the farthest it stands in front of the plane of any
// mirror wall particle it pairs with (<= 0: it is behind all of them; SPHSoilWalls::prepare())
struct MirrorPlanes {
  double **normal;
  const double *distance;
  const double *front_most;
};

// Whether mirror wall particle w stands for the image of soil particle s, which is `beyond` in
// front of w's plane and at most `front_most` in front of any mirror plane it pairs with: if s is
// in front of w's plane, and if s is behind every plane (it crossed the wall: the images push it
// back out, as the contact does). Not for s behind w's plane but in front of another: that is a
// particle beside the other face of a body, past a convex corner (a footing's edge), whose mirror
// point in w's plane lies in the soil. There the images of the base of a smooth footing held the
// surface particle at its corner down while the heave beside the footing rose, then let it go
// when their push turned into a pull, and it shot out of the box at 1.5 m/s (doc/theory.rst 4.3).
inline bool has_image(double beyond, double front_most)
{
  return beyond > 0.0 || !(front_most > 0.0);
}

// beyond_wall_plane() of soil particle s and mirror wall particle w from their packed rows
template <int DIMENSION>
inline double beyond_wall_plane(const double *ps, const double *pw, const double n[3],
                                double wall_distance)
{
  double separation[3] = {0.0, 0.0, 0.0};
  for (int a = 0; a < DIMENSION; a++) separation[a] = ps[P_X + a] - pw[P_X + a];
  return beyond_wall_plane<DIMENSION>(separation, n, wall_distance);
}

// has_image() for soil particle s and mirror wall particle w from their packed rows
template <int DIMENSION>
inline bool has_image(const double *ps, const double *pw, const double n[3], double wall_distance,
                      double front_most)
{
  return has_image(beyond_wall_plane<DIMENSION>(ps, pw, n, wall_distance), front_most);
}

// The image of mirror wall particle w for soil particle s, from their packed rows
// (soil_packed_rows.h): the velocity difference dv = v_s - v_image, the stress sum
// sigma_s / rho_s^2 + sigma_image / rho_s^2, the approach dv . x_sw and the separation along the
// normal (x_s - x_w) . n. `separation` = x_s - x_w.
// Returns false, with only normal_separation set, where w stands for no image of s (has_image();
// `front_most` is s's MirrorPlanes::front_most).
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
inline bool mirror_image(const double *ps, const double *pw, const double normal[3],
                         double wall_distance, double front_most, const double separation[3],
                         int slip, MirrorImage &image)
{
  constexpr int D = DIMENSION;
  // the soil particle's distance beyond the wall plane
  const double ds = beyond_wall_plane<D>(separation, normal, wall_distance);
  image.normal_separation = ds + wall_distance;
  if (!has_image(ds, front_most)) return false;
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
  return true;
}

/* The wall's contact (doc/theory.rst 4.3). An image carries the soil particle's own stress, so a
   particle at zero stress (a free surface, the tension cut-off) feels no push from a wall and
   crosses it as fast as it comes: at a smooth footing's corner at B/d = 40 such particles ended
   up inside the footing. Each wall particle is therefore also a stiff contact: a soil particle
   closer to it than CONTACT_REACH of their mean spacing is pushed away from it with a force
   that rises from 0 with the soil's P-wave modulus M on the soil particle's face,
   M s^(D-1) (reach - r) / (CONTACT_SKIN s). The reach is 3/4 of a spacing: a soil particle that
   stands on a wall of its own spacing (half a spacing from the wall's plane, one spacing from
   the nearest wall particle) is out of reach by a quarter of a spacing, a strain of 50% of its
   first row, and one on the plane is within reach of a wall particle wherever it stands along
   the wall. Pairwise, not from the wall's plane: beside a convex corner (a footing's edge) a
   plane reaches soil that never stood in front of it (at B/d = 40 a plane contact pushed down
   the heave beside a footing and raised its load by 8%). A smooth or frictional wall keeps the
   contact's push along its normal only, as the image's. Its spring, c_p^2 / (skin s) per unit
   mass, keeps the explicit step stable (omega dt = 0.24 per contact at the examples'
   0.1 h / c_p, h = 1.2 s). */
constexpr double CONTACT_REACH = 0.75;
constexpr double CONTACT_SKIN = 0.25;

// Whether a soil particle of volume `soil_volume` and a wall particle of volume `wall_volume` at
// squared distance r2 may be within the contact's reach, without a root: the mean of two spacings
// is at most the D-th power mean of them, ((V_s + V_w) / 2)^(1/D), so reach^D <=
// CONTACT_REACH^D (V_s + V_w) / 2 (true for every pair in reach; the loop then computes the
// spacings only for the few that pass, none in a soil at rest)
template <int DIMENSION>
inline bool contact_possible(double r2, double soil_volume, double wall_volume)
{
  const double bound = 0.5 * (soil_volume + wall_volume);
  if (DIMENSION == 2) return r2 < CONTACT_REACH * CONTACT_REACH * bound;
  const double reach3 = CONTACT_REACH * CONTACT_REACH * CONTACT_REACH * bound;
  return r2 * r2 * r2 < reach3 * reach3;
}

// the contact's overlap strain between a soil particle of spacing `soil_spacing` and a wall
// particle of spacing `wall_spacing` at distance r: (reach - r) / (CONTACT_SKIN soil_spacing)
// within reach, else 0
inline double contact_strain(double r, double soil_spacing, double wall_spacing)
{
  const double reach = CONTACT_REACH * 0.5 * (soil_spacing + wall_spacing);
  return r < reach ? (reach - r) / (CONTACT_SKIN * soil_spacing) : 0.0;
}

// The contact force on the soil particle (scaled by `scale`), added to `force`: the spring,
// M s^(D-1) strain, and a dashpot that damps it critically, 2 sqrt(k m) = 4 rho c s^(D-1) for
// the spring's k = M s^(D-2) / CONTACT_SKIN and the particle's m = rho s^D (without it a particle
// squeezed against a wall by its neighbours rattled at +-0.6 m/s), on the opening velocity
// (v_s - v_w) . (x_s - x_w) / r; along the separation x_s - x_w (`separation`, of length r),
// never pulling. `modulus` = rho c^2, `impedance` = rho c.
template <int DIMENSION>
inline void add_contact_force(double modulus, double impedance, double soil_spacing,
                              double strain, const double separation[3], double r,
                              const double relative_velocity[3], double scale,
                              double force[DIMENSION])
{
  double opening = 0.0;
  for (int a = 0; a < DIMENSION; a++) opening += relative_velocity[a] * separation[a];
  opening /= r;
  const double face = DIMENSION == 3 ? soil_spacing * soil_spacing : soil_spacing;
  const double damping = 2.0 / std::sqrt(CONTACT_SKIN);    // 4: critical
  const double pressure = modulus * strain - damping * impedance * opening;
  if (pressure <= 0.0) return;
  const double push = scale * face * pressure / r;
  for (int a = 0; a < DIMENSION; a++) force[a] += push * separation[a];
}

/* A soil lifting off a drained wall (doc/theory.rst 7.3). Water at the wall's pressure fills the
   gap that opens between the wall and the soil, and the filter behind it offers no resistance:
   the wall stands where the soil's lowest particles would touch it, and its images carry, in
   proportion to the contact that remains, the soil's own total stress (in contact the wall
   reacts with the traction the soil puts on it) and, for the rest, the wall's water pressure;
   the separation is not a dilation of the soil. Without this, the images' relative velocity
   counted the separation as pore expansion (a suction of ~50 Pa that held a layer at 1.1 i_c)
   and the widening gap in the particle lattice pulled the layer back. */

// the gap between a soil particle and a mirror wall's plane: its distance beyond the plane less
// the half spacing at which a lattice of its volume per particle touches the plane. (A particle
// pressed on the wall but stretched along its normal relative to sideways by a strain e reads a
// gap of about e s/4 and holds less of the contact: pushed less, it settles towards the wall
// until it holds it again, a contact that gives by at most CONTACT_RANGE of the spacing. A
// tolerance before the gap counted, 1% of the spacing, kept a layer at 1.1 i_c at 4 mm on the
// floor: in contact its separation is a dilation, whose suction held it.)
template <int DIMENSION> inline double gap_to_wall(double beyond_plane, double volume)
{
  return beyond_plane - 0.5 * volume_spacing(volume, DIMENSION);
}

// the share of the skeleton's stress that a wall still holds across a gap: all of it in
// contact, none once the gap is CONTACT_RANGE of the particle's spacing (a stiff contact; a step
// would rattle a particle that rests on the wall)
constexpr double CONTACT_RANGE = 0.01;
template <int DIMENSION> inline double contact_share(double gap, double volume)
{
  if (gap <= 0.0) return 1.0;
  const double share = 1.0 - gap / (CONTACT_RANGE * volume_spacing(volume, DIMENSION));
  return share > 0.0 ? share : 0.0;
}

// The image of a drained wall across a gap, where it holds `share` (contact_share()) of the
// contact: `share` of the soil particle's image stress (its skeleton's and its pore pressure, as
// a mirror wall's in contact), and for the rest the wall's water at `wall_pressure`; along the
// normal it moves with the soil but for `share` of their relative velocity. `total_stress` is
// the soil particle's total stress sigma' - p I (in the units of the image's stress sum, and so
// is `wall_pressure`).
template <int DIMENSION>
inline void drained_image(const double total_stress[6], double wall_pressure, double share,
                          const double n[3], const double separation[3], MirrorImage &image)
{
  if (share == 1.0) return;
  for (int k = 0; k < 6; k++) {
    const int a = VOIGT_ROW[k], b = VOIGT_COL[k];
    if (a >= DIMENSION || b >= DIMENSION) continue;
    // the image's own part of the sum: share of it, and the rest the wall's water
    const double image_stress = image.stress_sum[k] - total_stress[k];
    image.stress_sum[k] -= (1.0 - share) * (image_stress + (a == b ? wall_pressure : 0.0));
  }
  // the separation's share of the relative velocity fades with the contact, as a function of
  // the gap alone (a dilation counted only while the soil lifts, as its velocity's sign would
  // have it, ratchets a layer at rest upwards)
  double vn = 0.0;
  for (int a = 0; a < DIMENSION; a++) vn += image.dv[a] * n[a];
  image.approach = 0.0;
  for (int a = 0; a < DIMENSION; a++) {
    image.dv[a] -= (1.0 - share) * vn * n[a];
    image.approach += image.dv[a] * separation[a];
  }
}

}    // namespace SPHSoil

#endif
