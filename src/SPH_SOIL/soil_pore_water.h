/* -*- c++ -*- ----------------------------------------------------------
   SPH_SOIL package: the pore water of a saturated soil (pure, no LAMMPS).

   A soil material with a 'porosity' is saturated: its particles carry the
   pore pressure p besides the effective stress sigma' that the constitutive
   model updates, and the pair style sums the total stress sigma' - p I
   (Biot's u-p formulation; doc/theory.rst section 7):

     dp/dt = (K_w / n) ( -div v + div( k / gamma_w  grad(p - rho_w g . x) ) )

   with the storage of the pore water (its bulk modulus K_w over the porosity n; the grains are
   incompressible) and Darcy's law, whose hydraulic conductivity k is measured under standard
   gravity (gamma_w = rho_w g_n). The material's rho0 is then the saturated density (grains
   and water), so that the particles' weight is the soil's total weight.

   Words on a soil material line, after the model's parameters, in any order:
     porosity n  permeability k  [water_density rho_w]  [water_modulus K_w]
     [permeability_law constant|kozeny_carman]
   kozeny_carman: k follows the porosity, k(n) = k n^3 / (1 - n)^2 / (n0^3 / (1 - n0)^2)
   (Kozeny 1927, Carman 1937), so that a dilating soil drains faster and a contracting one
   slower; n from the particle's density, its grains incompressible and kept.
------------------------------------------------------------------------- */

#ifndef LMP_SOIL_PORE_WATER_H
#define LMP_SOIL_PORE_WATER_H

#include <string>
#include <vector>

namespace SPHSoil {

// g_n (m/s^2): hydraulic conductivities are measured under it (SI units)
constexpr double STANDARD_GRAVITY = 9.80665;

// how the hydraulic conductivity follows the porosity
enum class PermeabilityLaw { CONSTANT, KOZENY_CARMAN };

struct PoreWater {
  double porosity = 0.0;                   // n, in (0, 1): at the material's rho0
  double conductivity = 0.0;               // hydraulic conductivity k (m/s), >= 0
  double water_density = DEFAULT_DENSITY;  // rho_w (kg/m^3)
  double water_modulus = DEFAULT_MODULUS;  // K_w (Pa)
  PermeabilityLaw law = PermeabilityLaw::CONSTANT;

  static constexpr double DEFAULT_DENSITY = 1000.0;
  static constexpr double DEFAULT_MODULUS = 2.2e9;

  // k / gamma_w (m^2 / (Pa s)): Darcy's flux q = -mobility (grad p - rho_w g)
  double mobility() const { return conductivity / (water_density * STANDARD_GRAVITY); }
  // K_w / n: the pore pressure's response to a change of volume
  double storage_modulus() const { return water_modulus / porosity; }
  // the diffusivity of the pore pressure in a rigid skeleton, mobility K_w / n (m^2/s): the
  // fastest the pore pressure spreads, which bounds an explicit time step
  double diffusivity() const { return mobility() * storage_modulus(); }

  // the porosity at density rho = density_ratio rho0: the grains are incompressible and stay
  // with the particle, (1 - n) / rho constant
  double porosity_at(double density_ratio) const { return 1.0 - (1.0 - porosity) * density_ratio; }
  // k at density ratio rho / rho0 over k at rho0: 1 for a constant k; Kozeny-Carman's
  // n^3 / (1 - n)^2 over its value at n0, 0 where the pores have closed (n <= 0)
  double conductivity_factor(double density_ratio) const
  {
    if (law == PermeabilityLaw::CONSTANT) return 1.0;
    const double n = porosity_at(density_ratio);
    if (n <= 0.0) return 0.0;
    const double solid = 1.0 - n, solid0 = 1.0 - porosity;
    return (n * n * n) / (porosity * porosity * porosity) * (solid0 * solid0) / (solid * solid);
  }
  // whether k changes with the density
  bool variable_conductivity() const { return law != PermeabilityLaw::CONSTANT; }
  // the names of the laws, for messages
  static std::string law_names();
  // the keywords a soil line takes for its pore water, for messages
  static std::string keyword_names();

  // the keywords and their values, taken out of `words` (the rest stays, in order). `found`:
  // whether there was any. False with the reason (naming the keyword, the value and the
  // allowed range) in `error`; porosity and permeability are both needed once either is given.
  static bool from_words(std::vector<std::string> &words, PoreWater &water, bool &found,
                         std::string &error);
  // empty if the saturated density rho_sat holds grains of positive mass (rho_sat > n rho_w),
  // else why
  std::string check_density(double saturated_density) const;
  // the grains' density (rho_sat - n rho_w) / (1 - n)
  double grain_density(double saturated_density) const
  {
    return (saturated_density - porosity * water_density) / (1.0 - porosity);
  }
};

/* ----------------------------------------------------------------------
   the pair term (Brookshaw 1985; Cleary & Monaghan 1999): particle a's share of
   div(lambda grad phi), phi = p - rho_w g . x the head in pressure units, from partner b:
     V_b  2 lambda_ab (phi_a - phi_b) (x_ab . grad_a W) / (r^2 + eta^2)
   with grad_a W = factor x_ab; b gets V_a times the same with the opposite sign (the water
   leaving a enters b: volume conserved pair by pair). lambda_ab: the harmonic mean of the two
   mobilities (the conductance of two layers in series); a drained partner (free water, a drained
   wall) has an infinite one, the limit 2 lambda_a (doc/theory.rst 7.3: the flux through a layer
   follows Darcy's law within 1.2% at two spacings, where the soil's own lambda_a gave 3-6% too
   little)
------------------------------------------------------------------------- */

// Brookshaw's form divides x.grad W = F r^2 by r^2 + eta^2, eta^2 = BROOKSHAW_ETA2 h^2, against a
// division by zero; F itself is finite at r = 0 for both kernels, so that eta only has to keep
// r = 0 from 0/0. (The customary 0.01 took 1.4% off the conductance of every nearest pair at
// h = 1.2 d: most of the 2% by which the flux through a layer fell short of Darcy's.)
constexpr double BROOKSHAW_ETA2 = 1.0e-6;

inline double harmonic_mobility(double lambda_a, double lambda_b)
{
  const double sum = lambda_a + lambda_b;
  return sum > 0.0 ? 2.0 * lambda_a * lambda_b / sum : 0.0;
}

// the pair's flow per unit partner volume: 2 lambda_ab (phi_a - phi_b) factor r^2 /
// (r^2 + eta^2), with phi_a - phi_b = p_a - p_b - rho_w g . x_ab
template <int DIMENSION>
inline double pore_flow(double pressure_a, double pressure_b, double water_density,
                        const double gravity[3], const double dx[3], double r2, double h,
                        double factor, double lambda_ab)
{
  double lift = 0.0;
  for (int a = 0; a < DIMENSION; a++) lift += gravity[a] * dx[a];
  const double head_difference = pressure_a - pressure_b - water_density * lift;
  return 2.0 * lambda_ab * head_difference * factor * r2 / (r2 + BROOKSHAW_ETA2 * h * h);
}

}    // namespace SPHSoil

#endif
