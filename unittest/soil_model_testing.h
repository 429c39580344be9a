// Helpers shared by the tests of the constitutive models (no LAMMPS).
#ifndef SPH_SOIL_MODEL_TESTING_H
#define SPH_SOIL_MODEL_TESTING_H

#include "soil_constitutive.h"

#include <cmath>

namespace SPHSoilTesting {

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
