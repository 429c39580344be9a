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
   with Monaghan's viscosity Pi_ab for approaching pairs. Plain inline code
   for the hot loop, reusable by a threaded or GPU variant of the loop. Three
   functions rather than one, so that the loop can apply each part as soon as
   it is computed: fewer values live at once (measured: one function holding
   all three parts made the 2D loop 5% slower through register spills).
------------------------------------------------------------------------- */

#ifndef LMP_SPH_SOIL_PAIR_TERM_H
#define LMP_SPH_SOIL_PAIR_TERM_H

namespace SPHSoil {

// the pair's inputs, as seen from soil particle a
struct PairPartner {
  double dx[3];            // x_a - x_b
  double grad[3];          // dW_ab/dx_a
  double velocity[3];      // v_a - v_b
  double stress_sum[6];    // sigma_a/rho_a^2 + sigma_b/rho_b^2 (Voigt; 2D uses xx yy xy)
  double mean_density;     // (rho_a + rho_b)/2
};

// Monaghan's Pi_ab = (-alpha c mu + beta mu^2) / rhobar with mu = N / D, N = h_ab v_ab.x_ab,
// D = r^2 + 0.01 h_ab^2, written over one division: N (beta N - alpha c D) / (D^2 rhobar)
inline double monaghan_viscosity(double alpha, double beta, double n, double d, double rhobar,
                                 double c)
{
  return n * (beta * n - alpha * c * d) / (d * d * rhobar);
}

// (v_a - v_b) . grad: the density rate per unit m_b; and (v_a - v_b) . (x_a - x_b), which says
// whether they approach (for the viscosity)
template <int DIMENSION>
inline double pair_density_rate(const PairPartner &p, double &approach)
{
  double vdotgrad = 0.0, vdotx = 0.0;
  for (int a = 0; a < DIMENSION; a++) {
    vdotgrad += p.velocity[a] * p.grad[a];
    vdotx += p.velocity[a] * p.dx[a];
  }
  approach = vdotx;
  return vdotgrad;
}

// the force on a: m_a m_b (sigma_a/rho_a^2 + sigma_b/rho_b^2 - Pi_ab) grad, with the viscosity
// only for approaching pairs (approach < 0)
template <int DIMENSION>
inline void pair_force(const PairPartner &p, double approach, double r2, double h,
                       double sound_speed, double alpha, double beta, double mass_product,
                       double force[3])
{
  double viscosity = 0.0;
  if (approach < 0.0)
    viscosity = monaghan_viscosity(alpha, beta, h * approach, r2 + 0.01 * h * h, p.mean_density,
                                   sound_speed);
  const double *s = p.stress_sum;
  const double *g = p.grad;
  if (DIMENSION == 2) {
    // written out: the 2D case is the one the paper's problems run
    force[0] = mass_product * ((s[0] - viscosity) * g[0] + s[3] * g[1]);
    force[1] = mass_product * (s[3] * g[0] + (s[1] - viscosity) * g[1]);
  } else {
    static const int voigt[3][3] = {{0, 3, 4}, {3, 1, 5}, {4, 5, 2}};
    for (int a = 0; a < DIMENSION; a++) {
      double sum = -viscosity * g[a];
      for (int b = 0; b < DIMENSION; b++) sum += s[voigt[a][b]] * g[b];
      force[a] = mass_product * sum;
    }
  }
}

// t^ab = -(v_a - v_b)^a grad^b: the velocity gradient per unit V_b
template <int DIMENSION>
inline void pair_velocity_gradient(const PairPartner &p, double t[3][3])
{
  for (int a = 0; a < DIMENSION; a++)
    for (int b = 0; b < DIMENSION; b++) t[a][b] = -p.velocity[a] * p.grad[b];
}

// sigma + R sigma R with R = I - 2 n n^T, the mirror in the plane of unit normal n: the
// stress sum of a soil particle and its image behind a smooth (free-slip) wall. The mirror
// keeps the normal stresses and flips the shear between the normal and the wall's plane, so
// that the wall carries no shear traction, as the mirrored velocity v - 2 (v.n) n has no
// tangential slip relative to the soil. Voigt order xx yy zz xy xz yz.
inline void mirrored_stress_sum(const double stress[6], const double n[3], double sum[6])
{
  static const int row[6] = {0, 1, 2, 0, 0, 1}, col[6] = {0, 1, 2, 1, 2, 2};
  static const int voigt[3][3] = {{0, 3, 4}, {3, 1, 5}, {4, 5, 2}};
  double sn[3];    // sigma n
  for (int a = 0; a < 3; a++)
    sn[a] = stress[voigt[a][0]] * n[0] + stress[voigt[a][1]] * n[1] + stress[voigt[a][2]] * n[2];
  const double nsn = n[0] * sn[0] + n[1] * sn[1] + n[2] * sn[2];
  for (int k = 0; k < 6; k++) {
    const int a = row[k], b = col[k];
    const double mirrored =
        stress[k] - 2.0 * (n[a] * sn[b] + sn[a] * n[b]) + 4.0 * n[a] * n[b] * nsn;
    sum[k] = stress[k] + mirrored;
  }
}

}    // namespace SPHSoil

#endif
