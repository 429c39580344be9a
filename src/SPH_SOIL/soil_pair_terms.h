/* -*- c++ -*- ----------------------------------------------------------
   SPH_SOIL package: what a soil particle and its partner exchange (pure, inline).

   The partner is another soil particle, a wall particle that extrapolates
   the soil's state, or the image of a mirror wall particle (soil_wall_images.h
   builds it); pair_style sph/soil applies the terms (a wall particle takes the
   opposite force), the functions here compute them (doc/theory.rst section 2):
     density rate     m_b (v_a - v_b) . grad W_ab
     acceleration     m_b (sigma_a/rho_a^2 + sigma_b/rho_b^2 - Pi_ab) grad W_ab
     velocity grad.   V_b (v_b - v_a) x grad W_ab
   with Monaghan's viscosity Pi_ab for approaching pairs (pair_terms()). Plain inline code for the hot loop, reusable by
   a threaded or GPU variant of the loop.
------------------------------------------------------------------------- */

#ifndef LMP_SOIL_PAIR_TERMS_H
#define LMP_SOIL_PAIR_TERMS_H

#include "soil_tensor.h"

#include <cmath>

namespace SPHSoil {

// Monaghan's Pi_ab = (-alpha c mu + beta mu^2) / rhobar with mu = N / D, N = h_ab v_ab.x_ab,
// D = r^2 + 0.01 h_ab^2, written over one division: N (beta N - alpha c D) / (D^2 rhobar)
inline double monaghan_viscosity(double alpha, double beta, double n, double d, double rhobar,
                                 double c)
{
  return n * (beta * n - alpha * c * d) / (d * d * rhobar);
}

// The artificial viscosity across refinement levels (doc/theory.rst 5.9). Monaghan's Pi acts
// as a kinematic viscosity of about alpha c h / 8, and beta's term grows with h^2: a daughter
// with half its parent's h gets half the dissipation. With a reference h0 > 0 a pair's alpha
// becomes alpha h0 / h_ij and its beta beta (h0 / h_ij)^2, so that every level gets the
// dissipation of particles of smoothing length h0; since mu = h v.x / (r^2 + 0.01 h^2), that is
// mu with h0 in place of h in its numerator: the length returned here (h_ij for h0 = 0).
// Written as h0 + w h with w = 1 for h0 = 0, else 0 (viscosity_h_weight()): a multiply-add in
// the pair loop rather than a select.
inline double viscosity_h_weight(double h0)
{
  return h0 > 0.0 ? 0.0 : 1.0;
}
inline double viscosity_length(double h0, double h_weight, double h)
{
  return h0 + h_weight * h;
}

// What viscosity_h0 costs in time step (doc/theory.rst 5.9). Monaghan's step for his viscosity
// is C h / (c + 0.6 (alpha c + beta max mu)); with h0 a pair's alpha is alpha h0 / h, so the
// signal speed of the alpha part grows by h0 / h on particles finer than h0. The calibrated
// step C h / c_p (fix sph/soil cfl) is that of alpha as it is: it shrinks by the ratio of the
// signal speeds, with and without h0, at the finest h (1 where h >= h0). (A level-3 collapse
// with alpha = 1 and h0 the coarse h, 5.8/1.6 = 3.6 here, ran away within a few steps at
// cfl 0.1 at the finest level and not at 0.03.) The beta part, which needs the flow's largest
// mu, is left to the cfl.
inline double viscosity_step_factor(double alpha, double h0, double h)
{
  const double ratio = h0 > h ? h0 / h : 1.0;
  return (1.0 + 0.6 * alpha * ratio) / (1.0 + 0.6 * alpha);
}

// A pair's terms, as seen from soil particle a, in the form of the hot loop. With
// grad W = factor x_ab, the density rate, the viscosity's approach and the velocity gradient are
// all made of v_ab and x_ab, so everything follows from the separation, the factor, the
// velocity difference and the stress sum:
//   density rate per unit m_b     factor (v_ab . x_ab)
//   force on a per unit m_a m_b   factor ((S - Pi_ab I) x_ab)
//   velocity gradient             t^cd = -factor v_ab^c x_ab^d, per unit V_b
// with S = sigma_a/rho_a^2 + sigma_b/rho_b^2 (Voigt) and Monaghan's Pi_ab for approaching pairs
// (viscosity_h: viscosity_length()). b is another soil particle, a wall particle that
// extrapolates the soil's state, or the image of a mirror wall particle (the pair style builds
// its velocity and stress). `approach` = v_ab . x_ab. Plain scalars
// with compile-time indices: the compiler keeps the pair in registers (a struct of the pair's
// inputs with the stress components through a table kept it in memory: 40% more instructions).
template <int DIMENSION> struct PairTerms {
  double density_rate;
  double force[DIMENSION];
  double gradient[DIMENSION][DIMENSION];
};

template <int DIMENSION>
inline void pair_terms(const double dx[3], double r2, double h, double viscosity_h, double factor,
                       const double dv[3], double approach,
                       const double stress_sum[6], double mean_density, double sound_speed,
                       double alpha, double beta, PairTerms<DIMENSION> &out)
{
  out.density_rate = factor * approach;
  double viscosity = 0.0;
  if (approach < 0.0)
    viscosity = monaghan_viscosity(alpha, beta, viscosity_h * approach,
                                   r2 + 0.01 * h * h, mean_density, sound_speed);
  for (int a = 0; a < DIMENSION; a++) {
    double sum = -viscosity * dx[a];
    for (int b = 0; b < DIMENSION; b++) sum += stress_sum[voigt_index(a, b)] * dx[b];
    out.force[a] = factor * sum;
  }
  for (int c = 0; c < DIMENSION; c++) {
    const double scaled = -factor * dv[c];
    for (int d = 0; d < DIMENSION; d++) out.gradient[c][d] = scaled * dx[d];
  }
}

// a pair that exchanges nothing (a soil particle behind a mirror wall's plane, whose image is
// not defined: soil_wall_images.h)
template <int DIMENSION> inline void no_pair_terms(PairTerms<DIMENSION> &out)
{
  out.density_rate = 0.0;
  for (int a = 0; a < DIMENSION; a++) {
    out.force[a] = 0.0;
    for (int b = 0; b < DIMENSION; b++) out.gradient[a][b] = 0.0;
  }
}

}    // namespace SPHSoil

#endif
