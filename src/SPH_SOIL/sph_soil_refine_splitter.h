/* -*- c++ -*- ----------------------------------------------------------
   SPH_SOIL package for LAMMPS: particle splitting shared by
   fix sph/soil/refine (dynamic) and the sph_soil/refine command (static).

   Replaces owned particles by their daughters (soil_refine_split.h): mass, h,
   level and position as specified, velocity copied, density, stress and
   total strain interpolated by CSPM at the daughter's position over the
   atoms of the parent's type, every other per-atom value (including other fixes' per-atom
   arrays, via AtomVec::copy) inherited from the parent.
------------------------------------------------------------------------- */

#ifndef LMP_SPH_SOIL_REFINE_SPLITTER_H
#define LMP_SPH_SOIL_REFINE_SPLITTER_H

#include "pointers.h"
#include "soil_kernels.h"
#include "soil_neighbours.h"

#include "lmptype.h"

#include <string>
#include <vector>

namespace LAMMPS_NS {

class SPHSoilRefineSplitter : protected Pointers {
 public:
  // `who` names the command or fix in error messages
  SPHSoilRefineSplitter(class LAMMPS *, const std::string &who);

  double separation = 0.5;         // eps_r: side of the daughters' square / d_p
  double smoothing_ratio = 0.5;    // alpha_r: h_d / h_p
  // d_ref, the spacing of level-0 particles; 0: from each particle's mass and its material's
  // reference density, d_p = (m_p / rho_0)^(1/D) (which halves with each split)
  double reference_spacing = 0.0;

  // Read a keyword of the split pattern (separation, smoothing, dref) for `command` (as the
  // user types it, for error messages); false if `keyword` is not one of them.
  bool parse_keyword(const std::string &command, const std::string &keyword, const char *value);
  static constexpr const char *KEYWORDS = "separation, smoothing, dref";

  // the pair style and atom style this run uses (call at init)
  void init();
  // the pair style's kernel (after init)
  SPHSoil::KernelKind kernel_kind() const;
  // spacing d_p of owned particle i
  double spacing(int i) const;
  // ratio h / d of owned particle i, the r_a of the refinement analysis
  double smoothing_over_spacing(int i) const { return smoothing_length(i) / spacing(i); }

  // Split the owned particles `parents`; the ghost atoms must be current (as after a
  // reneighbouring). Refreshes the ghosts' state first (forward communication).
  // Daughters get new atom IDs after the largest existing one, ordered by the parents' IDs
  // and the daughter index, so they do not depend on the number of ranks. Afterwards the
  // ghost atoms are gone (nghost = 0): the caller must reneighbour before the next force
  // evaluation (fixes: next_reneighbor; commands: the next run's setup does it).
  // Returns the number of parents split on all ranks.
  bigint split(const std::vector<int> &parents);
  // return owned particle i's stress to its material's admissible set (after an average)
  void return_to_admissible(int i) const;

 private:
  std::string who;
  class AtomVecSPHSoil *avec;
  // the pair style's materials and kernel (its extract(): the splitter needs no more of it)
  const class SPHSoilMaterials *materials;
  SPHSoil::KernelKind kernel;
  double smoothing_length(int i) const;
  void interpolate(int parent, const double *position, const SPHSoil::SmoothingClassGrids &near,
                   double *state) const;
  std::vector<tagint> first_new_tags(const std::vector<int> &parents, bigint &total);

  // the planned daughters of the parents: per parent n and daughter k, a position and the
  // interpolated state (density, stress, total strain, pore pressure)
  static constexpr int NSTATE = 14;
  struct Daughters {
    int count = 0;    // per parent
    std::vector<double> position, state;
    double *position_of(int n, int k) { return &position[((size_t) n * count + k) * 3]; }
    double *state_of(int n, int k) { return &state[((size_t) n * count + k) * NSTATE]; }
  };
  struct Parent {
    int level;
    double mass, h, force[3];
  };
  void plan_daughters(const std::vector<int> &parents, Daughters &daughters);
  void stop_if_outside_box(const std::vector<int> &parents, Daughters &daughters);
  void add_daughters(const std::vector<int> &parents, const std::vector<tagint> &first_tag,
                     Daughters &daughters);
  void set_daughter(int j, const Parent &parent, const double *position, const double *state,
                    int count);
};

}    // namespace LAMMPS_NS

#endif
