/* ----------------------------------------------------------------------
   SPH_SOIL package: constitutive models of the soil (pure, no LAMMPS).
   Drucker-Prager as in doc/theory.rst section 3 (Bui et al. 2008).
------------------------------------------------------------------------- */

#include "soil_constitutive.h"

#include "soil_material.h"

#include <cmath>
#include <sstream>
#include <stdexcept>

using namespace SPHSoil;

namespace {

constexpr double DEG2RAD = 3.14159265358979323846 / 180.0;

std::string format(double value)
{
  std::ostringstream out;
  out << value;
  return out.str();
}

// Jaumann terms of the stress rate, sigma^ag omega^bg + sigma^gb omega^ag, i.e. the
// matrix W sigma - sigma W with W^ab = omega^ab. Since W is antisymmetric and sigma
// symmetric, (sigma W)^ab = -(W sigma)^ba, so the term is M^ab + M^ba with M = W sigma.
// Under a rigid rotation x -> R x with dR/dt = W R this is exactly d(R sigma R^T)/dt.
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

}    // namespace

/* ---------------------------------------------------------------------- */

DruckerPragerParameters DruckerPragerParameters::from_young_modulus(
    double young_modulus, double poisson_ratio, double friction_angle, double dilatancy_angle,
    double cohesion)
{
  DruckerPragerParameters parameters;
  parameters.bulk_modulus = young_modulus / (3.0 * (1.0 - 2.0 * poisson_ratio));
  parameters.poisson_ratio = poisson_ratio;
  parameters.friction_angle = friction_angle;
  parameters.dilatancy_angle = dilatancy_angle;
  parameters.cohesion = cohesion;
  return parameters;
}

/* ----------------------------------------------------------------------
   the negated comparisons also reject NaN
------------------------------------------------------------------------- */

std::string DruckerPrager::check(const DruckerPragerParameters &p)
{
  if (!(p.bulk_modulus > 0.0 && std::isfinite(p.bulk_modulus)))
    return "bulk modulus K = " + format(p.bulk_modulus) + " must be finite and > 0";
  if (!(p.poisson_ratio > -1.0 && p.poisson_ratio < 0.5))
    return "Poisson ratio nu = " + format(p.poisson_ratio) + " must be in (-1, 0.5)";
  if (!(p.friction_angle >= 0.0 && p.friction_angle < 90.0))
    return "friction angle phi = " + format(p.friction_angle) + " must be in [0, 90) degrees";
  if (!(p.dilatancy_angle >= 0.0 && p.dilatancy_angle <= p.friction_angle))
    return "dilatancy angle psi = " + format(p.dilatancy_angle) + " must be in [0, phi = " +
        format(p.friction_angle) + "] degrees";
  if (!(p.cohesion >= 0.0 && std::isfinite(p.cohesion)))
    return "cohesion c = " + format(p.cohesion) + " must be finite and >= 0";
  return "";
}

std::string DruckerPrager::check_young_modulus(double young_modulus, double poisson_ratio,
                                               double friction_angle, double dilatancy_angle,
                                               double cohesion)
{
  if (!(young_modulus > 0.0 && std::isfinite(young_modulus)))
    return "Young's modulus E = " + format(young_modulus) + " must be finite and > 0";
  // nu before K: a bad nu would otherwise show up as a puzzling K
  if (!(poisson_ratio > -1.0 && poisson_ratio < 0.5))
    return "Poisson ratio nu = " + format(poisson_ratio) + " must be in (-1, 0.5)";
  return check(DruckerPragerParameters::from_young_modulus(young_modulus, poisson_ratio,
                                                           friction_angle, dilatancy_angle,
                                                           cohesion));
}

/* ---------------------------------------------------------------------- */

DruckerPrager::DruckerPrager(const DruckerPragerParameters &parameters) : params(parameters)
{
  const std::string problem = check(parameters);
  if (!problem.empty()) throw std::invalid_argument("Drucker-Prager: " + problem);

  bulk = params.bulk_modulus;
  const double nu = params.poisson_ratio;
  shear = 3.0 * bulk * (1.0 - 2.0 * nu) / (2.0 * (1.0 + nu));

  // plane-strain match of Drucker-Prager to Mohr-Coulomb (see the header)
  const double phi = params.friction_angle * DEG2RAD;
  if (params.fit == DruckerPragerFit::nonassociated) {
    alpha = std::sin(phi) / 3.0;
    kc = params.cohesion * std::cos(phi);
  } else {
    const double tan_phi = std::tan(phi);
    const double root = std::sqrt(9.0 + 12.0 * tan_phi * tan_phi);
    alpha = tan_phi / root;
    kc = 3.0 * params.cohesion / root;
  }

  sin_psi = std::sin(params.dilatancy_angle * DEG2RAD);
  flow_volumetric = 9.0 * bulk * sin_psi;
  plastic_denominator = 27.0 * alpha * bulk * sin_psi + shear;
  p_modulus = bulk + 4.0 * shear / 3.0;
}

/* ----------------------------------------------------------------------
   Jaumann terms + 2G edot + K epsdot^gg delta - lambdadot (9 K sin(psi) delta + G s/sqrt(J2))

   The plastic term applies when the stress is on the yield surface within
   YIELD_TOLERANCE and lambdadot > 0. The tolerance is relative to
   sqrt(J2) + alpha_phi |I1| + k_c, the size of the terms that make up f:
   a stress just returned by return_to_admissible() has |f| of a few 1e-16
   of that, so an exact f >= 0 test would miss about half of the particles
   that sit on the surface (their plastic dilatancy would be lost and the
   radial scaling would do all the work), while 1e-10 is far below any
   physically meaningful distance to the surface.
   At sqrt(J2) = 0 (the apex for c = 0, i.e. a stress-free particle) the flow
   direction is undefined: the rate is elastic and the return mapping acts.
------------------------------------------------------------------------- */

void DruckerPrager::stress_rate(const double stress[6], const double strain_rate[6],
                                const double spin[3], double rate[6]) const
{
  jaumann_terms(stress, spin, rate);

  // elastic: 2G (epsdot - epsdot^gg/3 delta) + K epsdot^gg delta
  const double volumetric_rate = strain_rate[0] + strain_rate[1] + strain_rate[2];
  const double normal_shift = (bulk - 2.0 * shear / 3.0) * volumetric_rate;
  for (int k = 0; k < 3; k++) rate[k] += 2.0 * shear * strain_rate[k] + normal_shift;
  for (int k = 3; k < 6; k++) rate[k] += 2.0 * shear * strain_rate[k];

  // plastic
  const double i1 = first_invariant(stress);
  const double mean = i1 / 3.0;
  const double deviator[6] = {stress[0] - mean, stress[1] - mean, stress[2] - mean,
                              stress[3], stress[4], stress[5]};
  const double j2 = second_invariant(stress);
  // well inside the surface (the test below, made certain without the square root by
  // bounding its tolerance from above with sqrt(J2) <= radius): elastic
  const double radius = kc - alpha * i1;
  const double margin = radius - YIELD_TOLERANCE * (radius + alpha * std::fabs(i1) + kc);
  if (margin > 0.0 && j2 < (1.0 - SQUARED_MARGIN) * margin * margin) return;
  const double root_j2 = std::sqrt(j2);
  if (!(root_j2 > 0.0)) return;
  const double f = root_j2 + alpha * i1 - kc;
  if (f < -YIELD_TOLERANCE * (root_j2 + alpha * std::fabs(i1) + kc)) return;

  // s^ab epsdot^ab, shear components twice
  const double s_dot_strain_rate = deviator[0] * strain_rate[0] + deviator[1] * strain_rate[1] +
      deviator[2] * strain_rate[2] +
      2.0 * (deviator[3] * strain_rate[3] + deviator[4] * strain_rate[4] + deviator[5] * strain_rate[5]);
  const double g_over_root_j2 = shear / root_j2;
  const double lambdadot =
      (3.0 * alpha * bulk * volumetric_rate + g_over_root_j2 * s_dot_strain_rate) / plastic_denominator;
  if (!(lambdadot > 0.0)) return;    // elastic unloading

  for (int k = 0; k < 3; k++) rate[k] -= lambdadot * (flow_volumetric + g_over_root_j2 * deviator[k]);
  for (int k = 3; k < 6; k++) rate[k] -= lambdadot * g_over_root_j2 * deviator[k];
}

/* ----------------------------------------------------------------------
   Bui 2008's return: (1) tension cracking, (2) radial scaling of the deviator.
   For phi = 0 (alpha_phi = 0) the cracking rule -alpha I1 + k_c < 0 can never
   fire (k_c >= 0) and k_c/alpha is undefined: the surface is the cylinder
   sqrt(J2) = k_c = c with no tension cap, so only (2) acts.
------------------------------------------------------------------------- */

bool DruckerPrager::return_to_admissible(double stress[6]) const
{
  bool changed = false;
  double i1 = first_invariant(stress);

  // (1) tension cracking: move I1 back to the apex k_c/alpha, shear untouched
  if (alpha > 0.0 && kc - alpha * i1 < 0.0) {
    const double shift = (i1 - kc / alpha) / 3.0;
    for (int k = 0; k < 3; k++) stress[k] -= shift;
    i1 = first_invariant(stress);
    changed = true;
  }

  // (2) stress scaling. After (1), k_c - alpha I1 may be a round-off below 0:
  // clamp it, a negative factor would flip the deviator.
  const double distance = kc - alpha * i1;
  const double radius = distance > 0.0 ? distance : 0.0;
  // most particles are well inside: no square root for them (the margin keeps the
  // decision identical to the exact test below)
  const double j2 = second_invariant(stress);
  if (j2 <= (1.0 - SQUARED_MARGIN) * radius * radius) return changed;
  const double mean = i1 / 3.0;
  const double root_j2 = std::sqrt(j2);
  if (root_j2 > radius) {
    const double factor = radius / root_j2;
    for (int k = 0; k < 3; k++) stress[k] = mean + factor * (stress[k] - mean);
    for (int k = 3; k < 6; k++) stress[k] *= factor;
    changed = true;
  }
  return changed;
}

/* ---------------------------------------------------------------------- */

double DruckerPrager::yield_function(const double stress[6]) const
{
  return sqrt_j2(stress) + alpha * first_invariant(stress) - kc;
}

/* ----------------------------------------------------------------------
   same test as the plastic branch of stress_rate(); a stress-free particle of
   a cohesionless soil sits at the apex and therefore counts as yielded
------------------------------------------------------------------------- */

bool DruckerPrager::on_yield_surface(const double stress[6]) const
{
  const double i1 = first_invariant(stress);
  const double root_j2 = sqrt_j2(stress);
  return root_j2 + alpha * i1 - kc >= -YIELD_TOLERANCE * (root_j2 + alpha * std::fabs(i1) + kc);
}

/* ---------------------------------------------------------------------- */

double DruckerPrager::wave_speed(double reference_density) const
{
  return std::sqrt(p_modulus / reference_density);
}

/* ---------------------------------------------------------------------- */

std::unique_ptr<ConstitutiveModel> SPHSoil::make_constitutive_model(const SoilMaterial &material,
                                                                    DruckerPragerFit fit)
{
  if (material.wall) return std::unique_ptr<ConstitutiveModel>();
  DruckerPragerParameters parameters;
  parameters.bulk_modulus = material.bulk_modulus;
  parameters.poisson_ratio = material.poisson_ratio;
  parameters.friction_angle = material.friction_angle;
  parameters.dilatancy_angle = material.dilatancy_angle;
  parameters.cohesion = material.cohesion;
  parameters.fit = fit;
  return std::unique_ptr<ConstitutiveModel>(new DruckerPrager(parameters));
}

// out-of-class definition: C++11/14 need it when the constant is bound to a reference
constexpr double DruckerPrager::YIELD_TOLERANCE;
constexpr double DruckerPrager::SQUARED_MARGIN;
