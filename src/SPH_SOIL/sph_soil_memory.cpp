/* ----------------------------------------------------------------------
   SPH_SOIL package for LAMMPS: the memory a run can have (see the header)
------------------------------------------------------------------------- */

#include "sph_soil_memory.h"

#include "fmt/format.h"

#include <climits>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <sys/resource.h>
#include <unistd.h>
#include <vector>

using namespace LAMMPS_NS;
using namespace SPHSoilMemory;

namespace {

constexpr double GB = 1.0e9;

// the first number in file `path`, or 0 if there is none ("max", an absent file)
double number_in(const std::string &path)
{
  std::ifstream in(path);
  double value = 0.0;
  return (in >> value) ? value : 0.0;
}

// a cgroup hierarchy's mount: where it is mounted, and which cgroup is its root there
struct Mount {
  std::string point, root;
};

// the mount of the cgroup v2 hierarchy (v2) or of v1's memory controller, from mountinfo's
// lines "id parent dev root point options ... - fstype source super-options"
bool find_mount(const std::string &mountinfo_file, bool v2, Mount &mount)
{
  std::ifstream in(mountinfo_file);
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream words(line);
    std::vector<std::string> w;
    std::string word;
    while (words >> word) w.push_back(word);
    size_t dash = 0;
    while (dash < w.size() && w[dash] != "-") dash++;
    if (dash < 5 || dash + 3 > w.size()) continue;
    const std::string &fstype = w[dash + 1];
    bool memory = false;
    if (dash + 3 < w.size()) {
      std::istringstream options(w[dash + 3]);
      std::string option;
      while (std::getline(options, option, ','))
        if (option == "memory") memory = true;
    }
    if (v2 ? fstype == "cgroup2" : (fstype == "cgroup" && memory)) {
      mount.root = w[3];
      mount.point = w[4];
      return true;
    }
  }
  return false;
}

// the process's cgroup path in the v2 hierarchy ("0::/path") or in v1's memory controller
// ("N:...,memory,...:/path")
bool find_path(const std::string &cgroup_file, bool v2, std::string &path)
{
  std::ifstream in(cgroup_file);
  std::string line;
  while (std::getline(in, line)) {
    const auto first = line.find(':'), second = line.find(':', first + 1);
    if (first == std::string::npos || second == std::string::npos) continue;
    const std::string controllers = line.substr(first + 1, second - first - 1);
    bool match = v2 ? line.compare(0, first, "0") == 0 && controllers.empty() : false;
    if (!v2) {
      std::istringstream list(controllers);
      std::string controller;
      while (std::getline(list, controller, ','))
        if (controller == "memory") match = true;
    }
    if (match) {
      path = line.substr(second + 1);
      return true;
    }
  }
  return false;
}

// the limit of one hierarchy: its file in the process's cgroup and in each parent up to the
// mount's root (a job's limit may sit on a parent: the effective limit is the least)
Limit hierarchy_limit(const std::string &cgroup_file, const std::string &mountinfo_file,
                      const std::string &root, bool v2)
{
  Limit limit;
  Mount mount;
  std::string path;
  if (!find_mount(mountinfo_file, v2, mount) || !find_path(cgroup_file, v2, path)) return limit;
  // the path below the mount's root (in a container the mount's root is the container's own
  // cgroup); a path outside it (another namespace's view) starts at the mount's root
  std::string relative;
  if (mount.root == "/") relative = path;
  else if (path.compare(0, mount.root.size(), mount.root) == 0) relative = path.substr(mount.root.size());
  while (!relative.empty() && relative.back() == '/') relative.pop_back();
  const char *file = v2 ? "memory.max" : "memory.limit_in_bytes";
  for (;;) {
    const std::string at = root + mount.point + relative + "/" + file;
    const double bytes = number_in(at);
    // (v1 writes "no limit" as the largest page multiple of a 64-bit integer: above any
    // physical memory, which node_limit() then keeps)
    if (bytes > 0.0 && (limit.bytes == 0.0 || bytes < limit.bytes)) {
      limit.bytes = bytes;
      limit.source = fmt::format("the cgroup {} {} in {}", v2 ? "v2" : "v1", file,
                                 mount.point + relative);
    }
    if (relative.empty()) break;
    relative.erase(relative.rfind('/'));
  }
  return limit;
}

std::string gigabytes(double bytes)
{
  return fmt::format("{:.3g} GB", bytes / GB);
}

}    // namespace

/* ---------------------------------------------------------------------- */

Usage SPHSoilMemory::process_usage(const std::string &status_file)
{
  Usage usage;
  std::ifstream in(status_file);
  std::string key;
  double kilobytes;
  while (in >> key) {
    if (key == "VmSize:" && in >> kilobytes) usage.address_space = 1024.0 * kilobytes;
    else if (key == "VmData:" && in >> kilobytes) usage.data = 1024.0 * kilobytes;
    else if (key == "VmRSS:" && in >> kilobytes) usage.resident = 1024.0 * kilobytes;
    in.ignore(INT_MAX, '\n');
  }
  return usage;
}

Limit SPHSoilMemory::process_limit(int resource)
{
  Limit limit;
  struct rlimit value;
  if (getrlimit(resource, &value) == 0 && value.rlim_cur != RLIM_INFINITY) {
    limit.bytes = (double) value.rlim_cur;
    limit.source = resource == RLIMIT_AS ? "RLIMIT_AS (ulimit -v)" : "RLIMIT_DATA (ulimit -d)";
  }
  return limit;
}

Limit SPHSoilMemory::cgroup_limit(const std::string &cgroup_file, const std::string &mountinfo_file,
                                  const std::string &root)
{
  Limit limit = hierarchy_limit(cgroup_file, mountinfo_file, root, true);
  const Limit v1 = hierarchy_limit(cgroup_file, mountinfo_file, root, false);
  if (v1.bytes > 0.0 && (limit.bytes == 0.0 || v1.bytes < limit.bytes)) limit = v1;
  return limit;
}

Limit SPHSoilMemory::node_limit()
{
  Limit limit;
  if (const char *env = getenv("SPH_SOIL_MEMORY_LIMIT")) {
    const double set = atof(env);
    if (set > 0.0) {
      limit.bytes = set;
      limit.source = "SPH_SOIL_MEMORY_LIMIT";
      return limit;
    }
  }
  const long pages = sysconf(_SC_PHYS_PAGES), page_size = sysconf(_SC_PAGE_SIZE);
  if (pages > 0 && page_size > 0) {
    limit.bytes = (double) pages * (double) page_size;
    limit.source = "its physical memory";
  }
  const Limit cgroup = cgroup_limit();
  if (cgroup.bytes > 0.0 && (limit.bytes == 0.0 || cgroup.bytes < limit.bytes)) limit = cgroup;
  return limit;
}

/* ---------------------------------------------------------------------- */

Verdict SPHSoilMemory::check(MPI_Comm world, double more)
{
  int me;
  MPI_Comm_rank(world, &me);
  const Usage usage = process_usage();
  Verdict verdict;

  // the process's own limits: the first rank that would exceed one reports it
  struct ProcessLimit {
    int resource;
    const char *holds;
    double Usage::*held;
  };
  const ProcessLimit process_limits[] = {{RLIMIT_AS, "address space", &Usage::address_space},
                                         {RLIMIT_DATA, "data", &Usage::data}};
  for (const auto &kind : process_limits) {
    const Limit limit = process_limit(kind.resource);
    const double held = usage.*(kind.held);
    int mine = limit.bytes > 0.0 && more > limit.bytes - held ? me : INT_MAX, first = INT_MAX;
    MPI_Allreduce(&mine, &first, 1, MPI_INT, MPI_MIN, world);
    if (first == INT_MAX) continue;
    double numbers[3] = {more, limit.bytes, held};
    MPI_Bcast(numbers, 3, MPI_DOUBLE, first, world);
    verdict.fits = false;
    verdict.limit = fmt::format("rank {} may allocate (it would need {} more, and {} limits its {} "
                                "to {}, of which it holds {} already)",
                                first, gigabytes(numbers[0]), limit.source, kind.holds,
                                gigabytes(numbers[1]), gigabytes(numbers[2]));
    return verdict;
  }

  // the node's: what its ranks hold and would add, against its limit; the first node (by its
  // first rank) that would exceed it reports it
  MPI_Comm node;
  MPI_Comm_split_type(world, MPI_COMM_TYPE_SHARED, 0, MPI_INFO_NULL, &node);
  int node_rank, node_size;
  MPI_Comm_rank(node, &node_rank);
  MPI_Comm_size(node, &node_size);
  double mine[2] = {usage.resident + more, usage.resident}, sums[2] = {0.0, 0.0};
  MPI_Reduce(mine, sums, 2, MPI_DOUBLE, MPI_SUM, 0, node);
  MPI_Comm_free(&node);
  Limit limit;
  if (node_rank == 0) limit = node_limit();
  int short_of = node_rank == 0 && limit.bytes > 0.0 && sums[0] > limit.bytes ? me : INT_MAX,
      first = INT_MAX;
  MPI_Allreduce(&short_of, &first, 1, MPI_INT, MPI_MIN, world);
  if (first == INT_MAX) return verdict;
  // (the clause is made where the numbers are, and sent as text)
  std::string text;
  if (me == first) {
    char host[MPI_MAX_PROCESSOR_NAME];
    int length = 0;
    MPI_Get_processor_name(host, &length);
    text = fmt::format("the node of rank {} ({}) holds (its {} rank(s) would use {}, {} now, and {} "
                       "gives it {})",
                       me, std::string(host, length), node_size, gigabytes(sums[0]),
                       gigabytes(sums[1]), limit.source, gigabytes(limit.bytes));
  }
  int length = (int) text.size();
  MPI_Bcast(&length, 1, MPI_INT, first, world);
  text.resize(length);
  MPI_Bcast(&text[0], length, MPI_CHAR, first, world);
  verdict.fits = false;
  verdict.limit = text;
  return verdict;
}
