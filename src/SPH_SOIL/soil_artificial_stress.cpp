/* ----------------------------------------------------------------------
   SPH_SOIL package: artificial stress (pure, no LAMMPS); see the header
------------------------------------------------------------------------- */

#include "soil_artificial_stress.h"

void SPHSoil::artificial_stress(const double stress[6], double density, double epsilon, double R[6])
{
  for (int k = 0; k < 6; k++) R[k] = 0.0;
  double values[3], vectors[3][3];
  principal_stresses(stress, values, vectors);
  if (!(values[0] > 0.0)) return;    // no tension: descending, the largest is not positive
  const double scale = -epsilon / (density * density);
  for (int i = 0; i < 3; i++) {
    if (!(values[i] > 0.0)) continue;
    const double r = scale * values[i];
    for (int k = 0; k < 6; k++) R[k] += r * vectors[i][VOIGT_ROW[k]] * vectors[i][VOIGT_COL[k]];
  }
}
