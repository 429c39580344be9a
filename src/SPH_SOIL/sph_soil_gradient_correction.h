/* -*- c++ -*- ----------------------------------------------------------
   SPH_SOIL package for LAMMPS: the gradient correction of pair_style sph/soil
   (pair_style ... gradient_correction yes; the physics: soil_gradient_correction.h,
   doc/theory.rst 2.6).

   Every evaluation, before the pair loop: each owned atom's kernel first moment C_i from the
   pair list (plain partners with their volumes, a mirror wall particle's image with its mass at
   the soil's density), the ghosts' shares returned to their owners; its correction factor; the
   factors sent to the ghosts; the packed rows' stress multiplied by them. After the loop the
   pair style divides each atom's own velocity gradient and density rate by C_i through
   factor(i). Wall particles keep a factor 1 (their kernels are cut by the wall). With `full`
   (gradient_correction full) it also sums each atom's first-moment tensor and gives the velocity
   gradient's correction, its inverse, through velocity_correction(i). Its communication goes
   through the pair style's pack/unpack functions.
------------------------------------------------------------------------- */

#ifndef LMP_SPH_SOIL_GRADIENT_CORRECTION_H
#define LMP_SPH_SOIL_GRADIENT_CORRECTION_H

#include "pointers.h"
#include "soil_kernels.h"
#include "soil_neighbours.h"

#include <vector>

namespace SPHSoil {
struct MirrorPlanes;
}

namespace LAMMPS_NS {

class SPHSoilGradientCorrection : protected Pointers {
 public:
  // `owner` is the pair style whose communication carries the moments and the factors
  SPHSoilGradientCorrection(class LAMMPS *, class Pair *owner, bool full);

  // the factors of the owned and ghost atoms (collective), from the packed rows (soil_packed_rows.h:
  // positions, h, volumes, masses, densities) and the pair list; `wall_kind` per type
  // (SPHSoil::NeighbourKind); then the packed rows' stress multiplied by them
  // `slips` per type (SPHSoil::WallSlipCode) and `planes` per atom: the mirror walls'
  void correct(double *packed, const SPHSoil::NeighbourList &list, const int *wall_kind,
               const int *slips, const SPHSoil::MirrorPlanes &planes, SPHSoil::KernelKind kernel,
               int dimension);
  template <int DIMENSION, class Kernel, bool FULL>
  void moment_sums(const double *packed, const SPHSoil::NeighbourList &list, const int *wall_kind,
                   const int *slips, const SPHSoil::MirrorPlanes &planes);

  // owned or ghost atom i's factor at the last correct()
  double factor(int i) const { return factors[i]; }
  // with `full`, per atom: while summed, M over all partners and M_i over smooth wall images
  // (Voigt) and those images' normals by their share; then (M_p + M_i)^-1, M_p^-1 and the unit
  // normal (or 0) in the same places
  static constexpr int FULL_TENSOR = 0, IMAGE_TENSOR = 6, IMAGE_NORMAL = 12, PER_ATOM = 15;
  // the numbers per atom of its exchanges, at most
  static constexpr int COMM_SIZE = 1 + PER_ATOM;
  bool full() const { return full_tensor; }
  // owned or ghost atom i's velocity gradient correction at the last correct(), for
  // SPHSoil::corrected_velocity_gradient()
  struct VelocityCorrection {
    const double *full, *plain, *normal;
  };
  VelocityCorrection velocity_correction(int i) const
  {
    const double *c = &corrections[(size_t) i * PER_ATOM];
    return {c + FULL_TENSOR, c + IMAGE_TENSOR, c + IMAGE_NORMAL};
  }

  // the pair style's communication, while this unit uses it
  bool communicating() const { return exchange != NONE; }
  int pack_forward_comm(int n, int *list, double *buf);
  void unpack_forward_comm(int n, int first, double *buf);
  int pack_reverse_comm(int n, int first, double *buf);
  void unpack_reverse_comm(int n, int *list, double *buf);

 private:
  class Pair *owner;
  bool full_tensor;
  enum Exchange { NONE, MOMENT, FACTOR } exchange;
  std::vector<double> moments;        // D C_i while summed, then C_i (owned)
  std::vector<double> tensors;        // with full_tensor: PER_ATOM sums per atom
  std::vector<double> factors;        // owned and ghost atoms
  std::vector<double> corrections;    // with full_tensor: PER_ATOM numbers per atom
  void tensor_correction(int i, bool soil, double factor, int dimension);
};

}    // namespace LAMMPS_NS

#endif
