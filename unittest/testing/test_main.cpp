// gtest main for SPH_SOIL tests that create LAMMPS: LAMMPS's own MPI-aware main
// (unittest/testing/test_mpi_main.h of the LAMMPS tree in use), which collects the
// results of all ranks and prints them once. It needs LAMMPS's utils.h first.
#include "utils.h"

#include "test_mpi_main.h"
