/* -*- c++ -*- ----------------------------------------------------------
   SPH_SOIL package for LAMMPS: pair_style sph/soil

   One loop over a half neighbour list computes, for every soil particle,
   the density rate (continuity), the acceleration (momentum with Monaghan
   artificial viscosity) and the velocity gradient split into strain rate
   and spin (Bui et al. 2008; doc/theory.rst section 2). Wall particles are
   Morris-type ghosts with Bui's no-slip treatment, free slip or Coulomb
   friction per wall type, and take the soil's reaction.
   The stress update lives in fix sph/soil. See doc/pair_sph_soil.rst.
------------------------------------------------------------------------- */

#ifdef PAIR_CLASS
// clang-format off
PairStyle(sph/soil,PairSPHSoil);
// clang-format on
#else

#ifndef LMP_PAIR_SPH_SOIL_H
#define LMP_PAIR_SPH_SOIL_H

#include "pair.h"
#include "soil_constitutive.h"
#include "soil_kernels.h"
#include "soil_material.h"
#include "soil_neighbours.h"

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

  // for fix sph/soil and the computes
  const SPHSoil::SoilMaterial &material(int type) const { return materials[type]; }
  bool is_wall_type(int type) const { return type_set[type] && materials[type].is_wall(); }
  // constitutive model of a soil type, nullptr for wall types and types without material
  const SPHSoil::ConstitutiveModel *model(int type) const { return materials[type].model.get(); }
  double max_wave_speed() const;
  SPHSoil::KernelKind kernel_kind() const { return kernel; }
  // owned atom i's partners in the pair list (each pair is listed at one of its two atoms);
  // 0 for atoms added since the list was built
  int listed_partners(int i) const
  {
    return i < neighbours.size() ? neighbours.end(i) - neighbours.first(i) : 0;
  }
  double memory_usage() override;
  // with fix sph/soil, each particle's skin follows its h (neighbor's skin is that of the
  // largest h): the fix asks LAMMPS to reneighbour when neighbours_outdated() on some rank.
  // Needed only while some particle has a smaller h than the largest (LAMMPS's own check
  // watches the largest particles' skin): skin_check_needed(), the same on every rank, which
  // the caller of neighbours_outdated() checks first
  bool skin_follows_h() const { return integrator != nullptr; }
  bool skin_check_needed() const { return skin_follows_h() && smaller_h_anywhere; }
  bool neighbours_outdated() const;
  const SPHSoil::NeighbourList &neighbour_list() const { return neighbours; }
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
  // per owned and ghost atom: R (Voigt, the units of stress / rho^2) and 1 / w(d / h), w the
  // kernel's shape and d = (m / rho)^(1/D) the spacing: the pair's weight is
  // (W(r) / W(d))^4 = (w(r / h_ij) / w(d / h))^4, exact for two particles of the same d / h
  // (parents and daughters of smoothing ratio 1/2), with the mean of their 1 / w(d / h) otherwise
  enum { A_STRESS = 0, A_INVERSE_SHAPE = 6, ARTIFICIAL = 7 };
  int nmax_artificial;
  double *artificial;
  template <int DIMENSION, class Kernel> void pack_artificial_stress();
  bool free_slip;    // the slip of walls without their own (pair_style ... wall freeslip)
  SPHSoil::KernelKind kernel;                      // the pair loop is compiled once per kernel
  std::vector<SPHSoil::SoilMaterial> materials;    // per atom type, index 1..ntypes
  std::vector<int> type_set;                       // 1 once pair_coeff gave the type a material
  // per type, for the pair loop: SOIL or the wall's boundary (WALL_*); a wall's slip (SLIP_*)
  // and friction coefficient
  std::vector<int> type_wall_kind, type_wall_slip;
  std::vector<double> type_wall_friction;
  // (the neighbour list's kinds: it sorts the partners by them)
  enum {
    SOIL = SPHSoil::NEIGHBOUR_SOIL,
    WALL_MIRROR = SPHSoil::NEIGHBOUR_MIRROR_WALL,
    WALL_EXTRAPOLATE = SPHSoil::NEIGHBOUR_EXTRAPOLATED_WALL
  };
  enum { SLIP_NONE = 0, SLIP_FREE = 1, SLIP_FRICTION = 2 };

  // Walls that extrapolate the soil's state (Adami, Hu & Adams 2012; doc/theory.rst 4.5). Per
  // atom, the soil's kernel-weighted sums at a wall particle: weight sum V_s W, stress, density,
  // rho_s (x_w - x_s) for the hydrostatic correction, velocity; and the wall particle's state
  // from them: stress / rho^2, the image's velocity, density.
  enum { X_WEIGHT = 0, X_STRESS = 1, X_DENSITY = 7, X_HYDROSTATIC = 8, X_VELOCITY = 11, XSUMS = 14 };
  enum { W_STRESS = 0, W_VELOCITY = 6, W_DENSITY = 9, WSTATE = 10 };
  bool has_extrapolated_walls;
  bool walls_may_turn;    // mirror walls and a fix that may turn them: their normals go to
                          // the ghosts every step
  int nmax_extrapolation;
  double *extrapolation_sums, *extrapolated_state;
  std::vector<class Fix *> gravity_fixes;    // their 'gvec': the soil's body force
  class FixSPHSoil *integrator;              // the walls' acceleration
  template <int DIMENSION, class Kernel> void extrapolate_to_walls();
  int pack_forward_comm(int, int *, double *, int, int *) override;
  void unpack_forward_comm(int, int, double *) override;
  int pack_reverse_comm(int, int, double *) override;
  void unpack_reverse_comm(int, int *, double *) override;
  double **sound_speed_ij;                         // mean P-wave speed of a type pair
  double max_h;                                    // largest smoothing length at init
  class AtomVecSPHSoil *avec;
  bool warned_density, warned_spacing, warned_coinciding;    // set-up warnings, given once
  void check_particles();
  void warn_coinciding();
  // The pair loop's per-atom inputs, one row of PACKED doubles per owned and ghost atom:
  // position, velocity estimate, stress / rho^2 (Voigt), volume m / rho, mass, density, h
  enum { P_X = 0, P_V = 3, P_STRESS = 6, P_VOLUME = 12, P_MASS = 13, P_RHO = 14, P_H = 15,
         PACKED = 16 };
  // and its sums, one row per atom: force, density rate, the velocity gradient's sum
  // (sum V t^cd, row by row), split into strain rate and spin when unpacked; a row holds
  // SUM_ROW doubles (8 in 2D, 16 in 3D: whole cache lines), SUMS at most
  enum { S_FORCE = 0, SUMS = 16 };
  template <int DIMENSION> static constexpr int S_DRHO() { return DIMENSION; }
  template <int DIMENSION> static constexpr int S_GRADIENT() { return DIMENSION + 1; }
  template <int DIMENSION> static constexpr int SUM_ROW() { return DIMENSION == 2 ? 8 : 16; }
  int nmax_packed;
  double *packed;
  double *sums;
  template <int DIMENSION> void pack_atoms();
  template <int DIMENSION> void unpack_sums();

  void allocate();
  void set_type_material(int type, const SPHSoil::SoilMaterial &material);
  void read_material_file(const char *file, std::vector<SPHSoil::SoilMaterial> &list);
  template <int DIMENSION, class Kernel, bool ARTIFICIAL_STRESS> void eval();
  struct PairGeometry {
    double dx[3], r2, r, inv_h, hij, factor;
  };
  template <int DIMENSION, class Kernel>
  static bool pair_geometry(const double *xi, double hi, const double *pj, PairGeometry &g);
  // the pair list, each pair with its own cutoff and skin (soil_neighbours.h), rebuilt whenever
  // LAMMPS reneighbours
  SPHSoil::NeighbourList neighbours;
  bool smaller_h_anywhere;    // at the last build, some particle on some rank had h < max_h
  void build_neighbours();
  template <int DIMENSION>
  void mirror_wall_pair(int soil, int wall, double sign, const double dx[3], double r2, double hij,
                        double factor, double c_ij);
  // with_kernel() calls it with the kernel type: picks the dimension and whether the loop
  // adds the artificial stress (compiled apart, so that the loop without it stays as lean)
  struct Evaluate {
    PairSPHSoil *pair;
    int dimension;
    bool artificial_stress;
    template <class Kernel> void operator()() const
    {
      if (artificial_stress) {
        if (dimension == 2) pair->eval<2, Kernel, true>();
        else pair->eval<3, Kernel, true>();
      } else {
        if (dimension == 2) pair->eval<2, Kernel, false>();
        else pair->eval<3, Kernel, false>();
      }
    }
  };
};

}    // namespace LAMMPS_NS

#endif
#endif
