// The limits of the memory guard (sph_soil_memory.h): a cgroup's memory limit found along the
// process's own cgroup path (v2 and v1, in a container whose cgroup is the mount's root, from
// files of a fake /proc and /sys), what a process holds from its status file, and the verdict
// of every rank against its own RLIMIT_AS and against a node's SPH_SOIL_MEMORY_LIMIT.
// (The batch test, unittest/test_batch_errors.py, runs a runaway refinement under ulimit -v.)
#include "sph_soil_memory.h"

#include "gmock/gmock.h"
#include "gtest/gtest.h"

#include <cstdlib>
#include <fstream>
#include <mpi.h>
#include <string>
#include <sys/resource.h>
#include <sys/stat.h>
#include <unistd.h>

using namespace LAMMPS_NS;
using ::testing::HasSubstr;

namespace {

// a directory of files of this rank's own, removed at the end
class FakeRoot {
 public:
  FakeRoot()
  {
    int rank;
    MPI_Comm_rank(MPI_COMM_WORLD, &rank);
    dir = "memory_limits_" + std::to_string(rank);
    system(("rm -rf " + dir).c_str());
  }
  ~FakeRoot() { system(("rm -rf " + dir).c_str()); }
  // writes `text` to `path` below the directory, making the directories on the way
  void write(const std::string &path, const std::string &text)
  {
    const std::string full = dir + path;
    system(("mkdir -p " + full.substr(0, full.rfind('/'))).c_str());
    std::ofstream(full) << text;
  }
  std::string file(const std::string &path) const { return dir + path; }
  // the cgroup limit that this directory's /proc/cgroup, /proc/mountinfo and /sys give
  SPHSoilMemory::Limit cgroup_limit() const
  {
    return SPHSoilMemory::cgroup_limit(file("/proc/cgroup"), file("/proc/mountinfo"), dir);
  }
  std::string dir;
};

const char *const V2_MOUNT = "30 23 0:26 / /sys/fs/cgroup rw - cgroup2 cgroup2 rw,nsdelegate\n";
const char *const V1_MOUNTS =
    "31 23 0:28 / /sys/fs/cgroup/cpu rw - cgroup cgroup rw,cpu\n"
    "35 23 0:32 / /sys/fs/cgroup/memory rw,relatime - cgroup cgroup rw,memory\n";

}    // namespace

TEST(MemoryLimits, CgroupV2TheLeastAlongTheProcessOwnPath)
{
  FakeRoot root;
  root.write("/proc/cgroup", "0::/batch/job42/step0\n");
  root.write("/proc/mountinfo", V2_MOUNT);
  root.write("/sys/fs/cgroup/memory.max", "max\n");
  root.write("/sys/fs/cgroup/batch/memory.max", "8000000000\n");
  root.write("/sys/fs/cgroup/batch/job42/memory.max", "3000000000\n");
  root.write("/sys/fs/cgroup/batch/job42/step0/memory.max", "max\n");
  const auto limit = root.cgroup_limit();
  EXPECT_EQ(limit.bytes, 3.0e9);
  EXPECT_EQ(limit.source, "the cgroup v2 memory.max in /sys/fs/cgroup/batch/job42");
}

TEST(MemoryLimits, CgroupV1MemoryControllerUnlimitedReadsAsNone)
{
  FakeRoot root;
  root.write("/proc/cgroup", "9:name=systemd:/\n4:memory:/process_api/abc\n1:cpu:/\n0::/\n");
  root.write("/proc/mountinfo", V1_MOUNTS);
  root.write("/sys/fs/cgroup/memory/memory.limit_in_bytes", "9223372036854771712\n");
  root.write("/sys/fs/cgroup/memory/process_api/abc/memory.limit_in_bytes", "2147483648\n");
  const auto limit = root.cgroup_limit();
  EXPECT_EQ(limit.bytes, 2147483648.0);
  EXPECT_EQ(limit.source, "the cgroup v1 memory.limit_in_bytes in /sys/fs/cgroup/memory/process_api/abc");
}

// in a container without a cgroup namespace the mount's root is the container's own cgroup,
// which /proc/self/cgroup names in full: the path below it is where the files are
TEST(MemoryLimits, CgroupOfAContainerWhoseMountRootIsItsCgroup)
{
  FakeRoot root;
  root.write("/proc/cgroup", "0::/docker/c0ffee/app\n");
  root.write("/proc/mountinfo",
             "30 23 0:26 /docker/c0ffee /sys/fs/cgroup ro - cgroup2 cgroup2 rw\n");
  root.write("/sys/fs/cgroup/memory.max", "1000000000\n");
  root.write("/sys/fs/cgroup/app/memory.max", "max\n");
  const auto limit = root.cgroup_limit();
  EXPECT_EQ(limit.bytes, 1.0e9);
  EXPECT_EQ(limit.source, "the cgroup v2 memory.max in /sys/fs/cgroup");
}

TEST(MemoryLimits, NoCgroupLimit)
{
  FakeRoot root;
  root.write("/proc/cgroup", "0::/user.slice\n");
  root.write("/proc/mountinfo", V2_MOUNT);
  root.write("/sys/fs/cgroup/user.slice/memory.max", "max\n");
  EXPECT_EQ(root.cgroup_limit().bytes, 0.0);
}

TEST(MemoryLimits, ProcessUsageFromItsStatusFile)
{
  FakeRoot root;
  root.write("/proc/status", "Name:\tlmp\nVmPeak:\t  300000 kB\nVmSize:\t  223184 kB\n"
                             "VmRSS:\t   20524 kB\nVmData:\t   21288 kB\nThreads:\t3\n");
  const auto usage = SPHSoilMemory::process_usage(root.file("/proc/status"));
  EXPECT_EQ(usage.address_space, 223184.0 * 1024);
  EXPECT_EQ(usage.resident, 20524.0 * 1024);
  EXPECT_EQ(usage.data, 21288.0 * 1024);
  // this process's own: an MPI process holds address space from the start
  EXPECT_GT(SPHSoilMemory::process_usage().address_space, 0.0);
}

// every rank lowers its own RLIMIT_AS to what it holds and 0.1 GB more: 1 GB more does not fit,
// and the verdict, the same on every rank, names rank 0 (the first short of memory) and its limit
TEST(MemoryLimits, EachRankAgainstItsOwnAddressSpaceLimit)
{
  struct rlimit saved;
  ASSERT_EQ(getrlimit(RLIMIT_AS, &saved), 0);
  const double held = SPHSoilMemory::process_usage().address_space;
  struct rlimit lowered = saved;
  lowered.rlim_cur = (rlim_t) (held + 1.0e8);
  ASSERT_EQ(setrlimit(RLIMIT_AS, &lowered), 0);
  const auto fits = SPHSoilMemory::check(MPI_COMM_WORLD, 1.0e7);
  const auto short_of = SPHSoilMemory::check(MPI_COMM_WORLD, 1.0e9);
  ASSERT_EQ(setrlimit(RLIMIT_AS, &saved), 0);
  EXPECT_TRUE(fits.fits);
  EXPECT_FALSE(short_of.fits);
  EXPECT_THAT(short_of.limit, HasSubstr("rank 0 may allocate (it would need 1 GB more, and "
                                        "RLIMIT_AS (ulimit -v) limits its address space to"));
}

// a node's limit: its ranks' resident memory and what they would add, summed
TEST(MemoryLimits, TheNodeAgainstSphSoilMemoryLimit)
{
  setenv("SPH_SOIL_MEMORY_LIMIT", "5e9", 1);
  const auto fits = SPHSoilMemory::check(MPI_COMM_WORLD, 1.0e6);
  const auto short_of = SPHSoilMemory::check(MPI_COMM_WORLD, 5.0e9);
  unsetenv("SPH_SOIL_MEMORY_LIMIT");
  int ranks;
  MPI_Comm_size(MPI_COMM_WORLD, &ranks);
  EXPECT_TRUE(fits.fits);
  EXPECT_FALSE(short_of.fits);
  EXPECT_THAT(short_of.limit, HasSubstr("the node of rank 0 ("));
  EXPECT_THAT(short_of.limit, HasSubstr("holds (its " + std::to_string(ranks) + " rank(s) would use"));
  EXPECT_THAT(short_of.limit, HasSubstr("and SPH_SOIL_MEMORY_LIMIT gives it 5 GB)"));
}
