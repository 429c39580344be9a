/* -*- c++ -*- ----------------------------------------------------------
   SPH_SOIL package: choosing refinement parameters (pure, no LAMMPS).

   The kernel gradient error of one split and the instability conditions of
   doc/theory.rst sections 5.5 and 5.6 (the paper's Fig. 1). A parent p at the origin is
   replaced by M = 2^D daughters at the corners of a square (cube) of side
   eps_r * d_p with smoothing length alpha_r * h_p and mass m_p / M:

     E = integral sum_a ( dW_p(x)/dx^a - sum_d (1/M) dW_d(x)/dx^a )^2 dx

   where a particle seen from x with smoothing length h(x) uses the
   symmetrized (h_particle + h(x))/2; case (a) h(x) = h_p, case (b)
   h(x) = alpha_r h_p. Lengths are in units of the parent's spacing
   (d_p = 1, h_p = r_a), so E is in units of 1/d_p^2.
------------------------------------------------------------------------- */

#ifndef LMP_SOIL_REFINE_ERROR_H
#define LMP_SOIL_REFINE_ERROR_H

#include "soil_kernels.h"

namespace SPHSoil {

enum class NeighbourSmoothing {
  UNREFINED,    // case (a): h(x) = h_p
  REFINED       // case (b): h(x) = alpha_r h_p
};

struct KernelGradientError {
  double value;             // E
  double error_estimate;    // |E(n cells) - E(n/2 cells)| of the last refinement of the quadrature
  int cells;                // cells per dimension of the quadrature that was accepted
};

// E by composite Gauss-Legendre quadrature (4 points per cell and dimension) over the
// union of the supports, exploiting the pattern's mirror symmetries; the number of cells
// doubles until the relative change is below relative_tolerance (or max_cells is reached).
KernelGradientError kernel_gradient_error(int dimension, double separation, double smoothing_ratio,
                                          double r_a, NeighbourSmoothing neighbours,
                                          double relative_tolerance = 1.0e-5, int max_cells = 256,
                                          KernelKind kernel = KernelKind());

// E on a fixed grid of cells per dimension (for convergence studies).
double kernel_gradient_error_fixed(int dimension, double separation, double smoothing_ratio,
                                   double r_a, NeighbourSmoothing neighbours, int cells,
                                   KernelKind kernel = KernelKind());

// sum_a of the squared difference of the gradients at one point x (length `dimension`)
double gradient_difference_squared(int dimension, double separation, double smoothing_ratio,
                                   double r_a, NeighbourSmoothing neighbours, const double *x,
                                   KernelKind kernel = KernelKind());

// What a split does to a soil at rest (doc/theory.rst 5.11): in a uniform isotropic stress
// -p the momentum equation's sum form, a_i = -(2 p / rho) sum_j V_j grad_i W(r_ij, h_ij) with
// h_ij = (h_i + h_j)/2, vanishes at every particle of a regular lattice (square or cubic, spacing
// d_p = 1, h_p = r_a); after one particle is split it does not. The largest acceleration that
// appears at the parent's coarse neighbours and at the daughters, in units of p / (rho h_p):
// with the geostatic p = rho g z it is that number times (z / h_p) g, the kick of a split at
// depth z.
struct SplitStressDefect {
  double neighbours;    // the coarse particles around the split
  double daughters;     // the daughters (against the parent's 0)
};
SplitStressDefect split_stress_defect(int dimension, double separation, double smoothing_ratio,
                                      double r_a, KernelKind kernel = KernelKind());

// The same defect at the edge of a refined zone (doc/validation.rst, the slope): the lattice of
// spacing 1 (h_p = r_a) below a plane, every site above it split by (separation,
// smoothing_ratio), in a uniform isotropic stress -p. The largest acceleration of the coarse
// row next to the edge and of the daughters of the first refined row, in units of p / (rho h_p)
// (times (z / h_p) g at depth z); both vanish far from the edge. A buffer (fix sph/soil/refine
// buffer) keeps this edge away from the particles that shear.
SplitStressDefect level_edge_defect(int dimension, double separation, double smoothing_ratio,
                                    double r_a, KernelKind kernel = KernelKind());

// Swegle's criterion (W'' < 0 for r < q* h, q* the kernel's INFLECTION: 2/3 for the cubic
// spline, the paper's case, 1/2 for Wendland C2) applied to a split, for a refined particle i
// and a neighbour j at distance d_ij = neighbour_distance * d_ref:
struct InstabilityConditions {
  bool daughters_too_close;        // Cond. 1: 0 < q* alpha_r r_a - eps_r
  bool refined_neighbours;         // Cond. 2: d_ij/d_ref < q* alpha_r r_a + eps_r
  bool unrefined_neighbour;        // Cond. 3: d_ij/d_ref < q* (1 + alpha_r) r_a / 2 + eps_r / 2
  bool any() const { return daughters_too_close || refined_neighbours || unrefined_neighbour; }
};

InstabilityConditions instability_conditions(double separation, double smoothing_ratio, double r_a,
                                             double neighbour_distance,
                                             double inflection = CubicSpline::INFLECTION);

inline bool stable_refinement(double separation, double smoothing_ratio, double r_a,
                              double neighbour_distance, double inflection = CubicSpline::INFLECTION)
{
  return !instability_conditions(separation, smoothing_ratio, r_a, neighbour_distance, inflection).any();
}

}    // namespace SPHSoil

#endif
