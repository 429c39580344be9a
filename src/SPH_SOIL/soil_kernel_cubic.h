/* -*- c++ -*- ----------------------------------------------------------
   SPH_SOIL package: the cubic spline kernel (Monaghan & Lattanzio 1985).

   Pure functions, no LAMMPS dependency (doc/theory.rst section 1):
     W(r,h) = C/h^D * (1 - 1.5 q^2 + 0.75 q^3)   for 0 <= q < 1
            = C/h^D * 0.25 (2 - q)^3              for 1 <= q < 2
            = 0                                   otherwise,      q = r/h
   with C = 10/(7 pi) in 2D and 1/pi in 3D; support radius 2h.
------------------------------------------------------------------------- */

#ifndef LMP_SOIL_KERNEL_CUBIC_H
#define LMP_SOIL_KERNEL_CUBIC_H

#include <cmath>

namespace SPHSoil {

struct CubicSpline {
  static constexpr const char *NAME = "cubic";
  static constexpr double SUPPORT = 2.0;    // support radius in units of h
  // q = r/h below which W'' < 0: pairs closer than INFLECTION * h are unstable under
  // compression (Swegle et al. 1995; doc/theory.rst section 5.6)
  static constexpr double INFLECTION = 2.0 / 3.0;

  // normalisation C / h^D
  static inline double norm(int dimension, double h)
  {
    constexpr double PI = 3.14159265358979323846;
    return dimension == 3 ? 1.0 / (PI * h * h * h) : 10.0 / (7.0 * PI * h * h);
  }

  // the kernel's shape: W(r, h) = norm(D, h) shape(r/h)
  static inline double shape(double q)
  {
    if (q >= 2.0) return 0.0;
    if (q < 1.0) return 1.0 - 1.5 * q * q + 0.75 * q * q * q;
    const double t = 2.0 - q;
    return 0.25 * t * t * t;
  }

  // W(r, h)
  static inline double value(int dimension, double r, double h)
  {
    return norm(dimension, h) * shape(r / h);
  }

  // dW/dr (<= 0); the gradient is dW/dr * x/r.
  static inline double derivative(int dimension, double r, double h)
  {
    const double q = r / h;
    if (q >= 2.0) return 0.0;
    const double c = norm(dimension, h) / h;
    if (q < 1.0) return c * (-3.0 * q + 2.25 * q * q);
    const double t = 2.0 - q;
    return -c * 0.75 * t * t;
  }

  // (1/r) dW/dr, finite at r = 0 (where it tends to -3 C / h^(D+2)), so that
  // grad W = x * gradient_factor(r, h) needs no division by r in the pair loop.
  static inline double gradient_factor(int dimension, double r, double h)
  {
    const double q = r / h;
    if (q >= 2.0) return 0.0;
    const double c = norm(dimension, h) / (h * h);
    if (q < 1.0) return c * (-3.0 + 2.25 * q);
    const double t = 2.0 - q;
    return -c * 0.75 * t * t / q;
  }

  // The same as gradient_factor() inside the support (q < 2, which the pair loop has tested),
  // in the form the pair loop uses: from 1/h and h/r, which it gets from 1/h_ij and 1/r^2, so
  // that no division is left here; and without a branch: both pieces are computed and one is
  // selected (which piece a pair needs is a coin toss the processor would mispredict).
  template <int DIMENSION>
  static inline double gradient_factor_inside(double r, double inv_h, double h_over_r)
  {
    constexpr double PI = 3.14159265358979323846;
    constexpr double C = DIMENSION == 3 ? 1.0 / PI : 10.0 / (7.0 * PI);
    const double q = r * inv_h;
    const double inv_h2 = inv_h * inv_h;
    const double c = DIMENSION == 3 ? C * inv_h2 * inv_h2 * inv_h : C * inv_h2 * inv_h2;
    const double t = 2.0 - q;
    const double inner = -3.0 + 2.25 * q, outer = -0.75 * t * t * h_over_r;
    return c * (q < 1.0 ? inner : outer);
  }

  // d2W/dr2, whose sign decides the tensile/compressive (Swegle) instability:
  // negative for q < 2/3.
  static inline double second_derivative(int dimension, double r, double h)
  {
    const double q = r / h;
    if (q >= 2.0) return 0.0;
    const double c = norm(dimension, h) / (h * h);
    if (q < 1.0) return c * (-3.0 + 4.5 * q);
    return c * 1.5 * (2.0 - q);
  }
};

}    // namespace SPHSoil

#endif
