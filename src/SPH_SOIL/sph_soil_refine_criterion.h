/* -*- c++ -*- ----------------------------------------------------------
   SPH_SOIL package for LAMMPS: which particles a refinement splits.

   A criterion answers, for each owned particle, whether it wants to be
   split; fix sph/soil/refine and sph_soil/refine then apply their group,
   region and maxlevel on top (sph_soil_refine_selection.h). Criteria are
   chosen by keyword (`criterion strain|all|v_name`) from the registry
   (sph_soil_refine_criteria.h): a new criterion is one header with its
   class and one line there.
------------------------------------------------------------------------- */

#ifndef LMP_SPH_SOIL_REFINE_CRITERION_H
#define LMP_SPH_SOIL_REFINE_CRITERION_H

#include "pointers.h"

#include <string>

namespace LAMMPS_NS {

// What a refinement knows of each particle's history, per atom (fix sph/soil/refine keeps it;
// nullptr where nothing is kept, as in the sph_soil/refine command, whose criterion then
// measures the strain since the start): the total strain from which the criterion counts (at
// the particle's birth, the split or merge that made it, zero for a particle never split; with
// merging, at the last check at which it had been quiet for the hold time), since when it has been quiet (< 0: it is
// not), and its families: per level l = 1..maxlevel (column l - 1), the ID of the particle whose
// split made it or its ancestor of that level, which daughter 0 kept (0: unknown).
struct RefineHistory {
  double **strain_reference = nullptr;    // Voigt
  double *quiet_since = nullptr;
  double **family = nullptr;
};

class SPHSoilRefineCriterion : protected Pointers {
 public:
  explicit SPHSoilRefineCriterion(LAMMPS *lmp) : Pointers(lmp) {}
  virtual ~SPHSoilRefineCriterion() = default;

  // a keyword of this criterion (e.g. threshold) for `command`; false if not one of its own
  virtual bool parse_keyword(const std::string & /*command*/, const std::string & /*keyword*/,
                             const char * /*value*/)
  {
    return false;
  }
  // check what it needs, at init (e.g. that a variable exists)
  virtual void init(const std::string & /*command*/) {}
  // before each selection (e.g. evaluate a variable); collective
  virtual void prepare(const RefineHistory &) {}
  // whether owned particle i wants to be split
  virtual bool wants(int i) const = 0;
  // whether owned particle i is quiet enough to merge back (fix sph/soil/refine merge T, the
  // time it must stay so): by default, when it does not want to split
  virtual bool quiet(int i, double /*hold_time*/) const { return !wants(i); }
  // owned particle i has been quiet for the hold time of a refinement that merges (it rests):
  // what it did so far is history, and a criterion that counts its deformation counts from here
  virtual void rest(int /*i*/) {}
  // what it selects, for the log: "strain measure > 0.05"
  virtual std::string describe() const = 0;
};

}    // namespace LAMMPS_NS

#endif
