/* -*- c++ -*- ----------------------------------------------------------
   SPH_SOIL package for LAMMPS: the pore water of pair_style sph/soil.

   Everything about saturated soil on the LAMMPS side, in one unit that the pair
   style owns (the physics: soil_pore_water.h, doc/theory.rst section 7):
   - per atom type, the mobility k / gamma_w of a saturated soil, a drained
     wall's mark, and the pore water (its density, its permeability law); per atom, the mobility at its
     density where k follows the porosity (permeability_law kozeny_carman);
   - the pore pressure and mass of the ghosts, every step before the pair loop packs the
     total stress (the atom style sends them at reneighbouring only, so that runs
     of dry soil do not carry them);
   - the pore water's flow, div(k / gamma_w grad(p - rho_w g . x)), summed over
     the pair list into the atom style's pore_flow, the ghosts' shares returned
     to their owners; fix sph/soil integrates the pore pressure from it.
   Its communication goes through the pair style's pack/unpack functions.
------------------------------------------------------------------------- */

#ifndef LMP_SPH_SOIL_PORE_WATER_H
#define LMP_SPH_SOIL_PORE_WATER_H

#include "pointers.h"
#include "soil_kernels.h"
#include "soil_material.h"
#include "soil_neighbours.h"

#include <vector>

namespace LAMMPS_NS {

class SPHSoilPoreWater : protected Pointers {
 public:
  // `owner` is the pair style whose communication carries the pore pressure and its flow
  SPHSoilPoreWater(class LAMMPS *, class Pair *owner);

  // at the pair style's init, from the materials of the types (materials[t] set where
  // `has_material[t]`): errors and warnings for what a saturated soil cannot be
  // `density_diffusion`: delta of the free water's density diffusion (0: none)
  void init(const std::vector<SPHSoil::SoilMaterial> &materials,
            const std::vector<int> &has_material, double density_diffusion);
  // whether some type carries a pressure (saturated soil, free water): the ghosts need it
  bool pressures() const { return saturated || water; }
  // whether the flow pass has something to do: a saturated soil's pore water flows, free
  // water's density diffuses
  bool flows() const { return saturated || diffuses_water; }
  // whether some type is free water
  bool free_water() const { return water; }
  // whether some saturated soil's k follows its porosity (the time step then follows the
  // particles' densities: largest_diffusivity())
  bool variable_conductivity() const { return variable; }
  // the largest diffusivity k K_w / (gamma_w n) of this rank's owned atoms in group
  // `groupbit`, at their densities; 0 without saturated soil
  double largest_diffusivity(int groupbit) const;

  // the ghosts' pore pressure and mass (which the water's exchange changes), from their owners
  // (collective)
  void share_pressures();
  // the pore water's flow of every owned atom (avec->pore_flow), from the packed rows
  // (soil_packed_rows.h: positions, h, volumes) and the pair list; collective
  // (`correction`: the pair style's gradient correction, whose factors 1 / C normalise the
  // Laplacian as they do the stress's divergence, or nullptr)
  void flow(const double *packed, const SPHSoil::NeighbourList &list, SPHSoil::KernelKind kernel,
            int dimension, const class SPHSoilGradientCorrection *correction);
  // (PER_ATOM: each atom's mobility at its density, a permeability law; else its type's)
  template <int DIMENSION, class Kernel, bool PER_ATOM>
  void flow_sums(const double *packed, const SPHSoil::NeighbourList &list,
                 const class SPHSoilGradientCorrection *correction);

  // the pore water volume per unit time that owned atom i took in from drained partners (drained
  // walls, free water) at the last evaluation, negative where it drained into them: summed over
  // a boundary's soil, the flux through it (m^3/s, per unit depth in 2D). 0 without flow
  double drained_inflow(int i) const
  {
    return saturated && i < (int) inflow.size() ? inflow[i] : 0.0;
  }

  // the mass (kg/s) and momentum (3, kg m/s^2) that owned atom i takes in with the water it
  // exchanges with its partners at the last evaluation (a saturated soil's pores, free water;
  // doc/theory.rst 7.4): each pair gives one what it takes from the other, the momentum being
  // the water's mass times the velocity of the particle that gives it; fix sph/soil moves them
  const double *moved_water(int i) const { return &moved[(size_t) i * MOVED]; }
  // the numbers of moved_water(), and of an atom in the flow's reverse exchange
  static constexpr int MOVED = 4, FLOW_COMM_SIZE = 1 + MOVED;

  // the pair style's communication, while this unit uses it
  bool communicating() const { return exchange != NONE; }
  int pack_forward_comm(int n, int *list, double *buf);
  void unpack_forward_comm(int n, int first, double *buf);
  int pack_reverse_comm(int n, int first, double *buf);
  void unpack_reverse_comm(int n, int *list, double *buf);

  // a drained partner's mark: an infinite mobility, the pair's conductance is the soil's alone
  static constexpr double DRAINED = -1.0;

 private:
  class Pair *owner;
  class AtomVecSPHSoil *avec;
  bool saturated, water, variable;
  bool diffuses_water;    // some free water type with a density diffusion
  // a free water type's numbers (others: 0)
  struct FreeWaterType {
    double density = 0.0;            // rho_w of its equation of state
    double compliance = 0.0;         // rho_w / K_w: its density's change per pascal
    double diffusion_speed = 0.0;    // delta c_w: its density diffusion's coefficient per h
    bool is_water() const { return density > 0.0; }
  };
  std::vector<FreeWaterType> free_water_of_type;
  enum Exchange { NONE, PRESSURE, FLOW } exchange;
  std::vector<double> mobility_of_type;         // k / gamma_w; DRAINED; 0: no pore water
  std::vector<SPHSoil::PoreWater> water_of_type;  // a saturated soil's pore water (its rho_w, law)
  std::vector<double> density_of_type;          // a saturated soil's rho0
  std::vector<double> atom_mobility;            // owned and ghost atoms' mobility this step
  // the mobility of atom i at density rho (the type's, where k is constant)
  double mobility_at(int type, double rho) const
  {
    const double lambda = mobility_of_type[type];
    if (lambda <= 0.0 || !water_of_type[type].variable_conductivity()) return lambda;
    return lambda * water_of_type[type].conductivity_factor(rho / density_of_type[type]);
  }
  std::vector<class Fix *> gravity_fixes;       // their 'gvec': the water's weight
  std::vector<double> inflow;                   // drained_inflow() of the owned atoms
  std::vector<double> moved;                    // moved_water() of owned and ghost atoms
};

}    // namespace LAMMPS_NS

#endif
