/* -*- c++ -*- ----------------------------------------------------------
   SPH_SOIL package: the diffusion of the stress that removes SPH's row-to-row
   zigzag (pure, inline; doc/theory.rst 2.8).

   A stress that alternates from one row of particles to the next exerts no
   force in the momentum sum (each particle's neighbours on either side carry
   the same stress: their terms cancel), so nothing removes it once a surface
   or a wall has started it. A diffusion of the stress sees it at full
   strength. So that it leaves every linear field alone (a geostatic state, a
   seepage gradient, a state that a wall's load puts in), each pair diffuses
   only the part of the difference that the two particles' gradients do not
   explain, after Antuono, Colagrossi, Marrone & Molteni (2010)'s delta-SPH:

     psi_ab = sigma_a - sigma_b - (G_a + G_b) . x_ab / 2, limited to between 0 and
              sigma_a - sigma_b (unexplained_difference())
     dsigma_a/dt += sum_b V_b  2 delta c_ab h_ab  psi_ab  F_ab  r^2 / (r^2 + eta^2)

   (grad W = F x_ab, F < 0: the Brookshaw Laplacian of the pore water's flow),
   with G the renormalised gradient G = g M^-1 of Randles & Libersky,
   g = sum_b V_b (sigma_b - sigma_a) (x) grad_a W, M = sum_b V_b (x_b - x_a) (x) grad_a W,
   exact for linear fields whatever the neighbourhood, at a free surface too:
   psi vanishes pair by pair for any linear stress, and the diffusion with it.
   Each pair gives the same amount to one as it takes from the other (the sum
   of V sigma is kept). Plain inline code for a pass over the pairs, reusable
   by a threaded or GPU variant.
------------------------------------------------------------------------- */

#ifndef LMP_SOIL_STRESS_DIFFUSION_H
#define LMP_SOIL_STRESS_DIFFUSION_H

#include "soil_pore_water.h"

namespace SPHSoil {

// the stress components that a D-dimensional run carries (Voigt: xx yy zz xy xz yz; in 2D the
// first four, xz and yz staying 0)
template <int DIMENSION> constexpr int diffused_components()
{
  return DIMENSION == 2 ? 4 : 6;
}

// per atom while summed: M (Voigt, D (D + 1) / 2) then g (components x D); after
// renormalised_gradient(), G in g's place
template <int DIMENSION> constexpr int moment_size()
{
  return DIMENSION * (DIMENSION + 1) / 2;
}
template <int DIMENSION> constexpr int gradient_size()
{
  return moment_size<DIMENSION>() + diffused_components<DIMENSION>() * DIMENSION;
}

// the index of M_ab in the moment's Voigt storage (xx yy [zz] xy [xz yz])
template <int DIMENSION> constexpr int moment_index(int a, int b)
{
  return a == b ? a : (DIMENSION == 2 ? 2 : (a + b == 1 ? 3 : (a + b == 2 ? 4 : 5)));
}

// a pair's share to both of its particles' sums (each gets the same: M is even in x_ab, and
// g's term V (sigma_b - sigma_a) F x_ab is the same seen from either side), per unit partner
// volume: `difference` = sigma_b - sigma_a (diffused_components of them), `factor` = F
template <int DIMENSION>
inline void gradient_pair_sums(const double dx[3], double factor, const double *difference,
                               double sums[gradient_size<DIMENSION>()])
{
  constexpr int D = DIMENSION, M = moment_size<DIMENSION>();
  for (int a = 0; a < D; a++)
    for (int b = a; b < D; b++) sums[moment_index<D>(a, b)] -= factor * dx[a] * dx[b];
  for (int k = 0; k < diffused_components<D>(); k++)
    for (int a = 0; a < D; a++) sums[M + k * D + a] += factor * difference[k] * dx[a];
}

// G = g M^-1 in g's place; false (and G = 0) where M is too near singular to be trusted (a
// particle with partners along one line only): its pairs are then not diffused. M is
// dimensionless (about the identity in a full neighbourhood, diag(0.79, 0.50) on the surface
// of a square lattice); `smallest_determinant` bounds its determinant from below.
template <int DIMENSION>
inline bool renormalised_gradient(double sums[gradient_size<DIMENSION>()],
                                  double smallest_determinant)
{
  constexpr int D = DIMENSION, M = moment_size<DIMENSION>();
  double inverse[3][3];
  double det;
  if (D == 2) {
    const double xx = sums[0], yy = sums[1], xy = sums[2];
    det = xx * yy - xy * xy;
    if (det > smallest_determinant) {
      inverse[0][0] = yy / det;
      inverse[1][1] = xx / det;
      inverse[0][1] = inverse[1][0] = -xy / det;
    }
  } else {
    const double xx = sums[0], yy = sums[1], zz = sums[2], xy = sums[3], xz = sums[4], yz = sums[5];
    const double c00 = yy * zz - yz * yz, c01 = xz * yz - xy * zz, c02 = xy * yz - xz * yy;
    det = xx * c00 + xy * c01 + xz * c02;
    if (det > smallest_determinant) {
      inverse[0][0] = c00 / det;
      inverse[0][1] = inverse[1][0] = c01 / det;
      inverse[0][2] = inverse[2][0] = c02 / det;
      inverse[1][1] = (xx * zz - xz * xz) / det;
      inverse[1][2] = inverse[2][1] = (xy * xz - xx * yz) / det;
      inverse[2][2] = (xx * yy - xy * xy) / det;
    }
  }
  const bool valid = det > smallest_determinant;
  for (int k = 0; k < diffused_components<D>(); k++) {
    double *row = sums + M + k * D;
    double g[3];
    for (int a = 0; a < D; a++) g[a] = row[a];
    for (int b = 0; b < D; b++) {
      double value = 0.0;
      if (valid)
        for (int a = 0; a < D; a++) value += g[a] * inverse[a][b];
      row[b] = value;
    }
  }
  return valid;
}

// psi: the part of a pair's difference that its gradients do not explain, limited to between 0
// and the difference itself, so that every pair's flux runs from the larger stress to the
// smaller (the diffusion only ever lowers sum V sigma^2: stable whatever the gradients, also
// where a kernel cut at a corner makes them one-sided), and a linear field's is 0
inline double unexplained_difference(double difference, double explained)
{
  // difference - explained clamped to the interval between 0 and the difference (no division)
  const double rest = difference - explained;
  const double low = difference < 0.0 ? difference : 0.0, high = difference < 0.0 ? 0.0 : difference;
  return rest < low ? low : (rest > high ? high : rest);
}

// the pair's diffusion rate of particle a's stress, per unit partner volume (b gets minus it,
// per unit volume of a): 2 delta c h psi_ab F r^2 / (r^2 + eta^2) (soil_pore_water.h). `gradient_a`,
// `gradient_b`: G of each (components x D); `rate` receives diffused_components values
template <int DIMENSION>
inline void stress_diffusion_pair(const double *stress_a, const double *stress_b,
                                  const double *gradient_a, const double *gradient_b,
                                  const double dx[3], double r2, double h, double factor,
                                  double coefficient, double *rate)
{
  constexpr int D = DIMENSION;
  const double weight = 2.0 * coefficient * factor * r2 / (r2 + BROOKSHAW_ETA2 * h * h);
  for (int k = 0; k < diffused_components<D>(); k++) {
    double explained = 0.0;
    for (int a = 0; a < D; a++) explained += (gradient_a[k * D + a] + gradient_b[k * D + a]) * dx[a];
    rate[k] = weight * unexplained_difference(stress_a[k] - stress_b[k], 0.5 * explained);
  }
}

}    // namespace SPHSoil

#endif
