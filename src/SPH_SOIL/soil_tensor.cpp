/* ----------------------------------------------------------------------
   SPH_SOIL package: principal stresses (pure, no LAMMPS)
------------------------------------------------------------------------- */

#include "soil_tensor.h"

#include <cmath>
#include <utility>

using namespace SPHSoil;

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
  double a[3][3];
  for (int r = 0; r < 3; r++)
    for (int c = 0; c < 3; c++) a[r][c] = stress[voigt_index(r, c)];
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

