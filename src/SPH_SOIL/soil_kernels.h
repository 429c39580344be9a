/* -*- c++ -*- ----------------------------------------------------------
   SPH_SOIL package: the kernels by keyword (pure, no LAMMPS).

   A kernel is a struct of static functions and constants (CubicSpline in
   soil_kernel_cubic.h is the reference: NAME, SUPPORT, INFLECTION, norm(),
   shape(), value(), gradient_factor(), gradient_factor_inside()). Code that
   needs a kernel is a template on it; code that picks one at run time calls
   with_kernel(kind, functor), which calls functor.template operator()<Kernel>()
   for the kernel of `kind`, so the hot loops are compiled once per kernel and
   pay nothing for the choice.

   The registry is the one line `using Kernels = KernelRegistry<...>` below:
   a new kernel is its header and its name in that list. Its keyword, the
   "allowed:" lists of errors, the dispatch and every fact below follow from it.
------------------------------------------------------------------------- */

#ifndef LMP_SOIL_KERNELS_H
#define LMP_SOIL_KERNELS_H

#include "soil_kernel_cubic.h"
#include "soil_kernel_wendland.h"

#include <cmath>
#include <string>
#include <utility>

namespace SPHSoil {

// a kernel chosen at run time: its position in the registry (0, the first, is the default)
struct KernelKind {
  int index = 0;
  bool operator==(KernelKind other) const { return index == other.index; }
  bool operator!=(KernelKind other) const { return index != other.index; }
};

// What a list of kernel types gives: their names, a kernel by name, and the dispatch to the
// kernel of a KernelKind. Any list works (the tests register a dummy kernel in one of their own).
template <class First, class... Rest> struct KernelRegistry {
  static constexpr int COUNT = 1 + sizeof...(Rest);

  // f.template operator()<Kernel>() for the kernel at `index` (the last one beyond the list)
  template <class F>
  static auto dispatch(int index, F &&f) -> decltype(f.template operator()<First>())
  {
    if (index <= 0) return f.template operator()<First>();
    return KernelRegistry<Rest...>::dispatch(index - 1, std::forward<F>(f));
  }
  // "cubic, wendland2": for messages
  static std::string names() { return std::string(First::NAME) + ", " + KernelRegistry<Rest...>::names(); }
  // the position of the kernel named `name`, -1 if there is none
  static int find(const std::string &name)
  {
    if (name == First::NAME) return 0;
    const int rest = KernelRegistry<Rest...>::find(name);
    return rest < 0 ? -1 : rest + 1;
  }
};

// a list of one: the end of the recursion
template <class Only> struct KernelRegistry<Only> {
  static constexpr int COUNT = 1;
  template <class F> static auto dispatch(int, F &&f) -> decltype(f.template operator()<Only>())
  {
    return f.template operator()<Only>();
  }
  static std::string names() { return Only::NAME; }
  static int find(const std::string &name) { return name == Only::NAME ? 0 : -1; }
};

// THE registry of the package's kernels, the first one the default
using Kernels = KernelRegistry<CubicSpline, WendlandC2>;

// the kernel named `name`; false if there is none
inline bool kernel_kind(const std::string &name, KernelKind &kind)
{
  const int index = Kernels::find(name);
  if (index < 0) return false;
  kind.index = index;
  return true;
}
// the names of all kernels, for messages
inline std::string kernel_names()
{
  return Kernels::names();
}

template <class Functor>
auto with_kernel(KernelKind kind, Functor &&f) -> decltype(f.template operator()<CubicSpline>())
{
  return Kernels::dispatch(kind.index, std::forward<Functor>(f));
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

// The spacing d = V^(1/D) of a particle of volume V = m / rho, in `dimension` 2 or 3.
inline double volume_spacing(double volume, int dimension)
{
  return dimension == 3 ? std::cbrt(volume) : std::sqrt(volume);
}

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
