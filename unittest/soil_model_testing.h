// Helpers shared by the tests of the constitutive models (no LAMMPS).
#ifndef SPH_SOIL_MODEL_TESTING_H
#define SPH_SOIL_MODEL_TESTING_H

#include "soil_constitutive.h"

#include <cmath>
#include <random>

namespace SPHSoilTesting {

// R sigma R^T of a Voigt tensor
inline void rotate(const double r[3][3], const double v[6], double out[6])
{
  const double m[3][3] = {{v[0], v[3], v[4]}, {v[3], v[1], v[5]}, {v[4], v[5], v[2]}};
  double t[3][3];
  for (int a = 0; a < 3; a++)
    for (int b = 0; b < 3; b++) {
      t[a][b] = 0.0;
      for (int c = 0; c < 3; c++)
        for (int d = 0; d < 3; d++) t[a][b] += r[a][c] * m[c][d] * r[b][d];
    }
  out[0] = t[0][0]; out[1] = t[1][1]; out[2] = t[2][2];
  out[3] = t[0][1]; out[4] = t[0][2]; out[5] = t[1][2];
}

inline void random_rotation(std::mt19937 &rng, double r[3][3])
{
  // a random unit quaternion
  std::normal_distribution<double> normal;
  double q[4], n = 0.0;
  for (double &x : q) {
    x = normal(rng);
    n += x * x;
  }
  n = std::sqrt(n);
  const double w = q[0] / n, x = q[1] / n, y = q[2] / n, z = q[3] / n;
  const double m[3][3] = {{1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)},
                          {2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)},
                          {2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)}};
  for (int a = 0; a < 3; a++)
    for (int b = 0; b < 3; b++) r[a][b] = m[a][b];
}


// the parameters of a frictional soil (sand-like elasticity unless told)
inline SPHSoil::FrictionalParameters frictional(double phi, double psi, double c, double bulk = 1.5e6,
                                                double nu = 0.3)
{
  SPHSoil::FrictionalParameters p;
  p.bulk_modulus = bulk;
  p.poisson_ratio = nu;
  p.friction_angle = phi;
  p.dilatancy_angle = psi;
  p.cohesion = c;
  return p;
}

// Plane-strain simple shear at unit shear rate (strain rate xy = spin xy = 1/2) from the
// isotropic stress -p0, explicit steps of dt each followed by the model's return: shear strain
// steps * dt (the default 0.2 is far past first yield)
inline void simple_shear(const SPHSoil::ConstitutiveModel &model, double p0, double stress[6],
                         int steps = 20000, double dt = 1.0e-5)
{
  const double strain_rate[6] = {0.0, 0.0, 0.0, 0.5, 0.0, 0.0};
  const double spin[3] = {0.5, 0.0, 0.0};
  for (int k = 0; k < 6; k++) stress[k] = k < 3 ? -p0 : 0.0;
  for (int n = 0; n < steps; n++) {
    double rate[6];
    model.stress_rate(stress, strain_rate, spin, rate);
    for (int m = 0; m < 6; m++) stress[m] += dt * rate[m];
    model.return_to_admissible(stress);
  }
}

// the in-plane maximum shear stress sqrt(((sxx - syy)/2)^2 + sxy^2)
inline double in_plane_shear(const double stress[6])
{
  const double half_difference = 0.5 * (stress[0] - stress[1]);
  return std::sqrt(half_difference * half_difference + stress[3] * stress[3]);
}

// Mohr-Coulomb's in-plane strength c cos(phi) - sigma_m sin(phi), sigma_m the in-plane mean
// (tension positive), phi in degrees
inline double mohr_coulomb_strength(double cohesion, double phi, const double stress[6])
{
  const double mean = 0.5 * (stress[0] + stress[1]);
  return cohesion * std::cos(phi * SPHSoil::DEG2RAD) - mean * std::sin(phi * SPHSoil::DEG2RAD);
}

}    // namespace SPHSoilTesting

#endif
