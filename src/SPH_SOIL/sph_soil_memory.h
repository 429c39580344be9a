/* -*- c++ -*- ----------------------------------------------------------
   SPH_SOIL package for LAMMPS: the memory a run can have, to stop a set-up
   that cannot fit (a huge h, a deep refinement) with a message that says why,
   rather than with an allocation failure somewhere in LAMMPS.

   Two kinds of limit, compared at their own level:
   - a process's own: RLIMIT_AS (ulimit -v) bounds its address space, which an
     MPI process holds a good part of from the start (libraries, shared-memory
     segments, reserved heaps), and RLIMIT_DATA (ulimit -d) its data. They are
     per process, so each rank compares what it is about to allocate with its
     own limit less what it holds already (/proc/self/status);
   - a node's: its physical memory, or less where the cgroups that hold the
     process set a limit (a batch system's; cgroup v2 memory.max or v1
     memory.limit_in_bytes, along the process's own cgroup path from
     /proc/self/cgroup), or SPH_SOIL_MEMORY_LIMIT (bytes per node), if set.
     All ranks of a node share it: their resident memory and what they are
     about to allocate are summed.
------------------------------------------------------------------------- */

#ifndef LMP_SPH_SOIL_MEMORY_H
#define LMP_SPH_SOIL_MEMORY_H

#include <mpi.h>
#include <string>

namespace LAMMPS_NS {
namespace SPHSoilMemory {

// What LAMMPS's accounting of memory (the memory_usage() of the atoms, fixes and pair style)
// misses of what a process allocates as its particles grow, as a fraction of what it counts: the
// allocator's own, the communication buffers, the package's temporary vectors, and an array's
// old and new copies while it grows. Measured in a runaway refinement (2D, 1 and 2 ranks, 25k
// to 1.6M particles): the address space grew by 1.13 to 1.18 times what the accounting grew,
// and its peak within a step by up to 2.5% more; 0.25 stops such a refinement before any
// allocation fails at every limit of ulimit -v from 0.3 to 4.2 GB (2D and 3D, 1 and 2 ranks).
constexpr double UNCOUNTED = 0.25;

// a limit in bytes and where it comes from, for messages ("RLIMIT_AS (ulimit -v)", "cgroup v2
// memory.max of /sys/fs/cgroup/job/memory.max", ...); bytes 0: no limit known
struct Limit {
  double bytes = 0.0;
  std::string source;
};

// what a process holds (bytes, 0 where unknown): VmSize, which RLIMIT_AS counts; VmData, which
// RLIMIT_DATA counts (Linux 4.7 and later); VmRSS, what the node's memory holds of it
struct Usage {
  double address_space = 0.0;
  double data = 0.0;
  double resident = 0.0;
};
Usage process_usage(const std::string &status_file = "/proc/self/status");

// the soft limit of getrlimit(resource) (RLIMIT_AS or RLIMIT_DATA); bytes 0 if unlimited
Limit process_limit(int resource);

// The tightest memory limit of the cgroups that hold this process: its own cgroup (from
// `cgroup_file`, /proc/self/cgroup) and each parent up to the root of its hierarchy, found
// where `mountinfo_file` (/proc/self/mountinfo) says that hierarchy is mounted; cgroup v2's
// memory.max, else v1's memory.limit_in_bytes. `root` is put before the mount points (tests give
// a directory of their own files). Bytes 0 if no cgroup limits memory.
Limit cgroup_limit(const std::string &cgroup_file = "/proc/self/cgroup",
                   const std::string &mountinfo_file = "/proc/self/mountinfo",
                   const std::string &root = "");

// the memory of this node: the least of its physical memory and cgroup_limit(), or
// SPH_SOIL_MEMORY_LIMIT (bytes) if set
Limit node_limit();

// whether each rank can allocate `more` bytes (its own, > 0) beyond what it holds now: against
// its own RLIMIT_AS and RLIMIT_DATA (less what it holds), then, summed over the ranks of each
// node with their resident memory, against the node's limit. If not, `limit` says which limit
// of which rank or node it would exceed, from where, with the numbers, as a clause that follows
// "more than" ("rank 1 may allocate: ..."). The same on every rank. Collective.
struct Verdict {
  bool fits = true;
  std::string limit;
};
Verdict check(MPI_Comm world, double more);

}    // namespace SPHSoilMemory
}    // namespace LAMMPS_NS

#endif
