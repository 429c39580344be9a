/* -*- c++ -*- ----------------------------------------------------------
   SPH_SOIL package: artificial stress against the tensile instability (pure, no LAMMPS).

   Gray, Monaghan & Swift (2001), as Bui et al. (2008) use it for cohesive soil: a particle
   under tension gets a repulsive artificial stress, in its principal frame
     R'_i = -epsilon sigma'_i / rho^2   for a principal stress sigma'_i > 0 (tension),
     R'_i = 0                           otherwise,
   R = Q diag(R') Q^T; a pair adds (R_a + R_b) f_ab^n to the stress sum of its momentum term,
   with f_ab = W(r_ab) / W(d), d the initial particle spacing: a term that grows as two
   particles under tension come closer than d, and keeps them apart (no clumping). Symmetric
   in a and b, so that the pair's forces stay equal and opposite. Typical: epsilon = 0.3,
   n = 4 (Gray 2001). Groundwork of the cohesive-soil issue: not yet in the pair loop.
------------------------------------------------------------------------- */

#ifndef LMP_SOIL_ARTIFICIAL_STRESS_H
#define LMP_SOIL_ARTIFICIAL_STRESS_H

namespace SPHSoil {

// R / 1 of a particle of this stress (Voigt, tension positive) and density; 0 without tension
void artificial_stress(const double stress[6], double density, double epsilon, double R[6]);

// f^n, f = W(r) / W(spacing): the pair's weight of the artificial stress
inline double artificial_stress_weight(double kernel_value, double kernel_value_at_spacing,
                                       int exponent)
{
  const double f = kernel_value / kernel_value_at_spacing;
  double weight = 1.0;
  for (int k = 0; k < exponent; k++) weight *= f;
  return weight;
}

}    // namespace SPHSoil

#endif
