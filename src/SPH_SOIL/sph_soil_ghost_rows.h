/* -*- c++ -*- ----------------------------------------------------------
   SPH_SOIL package for LAMMPS: per-atom rows of a few doubles that the owned
   atoms fill and their ghosts receive (comm->forward_comm_array), for values
   that do not travel with the atom style's ghosts (levels, flags): the
   refinement's 2:1 balance and its buffer.
------------------------------------------------------------------------- */

#ifndef LMP_SPH_SOIL_GHOST_ROWS_H
#define LMP_SPH_SOIL_GHOST_ROWS_H

#include "atom.h"
#include "comm.h"
#include "memory.h"
#include "pointers.h"

namespace LAMMPS_NS {

class SPHSoilGhostRows : protected Pointers {
 public:
  SPHSoilGhostRows(LAMMPS *lmp, int columns, const char *name) :
      Pointers(lmp), columns(columns), name(name)
  {
  }
  ~SPHSoilGhostRows() override { memory->destroy(rows); }

  // the rows, at least atom->nmax of them: fill the owned atoms' (0 .. nlocal-1), then forward()
  double **owned()
  {
    if (atom->nmax > allocated) {
      allocated = atom->nmax;
      memory->destroy(rows);
      memory->create(rows, allocated, columns, name);
    }
    return rows;
  }
  // the owned rows to the ghosts' (nlocal .. nlocal+nghost-1); collective
  double **forward()
  {
    comm->forward_comm_array(columns, rows);
    return rows;
  }

 private:
  const int columns;
  const char *name;
  double **rows = nullptr;
  int allocated = 0;
};

}    // namespace LAMMPS_NS

#endif
