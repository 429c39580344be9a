/* -*- c++ -*- ----------------------------------------------------------
   SPH_SOIL package: the first-moment correction of the SPH gradients (pure, inline).

   The pair sums of the stress divergence and of the velocity gradient are exact for a linear
   field only where the kernel's first moment
     C_i = -(1/D) sum_j V_j (x_i - x_j) . grad_i W_ij        (D the dimension)
   is 1. On a lattice it is not (0.991 for the cubic spline at h = 1.2 d in 2D): a column at rest
   then needs a stress gradient 1/C_i times its weight, and a saturated soil, whose effective
   stress is the total less the pore pressure, carries the whole error in its effective stress
   (twice the error where the buoyant weight is half the total). With pair_style sph/soil
   gradient_correction yes, each particle's stress enters the pair sums as sigma_i / C_i and its
   own velocity gradient and density rate are divided by C_i (the scalar form of Bonet & Lok's
   correction, doc/theory.rst 2.7): the force of a pair stays antisymmetric, momentum is still
   conserved pair by pair, and the sums are exact for a linear field on any lattice of full
   kernels. Where the kernel is truncated (a free surface: C_i = 0.64 on a square lattice at
   h = 1.2 d) dividing by C_i would amplify the plain sum, which stands there for a boundary
   condition rather than a gradient: the correction fades out between C_i = FADE_END and
   FADE_START.
------------------------------------------------------------------------- */

#ifndef LMP_SOIL_GRADIENT_CORRECTION_H
#define LMP_SOIL_GRADIENT_CORRECTION_H

namespace SPHSoil {

// below FADE_START the kernel is taken as truncated: the correction fades linearly to none at
// FADE_END (on a square lattice at h = 1.2 d: C = 0.64 on a free surface, 0.96 one row below)
constexpr double GRADIENT_FADE_START = 0.9;
constexpr double GRADIENT_FADE_END = 0.8;

// a partner's share of D C_i: -V_j factor r^2, with grad_i W_ij = factor (x_i - x_j)
inline double first_moment_term(double volume, double factor, double r2)
{
  return -volume * factor * r2;
}

// the factor that multiplies particle i's stress in the pair sums and its own gradients, from
// its first moment C_i: 1 / C_i for a full kernel, 1 for a truncated one, linear in between
inline double gradient_correction(double moment)
{
  if (moment >= GRADIENT_FADE_START) return 1.0 / moment;
  if (moment <= GRADIENT_FADE_END) return 1.0;
  const double weight = (moment - GRADIENT_FADE_END) / (GRADIENT_FADE_START - GRADIENT_FADE_END);
  return 1.0 + weight * (1.0 / moment - 1.0);
}

}    // namespace SPHSoil

#endif
