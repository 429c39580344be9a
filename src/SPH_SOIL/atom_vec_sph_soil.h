/* -*- c++ -*- ----------------------------------------------------------
   SPH_SOIL package for LAMMPS: atom_style sph/soil

   Per-atom state of elastic-plastic SPH soil (Bui et al. 2008) with
   dynamic particle refinement. See doc/atom_style_sph_soil.rst.
------------------------------------------------------------------------- */

#ifdef ATOM_CLASS
// clang-format off
AtomStyle(sph/soil,AtomVecSPHSoil);
// clang-format on
#else

#ifndef LMP_ATOM_VEC_SPH_SOIL_H
#define LMP_ATOM_VEC_SPH_SOIL_H

#include "atom_vec.h"
#include "sph_soil_compat.h"

#include <string>

namespace LAMMPS_NS {

class AtomVecSPHSoil : public AtomVec {
 public:
  AtomVecSPHSoil(class LAMMPS *);

  void process_args(int, char **) override;
  void grow_pointers() override;
  void force_clear(int, size_t) override;
  void create_atom_post(int) override;
  void data_atom_post(int) override;
  void data_vel(int, SPHSoilCompat::DataVelValues) override;
  int property_atom(SPHSoilCompat::PropertyAtomName) override;
  void pack_property_atom(int, double *, int, int) override;

  // Per-atom arrays owned by this style (registered with Atom::add_peratom; the
  // pointers LAMMPS grows live in a block that outlives the style, see the .cpp,
  // and are copied here by grow_pointers()).
  // Tensors are stored in Voigt order xx, yy, zz, xy, xz, yz; in 2D (plane
  // strain) xz and yz stay zero while zz is carried.
  double *smoothing_length;    // h, kernel support is 2h
  double **stress;             // Cauchy stress, positive in tension
  double **stress_rate;        // d(stress)/dt of the last force evaluation
  double **total_strain;       // accumulated total strain, integral of strain_rate dt
  double **strain_rate;        // symmetric part of the velocity gradient
  double **spin;               // antisymmetric part: xy, xz, yz
  int *level;                  // refinement level, 0 for an original particle
  double **wall_normal;        // Atom's mu: unit normal into the soil (and 1) for wall
                               // particles, else 0; see the constructor
  double *wall_distance;       // distance of a wall particle behind the wall surface
  // the rates of the last step of the last run (fix sph/soil's post_run), which the first half
  // step of the next run uses instead of those that its set-up recomputes from the full-step
  // state: so a continued or restarted run is identical to an uninterrupted one. They travel
  // with the atom (and into restart files), whichever fix integrates it. SAVED_FLAG is 1 while
  // they are there to be used; 0 after a data file, create_atoms or sph_soil/set.
  double **saved_rates;
  enum {
    SAVED_FLAG = 0,
    SAVED_ACCELERATION = 1,    // 3
    SAVED_DRHO = 4,
    SAVED_STRAIN_RATE = 5,     // 6
    SAVED_STRESS_RATE = 11,    // 6
    SAVED_PORE_FLOW = 17,
    NSAVED = 18
  };
  // a saturated soil's pore pressure p (positive in compression, while the stress above is
  // the effective stress, positive in tension: the total stress is stress - p I), and the
  // pair style's sum of the pore water's flow, div(k/gamma_w grad(p - rho_w g.x))
  // (soil_pore_water.h): the volume of water the particle takes in per unit time and per unit
  // of its own volume (a free water particle's: what it takes from the pores); 0 for dry soil.
  // A wall particle's p is the pressure of a drained wall
  double *pore_pressure;
  double *pore_flow;

  // the axis along which sph_soil/set geostatic last put the overburden (0 x, 1 y, 2 z), -1
  // if never: pair_style sph/soil warns when gravity points along another
  int geostatic_vertical = -1;
  // the group (its bit) and K0 of the last sph_soil/set geostatic whose state was not yet held
  // against the materials' yield surfaces (0: none): pair_style sph/soil does it at its init
  // where the materials were not known to the command
  int geostatic_unchecked_group = 0;
  double geostatic_k0 = 0.0;

  // The layout of this style's per-atom restart data has a number; a restart file of another
  // number stops read_restart with a message that names both (process_args()).
  static constexpr int RESTART_FORMAT = 3;

  struct Arrays {
    double *smoothing_length = nullptr;
    double **stress = nullptr, **stress_rate = nullptr, **total_strain = nullptr;
    double **strain_rate = nullptr, **spin = nullptr;
    int *level = nullptr;
    double *wall_distance = nullptr;
    double **saved_rates = nullptr;
    double *pore_pressure = nullptr, *pore_flow = nullptr;
  };

  // Core Atom arrays with the same meaning as in atom_style sph.
  double *rmass, *rho, *drho, **vest;

  static constexpr int NVOIGT = 6;
  static constexpr int NSPIN = 3;

 private:
  Arrays *arrays;    // the registered pointers
  std::string field_storage[12];
  void store_format_args();
};

}    // namespace LAMMPS_NS

#endif
#endif
