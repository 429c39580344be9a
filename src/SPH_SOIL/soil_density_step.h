/* -*- c++ -*- ----------------------------------------------------------
   SPH_SOIL package: the density's time step (pure, no LAMMPS).

   fix sph/soil steps the logarithm of the density (doc/theory.rst 4.1): rho <- rho exp(x), with
   x = dt drho/rho, so that the density stays positive for any rate (doc/theory.rst 2.1).
------------------------------------------------------------------------- */

#ifndef LMP_SOIL_DENSITY_STEP_H
#define LMP_SOIL_DENSITY_STEP_H

#include <cmath>

namespace SPHSoil {

// exp(x). A stable step changes the density by far less than 0.1% (|x| ~ 1e-5 in a collapse at
// the CFL limit): there the series to x^4 (relative error below x^5/120 < 1e-17, round-off)
// costs a few multiplications where std::exp costs some 40 instructions, twice per
// particle-step.
inline double density_growth(double x)
{
  if (std::fabs(x) < 1.0e-3) return 1.0 + x * (1.0 + x * (0.5 + x * (1.0 / 6.0 + x * (1.0 / 24.0))));
  return std::exp(x);
}

}    // namespace SPHSoil

#endif
