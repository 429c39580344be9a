/* -*- c++ -*- ----------------------------------------------------------
   SPH_SOIL package for LAMMPS: compute sph/soil/atom

   Per-atom soil quantities for dump custom, dump image and compute
   reduce: stress components, pressure, sqrt(J2), the strain measure
   exx^2 + eyy^2 + ezz^2 of the refinement criterion, a yielded flag,
   density, h and refinement level. See doc/compute_sph_soil_atom.rst.
------------------------------------------------------------------------- */

#ifdef COMPUTE_CLASS
// clang-format off
ComputeStyle(sph/soil/atom,ComputeSPHSoilAtom);
// clang-format on
#else

#ifndef LMP_COMPUTE_SPH_SOIL_ATOM_H
#define LMP_COMPUTE_SPH_SOIL_ATOM_H

#include "compute.h"

#include <vector>

namespace LAMMPS_NS {

class ComputeSPHSoilAtom : public Compute {
 public:
  ComputeSPHSoilAtom(class LAMMPS *, int, char **);
  ~ComputeSPHSoilAtom() override;
  void init() override;
  void compute_peratom() override;
  double memory_usage() override;

 private:
  enum Quantity { SXX, SYY, SZZ, SXY, SXZ, SYZ, PRESSURE, SQRTJ2, STRAIN, YIELDED, DENSITY, H, LEVEL,
                  NEIGHBOURS, SHEAR_STRAIN, SHEAR_STRAIN_RATE };
  std::vector<Quantity> quantities;
  int nmax;
  double *values;      // one quantity
  double **table;      // several quantities
  class PairSPHSoil *pair;

  double evaluate(Quantity, int i) const;
};

}    // namespace LAMMPS_NS

#endif
#endif
