/* -*- c++ -*- ----------------------------------------------------------
   SPH_SOIL package for LAMMPS: the stress diffusion of pair_style sph/soil
   (pair_style ... stress_diffusion delta; the physics: soil_stress_diffusion.h,
   doc/theory.rst 2.8).

   Every evaluation, after the pair loop: a pass over the pairs of soil particles of one type
   sums each atom's first-moment tensor and stress gradient (the ghosts' shares returned to
   their owners), renormalises the gradients and sends them to the ghosts; a second pass sums
   each atom's diffusion rate of its (effective) stress, the ghosts' shares returned. Fix
   sph/soil adds rate(i) times the step to the stress before the return to the admissible set.
   Pairs of two types, with walls or with free water are not diffused: the stress may jump
   across a material's boundary, and a mirror wall's image is no linear continuation of it.
   Its communication goes through the pair style's pack/unpack functions.
------------------------------------------------------------------------- */

#ifndef LMP_SPH_SOIL_STRESS_DIFFUSION_H
#define LMP_SPH_SOIL_STRESS_DIFFUSION_H

#include "pointers.h"
#include "soil_kernels.h"
#include "soil_neighbours.h"

#include <vector>

namespace LAMMPS_NS {

class SPHSoilStressDiffusion : protected Pointers {
 public:
  // `owner` is the pair style whose communication carries the sums, gradients and rates
  SPHSoilStressDiffusion(class LAMMPS *, class Pair *owner);

  // per type, the coefficient delta c of its diffusion (c the soil's wave speed; 0: none)
  void init(const std::vector<double> &coefficient_of_type);
  // the rates of the owned atoms (collective), from the packed rows (soil_packed_rows.h:
  // positions, h, volumes), the atoms' stress and the pair list
  void diffuse(const double *packed, const SPHSoil::NeighbourList &list, SPHSoil::KernelKind kernel,
               int dimension);
  template <int DIMENSION, class Kernel>
  void diffuse_sums(const double *packed, const SPHSoil::NeighbourList &list);
  // owned atom i's stress rate at the last diffuse() (Voigt, 6 values)
  const double *rate(int i) const { return &rates[(size_t) i * VOIGT]; }

  // the largest numbers per atom of its exchanges
  static constexpr int COMM_SIZE = 24;
  bool communicating() const { return exchange != NONE; }
  int pack_forward_comm(int n, int *list, double *buf);
  void unpack_forward_comm(int n, int first, double *buf);
  int pack_reverse_comm(int n, int first, double *buf);
  void unpack_reverse_comm(int n, int *list, double *buf);

  // the smallest determinant of a particle's first-moment tensor for which its gradient is
  // trusted (1 in a full neighbourhood, 0.40 on the surface of a square lattice, about 0.25 at
  // its corner)
  static constexpr double SMALLEST_DETERMINANT = 0.05;

 private:
  static constexpr int VOIGT = 6;
  class Pair *owner;
  class AtomVecSPHSoil *avec;
  std::vector<double> coefficient;    // per type
  enum Exchange { NONE, SUMS, GRADIENTS, RATES } exchange;
  int gradient_width;                 // the sums' (gradient_size) for the run's dimension
  int moment;                         // where the gradient starts in them (moment_size)
  int components;                     // the stress components diffused
  std::vector<double> gradients;      // per atom (owned and ghost): gradient_width numbers
  std::vector<double> valid;          // per atom: 1 where its gradient is trusted
  std::vector<double> rates;          // per atom (owned and ghost): VOIGT numbers
  // the diffused pairs of the first pass, owned atom i's from pair_start[i] on
  struct DiffusedPair {
    int partner;
    double dx[3], r2, h, factor;
  };
  std::vector<DiffusedPair> pairs;
  std::vector<int> pair_start;
};

}    // namespace LAMMPS_NS

#endif
