/* -*- c++ -*- ----------------------------------------------------------
   SPH_SOIL package for LAMMPS: the fixes the package depends on, found by what
   they do rather than by their style's name, so that variants and accelerated
   styles (gravity/omp, rigid/small, rigid/nve/small, ...) count as the plain
   ones do:
   - a fix that sets a gravity vector answers extract("gvec");
   - a fix that moves atoms has time_integrate (fix move, fix nve, ...) or
     rigid_flag (fix rigid and its variants) set;
   - fix sph/soil answers extract("sph_soil_integrator"): it never moves
     wall particles, whatever its group.
------------------------------------------------------------------------- */

#ifndef LMP_SPH_SOIL_FIXES_H
#define LMP_SPH_SOIL_FIXES_H

#include "atom.h"
#include "fix.h"
#include "lammps.h"
#include "modify.h"
#include "update.h"
#include "soil_level_steps.h"

#include <mpi.h>
#include <vector>

namespace LAMMPS_NS {
namespace SPHSoilFixes {

// the name under which fix sph/soil answers extract()
constexpr const char *INTEGRATOR = "sph_soil_integrator";
// and under which it hands out its time-step hierarchy (SPHSoil::StepSchedule)
constexpr const char *SCHEDULE = "sph_soil_schedule";

// the time-step hierarchy of the first fix sph/soil; nullptr without one
inline const SPHSoil::StepSchedule *step_schedule(LAMMPS *lmp)
{
  for (int i = 0; i < lmp->modify->nfix; i++) {
    int dim = 0;
    if (void *found = lmp->modify->fix[i]->extract(SCHEDULE, dim))
      return static_cast<const SPHSoil::StepSchedule *>(found);
  }
  return nullptr;
}

// the simulated time now (LAMMPS's thermo keyword `time`), also across changes of the time step
inline double elapsed_time(const Update *update)
{
  return update->atime + (update->ntimestep - update->atimestep) * update->dt;
}

// after owned atoms were added or deleted within a run: the total count and the ID map
inline void recount_atoms(Atom *atom, MPI_Comm world)
{
  bigint nlocal = atom->nlocal;
  MPI_Allreduce(&nlocal, &atom->natoms, 1, MPI_LMP_BIGINT, MPI_SUM, world);
  if (atom->map_style != Atom::MAP_NONE) {
    atom->map_init();
    atom->map_set();
  }
}

// A fix's per-atom arrays, the LAMMPS way: grown with the atoms, copied and exchanged with
// them, set for new atoms, and kept in restart files. Call from the fix's constructor (LAMMPS
// registers the fix being created) and keep_per_atom_end() from its destructor.
inline void keep_per_atom(Fix *fix, Atom *atom)
{
  fix->restart_peratom = 1;
  fix->create_attribute = 1;
  fix->grow_arrays(atom->nmax);
  atom->add_callback(Atom::GROW);
  atom->add_callback(Atom::RESTART);
  for (int i = 0; i < atom->nmax; i++) fix->set_arrays(i);
}
inline void keep_per_atom_end(Fix *fix, Atom *atom)
{
  atom->delete_callback(fix->id, Atom::GROW);
  atom->delete_callback(fix->id, Atom::RESTART);
}

inline bool sets_gravity(Fix *fix)
{
  int dim = 0;
  return fix->extract("gvec", dim) != nullptr;
}

inline bool is_sph_soil_integrator(Fix *fix)
{
  int dim = 0;
  return fix->extract(INTEGRATOR, dim) != nullptr;
}

// moves its atoms (other than fix sph/soil, which integrates soil particles only)
inline bool moves_atoms(Fix *fix)
{
  return (fix->time_integrate || fix->rigid_flag) && !is_sph_soil_integrator(fix);
}

inline std::vector<Fix *> gravity_fixes(LAMMPS *lmp)
{
  std::vector<Fix *> found;
  for (int i = 0; i < lmp->modify->nfix; i++)
    if (sets_gravity(lmp->modify->fix[i])) found.push_back(lmp->modify->fix[i]);
  return found;
}

// the soil's body force: the sum of those fixes' gravity vectors
inline void gravity_sum(const std::vector<Fix *> &fixes, double g[3])
{
  for (int a = 0; a < 3; a++) g[a] = 0.0;
  for (Fix *fix : fixes) {
    int dim = 0;
    if (const double *gvec = static_cast<const double *>(fix->extract("gvec", dim)))
      for (int a = 0; a < 3; a++) g[a] += gvec[a];
  }
}

// the first fix (by the order of the input) that `selects` and whose group holds an owned atom
// i with `holds(i)` on some rank; nullptr if none. Collective.
template <class Selects, class Holds> Fix *first_fix_holding(LAMMPS *lmp, Selects selects, Holds holds)
{
  const Atom *atom = lmp->atom;
  for (int f = 0; f < lmp->modify->nfix; f++) {
    Fix *fix = lmp->modify->fix[f];
    if (!selects(fix)) continue;
    int mine = 0, anywhere = 0;
    for (int i = 0; i < atom->nlocal && !mine; i++)
      if ((atom->mask[i] & fix->groupbit) && holds(i)) mine = 1;
    MPI_Allreduce(&mine, &anywhere, 1, MPI_INT, MPI_MAX, lmp->world);
    if (anywhere) return fix;
  }
  return nullptr;
}

// whether a fix other than fix sph/soil moves some atom i with `holds(i)`. Collective.
template <class Holds> bool moved_by_other_fixes(LAMMPS *lmp, Holds holds)
{
  return first_fix_holding(lmp, moves_atoms, holds) != nullptr;
}

}    // namespace SPHSoilFixes
}    // namespace LAMMPS_NS

#endif
