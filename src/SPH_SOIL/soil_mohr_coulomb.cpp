/* ----------------------------------------------------------------------
   SPH_SOIL package: Mohr-Coulomb soil model (pure, no LAMMPS).
   doc/theory.rst section 3.10.
------------------------------------------------------------------------- */

#include "soil_mohr_coulomb.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

using namespace SPHSoil;

/* ---------------------------------------------------------------------- */

std::string MohrCoulomb::check(const FrictionalParameters &parameters, double tension)
{
  const std::string problem = parameters.check();
  if (!problem.empty()) return problem;
  const double sin_phi = std::sin(parameters.friction_angle * DEG2RAD);
  const double apex = sin_phi > 0.0
      ? parameters.cohesion * std::cos(parameters.friction_angle * DEG2RAD) / sin_phi
      : std::numeric_limits<double>::infinity();
  return FrictionalParameters::check_tension(tension, apex, "the apex c cot(phi)");
}

MohrCoulomb::MohrCoulomb(const FrictionalParameters &parameters, double tension_cutoff) :
    params(parameters), tension(tension_cutoff)
{
  const std::string problem = check(parameters, tension_cutoff);
  if (!problem.empty()) throw std::invalid_argument(std::string(KEYWORD) + " " + problem);
  bulk = params.bulk_modulus;
  shear = params.shear_modulus();
  lame = bulk - 2.0 * shear / 3.0;
  const double phi = params.friction_angle * DEG2RAD;
  sin_phi = std::sin(phi);
  sin_psi = std::sin(params.dilatancy_angle * DEG2RAD);
  cohesion_term = 2.0 * params.cohesion * std::cos(phi);
  apex = sin_phi > 0.0 ? params.cohesion * std::cos(phi) / sin_phi : 0.0;
  // twice f and g: a_A = (1 + sin phi, 0, -1 + sin phi), N_A = (1 + sin psi, 0, -1 + sin psi),
  // D N = 2G N + lame tr(N) (1, 1, 1), tr N = 2 sin psi
  const double sp = sin_phi * sin_psi;
  face_stiffness = 4.0 * shear * (1.0 + sp) + 4.0 * lame * sp;
  edge_coupling_12 = 2.0 * shear * (1.0 - sin_phi) * (1.0 - sin_psi) + 4.0 * lame * sp;
  edge_coupling_23 = 2.0 * shear * (1.0 + sin_phi) * (1.0 + sin_psi) + 4.0 * lame * sp;
}

std::unique_ptr<ConstitutiveModel> MohrCoulomb::create(const std::vector<std::string> &words,
                                                       std::string &error)
{
  FrictionalParameters parameters;
  std::vector<std::string> options;
  if (!FrictionalParameters::from_words(KEYWORD, words, parameters, options, error)) return nullptr;
  double tension = std::numeric_limits<double>::infinity();
  for (size_t k = 0; k < options.size(); k += 2) {
    const std::string value = k + 1 < options.size() ? options[k + 1] : "";
    if (options[k] != "tension") {
      error = std::string(KEYWORD) + ": unknown option '" + options[k] + "' (allowed: " +
          usage_options(USAGE) + ")";
      return nullptr;
    }
    if (!FrictionalParameters::tension_from_word(KEYWORD, value, tension, error)) return nullptr;
  }
  const std::string problem = check(parameters, tension);
  if (!problem.empty()) {
    error = std::string(KEYWORD) + " " + problem;
    return nullptr;
  }
  return std::unique_ptr<ConstitutiveModel>(new MohrCoulomb(parameters, tension));
}

/* ---------------------------------------------------------------------- */

void MohrCoulomb::stress_rate(const double stress[6], const double strain_rate[6],
                              const double spin[3], double rate[6]) const
{
  jaumann_terms(stress, spin, rate);
  add_elastic_rate(bulk, shear, strain_rate, rate);
}

/* ----------------------------------------------------------------------
   Closest-point return for perfect plasticity. Each active face k lowers the
   trial stress by dgamma_k D N_k; with linear faces the consistency conditions
   are linear in the dgamma_k: one equation on a face, two on an edge.
------------------------------------------------------------------------- */

MohrCoulomb::Return MohrCoulomb::return_principal(double s[3]) const
{
  const double f_13 = yield_twice(s);
  if (!(f_13 > 0.0)) return Return::none;

  const double volumetric = 2.0 * lame * sin_psi;    // lame tr(N)
  const double up = 2.0 * shear * (1.0 + sin_psi) + volumetric;
  const double down = 2.0 * shear * (-1.0 + sin_psi) + volumetric;

  // face (sigma_1, sigma_3): D N = (up, volumetric, down)
  const double gamma = f_13 / face_stiffness;
  const double face[3] = {s[0] - gamma * up, s[1] - gamma * volumetric, s[2] - gamma * down};
  if (face[0] >= face[1] && face[1] >= face[2]) {
    for (int k = 0; k < 3; k++) s[k] = face[k];
    return Return::face;
  }

  // an edge: faces (1,3) and (1,2) or (2,3); the one the face return crossed first
  const double det_12 = face_stiffness * face_stiffness - edge_coupling_12 * edge_coupling_12;
  const double det_23 = face_stiffness * face_stiffness - edge_coupling_23 * edge_coupling_23;
  auto edge_12 = [&](double r[3]) {    // sigma_1 = sigma_2: faces (1,3) and (2,3)
    const double f_23 = (s[1] - s[2]) + (s[1] + s[2]) * sin_phi - cohesion_term;
    const double g_13 = (face_stiffness * f_13 - edge_coupling_12 * f_23) / det_12;
    const double g_23 = (face_stiffness * f_23 - edge_coupling_12 * f_13) / det_12;
    r[0] = s[0] - g_13 * up - g_23 * volumetric;
    r[1] = s[1] - g_13 * volumetric - g_23 * up;
    r[2] = s[2] - (g_13 + g_23) * down;
    const double top = 0.5 * (r[0] + r[1]);
    r[0] = r[1] = top;
    return g_13 >= 0.0 && g_23 >= 0.0 && top >= r[2];
  };
  auto edge_23 = [&](double r[3]) {    // sigma_2 = sigma_3: faces (1,3) and (1,2)
    const double f_12 = (s[0] - s[1]) + (s[0] + s[1]) * sin_phi - cohesion_term;
    const double g_13 = (face_stiffness * f_13 - edge_coupling_23 * f_12) / det_23;
    const double g_12 = (face_stiffness * f_12 - edge_coupling_23 * f_13) / det_23;
    r[0] = s[0] - (g_13 + g_12) * up;
    r[1] = s[1] - g_13 * volumetric - g_12 * down;
    r[2] = s[2] - g_13 * down - g_12 * volumetric;
    const double bottom = 0.5 * (r[1] + r[2]);
    r[1] = r[2] = bottom;
    return g_13 >= 0.0 && g_12 >= 0.0 && r[0] >= bottom;
  };
  double r[3];
  const bool crossed_12 = face[0] < face[1];
  if (crossed_12 ? edge_12(r) : edge_23(r)) {
    for (int k = 0; k < 3; k++) s[k] = r[k];
    return crossed_12 ? Return::edge_12 : Return::edge_23;
  }
  if (crossed_12 ? edge_23(r) : edge_12(r)) {
    for (int k = 0; k < 3; k++) s[k] = r[k];
    return crossed_12 ? Return::edge_23 : Return::edge_12;
  }

  // the apex c cot(phi); phi = 0 (Tresca) has none, and an edge always takes the stress
  for (int k = 0; k < 3; k++) s[k] = apex;
  return Return::apex;
}

/* ---------------------------------------------------------------------- */

bool MohrCoulomb::return_to_admissible(double stress[6]) const
{
  double values[3], vectors[3][3];
  principal_stresses(stress, values, vectors);
  bool returned = return_principal(values) != Return::none;
  // the tension cut-off (descending: the largest first)
  for (int k = 0; k < 3 && values[k] > tension; k++) {
    values[k] = tension;
    returned = true;
  }
  if (!returned) return false;
  for (int k = 0; k < 6; k++) stress[k] = 0.0;
  for (int k = 0; k < 3; k++)
    for (int m = 0; m < 6; m++)
      stress[m] += values[k] * vectors[k][VOIGT_ROW[m]] * vectors[k][VOIGT_COL[m]];
  return true;
}

/* ---------------------------------------------------------------------- */

double MohrCoulomb::yield_function(const double stress[6]) const
{
  double values[3], vectors[3][3];
  principal_stresses(stress, values, vectors);
  return std::max(0.5 * yield_twice(values), values[0] - tension);
}

bool MohrCoulomb::on_yield_surface(const double stress[6]) const
{
  double s[3], vectors[3][3];
  principal_stresses(stress, s, vectors);
  const double scale = (s[0] - s[2]) + std::fabs(s[0] + s[2]) * sin_phi + cohesion_term;
  const bool at_cutoff = std::isfinite(tension) &&
      s[0] - tension >= -YIELD_TOLERANCE * (std::fabs(s[0]) + tension);
  return yield_twice(s) >= -YIELD_TOLERANCE * scale || at_cutoff;
}

// out-of-class definitions: C++11/14 need them when the constants are bound to a reference
constexpr const char *MohrCoulomb::KEYWORD;
constexpr const char *MohrCoulomb::USAGE;
constexpr double MohrCoulomb::YIELD_TOLERANCE;
