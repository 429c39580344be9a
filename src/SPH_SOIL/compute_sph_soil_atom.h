/* -*- c++ -*- ----------------------------------------------------------
   SPH_SOIL package for LAMMPS: compute sph/soil/atom

   Per-atom soil quantities for dump custom, dump image and compute
   reduce: stress components, pressure, sqrt(J2), the strain measure
   exx^2 + eyy^2 + ezz^2 of the refinement criterion, shear strain and its
   rate, a yielded flag, density, h, refinement level, listed neighbours.
   The values are a table in the .cpp: a new value is one line there.
   See doc/compute_sph_soil_atom.rst.
------------------------------------------------------------------------- */

#ifdef COMPUTE_CLASS
// clang-format off
ComputeStyle(sph/soil/atom,ComputeSPHSoilAtom);
// clang-format on
#else

#ifndef LMP_COMPUTE_SPH_SOIL_ATOM_H
#define LMP_COMPUTE_SPH_SOIL_ATOM_H

#include "compute.h"
#include "soil_level_steps.h"

#include <string>
#include <vector>

namespace LAMMPS_NS {

class ComputeSPHSoilAtom : public Compute {
 public:
  ComputeSPHSoilAtom(class LAMMPS *, int, char **);
  ~ComputeSPHSoilAtom() override;
  void init() override;
  void compute_peratom() override;
  double memory_usage() override;

  // what a value is computed from
  struct Source {
    class AtomVecSPHSoil *avec;
    class Atom *atom;
    class PairSPHSoil *pair;    // nullptr without pair_style sph/soil
    const SPHSoil::StepSchedule *schedule;    // fix sph/soil's, nullptr without one
  };
  // one value of the table: its names (the first, then aliases that users of other codes
  // would type), whether it needs the pair style (its materials or its list) and the value of
  // owned atom i
  struct Value {
    std::vector<std::string> names;
    const char *needs_pair;    // what of the pair it needs, for the error; nullptr: nothing
    double (*of)(const Source &, int i);
  };
  static const std::vector<Value> &values();
  // the first names, for the "allowed" list of errors
  static std::string value_names();

 private:
  std::vector<const Value *> chosen;
  int nmax;
  double *vector;    // one value
  double **array;    // several values
  class PairSPHSoil *pair;
  const SPHSoil::StepSchedule *schedule;
};

}    // namespace LAMMPS_NS

#endif
#endif
