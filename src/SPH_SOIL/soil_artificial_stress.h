/* -*- c++ -*- ----------------------------------------------------------
   SPH_SOIL package: artificial stress against the tensile instability (pure, no LAMMPS).

   Gray, Monaghan & Swift (2001), as Bui et al. (2008) use it for cohesive soil: a particle
   under tension gets a repulsive artificial stress, in its principal frame
     R'_i = -epsilon sigma'_i / rho^2   for a principal stress sigma'_i > 0 (tension),
     R'_i = 0                           otherwise,
   R = Q diag(R') Q^T; a pair adds (R_a + R_b) f_ab^n to the stress sum of its momentum term,
   with f_ab = W(r_ab) / W(d), d the particle spacing (pair_style sph/soil: each particle's
   (m / rho)^(1/D)): a term that grows as two particles under tension come closer than d, and
   keeps them apart (no clumping). Symmetric
   in a and b, so that the pair's forces stay equal and opposite. Gray 2001: epsilon = 0.3,
   n = 4. pair_style sph/soil adds it for the soils that can carry tension (c > 0).
------------------------------------------------------------------------- */

#ifndef LMP_SOIL_ARTIFICIAL_STRESS_H
#define LMP_SOIL_ARTIFICIAL_STRESS_H

#include "soil_tensor.h"

namespace SPHSoil {

// Gray 2001's values: the default coefficient and the exponent n
constexpr double ARTIFICIAL_STRESS_EPSILON = 0.3;
constexpr int ARTIFICIAL_STRESS_EXPONENT = 4;

// R of a particle of this stress (Voigt, tension positive) and density; 0 without tension
void artificial_stress(const double stress[6], double density, double epsilon, double R[6]);

// the same in DIMENSION: 3 is the above; 2 (plane strain: xz = yz = 0, z a principal
// direction) in closed form, R = sum g(s_k) P_k with the in-plane projectors
// P_1 = (S - s_2 I) / (s_1 - s_2), P_2 = I - P_1: no angles, no eigenvectors
template <int DIMENSION>
inline void artificial_stress(const double stress[6], double density, double epsilon, double R[6])
{
  if (DIMENSION == 3) {
    artificial_stress(stress, density, epsilon, R);
    return;
  }
  const double scale = -epsilon / (density * density);
  double center, radius;
  mohr_circle(stress, center, radius);
  const double s1 = center + radius, s2 = center - radius;
  const double r1 = s1 > 0.0 ? scale * s1 : 0.0, r2 = s2 > 0.0 ? scale * s2 : 0.0;
  // R_inplane = r2 I + (r1 - r2) P_1, P_1 = (S - s_2 I) / (2 radius); equal principal
  // stresses (radius 0) have r1 = r2
  const double share = radius > 0.0 ? (r1 - r2) / (2.0 * radius) : 0.0;
  R[0] = r2 + share * (stress[0] - s2);
  R[1] = r2 + share * (stress[1] - s2);
  R[3] = share * stress[3];
  R[2] = stress[2] > 0.0 ? scale * stress[2] : 0.0;
  R[4] = R[5] = 0.0;
}

// f^n, f = W(r) / W(spacing) (given as f): the pair's weight of the artificial stress
inline double artificial_stress_weight(double f)
{
  double weight = 1.0;
  for (int k = 0; k < ARTIFICIAL_STRESS_EXPONENT; k++) weight *= f;
  return weight;
}

}    // namespace SPHSoil

#endif
