/* ----------------------------------------------------------------------
   SPH_SOIL package: Drucker-Prager soil model (pure, no LAMMPS).
   doc/theory.rst section 3 (Bui et al. 2008).
------------------------------------------------------------------------- */

#include "soil_drucker_prager.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

using namespace SPHSoil;

namespace {

// the I1 coefficient of the flow potential g = sqrt(J2) + beta I1
double flow_beta(double dilatancy_angle)
{
  return 3.0 * std::sin(dilatancy_angle * DEG2RAD);
}

// alpha_phi and k_c of the plane-strain fit (see the header)
void cone(const DruckerPragerParameters &p, double &alpha, double &kc)
{
  const double phi = p.friction_angle * DEG2RAD;
  if (p.fit == DruckerPragerFit::associated) {
    const double tan_phi = std::tan(phi);
    const double root = std::sqrt(9.0 + 12.0 * tan_phi * tan_phi);
    alpha = tan_phi / root;
    kc = 3.0 * p.cohesion / root;
  } else {
    // nonassociated is the exact fit of psi = 0; for psi = 0 both lines below reduce to
    // sin(phi)/3 and c cos(phi) in floating point too (root = 1, beta = 0)
    const double beta = p.fit == DruckerPragerFit::exact ? flow_beta(p.dilatancy_angle) : 0.0;
    const double root = std::sqrt(1.0 - 3.0 * beta * beta);
    alpha = std::sin(phi) / (3.0 * (root + beta * std::sin(phi)));
    kc = p.cohesion * std::cos(phi) * (1.0 - 3.0 * alpha * beta) / root;
  }
}

// the apex's mean stress k_c / (3 alpha_phi): infinite for phi = 0
double apex_mean_stress(double alpha, double kc)
{
  return alpha > 0.0 ? kc / (3.0 * alpha) : std::numeric_limits<double>::infinity();
}

}    // namespace

double DruckerPrager::largest_exact_dilatancy()
{
  return std::asin(1.0 / (3.0 * std::sqrt(3.0))) / DEG2RAD;
}

std::string DruckerPrager::check(const DruckerPragerParameters &p)
{
  const std::string problem = p.check();
  if (!problem.empty()) return problem;
  const double beta = flow_beta(p.dilatancy_angle);
  if (p.fit == DruckerPragerFit::exact && !(3.0 * beta * beta < 1.0))
    return "fit exact: no plane-strain fit is exact for dilatancy angle psi = " +
        format_number(p.dilatancy_angle) + " degrees: the flow potential sqrt(J2) + 3 sin(psi) I1 " +
        "allows plastic flow in plane strain only for psi in [0, " +
        format_number(largest_exact_dilatancy()) + ") degrees; choose 'fit associated' or 'fit " +
        "nonassociated'";
  double alpha, kc;
  cone(p, alpha, kc);
  return FrictionalParameters::check_tension(p.tension, apex_mean_stress(alpha, kc),
                                             "the mean stress at the apex of the cone k_c / (3 alpha_phi)");
}

std::unique_ptr<ConstitutiveModel> DruckerPrager::create(const std::vector<std::string> &words,
                                                         std::string &error)
{
  DruckerPragerParameters parameters;
  std::vector<std::string> options;
  if (!FrictionalParameters::from_words(KEYWORD, words, parameters, options, error)) return nullptr;
  for (size_t k = 0; k < options.size(); k += 2) {
    const std::string value = k + 1 < options.size() ? options[k + 1] : "";
    if (options[k] == "fit") {
      if (value == "exact") parameters.fit = DruckerPragerFit::exact;
      else if (value == "associated") parameters.fit = DruckerPragerFit::associated;
      else if (value == "nonassociated") parameters.fit = DruckerPragerFit::nonassociated;
      else {
        error = std::string(KEYWORD) + " fit '" + value +
            "': must be exact, associated or nonassociated";
        return nullptr;
      }
    } else if (options[k] == "tension") {
      if (!FrictionalParameters::tension_from_word(KEYWORD, value, parameters.tension, error))
        return nullptr;
    } else {
      error = std::string(KEYWORD) + ": unknown option '" + options[k] + "' (allowed: " +
          usage_options(USAGE) + ")";
      return nullptr;
    }
  }
  const std::string problem = check(parameters);
  if (!problem.empty()) {
    error = std::string(KEYWORD) + " " + problem;
    return nullptr;
  }
  return std::unique_ptr<ConstitutiveModel>(new DruckerPrager(parameters));
}

/* ---------------------------------------------------------------------- */

DruckerPrager::DruckerPrager(const DruckerPragerParameters &parameters) : params(parameters)
{
  const std::string problem = check(parameters);
  if (!problem.empty()) throw std::invalid_argument(std::string(KEYWORD) + " " + problem);

  bulk = params.bulk_modulus;
  shear = params.shear_modulus();

  // plane-strain match of Drucker-Prager to Mohr-Coulomb (see the header); the tension cut-off
  cone(params, alpha, kc);
  largest_i1 = 3.0 * std::min(params.tension, apex_mean_stress(alpha, kc));

  const double sin_psi = std::sin(params.dilatancy_angle * DEG2RAD);
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
  add_elastic_rate(bulk, shear, strain_rate, rate);

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
  const double volumetric_rate = strain_rate[0] + strain_rate[1] + strain_rate[2];
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
   (1) moves I1 back to the tension cut-off 3T, at most the apex k_c/alpha_phi
   (Bui's rule), shear untouched. For phi = 0 without 'tension' there is no
   cut-off: the surface is the cylinder sqrt(J2) = k_c = c, only (2) acts.
------------------------------------------------------------------------- */

bool DruckerPrager::return_to_admissible(double stress[6]) const
{
  bool changed = false;
  double i1 = first_invariant(stress);

  // (1) tension cracking: move I1 back to the cut-off, shear untouched
  if (i1 > largest_i1) {
    const double shift = (i1 - largest_i1) / 3.0;
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
  const double i1 = first_invariant(stress);
  const double shear_surface = sqrt_j2(stress) + alpha * i1 - kc;
  // beyond a cut-off below the apex: the distance to it
  return std::max(shear_surface, (i1 - largest_i1) / 3.0);
}

/* ----------------------------------------------------------------------
   same test as the plastic branch of stress_rate(); a stress-free particle of
   a cohesionless soil sits at the apex and therefore counts as yielded
------------------------------------------------------------------------- */

bool DruckerPrager::on_yield_surface(const double stress[6]) const
{
  const double i1 = first_invariant(stress);
  const double root_j2 = sqrt_j2(stress);
  const double scale = root_j2 + alpha * std::fabs(i1) + kc;
  // on the cone, or cracked (at the tension cut-off)
  return root_j2 + alpha * i1 - kc >= -YIELD_TOLERANCE * scale ||
      i1 - largest_i1 >= -YIELD_TOLERANCE * (std::fabs(i1) + scale);
}

// out-of-class definitions: C++11/14 need them when the constants are bound to a reference
constexpr const char *DruckerPrager::KEYWORD;
constexpr const char *DruckerPrager::USAGE;
constexpr double DruckerPrager::YIELD_TOLERANCE;
constexpr double DruckerPrager::SQUARED_MARGIN;
