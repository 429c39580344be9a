/* -*- c++ -*- ----------------------------------------------------------
   SPH_SOIL package: what a soil particle and its partner exchange (pure, inline).

   The partner is another soil particle or the image of a wall particle
   (Bui 2008: relative velocity beta (v_s - v_w), the soil particle's density,
   and its stress, mirrored in the wall's plane behind a free-slip wall);
   pair_style sph/soil builds the partner and applies the term (a wall
   particle takes the opposite force), the functions here compute it
   (doc/theory.rst section 2):
     density rate     m_b (v_a - v_b) . grad W_ab
     acceleration     m_b (sigma_a/rho_a^2 + sigma_b/rho_b^2 - Pi_ab) grad W_ab
     velocity grad.   V_b (v_b - v_a) x grad W_ab
   with Monaghan's viscosity Pi_ab for approaching pairs (pair_terms()), and the
   images' stresses behind walls. Plain inline code for the hot loop, reusable by
   a threaded or GPU variant of the loop.
------------------------------------------------------------------------- */

#ifndef LMP_SPH_SOIL_PAIR_TERM_H
#define LMP_SPH_SOIL_PAIR_TERM_H

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

// The Voigt index of stress component (a, b): xx yy zz xy xz yz
constexpr int voigt_index(int a, int b)
{
  return a == b ? a : (a + b == 1 ? 3 : (a + b == 2 ? 4 : 5));
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
// its velocity and stress). `approach` = v_ab . x_ab; `viscous_approach` the part of it that the
// viscosity sees: the same, except behind a frictional wall (its normal part). Plain scalars
// with compile-time indices: the compiler keeps the pair in registers (a struct of the pair's
// inputs with the stress components through a table kept it in memory: 40% more instructions).
template <int DIMENSION> struct PairTerms {
  double density_rate;
  double force[DIMENSION];
  double gradient[DIMENSION][DIMENSION];
};

template <int DIMENSION>
inline void pair_terms(const double dx[3], double r2, double h, double viscosity_h, double factor,
                       const double dv[3], double approach, double viscous_approach,
                       const double stress_sum[6], double mean_density, double sound_speed,
                       double alpha, double beta, PairTerms<DIMENSION> &out)
{
  out.density_rate = factor * approach;
  double viscosity = 0.0;
  if (viscous_approach < 0.0)
    viscosity = monaghan_viscosity(alpha, beta, viscosity_h * viscous_approach,
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

// R sigma R with R = I - 2 n n^T, the mirror image of a stress in the plane of unit normal n:
// it keeps the normal stresses and flips the shear between the normal and the plane. Also
// returns the traction's normal part n.sigma.n and its shear part |sigma n - (n.sigma.n) n|.
// Voigt order xx yy zz xy xz yz.
inline void mirror_stress(const double stress[6], const double n[3], double mirrored[6],
                          double &normal_traction, double &shear_traction)
{
  static const int row[6] = {0, 1, 2, 0, 0, 1}, col[6] = {0, 1, 2, 1, 2, 2};
  static const int voigt[3][3] = {{0, 3, 4}, {3, 1, 5}, {4, 5, 2}};
  double sn[3];    // sigma n
  for (int a = 0; a < 3; a++)
    sn[a] = stress[voigt[a][0]] * n[0] + stress[voigt[a][1]] * n[1] + stress[voigt[a][2]] * n[2];
  const double nsn = n[0] * sn[0] + n[1] * sn[1] + n[2] * sn[2];
  for (int k = 0; k < 6; k++) {
    const int a = row[k], b = col[k];
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

}    // namespace SPHSoil

#endif
