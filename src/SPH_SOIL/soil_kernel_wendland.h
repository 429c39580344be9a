/* -*- c++ -*- ----------------------------------------------------------
   SPH_SOIL package: the Wendland C2 kernel (Wendland 1995), support 2h.

   Pure functions, no LAMMPS dependency (doc/theory.rst section 1):
     W(r,h) = C/h^D * (1 - q/2)^4 (2q + 1)   for 0 <= q < 2, else 0,   q = r/h
   with C = 7/(4 pi) in 2D and 21/(16 pi) in 3D. Its Fourier transform is
   positive, so it does not suffer the pairing instability of the cubic
   spline at many neighbours (Dehnen & Aly 2012), which matters where
   refined particles see a coarse cutoff. (1/r) dW/dr = -5 C/h^(D+2) (1 - q/2)^3
   needs no division by r; W'' < 0 for q < 1/2.
   The interface is that of CubicSpline (soil_kernel_cubic.h).
------------------------------------------------------------------------- */

#ifndef LMP_SOIL_KERNEL_WENDLAND_H
#define LMP_SOIL_KERNEL_WENDLAND_H

#include <cmath>

namespace SPHSoil {

struct WendlandC2 {
  static constexpr const char *NAME = "wendland2";
  static constexpr double SUPPORT = 2.0;
  static constexpr double INFLECTION = 0.5;

  static inline double norm(int dimension, double h)
  {
    constexpr double PI = 3.14159265358979323846;
    return dimension == 3 ? 21.0 / (16.0 * PI * h * h * h) : 7.0 / (4.0 * PI * h * h);
  }

  // the kernel's shape: W(r, h) = norm(D, h) shape(r/h)
  static inline double shape(double q)
  {
    if (q >= 2.0) return 0.0;
    const double t = 1.0 - 0.5 * q, t2 = t * t;
    return t2 * t2 * (2.0 * q + 1.0);
  }

  static inline double value(int dimension, double r, double h)
  {
    return norm(dimension, h) * shape(r / h);
  }

  static inline double derivative(int dimension, double r, double h)
  {
    const double q = r / h;
    if (q >= 2.0) return 0.0;
    const double t = 1.0 - 0.5 * q;
    return -5.0 * norm(dimension, h) / h * q * t * t * t;
  }

  static inline double gradient_factor(int dimension, double r, double h)
  {
    const double q = r / h;
    if (q >= 2.0) return 0.0;
    const double t = 1.0 - 0.5 * q;
    return -5.0 * norm(dimension, h) / (h * h) * t * t * t;
  }

  // as CubicSpline's, inside the support: from 1/h (h/r is not needed: the factor has no 1/r)
  template <int DIMENSION>
  static inline double gradient_factor_inside(double r, double inv_h, double /*h_over_r*/)
  {
    constexpr double PI = 3.14159265358979323846;
    constexpr double C = DIMENSION == 3 ? 21.0 / (16.0 * PI) : 7.0 / (4.0 * PI);
    const double q = r * inv_h;
    const double inv_h2 = inv_h * inv_h;
    const double c = DIMENSION == 3 ? C * inv_h2 * inv_h2 * inv_h : C * inv_h2 * inv_h2;
    const double t = 1.0 - 0.5 * q;
    return -5.0 * c * t * t * t;
  }

  static inline double second_derivative(int dimension, double r, double h)
  {
    const double q = r / h;
    if (q >= 2.0) return 0.0;
    const double t = 1.0 - 0.5 * q;
    return 5.0 * norm(dimension, h) / (h * h) * t * t * (2.0 * q - 1.0);
  }
};

}    // namespace SPHSoil

#endif
