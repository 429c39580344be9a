/* -*- c++ -*- ----------------------------------------------------------
   SPH_SOIL package: the density's time step (pure, no LAMMPS).

   fix sph/soil steps the logarithm of the density (doc/theory.rst 4.1): rho <- rho exp(x), with
   x = dt drho/rho, so that the density stays positive for any rate (doc/theory.rst 2.1).
------------------------------------------------------------------------- */

#ifndef LMP_SOIL_DENSITY_STEP_H
#define LMP_SOIL_DENSITY_STEP_H

#include <cmath>

namespace SPHSoil {

// The least density, as a fraction of the material's: exp(-1). A particle that loses its
// neighbours keeps at least exp(-S) of its density, S < 1 the Shepard sum of its neighbours
// (doc/theory.rst 2.1); a density below exp(-1) is the continuity density's drift from the
// particles' positions (splits and merges around it change the sums, not the density), and its
// volume m / rho would weigh in its neighbours' sums out of all proportion.
constexpr double DENSITY_FLOOR = 0.36787944117144233;

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
