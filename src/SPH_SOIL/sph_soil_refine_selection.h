/* -*- c++ -*- ----------------------------------------------------------
   SPH_SOIL package for LAMMPS: the particles a refinement splits: group,
   region, level limit and criterion (sph_soil_refine_criteria.h), widened by
   a buffer around the particles the criterion wants, with one parser for the
   keywords that fix sph/soil/refine and sph_soil/refine share.
------------------------------------------------------------------------- */

#ifndef LMP_SPH_SOIL_REFINE_SELECTION_H
#define LMP_SPH_SOIL_REFINE_SELECTION_H

#include "sph_soil_ghost_rows.h"
#include "sph_soil_refine_criterion.h"

#include <memory>
#include <string>
#include <vector>

namespace LAMMPS_NS {

class SPHSoilRefineSelection : protected Pointers {
 public:
  // `command` as the user types it ("fix sph/soil/refine"), `default_criterion` its default
  SPHSoilRefineSelection(LAMMPS *lmp, const std::string &command, const std::string &default_criterion);

  // criterion, region, buffer and the criterion's own keywords; false if `keyword` is none of
  // them
  bool parse_keyword(const std::string &keyword, const char *value);
  // its keywords and every criterion's own, for messages: "criterion, region, buffer, threshold"
  static std::string keywords();
  // at init: the region (it may have been redefined), the criterion's needs, the kernel's
  // support (in h: the buffer's unit) and the split's smoothing ratio alpha_r (a daughter's
  // parent had h / alpha_r)
  void init(double kernel_support, double smoothing_ratio);
  // owned particles of `groupbit` below `maxlevel` (0: no limit) that the region contains and
  // the criterion wants, and with a buffer b those whose kernel's support times b (b support
  // h_k, their own h: the reach of their kernel) reaches a particle j of the group and region
  // that the criterion wants (at any level, maxlevel included), if they are not finer than j;
  // collective (the criterion may evaluate a variable; with a buffer the ghosts must be
  // current). `may_split`, if given, gets per owned particle whether it may split (group,
  // level, region) whatever the criterion says.
  std::vector<int> parents(int groupbit, int maxlevel, const RefineHistory &history = RefineHistory(),
                           std::vector<char> *may_split = nullptr);
  // whether owned particle i is quiet enough to merge (after parents(), which prepares the
  // criterion): the criterion says so, and the particle it would merge into would not be in
  // the buffer of a particle the criterion wants (else it would merge back and split again)
  bool quiet(int i, double hold_time) const
  {
    return !(i < (int) parent_in_buffer.size() && parent_in_buffer[i]) && criterion->quiet(i, hold_time);
  }
  // owned particle i has been quiet for the hold time (after parents()): it rests, and a
  // criterion that counts its deformation counts from here (SPHSoilRefineCriterion::rest())
  void rest(int i) { criterion->rest(i); }
  std::string describe() const;

 private:
  std::string command;
  std::string criterion_word;       // as given to `criterion`
  std::string criterion_keyword;    // the last keyword of the criterion's own that was given
  std::unique_ptr<SPHSoilRefineCriterion> criterion;
  std::string region_id;
  class Region *region;
  double buffer = 0.0;              // b: in kernel supports of the buffered particle's own h
  double support = 2.0;             // the kernel's support in h (init)
  double smoothing_ratio = 0.5;     // alpha_r (init)
  // per owned particle, at the last parents(): within the buffer of a wanted particle, and
  // (a refined one) with its parent's reach
  std::vector<char> in_buffer, parent_in_buffer;
  SPHSoilGhostRows shared;          // wanted flags and levels to the ghosts
  // the owned particles in the buffer of the `wanted` ones (owned and ghosts), and those of
  // them that may split, added to `selected`
  void widen(int groupbit, const std::vector<char> &wanted, const std::vector<char> &may_split,
             std::vector<int> &selected);
};

}    // namespace LAMMPS_NS

#endif
