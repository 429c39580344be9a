/* -*- c++ -*- ----------------------------------------------------------
   SPH_SOIL package for LAMMPS: particles that fail a check, over all ranks.

   A check of per-particle state (a bad value in a data file, a particle
   that went unstable, a wall particle without its plane) must give the
   same answer on every rank, so that the error or warning is raised by all
   of them and reaches the screen and the log (an error raised on one rank
   reaches only that rank's screen). find_offenders() counts the owned
   particles that fail, and returns on every rank the total, the lowest ID
   among them and a few values of that particle, sent by its owner.
------------------------------------------------------------------------- */

#ifndef LMP_SPH_SOIL_OFFENDERS_H
#define LMP_SPH_SOIL_OFFENDERS_H

#include "atom.h"
#include "lammps.h"
#include "lmptype.h"

#include <mpi.h>

namespace LAMMPS_NS {
namespace SPHSoilOffenders {

constexpr int MAX_VALUES = 6;

struct Offenders {
  bigint count = 0;                     // on all ranks
  tagint first = 0;                     // the lowest ID among them (0 if none)
  double values[MAX_VALUES] = {0.0};    // of that particle
  explicit operator bool() const { return count > 0; }
};

// The reduction: `local_count` owned particles of this rank fail, `first_local` is the one with
// the lowest ID (-1 if none); `values(i, out)` writes the values to report of particle i (at
// most MAX_VALUES). Collective: every rank must call it.
template <class Values>
Offenders reduce_offenders(LAMMPS *lmp, bigint local_count, int first_local, Values values)
{
  Offenders result;
  MPI_Allreduce(&local_count, &result.count, 1, MPI_LMP_BIGINT, MPI_SUM, lmp->world);
  if (result.count == 0) return result;
  struct {
    double id;
    int rank;
  } mine, lowest;
  MPI_Comm_rank(lmp->world, &mine.rank);
  // IDs as doubles: exact up to 2^53; a rank without offenders bids above every ID
  mine.id = first_local >= 0 ? (double) lmp->atom->tag[first_local] : 9.0e18;
  MPI_Allreduce(&mine, &lowest, 1, MPI_DOUBLE_INT, MPI_MINLOC, lmp->world);
  result.first = (tagint) lowest.id;
  if (lowest.rank == mine.rank) values(first_local, result.values);
  MPI_Bcast(result.values, MAX_VALUES, MPI_DOUBLE, lowest.rank, lmp->world);
  return result;
}

// `fails(i)`: whether owned particle i fails. Collective.
template <class Fails, class Values>
Offenders find_offenders(LAMMPS *lmp, Fails fails, Values values)
{
  const Atom *atom = lmp->atom;
  bigint count = 0;
  int first_local = -1;
  for (int i = 0; i < atom->nlocal; i++) {
    if (!fails(i)) continue;
    count++;
    if (first_local < 0 || atom->tag[i] < atom->tag[first_local]) first_local = i;
  }
  return reduce_offenders(lmp, count, first_local, values);
}

}    // namespace SPHSoilOffenders
}    // namespace LAMMPS_NS

#endif
