/* -*- c++ -*- ----------------------------------------------------------
   SPH_SOIL package: materials of pair_style sph/soil (pure, no LAMMPS).

   A material is either soil (density, elastic and Drucker-Prager
   parameters) or wall (boundary particles, which borrow the state of the
   soil particle they interact with). Material files list one material per
   line (see potentials/README.md):

     name  soil  density  bulk_modulus  poisson_ratio  friction_deg  dilatancy_deg  cohesion
     name  wall
------------------------------------------------------------------------- */

#ifndef LMP_SOIL_MATERIAL_H
#define LMP_SOIL_MATERIAL_H

#include <string>
#include <vector>

namespace SPHSoil {

struct SoilMaterial {
  std::string name;
  bool wall = false;
  double density = 0.0;             // reference density rho_0 (kg/m^3)
  double bulk_modulus = 0.0;        // K (Pa)
  double poisson_ratio = 0.0;       // nu
  double friction_angle = 0.0;      // phi (degrees)
  double dilatancy_angle = 0.0;     // psi (degrees)
  double cohesion = 0.0;            // c (Pa)

  // empty if the parameters are admissible, else what is wrong and the allowed range
  std::string check() const;
  double shear_modulus() const { return 3.0 * bulk_modulus * (1.0 - 2.0 * poisson_ratio) / (2.0 * (1.0 + poisson_ratio)); }
  // elastic P-wave speed sqrt((K + 4G/3)/rho_0): bounds the time step, scales the viscosity
  double wave_speed() const;
};

// Build a material from words: {"soil", rho0, K, nu, phi, psi, c} or {"wall"}.
// On failure returns false and says why in `error`.
bool material_from_words(const std::string &name, const std::vector<std::string> &words,
                         SoilMaterial &material, std::string &error);

// Parse the text of a material file ('#' starts a comment). On failure returns false with
// the line number and reason in `error`.
bool parse_material_file(const std::string &text, std::vector<SoilMaterial> &materials,
                         std::string &error);

}    // namespace SPHSoil

#endif
