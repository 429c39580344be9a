/* -*- c++ -*- ----------------------------------------------------------
   SPH_SOIL package for LAMMPS: the walls of pair_style sph/soil.

   Everything about wall particles on the LAMMPS side, in one unit that the
   pair style owns and asks for wall data:
   - classification per atom type: soil, or a wall with its boundary (mirror
     images or extrapolation) and its slip (no slip, free slip, friction);
   - the set-up checks of wall particles (a plane, and the particles behind it);
   - kinematics: a wall particle's velocity is its own (a fix such as move or
     rigid sets it), its acceleration over the last step that of the internal
     fix SPH_SOIL_WALLS (fix_sph_soil_walls.h), which this unit creates; the
     normals of walls that a fix may turn go to the ghosts every step;
   - the boundaries: mirror images (soil_wall_images.h, applied in the pair
     loop) and walls that extrapolate the soil's state (Adami, Hu & Adams 2012;
     doc/theory.rst 4.5), with their own communication, which the pair style's
     pack/unpack functions hand on to this unit;
   - the Coulomb interface of frictional walls (sph_soil_wall_friction.h), whose
     friction forces the internal fix applies after every other force of the step.
   A new wall boundary is a kind here (NeighbourKind, for the pair list's
   order), its state before the loop (prepare()) and, if its pairs are not
   plain SPH pairs, its image in the loop.
------------------------------------------------------------------------- */

#ifndef LMP_SPH_SOIL_WALLS_H
#define LMP_SPH_SOIL_WALLS_H

#include "atom.h"
#include "lmptype.h"
#include "pointers.h"
#include "soil_kernels.h"
#include "soil_material.h"
#include "soil_neighbours.h"

#include <string>
#include <vector>

namespace SPHSoil {
struct MirrorPlanes;
}

namespace LAMMPS_NS {

class SPHSoilWalls : protected Pointers {
 public:
  // `owner` is the pair style whose communication carries the extrapolated walls' data
  SPHSoilWalls(class LAMMPS *, class Pair *owner);
  ~SPHSoilWalls() override;

  // per-type classification, from the materials of the types that have one (materials[t] is a
  // wall or a soil, `has_material[t]` whether pair_coeff set it); `free_slip` is the slip of
  // walls without their own (pair_style sph/soil wall freeslip). Errors for walls that cannot
  // be what their material asks.
  void classify(const std::vector<SPHSoil::SoilMaterial> &materials,
                const std::vector<int> &has_material, bool free_slip);
  // the wall particles' state against their kind (a plane for mirror walls, the particles
  // behind it): an error naming the first offender
  void check_particles() const;
  // at the pair style's init: the fixes the walls depend on (gravity, fixes that may turn
  // walls) and the kinematics fix
  void init();

  bool any() const { return has_mirror || has_extrapolated; }
  bool is_wall(int type) const { return kind_of_type[type] != SPHSoil::NEIGHBOUR_SOIL; }
  // SPHSoil::NeighbourKind per atom type (index 0..ntypes), for the pair list
  const int *kinds() const { return kind_of_type.data(); }
  // the slip (SPHSoil::WallSlipCode) and friction coefficient of a mirror wall type
  const int *slips() const { return slip_of_type.data(); }
  const double *frictions() const { return friction_of_type.data(); }
  const double *adhesions() const { return adhesion_of_type.data(); }
  // whether a type is a drained mirror wall, and the gap between such a wall particle and the
  // soil lifting off it (0 in contact; soil_wall_images.h's drained_image()), this step
  bool drained_mirror(int type) const { return drained_mirror_of_type[type] != 0; }
  double gap(int i) const { return gaps[i]; }
  // per owned or ghost soil particle, this step: the farthest it stands in front of the plane of
  // a mirror wall particle it pairs with (<= 0: behind all of them; soil_wall_images.h's
  // has_image()); and the mirror walls' planes with it
  double front_most(int i) const { return fronts[i]; }
  SPHSoil::MirrorPlanes planes() const;

  // before the pair loop, with the loop's packed rows (soil_packed_rows.h) of the owned and
  // ghost atoms and the pair list: turned normals to the ghosts; the extrapolated walls' state
  // (stress, velocity, density, volume) written into their rows
  // (`stress_itself`: the packed rows hold the stress, not stress / rho^2: the pair style's
  // multiphase form)
  void prepare(double *packed, const SPHSoil::NeighbourList &list, SPHSoil::KernelKind kernel,
               int dimension, bool stress_itself);

  // the Coulomb interface of frictional walls (sph_soil_wall_friction.h), nullptr if none;
  // the pair loop adds its pairs to it
  class SPHSoilWallFriction *interface() const { return friction; }

  // the communication of the extrapolated walls and of the interface, handed on by the pair
  // style (the larger of their sizes)
  int forward_size() const;
  int reverse_size() const;
  int pack_forward_comm(int n, int *list, double *buf);
  void unpack_forward_comm(int n, int first, double *buf);
  int pack_reverse_comm(int n, int first, double *buf);
  void unpack_reverse_comm(int n, int *list, double *buf);
  double memory_usage() const;
  // owned soil particles behind the plane of every mirror wall particle they paired with at the
  // last pair loop, over every rank's pairs (this rank's owned particles)
  bigint soil_behind_planes() const;

  // the gaps under soil lifting off drained mirror walls, each such wall particle moved in its
  // packed row to where the soil would touch it (public: prepare()'s dimension dispatch)
  template <int DIMENSION> void follow_lifting_soil(double *packed, const SPHSoil::NeighbourList &list);
  // front_most() of every owned and ghost soil particle (public: prepare()'s dimension dispatch)
  template <int DIMENSION> void find_front_most(const double *packed, const SPHSoil::NeighbourList &list);

  // the extrapolation's own pass over the soil-wall pairs (public: with_kernel() calls it)
  template <int DIMENSION, class Kernel>
  void extrapolate(double *packed, const SPHSoil::NeighbourList &list);

 private:
  class Pair *owner;
  class AtomVecSPHSoil *avec;
  std::vector<int> kind_of_type, slip_of_type, drained_mirror_of_type;
  std::vector<double> friction_of_type, adhesion_of_type;
  bool has_mirror, has_extrapolated, has_friction, has_drained_mirror;
  class SPHSoilWallFriction *friction;
  // whose data the communication in progress carries
  enum class Exchange { EXTRAPOLATION, FRICTION, GAPS, FRONTS } exchange;
  std::vector<double> gaps;      // gap() of the owned and ghost atoms
  std::vector<double> fronts;    // front_most() of the owned and ghost atoms
  static constexpr double NO_FRONT = -1.0e300;    // fronts' value without a mirror partner
  bool warned_reach = false;   // that soil has lifted off a drained wall beyond its reach
  bool may_turn;    // mirror walls and a fix that may turn them: their normals go to the
                    // ghosts every step
  std::vector<class Fix *> gravity_fixes;    // their 'gvec': the soil's body force
  class FixSPHSoilWalls *kinematics;
  std::string kinematics_id;
  void create_kinematics();
  // f(soil, wall) for every pair of a soil particle and a mirror wall particle listed at the
  // first `count` atoms of the pair list (soil_neighbours.h: after each atom's plain pairs)
  template <class F> void each_mirror_pair(const SPHSoil::NeighbourList &list, int count, F f) const
  {
    const int *type = atom->type;
    const int *partners = list.partner_data();
    for (int i = 0; i < count; i++) {
      const bool wall_i = kind_of_type[type[i]] == SPHSoil::NEIGHBOUR_MIRROR_WALL;
      for (int jj = list.plain_end(i); jj < list.end(i); jj++)
        wall_i ? f(partners[jj], i) : f(i, partners[jj]);
    }
  }

  // Per atom, the soil's kernel-weighted sums at an extrapolated wall particle: weight sum
  // V_s W, stress, density, rho_s (x_w - x_s) for the hydrostatic correction, velocity; and
  // the wall particle's state from them: stress / rho^2, the image's velocity, density.
  enum { X_WEIGHT = 0, X_STRESS = 1, X_DENSITY = 7, X_HYDROSTATIC = 8, X_VELOCITY = 11, XSUMS = 14 };
  enum { W_STRESS = 0, W_VELOCITY = 6, W_DENSITY = 9, WSTATE = 10 };
  int nmax;
  double *sums, *state;
  template <int DIMENSION> void extrapolated_states(double *packed);
  bool packed_stress_itself = false;    // prepare()'s
};

}    // namespace LAMMPS_NS

#endif
