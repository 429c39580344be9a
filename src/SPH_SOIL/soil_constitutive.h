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

   The integrator only talks to the abstract ConstitutiveModel. Models are
   chosen by keyword from the registry in soil_models.cpp: a new model is
   one file with its class (it parses and checks its own parameters and
   derives its constants once) and one line there. The models here:
   soil_drucker_prager.h, soil_mohr_coulomb.h.
------------------------------------------------------------------------- */

#ifndef LMP_SOIL_CONSTITUTIVE_H
#define LMP_SOIL_CONSTITUTIVE_H

#include <cmath>
#include <string>
#include <vector>

namespace SPHSoil {

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

/* ----------------------------------------------------------------------
   interface seen by the integrator
------------------------------------------------------------------------- */

class ConstitutiveModel {
 public:
  virtual ~ConstitutiveModel() = default;

  // the keyword that chose it (drucker_prager, mohr_coulomb)
  virtual const char *keyword() const = 0;

  // d(stress)/dt from the current stress, strain rate and spin: Jaumann terms + the
  // model's rate (elastic-plastic for a rate-form model, elastic for one whose plastic
  // correction is all in return_to_admissible())
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

  // P-wave modulus K + 4G/3 (Pa)
  virtual double p_wave_modulus() const = 0;
  // the largest mean stress I1/3 the model admits (Pa): 0 for a soil without cohesion,
  // infinity for one without a limit (phi = 0); > 0 means the soil can be in tension, where
  // SPH needs the artificial stress (pair_style sph/soil)
  virtual double tensile_strength() const = 0;

  // elastic P-wave speed sqrt((K + 4G/3)/rho0), for the time step and artificial viscosity
  double wave_speed(double reference_density) const
  {
    return std::sqrt(p_wave_modulus() / reference_density);
  }
};

/* ----------------------------------------------------------------------
   the parameters of a frictional soil, shared by the models that have them:
   linear elasticity (K, nu) and a Mohr-Coulomb strength (phi, c) with a
   dilatancy angle psi for the flow rule
------------------------------------------------------------------------- */

struct FrictionalParameters {
  double bulk_modulus = 0.0;       // K (Pa)
  double poisson_ratio = 0.0;      // nu
  double friction_angle = 0.0;     // phi (degrees)
  double dilatancy_angle = 0.0;    // psi (degrees)
  double cohesion = 0.0;           // c (Pa)

  // G = 3K (1 - 2nu) / (2 (1 + nu))
  double shear_modulus() const
  {
    return 3.0 * bulk_modulus * (1.0 - 2.0 * poisson_ratio) / (2.0 * (1.0 + poisson_ratio));
  }
  // empty if admissible, else which parameter is wrong, its value and its allowed range
  std::string check() const;

  // the same from Young's modulus: K = E / (3 (1 - 2 nu))
  static FrictionalParameters from_young_modulus(double young_modulus, double poisson_ratio,
                                                 double friction_angle, double dilatancy_angle,
                                                 double cohesion);
  // check() for parameters given as (E, nu, phi, psi, c): names E rather than K
  static std::string check_young_modulus(double young_modulus, double poisson_ratio,
                                         double friction_angle, double dilatancy_angle,
                                         double cohesion);

  // the order of the words of a material line, for messages
  static constexpr const char *WORDS = "K nu phi psi c";
  static constexpr int COUNT = 5;
  // K nu phi psi c from the first COUNT words (the model's keyword names it in errors); the
  // words after them go to `options`. False with the reason in `error` if a word is missing,
  // not a finite number, or the set fails check().
  static bool from_words(const std::string &model, const std::vector<std::string> &words,
                         FrictionalParameters &parameters, std::vector<std::string> &options,
                         std::string &error);
};

// the decimal form of a number for messages: 19.8, not 19.800000
std::string format_number(double value);
// a whole word as a finite number (the words of material lines); false if it is not one
bool parse_finite_number(const std::string &word, double &value);

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
