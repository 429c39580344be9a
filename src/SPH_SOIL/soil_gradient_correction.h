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

   With gradient_correction full the velocity gradient (and so the strain rate, the spin and,
   in the volume form of continuity, the density rate) is corrected by the whole first-moment
   tensor, M_i = sum_j V_j (x_j - x_i) (x) grad_i W_ij, rather than its trace: the plain sum is
   g = G M for a linear velocity field of gradient G, so G = g M^-1, exact on a free surface too
   (Bonet & Lok 1999; Randles & Libersky 1996). A cut kernel's M is anisotropic (on the surface
   of a square lattice at h = 1.2 d 0.50 along the normal, 0.79 along the surface), which a
   scalar cannot undo: the surface's particles then see too small a strain rate and carry too
   little stress, and a block between plates settled 6-13% more than Hooke's law gives
   (doc/validation.rst, Mandel's problem). The stress keeps the scalar
   factor with its fade: the momentum stays conserved pair by pair, and the free surface's
   traction condition is what the plain sum gives there. A kernel too sparse or flat for the
   tensor (its determinant below MOMENT_TENSOR_MIN_DETERMINANT, about 1 for a full kernel) keeps
   the scalar factor.

   A smooth (or frictional) mirror wall's image moves with the soil particle along the wall and
   only its normal velocity differs (doc/theory.rst 4.3): its pairs carry the normal velocity's
   gradient and nothing of the tangential ones. Summed as plain partners they would make the rows
   next to the wall stretch too little along it (a block between smooth plates: those rows in
   lateral compression, the rest in tension, and the pore pressure of undrained soil off by
   tens of per cent in them). For a linear field the sum is then g = G M_p + (n n) G M_i (M_p
   over the plain partners, M_i over the images, n the wall's normal), solved row by row: the
   normal velocity's row by (M_p + M_i)^-1, the tangential ones by M_p^-1. Near two walls n is
   the mean of their normals, weighted by the images' share.
------------------------------------------------------------------------- */

#ifndef LMP_SOIL_GRADIENT_CORRECTION_H
#define LMP_SOIL_GRADIENT_CORRECTION_H

#include "soil_tensor.h"

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

// a partner's share of the first-moment tensor M_i (Voigt xx yy zz xy xz yz): -V_j factor dx dx,
// dx = x_i - x_j, grad_i W_ij = factor dx (its trace is first_moment_term's)
inline void first_moment_tensor_term(double volume, double factor, const double dx[3], double m[6])
{
  const double w = -volume * factor;
  m[0] += w * dx[0] * dx[0];
  m[1] += w * dx[1] * dx[1];
  m[2] += w * dx[2] * dx[2];
  m[3] += w * dx[0] * dx[1];
  m[4] += w * dx[0] * dx[2];
  m[5] += w * dx[1] * dx[2];
}

// a full kernel's determinant is about 1; below this the tensor is not inverted
constexpr double MOMENT_TENSOR_MIN_DETERMINANT = 0.1;

// the velocity gradient's correction L (Voigt, symmetric) of a particle with first-moment tensor
// `m` (its diagonal's mean C_i): M^-1 where M is well conditioned, else `fallback` times the
// identity (the scalar factor). In 2D the zz entries of m are unused and L's are 0.
template <int DIMENSION>
inline void velocity_gradient_correction(const double m[6], double fallback, double inverse[6])
{
  for (int k = 0; k < 6; k++) inverse[k] = 0.0;
  if (DIMENSION == 2) {
    const double det = m[0] * m[1] - m[3] * m[3];
    if (det >= MOMENT_TENSOR_MIN_DETERMINANT) {
      inverse[0] = m[1] / det;
      inverse[1] = m[0] / det;
      inverse[3] = -m[3] / det;
      return;
    }
  } else {
    // cofactors of the symmetric matrix [[xx xy xz] [xy yy yz] [xz yz zz]]
    const double c_xx = m[1] * m[2] - m[5] * m[5], c_yy = m[0] * m[2] - m[4] * m[4],
                 c_zz = m[0] * m[1] - m[3] * m[3], c_xy = m[4] * m[5] - m[3] * m[2],
                 c_xz = m[3] * m[5] - m[1] * m[4], c_yz = m[3] * m[4] - m[0] * m[5];
    const double det = m[0] * c_xx + m[3] * c_xy + m[4] * c_xz;
    if (det >= MOMENT_TENSOR_MIN_DETERMINANT) {
      inverse[0] = c_xx / det;
      inverse[1] = c_yy / det;
      inverse[2] = c_zz / det;
      inverse[3] = c_xy / det;
      inverse[4] = c_xz / det;
      inverse[5] = c_yz / det;
      return;
    }
  }
  for (int a = 0; a < DIMENSION; a++) inverse[a] = fallback;
}

// a velocity gradient g (D x D, row a = velocity component a) corrected by the inverses of
// the moment tensors: rows along `normal` (a unit vector, or zero without smooth wall images)
// by `full` (M_p + M_i)^-1, the others by `plain` M_p^-1 (both Voigt, symmetric)
template <int DIMENSION>
inline void corrected_velocity_gradient(const double *g, const double normal[3],
                                        const double full[6], const double plain[6],
                                        double *out)
{
  constexpr int D = DIMENSION;
  double by_full[D * D], by_plain[D * D];
  for (int a = 0; a < D; a++)
    for (int b = 0; b < D; b++) {
      double f = 0.0, p = 0.0;
      for (int c = 0; c < D; c++) {
        f += g[a * D + c] * full[voigt_index(c, b)];
        p += g[a * D + c] * plain[voigt_index(c, b)];
      }
      by_full[a * D + b] = f;
      by_plain[a * D + b] = p;
    }
  // out = n n^T by_full + (I - n n^T) by_plain
  for (int b = 0; b < D; b++) {
    double nf = 0.0, np = 0.0;
    for (int c = 0; c < D; c++) {
      nf += normal[c] * by_full[c * D + b];
      np += normal[c] * by_plain[c * D + b];
    }
    for (int a = 0; a < D; a++) out[a * D + b] = by_plain[a * D + b] + normal[a] * (nf - np);
  }
}

}    // namespace SPHSoil

#endif
