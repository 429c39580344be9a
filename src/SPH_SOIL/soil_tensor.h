/* -*- c++ -*- ----------------------------------------------------------
   SPH_SOIL package: symmetric tensors in Voigt order (pure, no LAMMPS).

   Conventions shared by the whole package:
   - stress is positive in tension;
   - symmetric tensors are double[6] in Voigt order xx, yy, zz, xy, xz, yz
     holding TENSOR components (strain rate xy = (g^xy + g^yx)/2, not the
     engineering shear rate); always 6 components: in 2D plane strain
     xz = yz = 0 and epsdot_zz = 0, while sigma_zz evolves;
   - the spin is double[3] = omega_xy, omega_xz, omega_yz with
     omega^ab = (g^ab - g^ba)/2, g^ab = dv^a/dx^b (so omega_yx = -omega_xy).
   Here: the Voigt table, invariants and measures, the Jaumann terms, Hooke's
   law in rate form and the principal stresses.
------------------------------------------------------------------------- */

#ifndef LMP_SOIL_TENSOR_H
#define LMP_SOIL_TENSOR_H

#include <cmath>

namespace SPHSoil {

/* ----------------------------------------------------------------------
   the Voigt table: component k holds the tensor's (VOIGT_ROW[k], VOIGT_COL[k]) entry, and
   entry (a, b) is component voigt_index(a, b); the one place that says so
------------------------------------------------------------------------- */

constexpr int VOIGT_ROW[6] = {0, 1, 2, 0, 0, 1};
constexpr int VOIGT_COL[6] = {0, 1, 2, 1, 2, 2};
constexpr int voigt_index(int a, int b)
{
  return a == b ? a : (a + b == 1 ? 3 : (a + b == 2 ? 4 : 5));
}

/* ----------------------------------------------------------------------
   invariants and measures of a Voigt tensor (inline: used in output loops)
------------------------------------------------------------------------- */

// first invariant I1 = trace
inline double first_invariant(const double stress[6])
{
  return stress[0] + stress[1] + stress[2];
}

// mean stress I1/3 (negative in compression)
inline double mean_stress(const double stress[6])
{
  return (stress[0] + stress[1] + stress[2]) / 3.0;
}

// pressure p = -I1/3 (positive in compression)
inline double pressure(const double stress[6])
{
  return -mean_stress(stress);
}

// J2 = s^ab s^ab / 2 with s the deviatoric stress; the shear components count
// twice in the full contraction
inline double second_invariant(const double stress[6])
{
  const double mean = mean_stress(stress);
  const double sxx = stress[0] - mean, syy = stress[1] - mean, szz = stress[2] - mean;
  return 0.5 * (sxx * sxx + syy * syy + szz * szz) + stress[3] * stress[3] +
         stress[4] * stress[4] + stress[5] * stress[5];
}

inline double sqrt_j2(const double stress[6])
{
  return std::sqrt(second_invariant(stress));
}

// the paper's refinement measure of the total strain: eps_xx^2 + eps_yy^2 + eps_zz^2
inline double strain_measure(const double strain[6])
{
  return strain[0] * strain[0] + strain[1] * strain[1] + strain[2] * strain[2];
}

// equivalent shear strain sqrt(2 e^ab e^ab) of a strain (or strain-rate) tensor, e its
// deviatoric part: gamma in simple shear (eps_xy = gamma / 2), blind to volume change; the
// shear components count twice in the contraction, so it is 2 sqrt(J2) of the tensor
inline double shear_strain(const double strain[6])
{
  return 2.0 * std::sqrt(second_invariant(strain));
}

/* ----------------------------------------------------------------------
   Jaumann terms of the stress rate, sigma^ag omega^bg + sigma^gb omega^ag, i.e. the
   matrix W sigma - sigma W with W^ab = omega^ab. Since W is antisymmetric and sigma
   symmetric, (sigma W)^ab = -(W sigma)^ba, so the term is M^ab + M^ba with M = W sigma.
   Under a rigid rotation x -> R x with dR/dt = W R this is exactly d(R sigma R^T)/dt.
   Written into `rate` (not added).
------------------------------------------------------------------------- */

inline void jaumann_terms(const double stress[6], const double spin[3], double rate[6])
{
  // M = W sigma written out (W has zeros on the diagonal: no multiplications by them)
  const double sxx = stress[0], syy = stress[1], szz = stress[2];
  const double sxy = stress[3], sxz = stress[4], syz = stress[5];
  const double wxy = spin[0], wxz = spin[1], wyz = spin[2];
  const double m00 = wxy * sxy + wxz * sxz;
  const double m11 = -wxy * sxy + wyz * syz;
  const double m22 = -wxz * sxz - wyz * syz;
  const double m01 = wxy * syy + wxz * syz, m10 = -wxy * sxx + wyz * sxz;
  const double m02 = wxy * syz + wxz * szz, m20 = -wxz * sxx - wyz * sxy;
  const double m12 = -wxy * sxz + wyz * szz, m21 = -wxz * sxy - wyz * syy;
  rate[0] = 2.0 * m00;
  rate[1] = 2.0 * m11;
  rate[2] = 2.0 * m22;
  rate[3] = m01 + m10;
  rate[4] = m02 + m20;
  rate[5] = m12 + m21;
}

// Hooke's law in rate form, added to `rate`: 2G (epsdot - epsdot^gg/3 delta) + K epsdot^gg delta
inline void add_elastic_rate(double bulk, double shear, const double strain_rate[6], double rate[6])
{
  const double volumetric_rate = strain_rate[0] + strain_rate[1] + strain_rate[2];
  const double normal_shift = (bulk - 2.0 * shear / 3.0) * volumetric_rate;
  for (int k = 0; k < 3; k++) rate[k] += 2.0 * shear * strain_rate[k] + normal_shift;
  for (int k = 3; k < 6; k++) rate[k] += 2.0 * shear * strain_rate[k];
}

// the in-plane principal stresses of a plane-strain stress (xz = yz = 0) as Mohr's circle:
// its centre (sxx + syy)/2 and radius sqrt(((sxx - syy)/2)^2 + sxy^2)
inline void mohr_circle(const double stress[6], double &center, double &radius)
{
  const double half_difference = 0.5 * (stress[0] - stress[1]);
  center = 0.5 * (stress[0] + stress[1]);
  radius = std::sqrt(half_difference * half_difference + stress[3] * stress[3]);
}

// eigenvalues (descending) and unit eigenvectors (vectors[k] belongs to values[k]) of a
// symmetric tensor in Voigt order; with xz = yz = 0 (plane strain) in closed form, z an
// eigenvector exactly; else by Jacobi rotations
void principal_stresses(const double stress[6], double values[3], double vectors[3][3]);


constexpr double DEG2RAD = 3.14159265358979323846 / 180.0;

}    // namespace SPHSoil

#endif
