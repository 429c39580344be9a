/* -*- c++ -*- ----------------------------------------------------------
   SPH_SOIL package: the kernels by keyword (pure, no LAMMPS).

   A kernel is a struct of static functions (CubicSpline in soil_kernel.h
   is the reference). Code that needs a kernel is a template on it; code
   that picks one at run time calls with_kernel(kind, functor), which calls
   functor.template operator()<Kernel>() for the kernel of `kind`, so the
   hot loops are compiled once per kernel and pay nothing for the choice.
   A new kernel is one header and one line in each of the two lists below.
------------------------------------------------------------------------- */

#ifndef LMP_SOIL_KERNELS_H
#define LMP_SOIL_KERNELS_H

#include "soil_kernel.h"
#include "soil_kernel_wendland.h"

#include <string>

namespace SPHSoil {

enum class KernelKind { cubic, wendland2 };

// the kernel named `name`; false if there is none
inline bool kernel_kind(const std::string &name, KernelKind &kind)
{
  if (name == CubicSpline::NAME) kind = KernelKind::cubic;
  else if (name == WendlandC2::NAME) kind = KernelKind::wendland2;
  else return false;
  return true;
}
constexpr const char *KERNEL_NAMES = "cubic, wendland2";

template <class Functor> auto with_kernel(KernelKind kind, Functor &&f) -> decltype(f.template operator()<CubicSpline>())
{
  switch (kind) {
    case KernelKind::wendland2:
      return f.template operator()<WendlandC2>();
    case KernelKind::cubic:
    default:
      return f.template operator()<CubicSpline>();
  }
}

// facts of the kernel of `kind`
namespace kernel_facts {
  struct Support {
    template <class Kernel> double operator()() const { return Kernel::SUPPORT; }
  };
  struct Inflection {
    template <class Kernel> double operator()() const { return Kernel::INFLECTION; }
  };
  struct Name {
    template <class Kernel> const char *operator()() const { return Kernel::NAME; }
  };
  struct Value {
    int dimension;
    double r, h;
    template <class Kernel> double operator()() const { return Kernel::value(dimension, r, h); }
  };
  struct GradientFactor {
    int dimension;
    double r, h;
    template <class Kernel> double operator()() const { return Kernel::gradient_factor(dimension, r, h); }
  };
}    // namespace kernel_facts

inline double kernel_support(KernelKind kind) { return with_kernel(kind, kernel_facts::Support()); }
inline double kernel_inflection(KernelKind kind) { return with_kernel(kind, kernel_facts::Inflection()); }
inline const char *kernel_name(KernelKind kind) { return with_kernel(kind, kernel_facts::Name()); }
// W(r, h) and (1/r) dW/dr of the kernel of `kind`, for code outside the hot loops
inline double kernel_value(KernelKind kind, int dimension, double r, double h)
{
  return with_kernel(kind, kernel_facts::Value{dimension, r, h});
}
inline double kernel_gradient_factor(KernelKind kind, int dimension, double r, double h)
{
  return with_kernel(kind, kernel_facts::GradientFactor{dimension, r, h});
}

}    // namespace SPHSoil

#endif
