/* -*- c++ -*- ----------------------------------------------------------
   SPH_SOIL package: the geometry of one particle split and the CSPM
   interpolation of the daughters' state (pure, no LAMMPS). doc/theory.rst section 5.3.

   A parent of spacing d_p is replaced by M = 2^D daughters at the corners of
   an axis-aligned square (cube) of side separation * d_p centred on it, with
   mass m_p / M, the parent's velocity, smoothing length smoothing_ratio * h_p.
   Every other state variable is interpolated at the daughter's position by
   the corrected SPH (CSPM) average over the parent's neighbours:
     f(x_d) = sum_j V_j f_j W(x_d - x_j, h_j) / sum_j V_j W(x_d - x_j, h_j),
   V_j = m_j / rho_j, which reproduces a constant field exactly.
------------------------------------------------------------------------- */

#ifndef LMP_SOIL_REFINE_SPLIT_H
#define LMP_SOIL_REFINE_SPLIT_H

#include "soil_kernels.h"

#include <cmath>

namespace SPHSoil {

constexpr int MAX_DAUGHTERS = 8;
// the deepest refinement level: a level-30 particle has 2^-30 of the original spacing, and a
// particle split down to it 4^30 (2D) daughters, beyond any run; 2^level must fit an int
constexpr int MAX_LEVEL = 30;

inline int daughter_count(int dimension)
{
  return dimension == 3 ? 8 : 4;
}

// Offsets of the daughters from the parent: (+-s/2, +-s/2[, +-s/2]) with s = separation * d_p,
// in a fixed order (x fastest) so that daughter k is the same on every rank.
inline int daughter_offsets(int dimension, double separation, double parent_spacing,
                            double offsets[MAX_DAUGHTERS][3])
{
  const int count = daughter_count(dimension);
  const double half = 0.5 * separation * parent_spacing;
  for (int k = 0; k < count; k++) {
    offsets[k][0] = (k & 1) ? half : -half;
    offsets[k][1] = (k & 2) ? half : -half;
    offsets[k][2] = dimension == 3 ? ((k & 4) ? half : -half) : 0.0;
  }
  return count;
}

// The spacing of a particle of refinement level `level`: d_ref halves at each level.
inline double level_spacing(double reference_spacing, int level)
{
  return std::ldexp(reference_spacing, -level);
}

// Running CSPM sums for one point with the kernel of `kernel`: add neighbours one by one, then
// divide.
template <int NVALUES> struct CspmSum {
  explicit CspmSum(KernelKind kernel = KernelKind()) : kernel(kernel) {}
  KernelKind kernel;
  double weight = 0.0;
  double values[NVALUES] = {};

  // a neighbour of volume V at distance r with smoothing length h and state f[NVALUES]
  void add(int dimension, double volume, double r, double h, const double *f)
  {
    const double w = volume * kernel_value(kernel, dimension, r, h);
    if (w == 0.0) return;
    weight += w;
    for (int k = 0; k < NVALUES; k++) values[k] += w * f[k];
  }
  // false when no neighbour reaches the point (then `out` is left unchanged)
  bool result(double *out) const
  {
    if (!(weight > 0.0)) return false;
    const double inv = 1.0 / weight;
    for (int k = 0; k < NVALUES; k++) out[k] = values[k] * inv;
    return true;
  }
};

// The particle that siblings merge back into (doc/theory.rst 5.11): add the siblings one by one.
// Mass and linear momentum are sums (conserved to round-off), the position the centre of mass,
// the force the sum (the same acceleration of the centre of mass), the density the total mass
// over the total volume sum m/rho (volume conserved), and NVALUES further values (stress,
// strains, rates) mass-averaged. What one particle cannot carry is the siblings' motion about
// their centre of mass: their angular momentum about it, and their kinetic energy of relative
// motion.
template <int NVALUES> struct MergeSum {
  double mass = 0.0, volume = 0.0;
  double momentum[3] = {0.0, 0.0, 0.0}, moment[3] = {0.0, 0.0, 0.0}, force[3] = {0.0, 0.0, 0.0};
  double values[NVALUES] = {};
  int count = 0;

  void add(double m, double rho, const double *x, const double *v, const double *f, const double *value)
  {
    mass += m;
    volume += m / rho;
    for (int a = 0; a < 3; a++) {
      momentum[a] += m * v[a];
      moment[a] += m * x[a];
      force[a] += f[a];
    }
    for (int k = 0; k < NVALUES; k++) values[k] += m * value[k];
    count++;
  }
  double density() const { return mass / volume; }
  void position(double *x) const
  {
    for (int a = 0; a < 3; a++) x[a] = moment[a] / mass;
  }
  void velocity(double *v) const
  {
    for (int a = 0; a < 3; a++) v[a] = momentum[a] / mass;
  }
  void averages(double *value) const
  {
    for (int k = 0; k < NVALUES; k++) value[k] = values[k] / mass;
  }
};

}    // namespace SPHSoil

#endif
