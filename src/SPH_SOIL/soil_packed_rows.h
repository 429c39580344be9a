/* -*- c++ -*- ----------------------------------------------------------
   SPH_SOIL package: the pair loop's packed rows (pure, no LAMMPS).

   pair_style sph/soil copies the per-atom inputs of its sums once per step into
   one row of PACKED doubles per owned and ghost atom, so that a neighbour costs
   two cache lines instead of a load from each of eight arrays: position,
   velocity (a soil particle's estimate of v(t + dt); a wall particle's own, or
   for an extrapolated wall its image's), stress / rho^2 (Voigt), volume m / rho,
   mass, density, h. The walls' code reads and writes the same rows.
------------------------------------------------------------------------- */

#ifndef LMP_SOIL_PACKED_ROWS_H
#define LMP_SOIL_PACKED_ROWS_H

namespace SPHSoil {

enum PackedRow { P_X = 0, P_V = 3, P_STRESS = 6, P_VOLUME = 12, P_MASS = 13, P_RHO = 14, P_H = 15,
                 PACKED = 16 };

}    // namespace SPHSoil

#endif
