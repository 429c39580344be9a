/* -*- c++ -*- ----------------------------------------------------------
   SPH_SOIL package for LAMMPS: compatibility layer.

   Every LAMMPS call whose form changed between releases is made through
   this header, so that supporting another LAMMPS version means editing
   this file only. LAMMPS does not define a numeric version itself; the
   SPH_SOIL CMake build passes LAMMPS_VERSION_NUMBER=yyyymmdd derived from
   src/version.h. A plain drop-in build (make or cmake of LAMMPS itself)
   gets the default below, the version this package is developed against.

   Supported: 29Sep2021 (update 2, Debian's 20220106), the "old" API.
   The branches for >= 23Jun2022 (add_request(), forward_comm(this),
   std::vector field lists) follow the newer API but are not yet tested.
------------------------------------------------------------------------- */

#ifndef LMP_SPH_SOIL_COMPAT_H
#define LMP_SPH_SOIL_COMPAT_H

#ifndef LAMMPS_VERSION_NUMBER
#define LAMMPS_VERSION_NUMBER 20210929
#endif

#define SPH_SOIL_NEW_LAMMPS_API (LAMMPS_VERSION_NUMBER >= 20220623)

#include "comm.h"
#include "command.h"
#include "domain.h"
#include "region.h"
#include "neigh_list.h"
#include <string>
#include <vector>
#include "neighbor.h"
#if !SPH_SOIL_NEW_LAMMPS_API
#include "neigh_request.h"
#endif

namespace LAMMPS_NS {
namespace SphSoilCompat {

// Field lists of an AtomVec are `char *` (space separated) in old LAMMPS and
// std::vector<std::string> in new; overloads pick the right form from the member's type.
// `storage` must live as long as the AtomVec (old LAMMPS keeps the pointer).
inline void assign_fields(char *&dest, const std::vector<std::string> &names, std::string &storage)
{
  storage.clear();
  for (const auto &name : names) storage += (storage.empty() ? "" : " ") + name;
  dest = &storage[0];
}

inline void assign_fields(std::vector<std::string> &dest, const std::vector<std::string> &names,
                          std::string & /*storage*/)
{
  dest = names;
}

// Request a full, persistent-free neighbour list for a pair style or a fix.
template <class Client> inline void request_full_neighbor_list(Neighbor *neighbor, Client *client,
                                                                 bool is_fix, int instance = 0)
{
#if SPH_SOIL_NEW_LAMMPS_API
  (void) instance;
  neighbor->add_request(client, NeighConst::REQ_FULL);
  (void) is_fix;
#else
  int irequest = neighbor->request(client, instance);
  neighbor->requests[irequest]->half = 0;
  neighbor->requests[irequest]->full = 1;
  if (is_fix) {
    neighbor->requests[irequest]->pair = 0;
    neighbor->requests[irequest]->fix = 1;
  }
#endif
}

// Request the default (half) neighbour list for a pair style.
template <class Client> inline void request_half_neighbor_list(Neighbor *neighbor, Client *client,
                                                                 int instance = 0)
{
#if SPH_SOIL_NEW_LAMMPS_API
  (void) instance;
  neighbor->add_request(client);
#else
  neighbor->request(client, instance);
#endif
}

// Request an occasional full neighbour list for a fix or command (built on demand).
template <class Client> inline void request_occasional_full_list(Neighbor *neighbor, Client *client)
{
#if SPH_SOIL_NEW_LAMMPS_API
  neighbor->add_request(client, NeighConst::REQ_FULL | NeighConst::REQ_OCCASIONAL);
#else
  int irequest = neighbor->request(client);
  neighbor->requests[irequest]->pair = 0;
  neighbor->requests[irequest]->fix = 1;
  neighbor->requests[irequest]->half = 0;
  neighbor->requests[irequest]->full = 1;
  neighbor->requests[irequest]->occasional = 1;
#endif
}

// A command's occasional full list: request before lmp->init(), find after it.
// Returns a handle for command_neighbor_list().
inline int request_command_full_list(Neighbor *neighbor, Command *command, const char *style)
{
#if SPH_SOIL_NEW_LAMMPS_API
  neighbor->add_request(command, style, NeighConst::REQ_FULL | NeighConst::REQ_OCCASIONAL);
  return 0;
#else
  int irequest = neighbor->request(command);
  neighbor->requests[irequest]->pair = 0;
  neighbor->requests[irequest]->command = 1;
  neighbor->requests[irequest]->half = 0;
  neighbor->requests[irequest]->full = 1;
  neighbor->requests[irequest]->occasional = 1;
  neighbor->requests[irequest]->command_style = style;
  return irequest;
#endif
}

inline NeighList *command_neighbor_list(Neighbor *neighbor, Command *command, int handle)
{
#if SPH_SOIL_NEW_LAMMPS_API
  (void) handle;
  return neighbor->find_list(command);
#else
  (void) command;
  return neighbor->lists[handle];
#endif
}

// A region by its ID, nullptr if there is none (the index-based lookup was replaced in 2022).
inline Region *find_region(Domain *domain, const std::string &id)
{
#if LAMMPS_VERSION_NUMBER >= 20220915
  return domain->get_region_by_id(id);
#else
  const int index = domain->find_region(id);
  return index < 0 ? nullptr : domain->regions[index];
#endif
}

inline void forward_comm(Comm *comm, class Pair *pair)
{
#if SPH_SOIL_NEW_LAMMPS_API
  comm->forward_comm(pair);
#else
  comm->forward_comm_pair(pair);
#endif
}

inline void forward_comm(Comm *comm, class Fix *fix, int size = 0)
{
#if SPH_SOIL_NEW_LAMMPS_API
  comm->forward_comm(fix, size);
#else
  comm->forward_comm_fix(fix, size);
#endif
}

inline void reverse_comm(Comm *comm, class Fix *fix, int size = 0)
{
#if SPH_SOIL_NEW_LAMMPS_API
  comm->reverse_comm(fix, size);
#else
  comm->reverse_comm_fix(fix, size);
#endif
}

}    // namespace SphSoilCompat
}    // namespace LAMMPS_NS

#endif
