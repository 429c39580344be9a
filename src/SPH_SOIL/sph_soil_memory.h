/* -*- c++ -*- ----------------------------------------------------------
   SPH_SOIL package for LAMMPS: the memory a run can have, to stop a set-up
   that cannot fit (a huge h, a deep refinement) with a message that says why,
   rather than with an allocation failure somewhere in LAMMPS.
------------------------------------------------------------------------- */

#ifndef LMP_SPH_SOIL_MEMORY_H
#define LMP_SPH_SOIL_MEMORY_H

#include <cstdio>
#include <cstdlib>
#include <mpi.h>
#include <unistd.h>

namespace LAMMPS_NS {
namespace SPHSoilMemory {

struct Nodes {
  double bytes = 0.0;    // the physical memory of all nodes of the run (0 if unknown)
  int count = 0;         // the nodes
};

// the memory one node gives the run: its physical memory, or less where the job is limited (a
// cgroup's memory.max, as batch systems set it), or SPH_SOIL_MEMORY_LIMIT (bytes), if set
inline double node_limit()
{
  const long pages = sysconf(_SC_PHYS_PAGES), page_size = sysconf(_SC_PAGE_SIZE);
  double limit = pages > 0 && page_size > 0 ? (double) pages * (double) page_size : 0.0;
  if (FILE *fp = fopen("/sys/fs/cgroup/memory.max", "r")) {
    double cgroup = 0.0;
    if (fscanf(fp, "%lf", &cgroup) == 1 && cgroup > 0.0 && (limit == 0.0 || cgroup < limit))
      limit = cgroup;    // ("max" reads as no number: no limit)
    fclose(fp);
  }
  if (const char *env = getenv("SPH_SOIL_MEMORY_LIMIT")) {
    const double set = atof(env);
    if (set > 0.0) limit = set;
  }
  return limit;
}

// the memory of the nodes of `world`: each node's first rank counts its node's. Collective.
inline Nodes nodes(MPI_Comm world)
{
  MPI_Comm node;
  MPI_Comm_split_type(world, MPI_COMM_TYPE_SHARED, 0, MPI_INFO_NULL, &node);
  int node_rank;
  MPI_Comm_rank(node, &node_rank);
  MPI_Comm_free(&node);
  double mine[2] = {0.0, 0.0}, all[2];
  if (node_rank == 0) {
    mine[0] = node_limit();
    mine[1] = 1.0;
  }
  MPI_Allreduce(mine, all, 2, MPI_DOUBLE, MPI_SUM, world);
  Nodes result;
  result.bytes = all[0];
  result.count = (int) all[1];
  return result;
}

}    // namespace SPHSoilMemory
}    // namespace LAMMPS_NS

#endif
