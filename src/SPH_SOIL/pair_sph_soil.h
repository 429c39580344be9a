/* -*- c++ -*- ----------------------------------------------------------
   SPH_SOIL package for LAMMPS: pair_style sph/soil

   One loop over the pair style's own half neighbour list computes, for every
   particle, the density rate (continuity), the acceleration (momentum with
   Monaghan artificial viscosity) and the velocity gradient split into strain
   rate and spin (Bui et al. 2008; doc/theory.rst section 2). The stress update
   lives in fix sph/soil. See doc/pair_sph_soil.rst.

   The style is plumbing between rooms of its own:
     pair_sph_soil.cpp         input (settings, pair_coeff), init, restart
     sph_soil_materials.h      the materials per type (pair_coeff, files, restart)
     pair_sph_soil_checks.cpp  the set-up checks of the particles
     pair_sph_soil_loop.cpp    the packed rows, the loop, the virial
     sph_soil_walls.h          everything about wall particles
     sph_soil_pore_water.h     the pore water of saturated soil
     soil_neighbours.h         the list; fix SPH_SOIL_SKIN keeps it valid
------------------------------------------------------------------------- */

#ifdef PAIR_CLASS
// clang-format off
PairStyle(sph/soil,PairSPHSoil);
// clang-format on
#else

#ifndef LMP_PAIR_SPH_SOIL_H
#define LMP_PAIR_SPH_SOIL_H

#include "pair.h"
#include "soil_kernels.h"
#include "soil_level_steps.h"
#include "soil_neighbours.h"
#include "sph_soil_materials.h"

#include <memory>
#include <string>
#include <vector>

namespace LAMMPS_NS {

class PairSPHSoil : public Pair {
 public:
  PairSPHSoil(class LAMMPS *);
  ~PairSPHSoil() override;

  void compute(int, int) override;
  void settings(int, char **) override;
  void coeff(int, char **) override;
  void init_style() override;
  double init_one(int, int) override;
  void *extract(const char *, int &) override;
  void write_restart(FILE *) override;
  void read_restart(FILE *) override;
  void write_restart_settings(FILE *) override;
  void read_restart_settings(FILE *) override;
  // the layout of the style's restart data has a number: read_restart of another stops
  static constexpr int RESTART_FORMAT = 4;

  // for fix sph/soil, the refinement and the computes
  const SPHSoil::SoilMaterial &material(int type) const { return materials.of(type); }
  bool is_wall_type(int type) const { return materials.is_wall(type); }
  // constitutive model of a soil type, nullptr for wall types and types without material
  const SPHSoil::ConstitutiveModel *model(int type) const { return materials.model(type); }
  double max_wave_speed() const { return materials.max_wave_speed(); }
  // by how much viscosity_h0 shortens the stable step at smoothing length h (>= 1)
  double viscosity_step_factor(double h) const;
  SPHSoil::KernelKind kernel_kind() const { return kernel; }
  // owned atom i's partners in the pair list (each pair is listed at one of its two atoms);
  // 0 for atoms added since the list was built
  int listed_partners(int i) const
  {
    return i < neighbours.size() ? neighbours.end(i) - neighbours.first(i) : 0;
  }
  double memory_usage() override;
  const SPHSoil::NeighbourList &neighbour_list() const { return neighbours; }
  // soil particles behind the plane of a mirror wall they pair with, on all ranks (collective):
  // a diagnosis of an instability
  bigint soil_behind_walls() const;
  // the pore water that owned atom i took in from drained partners (sph_soil_pore_water.h)
  double drained_inflow(int i) const;
  // whether some type carries a pressure, saturated soil or free water (known after init)
  bool carries_pressures() const;
  // the pore water of saturated soil (known after init)
  const class SPHSoilPoreWater &pore_water_unit() const { return *pore_water; }
  // the stress diffusion (its rates of the last evaluation), or nullptr without one
  const class SPHSoilStressDiffusion *stress_diffusion_unit() const { return diffusion.get(); }
  // whether the pair loop adds the artificial stress (known after init)
  bool artificial_stress_active() const { return has_artificial_stress; }

 protected:
  double viscosity_alpha, viscosity_beta;    // Monaghan artificial viscosity
  double viscosity_h0;    // > 0: every pair gets the dissipation of h = h0
                          // (SPHSoil::viscosity_length); 0: alpha and beta as they are
  // Gray, Monaghan & Swift's artificial stress (doc/theory.rst 2.5): its epsilon, for the
  // types whose soil can carry tension (type_artificial_stress: tensile strength > 0)
  double artificial_stress_epsilon;
  std::vector<int> type_artificial_stress;
  bool has_artificial_stress;
  bool free_slip;    // the slip of walls without their own (pair_style ... wall freeslip)
  // continuity equation: rho_i sum_j V_j v_ij . grad W (true, the default: the density stays
  // positive however a thin front spreads, doc/theory.rst 2.1) or sum_j m_j v_ij . grad W
  bool continuity_volume;
  SPHSoil::KernelKind kernel;    // the pair loop is compiled once per kernel
  SPHSoilMaterials materials;
  std::unique_ptr<class SPHSoilWalls> walls;
  std::unique_ptr<class SPHSoilPoreWater> pore_water;
  // the first-moment correction of the gradients (sph_soil_gradient_correction.h), or none
  std::unique_ptr<class SPHSoilGradientCorrection> correction;
  // pair_style ... gradient_correction no, yes (scalar) or full (the velocity gradient by the
  // first-moment tensor too): the restart file's flag
  enum { CORRECTION_NONE = 0, CORRECTION_SCALAR = 1, CORRECTION_FULL = 2 };
  int gradient_correction;
  // delta-SPH's diffusions (doc/theory.rst 2.8, 7.4): of free water's density, and of the
  // soils' stress (stress_diffusion: AUTO_DIFFUSION until init resolves it, from whether the
  // run has pore water or free water); 0: none
  double density_diffusion, stress_diffusion;
  static constexpr double AUTO_DIFFUSION = -1.0;
  // delta of both by default: Marrone et al. (2011)'s and DualSPHysics's choice for water
  static constexpr double DEFAULT_DIFFUSION = 0.1;
  void init_stress_diffusion();
  std::unique_ptr<class SPHSoilStressDiffusion> diffusion;
  double **sound_speed_ij;    // mean P-wave speed of a type pair
  double max_h;               // largest smoothing length at init
  class AtomVecSPHSoil *avec;
  void set_defaults();
  void allocate();

  // the communication of the extrapolated walls (sph_soil_walls.h) and of the pore water
  // (sph_soil_pore_water.h)
  int pack_forward_comm(int, int *, double *, int, int *) override;
  void unpack_forward_comm(int, int, double *) override;
  int pack_reverse_comm(int, int, double *) override;
  void unpack_reverse_comm(int, int *, double *) override;

  // set-up checks (pair_sph_soil_checks.cpp): warnings given once
  bool warned_density, warned_spacing, warned_coinciding;
  void check_particles();
  void warn_density();
  void warn_spacing();
  void warn_coinciding();
  void warn_soil_in_rigid_bodies();
  void warn_geostatic_across_gravity();

 public:
  // sph_soil/set geostatic's check: a warning with the count of the group's soil particles
  // that its stress (from K0) puts on or outside their material's yield surface, if any.
  // False (and nothing done) where a type of the group has no material yet. Collective.
  bool warn_geostatic_yield(int groupbit, double k0);

 protected:
  void check_list_fits();

  // the loop (pair_sph_soil_loop.cpp). Per owned and ghost atom: the packed rows of its inputs
  // (soil_packed_rows.h), and its sums: force, density rate, the velocity gradient's sum
  // (sum V t^cd, row by row), split into strain rate and spin when unpacked, and with free
  // water the divergence of the soil-water pairs (sum V t^cc over them), which goes to the pore
  // water only (doc/theory.rst 7.5); a row holds SUM_ROW doubles (8 in 2D, 16 in 3D: whole
  // cache lines), SUMS at most
  enum { S_FORCE = 0, SUMS = 16 };
  template <int DIMENSION> static constexpr int S_DRHO() { return DIMENSION; }
  template <int DIMENSION> static constexpr int S_GRADIENT() { return DIMENSION + 1; }
  template <int DIMENSION> static constexpr int S_ACROSS() { return DIMENSION + 1 + DIMENSION * DIMENSION; }
  template <int DIMENSION> static constexpr int SUM_ROW() { return DIMENSION == 2 ? 8 : 16; }
  int nmax_packed;
  double *packed;
  double *sums;
  // the momentum sum's form: m_i m_j (sigma_i / rho_i^2 + sigma_j / rho_j^2) (Bui 2008), or, in
  // runs with free water, V_i V_j (sigma_i + sigma_j) (Colagrossi & Landrini 2003: the same for
  // particles of one density, and right across the jump from water to soil, where the first
  // form makes the interface unstable; doc/theory.rst 7.5). The packed rows then hold the stress
  // itself, not stress / rho^2
  bool multiphase;
  // In that form a pair of a soil particle and a free water particle sums their pressures and
  // the skeleton's tension only: the water bears on the grains through its pressure, and the
  // skeleton's effective stress ends at the soil's surface (sigma' n = 0 under water) as a free
  // surface's stress does, but for its tension, which SPH cannot leave at a free surface (the
  // tensile instability: a block whose drained sides were in effective tension came apart at
  // once); and its velocity terms do not enter the skeleton's strain rate (what the effective
  // stress does not act across, it must not deform with: a dense column's submerged face ran
  // away when it did), only their divergence enters the pore water's balance of volume (the
  // volume the pair's pressures work on is both particles'; doc/theory.rst 7.5). Per owned and
  // ghost atom, the pressure of its packed
  // stress (its pore or water pressure) and a soil particle's skeleton tension (the tensile
  // part of its effective stress; 0 for others), scaled as the packed stress is; per type
  // whether it is free water, or a soil
  std::vector<double> packed_pressure;
  std::vector<double> skeleton_tension;
  std::vector<int> type_free_water;
  std::vector<int> type_soil_by_water;
  // (PRESSURES: some type carries a pressure, which the total stress subtracts)
  template <int DIMENSION, bool PHASES, bool PRESSURES> void pack_atoms();
  // with a time step per level (fix sph/soil's schedule, soil_level_steps.h): per owned and
  // ghost atom its signed period (+n: it ends a step at this evaluation, -n: not; a wall
  // particle -infinity, it takes its partner's), from its h
  const SPHSoil::StepSchedule *schedule;
  int nmax_periods;
  double *step_periods;
  int *atom_periods;           // the periods (0: a wall), kept from one list to the next
  double periods_finest_h;     // the h_min they were computed with
  std::vector<int> active_partners;    // the loop's: an atom's partners that end a step
  bool per_level() const { return schedule && schedule->per_level; }
  void pack_step_periods();
  // (CORRECTION: none, the gradient correction's factors, or those and its velocity gradient
  // tensors; compiled apart, so that runs without it keep their cost)
  template <int DIMENSION, int CORRECTION, bool PHASES> void unpack_sums();
  // per owned and ghost atom: R (Voigt, the units of stress / rho^2) and 1 / w(d / h), w the
  // kernel's shape and d = (m / rho)^(1/D) the spacing: the pair's weight is
  // (W(r) / W(d))^4 = (w(r / h_ij) / w(d / h))^4, exact for two particles of the same d / h
  // (parents and daughters of smoothing ratio 1/2), with the mean of their 1 / w(d / h) otherwise
  enum { A_STRESS = 0, A_INVERSE_SHAPE = 6, ARTIFICIAL = 7 };
  int nmax_artificial;
  double *artificial;
  template <int DIMENSION, class Kernel, bool PHASES> void pack_artificial_stress();
  template <int DIMENSION, class Kernel, bool ARTIFICIAL_STRESS, bool VIRIAL, bool LEVELS, bool PHASES>
  void eval();
  template <int DIMENSION, bool VIRIAL, bool PHASES>
  void mirror_wall_pair(int soil, int wall, double sign, const double dx[3], double r2, double hij,
                        double factor, double c_ij, double weight);
  // with_kernel() calls it with the kernel type: picks the dimension, whether the loop adds the
  // artificial stress, whether it tallies the virial pair by pair and whether it steps per level
  // (each compiled apart, so that the loop without them stays as lean)
  struct Evaluate {
    PairSPHSoil *pair;
    int dimension;
    bool artificial_stress, virial, levels, phases;
    template <class Kernel> void operator()() const;
  };

  // the pair list, each pair with its own cutoff and skin (soil_neighbours.h), rebuilt whenever
  // LAMMPS reneighbours; fix SPH_SOIL_SKIN asks for a reneighbouring when some particle has
  // moved half its own skin, while some particle has a smaller h than the largest
  SPHSoil::NeighbourList neighbours;
  std::string skin_fix_id;
  class FixSPHSoilSkin *skin_fix;
  void build_neighbours();
};

}    // namespace LAMMPS_NS

#endif
#endif
