/* ----------------------------------------------------------------------
   SPH_SOIL package: what the constitutive models share (pure, no LAMMPS)
------------------------------------------------------------------------- */

#include "soil_constitutive.h"

#include <cmath>
#include <cstdlib>
#include <utility>
#include <sstream>

using namespace SPHSoil;

std::string SPHSoil::format_number(double value)
{
  std::ostringstream out;
  out << value;
  return out.str();
}

bool SPHSoil::parse_finite_number(const std::string &word, double &value)
{
  char *end = nullptr;
  value = std::strtod(word.c_str(), &end);
  return !word.empty() && end && *end == '\0' && std::isfinite(value);
}

/* ----------------------------------------------------------------------
   the negated comparisons also reject NaN
------------------------------------------------------------------------- */

std::string FrictionalParameters::check() const
{
  if (!(bulk_modulus > 0.0 && std::isfinite(bulk_modulus)))
    return "bulk modulus K = " + format_number(bulk_modulus) + " must be finite and > 0";
  if (!(poisson_ratio > -1.0 && poisson_ratio < 0.5))
    return "Poisson ratio nu = " + format_number(poisson_ratio) + " must be in (-1, 0.5)";
  if (!(friction_angle >= 0.0 && friction_angle < 90.0))
    return "friction angle phi = " + format_number(friction_angle) + " must be in [0, 90) degrees";
  if (!(dilatancy_angle >= 0.0 && dilatancy_angle <= friction_angle))
    return "dilatancy angle psi = " + format_number(dilatancy_angle) + " must be in [0, phi = " +
        format_number(friction_angle) + "] degrees";
  if (!(cohesion >= 0.0 && std::isfinite(cohesion)))
    return "cohesion c = " + format_number(cohesion) + " must be finite and >= 0";
  return "";
}

FrictionalParameters FrictionalParameters::from_young_modulus(double young_modulus,
                                                              double poisson_ratio,
                                                              double friction_angle,
                                                              double dilatancy_angle, double cohesion)
{
  FrictionalParameters parameters;
  parameters.bulk_modulus = young_modulus / (3.0 * (1.0 - 2.0 * poisson_ratio));
  parameters.poisson_ratio = poisson_ratio;
  parameters.friction_angle = friction_angle;
  parameters.dilatancy_angle = dilatancy_angle;
  parameters.cohesion = cohesion;
  return parameters;
}

std::string FrictionalParameters::check_young_modulus(double young_modulus, double poisson_ratio,
                                                      double friction_angle, double dilatancy_angle,
                                                      double cohesion)
{
  if (!(young_modulus > 0.0 && std::isfinite(young_modulus)))
    return "Young's modulus E = " + format_number(young_modulus) + " must be finite and > 0";
  // nu before K: a bad nu would otherwise show up as a puzzling K
  if (!(poisson_ratio > -1.0 && poisson_ratio < 0.5))
    return "Poisson ratio nu = " + format_number(poisson_ratio) + " must be in (-1, 0.5)";
  return from_young_modulus(young_modulus, poisson_ratio, friction_angle, dilatancy_angle, cohesion)
      .check();
}

bool FrictionalParameters::from_words(const std::string &model, const std::vector<std::string> &words,
                                      FrictionalParameters &parameters,
                                      std::vector<std::string> &options, std::string &error)
{
  static const char *const names[COUNT] = {"K", "nu", "phi", "psi", "c"};
  if ((int) words.size() < COUNT) {
    error = model + " needs " + std::to_string(COUNT) + " parameters (" + WORDS + "), got " +
        std::to_string(words.size());
    return false;
  }
  double values[COUNT];
  for (int k = 0; k < COUNT; k++) {
    if (!parse_finite_number(words[k], values[k])) {
      error = model + " parameter " + names[k] + ": '" + words[k] + "' is not a finite number";
      return false;
    }
  }
  parameters = FrictionalParameters();
  parameters.bulk_modulus = values[0];
  parameters.poisson_ratio = values[1];
  parameters.friction_angle = values[2];
  parameters.dilatancy_angle = values[3];
  parameters.cohesion = values[4];
  const std::string problem = parameters.check();
  if (!problem.empty()) {
    error = model + " " + problem;
    return false;
  }
  options.assign(words.begin() + COUNT, words.end());
  return true;
}

// out-of-class definitions: C++11/14 need them when the constants are bound to a reference
constexpr const char *FrictionalParameters::WORDS;
constexpr int FrictionalParameters::COUNT;

namespace {

// sort three eigenpairs into descending order of value
void sort_descending(double values[3], double vectors[3][3])
{
  for (int pass = 0; pass < 2; pass++)
    for (int k = 0; k < 2 - pass; k++)
      if (values[k] < values[k + 1]) {
        std::swap(values[k], values[k + 1]);
        for (int a = 0; a < 3; a++) std::swap(vectors[k][a], vectors[k + 1][a]);
      }
}

// cyclic Jacobi rotations of a symmetric 3x3 matrix: converges quadratically, a handful of
// sweeps to round-off
void jacobi_eigen(const double stress[6], double values[3], double vectors[3][3])
{
  double a[3][3] = {{stress[0], stress[3], stress[4]},
                    {stress[3], stress[1], stress[5]},
                    {stress[4], stress[5], stress[2]}};
  double v[3][3] = {{1.0, 0.0, 0.0}, {0.0, 1.0, 0.0}, {0.0, 0.0, 1.0}};
  static const int pairs[3][2] = {{0, 1}, {0, 2}, {1, 2}};
  for (int sweep = 0; sweep < 32; sweep++) {
    const double off = a[0][1] * a[0][1] + a[0][2] * a[0][2] + a[1][2] * a[1][2];
    const double diagonal = a[0][0] * a[0][0] + a[1][1] * a[1][1] + a[2][2] * a[2][2];
    if (off <= 1.0e-34 * diagonal || off == 0.0) break;
    for (const auto &pq : pairs) {
      const int p = pq[0], q = pq[1];
      if (a[p][q] == 0.0) continue;
      const double theta = (a[q][q] - a[p][p]) / (2.0 * a[p][q]);
      const double t = (theta >= 0.0 ? 1.0 : -1.0) / (std::fabs(theta) + std::sqrt(theta * theta + 1.0));
      const double c = 1.0 / std::sqrt(t * t + 1.0), s = t * c;
      for (int k = 0; k < 3; k++) {    // A P
        const double akp = a[k][p], akq = a[k][q];
        a[k][p] = c * akp - s * akq;
        a[k][q] = s * akp + c * akq;
      }
      for (int k = 0; k < 3; k++) {    // P^T (A P)
        const double apk = a[p][k], aqk = a[q][k];
        a[p][k] = c * apk - s * aqk;
        a[q][k] = s * apk + c * aqk;
      }
      for (int k = 0; k < 3; k++) {    // V P
        const double vkp = v[k][p], vkq = v[k][q];
        v[k][p] = c * vkp - s * vkq;
        v[k][q] = s * vkp + c * vkq;
      }
    }
  }
  for (int k = 0; k < 3; k++) {
    values[k] = a[k][k];
    for (int c = 0; c < 3; c++) vectors[k][c] = v[c][k];
  }
}

}    // namespace

/* ----------------------------------------------------------------------
   plane strain (xz = yz = 0, every 2D particle): the in-plane pair in closed
   form and z exactly; otherwise Jacobi
------------------------------------------------------------------------- */

void SPHSoil::principal_stresses(const double stress[6], double values[3], double vectors[3][3])
{
  if (stress[4] == 0.0 && stress[5] == 0.0) {
    double center, radius;
    mohr_circle(stress, center, radius);
    const double angle = 0.5 * std::atan2(stress[3], 0.5 * (stress[0] - stress[1]));
    const double c = std::cos(angle), s = std::sin(angle);
    values[0] = center + radius;
    values[1] = center - radius;
    values[2] = stress[2];
    const double in_plane[3][3] = {{c, s, 0.0}, {-s, c, 0.0}, {0.0, 0.0, 1.0}};
    for (int k = 0; k < 3; k++)
      for (int a = 0; a < 3; a++) vectors[k][a] = in_plane[k][a];
  } else {
    jacobi_eigen(stress, values, vectors);
  }
  sort_descending(values, vectors);
}

