/* -*- c++ -*- ----------------------------------------------------------
   SPH_SOIL package: free water (pure, no LAMMPS).

   A material of kind water is a weakly compressible fluid: its particles carry
   the water pressure in the atom style's pore pressure, from the density by the
   linear equation of state p = K_w (rho / rho_w - 1), and no other stress; the
   pair sums then see its total stress -p I, against soil particles as against
   water (doc/theory.rst section 7). Monaghan's artificial viscosity, with the
   water's speed of sound sqrt(K_w / rho_w), is its only viscosity. The
   constitutive model below is the integrator's view of it: a stress that stays
   zero, never yields, and a P-wave modulus K_w for the time step.

   A material line:   name  water  rho_w  K_w
------------------------------------------------------------------------- */

#ifndef LMP_SOIL_WATER_H
#define LMP_SOIL_WATER_H

#include "soil_constitutive.h"

#include <memory>
#include <string>
#include <vector>

namespace SPHSoil {

class FreeWater : public ConstitutiveModel {
 public:
  static constexpr const char *KEYWORD = "water";
  explicit FreeWater(double bulk_modulus) : modulus(bulk_modulus) {}

  const char *keyword() const override { return KEYWORD; }
  void stress_rate(const double[6], const double[6], const double[3], double rate[6]) const override
  {
    for (int k = 0; k < 6; k++) rate[k] = 0.0;
  }
  bool return_to_admissible(double[6]) const override { return false; }
  double yield_function(const double[6]) const override { return -1.0; }
  bool on_yield_surface(const double[6]) const override { return false; }
  double p_wave_modulus() const override { return modulus; }
  // no tension for SPH's artificial stress to hold together
  double tensile_strength() const override { return 0.0; }


  // the water pressure of a density (Pa, positive in compression)
  static double pressure(double density, double reference_density, double bulk_modulus)
  {
    return bulk_modulus * (density / reference_density - 1.0);
  }
  // the density of a pressure: the inverse
  static double density(double pressure, double reference_density, double bulk_modulus)
  {
    return reference_density * (1.0 + pressure / bulk_modulus);
  }

  // from the words after the density ({"K_w"}); nullptr with the reason in `error`
  static std::unique_ptr<FreeWater> from_words(const std::vector<std::string> &words,
                                               std::string &error);

 private:
  double modulus;
};

}    // namespace SPHSoil

#endif
