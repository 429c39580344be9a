/* -*- c++ -*- ----------------------------------------------------------
   SPH_SOIL package: constitutive models of the soil (pure, no LAMMPS).

   Conventions shared with pair_style sph/soil and fix sph/soil:
   - stress is positive in tension;
   - symmetric tensors are double[6] in Voigt order xx, yy, zz, xy, xz, yz
     holding TENSOR components (strain rate xy = (g^xy + g^yx)/2, not the
     engineering shear rate); always 6 components: in 2D plane strain
     xz = yz = 0 and epsdot_zz = 0, while sigma_zz evolves;
   - the spin is double[3] = omega_xy, omega_xz, omega_yz with
     omega^ab = (g^ab - g^ba)/2, g^ab = dv^a/dx^b (so omega_yx = -omega_xy).

   The integrator only talks to the abstract ConstitutiveModel, so other
   models (Mohr-Coulomb, cohesive Drucker-Prager with artificial stress,
   ...) can be added here and chosen in make_constitutive_model() without
   touching the pair style or the fix.
------------------------------------------------------------------------- */

#ifndef LMP_SOIL_CONSTITUTIVE_H
#define LMP_SOIL_CONSTITUTIVE_H

#include <cmath>
#include <memory>
#include <string>

namespace SPHSoil {

struct SoilMaterial;

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

/* ----------------------------------------------------------------------
   interface seen by the integrator
------------------------------------------------------------------------- */

class ConstitutiveModel {
 public:
  virtual ~ConstitutiveModel() = default;

  // d(stress)/dt from the current stress, strain rate and spin:
  // Jaumann terms + elastic-plastic part
  virtual void stress_rate(const double stress[6], const double strain_rate[6],
                           const double spin[3], double rate[6]) const = 0;

  // bring a stress back to the admissible set after an update;
  // returns true if it changed the stress
  virtual bool return_to_admissible(double stress[6]) const = 0;

  // > 0 outside the admissible set, 0 on its boundary (in stress units)
  virtual double yield_function(const double stress[6]) const = 0;

  // true if the stress is on (or outside) the yield surface within the model's
  // tolerance: the "yielded" flag of the output
  virtual bool on_yield_surface(const double stress[6]) const = 0;

  // elastic P-wave speed sqrt((K + 4G/3)/rho0), for the time step and artificial viscosity
  virtual double wave_speed(double reference_density) const = 0;
};

/* ----------------------------------------------------------------------
   Drucker-Prager, non-associated, perfectly plastic, plane-strain fit to
   Mohr-Coulomb (Bui et al. 2008; doc/theory.rst section 3):
     f = sqrt(J2) + alpha_phi I1 - k_c,   g = sqrt(J2) + 3 I1 sin(psi)
   with one of two plane-strain fits (DruckerPragerFit):
     associated (Bui 2008; exact for associated flow, psi = phi):
       alpha_phi = tan(phi)/sqrt(9 + 12 tan^2 phi),  k_c = 3c/sqrt(9 + 12 tan^2 phi)
     nonassociated (exact for psi = 0: no plastic volume change, so s_zz = 0
     on the surface and sqrt(J2) is the in-plane maximum shear stress):
       alpha_phi = sin(phi)/3,  k_c = c cos(phi)
   phi = 0 gives a pressure-independent (von Mises-like) surface sqrt(J2) <= c
   with no tension cap (both fits agree there).
------------------------------------------------------------------------- */

enum class DruckerPragerFit { associated, nonassociated };

struct DruckerPragerParameters {
  double bulk_modulus = 0.0;       // K (Pa)
  double poisson_ratio = 0.0;      // nu
  double friction_angle = 0.0;     // phi (degrees)
  double dilatancy_angle = 0.0;    // psi (degrees)
  double cohesion = 0.0;           // c (Pa)
  DruckerPragerFit fit = DruckerPragerFit::associated;    // plane-strain fit to Mohr-Coulomb

  // the same from Young's modulus: K = E / (3 (1 - 2 nu))
  static DruckerPragerParameters from_young_modulus(double young_modulus, double poisson_ratio,
                                                    double friction_angle, double dilatancy_angle,
                                                    double cohesion);
};

class DruckerPrager final : public ConstitutiveModel {
 public:
  // relative distance to the yield surface below which a stress counts as on it,
  // in units of sqrt(J2) + alpha_phi |I1| + k_c (see soil_constitutive.cpp)
  static constexpr double YIELD_TOLERANCE = 1.0e-10;
  // J2 below (1 - SQUARED_MARGIN) r^2 means sqrt(J2) < r whatever the rounding of the square
  // root (0.5 ulp): the tests that decide "inside" skip the square root with no change of result
  static constexpr double SQUARED_MARGIN = 1.0e-12;

  // the parameters must pass check(); throws std::invalid_argument otherwise
  explicit DruckerPrager(const DruckerPragerParameters &parameters);

  // empty if the parameters are admissible, else which one is wrong and its allowed range
  static std::string check(const DruckerPragerParameters &parameters);
  // the same for parameters given as (E, nu, phi, psi, c): names E rather than K
  static std::string check_young_modulus(double young_modulus, double poisson_ratio,
                                         double friction_angle, double dilatancy_angle,
                                         double cohesion);

  void stress_rate(const double stress[6], const double strain_rate[6], const double spin[3],
                   double rate[6]) const override;
  bool return_to_admissible(double stress[6]) const override;
  double yield_function(const double stress[6]) const override;
  bool on_yield_surface(const double stress[6]) const override;
  double wave_speed(double reference_density) const override;

  const DruckerPragerParameters &parameters() const { return params; }
  double bulk_modulus() const { return bulk; }
  double shear_modulus() const { return shear; }
  double alpha_phi() const { return alpha; }
  double k_c() const { return kc; }

 private:
  DruckerPragerParameters params;
  double bulk, shear;          // K, G
  double alpha, kc;            // alpha_phi, k_c
  double sin_psi;              // sin(dilatancy angle)
  double flow_volumetric;      // 9 K sin(psi): volumetric part of the plastic stress rate
  double plastic_denominator;  // 27 alpha_phi K sin(psi) + G, > 0
  double p_modulus;            // K + 4G/3
};

// The model of a soil material (nullptr for a wall). Today always Drucker-Prager, with the
// given fit to Mohr-Coulomb; this is where a material keyword would pick another model.
// Throws std::invalid_argument if the material's parameters are not admissible.
std::unique_ptr<ConstitutiveModel>
make_constitutive_model(const SoilMaterial &material,
                        DruckerPragerFit fit = DruckerPragerFit::associated);

}    // namespace SPHSoil

#endif
