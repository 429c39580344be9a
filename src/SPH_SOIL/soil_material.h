/* -*- c++ -*- ----------------------------------------------------------
   SPH_SOIL package: materials of pair_style sph/soil (pure, no LAMMPS).

   A material is either soil (a reference density and a constitutive model
   with its parameters) or wall (boundary particles, which borrow the state
   of the soil particle they interact with, with a slip condition and a
   boundary treatment). Material files list one material per line (see
   potentials/README.md):

     name  soil  rho0  model  parameters...     (model: see soil_models.h)
     name  soil  rho0  K nu phi psi c           (no model word: drucker_prager)
     name  soil  rho0  model parameters... porosity n permeability k ...  (saturated:
                                                 soil_pore_water.h; rho0 the saturated density)
     name  wall  [noslip | freeslip | friction mu]  [boundary mirror | extrapolate]  [drained]
     name  water  rho_w  K_w                    (free water: soil_water.h)
------------------------------------------------------------------------- */

#ifndef LMP_SOIL_MATERIAL_H
#define LMP_SOIL_MATERIAL_H

#include "soil_constitutive.h"
#include "soil_pore_water.h"

#include <cmath>
#include <memory>
#include <string>
#include <vector>

namespace SPHSoil {

// how a wall holds the soil along its surface: as pair_style sph/soil's 'wall' keyword says
// (default), no slip, no shear traction, or Coulomb friction in between (doc/theory.rst 4.4)
enum class WallSlip { pair_default, noslip, freeslip, friction };
// how the wall particle stands in for the soil: the soil particle's image in the wall's plane
// (Morris 1997 / Bui 2008: a plane per particle), or the soil's stress and velocity
// extrapolated to the wall particle (Adami 2012: any shape, no plane)
enum class WallBoundary { mirror, extrapolate };

struct SoilMaterial {
  std::string name;
  double density = 0.0;                               // reference density rho_0 (kg/m^3)
  std::shared_ptr<const ConstitutiveModel> model;     // nullptr for a wall
  WallSlip slip = WallSlip::pair_default;             // walls only
  double friction = 0.0;                              // Coulomb coefficient, WallSlip::friction
  double adhesion = 0.0;                              // c_a (Pa), WallSlip::friction
  WallBoundary boundary = WallBoundary::mirror;       // walls only
  // walls only: the pore water of saturated soil drains through the wall at the wall
  // particles' own pore pressure (a filter, a porous stone), else it is impermeable
  bool drained = false;
  bool saturated = false;                             // a soil with pore water
  bool water = false;                                 // free water (model: SPHSoil::FreeWater)
  PoreWater pore_water;                               // its water, if saturated
  // the words that defined it (after its name): material_from_words(name, words) builds it
  // again, e.g. from a restart file
  std::vector<std::string> words;

  bool is_wall() const { return !model; }
  // elastic P-wave speed sqrt((K + 4G/3)/rho_0) of a soil, undrained for a saturated one
  // (sqrt((K + 4G/3 + K_w/n)/rho_sat)): bounds the time step, scales the viscosity; 0 for a wall
  double wave_speed() const
  {
    if (!model) return 0.0;
    const double modulus = model->p_wave_modulus() + (saturated ? pore_water.storage_modulus() : 0.0);
    return std::sqrt(modulus / density);
  }
};

// Build a material from words: {"soil", rho0, [model,] parameters...} or {"wall", options...}.
// On failure returns false and says why in `error`.
bool material_from_words(const std::string &name, const std::vector<std::string> &words,
                         SoilMaterial &material, std::string &error);

// Parse the text of a material file ('#' starts a comment). On failure returns false with
// the line number and reason in `error`.
bool parse_material_file(const std::string &text, std::vector<SoilMaterial> &materials,
                         std::string &error);

}    // namespace SPHSoil

#endif
