/* -*- c++ -*- ----------------------------------------------------------
   SPH_SOIL package for LAMMPS: compatibility layer.

   Every LAMMPS call of the package and of its tests whose form changed
   between LAMMPS 29Sep2021 and today is made through this header. The form
   is chosen at compile time from LAMMPS's own classes (which members exist,
   which signatures they have), never from a version number or a date: the
   header compiles unchanged in the CMake superbuild and in LAMMPS's
   traditional make, with no define set, and on a release in between it
   takes, call by call, whichever form that release has.

   How: a helper has a preferred overload, whose return type is the
   decltype of its LAMMPS call, so that it exists only where that call is
   well-formed (SFINAE), and a fallback; the preferred one takes Preferred,
   a better match than the fallback's Fallback. Both are templates on the
   LAMMPS class, so only the chosen body is ever compiled.

   What changed (and what is detected):
   - AtomVec field lists: space-separated `char *` -> std::vector<std::string>
     (the member's type picks an assign_fields() overload)
   - AtomVec::property_atom(char *) -> property_atom(const std::string &), and
     AtomVec::data_vel(int, char **) -> data_vel(int, const std::vector<std::string> &)
     (PropertyAtomName, DataVelValues: the parameter types of the base class's functions)
   - Atom::peratom: array + nperatom, `char *` names -> std::vector, std::string
     (whether Atom has nperatom)
   - Domain::find_region() index -> Domain::get_region_by_id()
   - Comm::forward_comm_pair(Pair *) -> forward_comm(Pair *), and reverse likewise
     (whether the Pair overload compiles); forward_comm_fix(Fix *) likewise
   - Input::command, the command being executed: protected in 29Sep2021
     (whether it can be read; before, read_restart is told from the atom_style
     command by the first argument of the command in hand)
   - Error::one() and Error::all() with exceptions on: 29Sep2021 writes the
     message but does not flush screen and log. After one() its main() calls
     MPI_Abort, which discards unflushed output; after all() every rank calls
     exit(1), and mpirun may kill rank 0 (whose log holds the message, less
     than a buffer) when another rank exits first. error_one() and error_all()
     flush on every release (no detection needed); the package raises its
     errors through them only.
------------------------------------------------------------------------- */

#ifndef LMP_SPH_SOIL_COMPAT_H
#define LMP_SPH_SOIL_COMPAT_H

#include "atom.h"
#include "atom_vec.h"
#include "domain.h"
#include "error.h"
#include "input.h"
#include "lammps.h"
#include "region.h"

#include <cstdio>
#include <string>
#include <utility>
#include <vector>

namespace LAMMPS_NS {

class Pair;
class Fix;

namespace SPHSoilCompat {

struct Fallback {};
struct Preferred : Fallback {};

/* ---------------------------------------------------------------------- */
// AtomVec

// Field lists of an AtomVec: overloads pick the form from the member's type.
// `storage` must live as long as the AtomVec (the older form keeps the pointer).
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

// The parameter type of AtomVec::property_atom(): an AtomVec declares its override with it.
template <class F> struct FirstParameter;
template <class C, class R, class A> struct FirstParameter<R (C::*)(A)> {
  using type = A;
};
template <class C, class R, class A> struct FirstParameter<R (C::*)(A) const> {
  using type = A;
};
using PropertyAtomName = FirstParameter<decltype(&AtomVec::property_atom)>::type;

// The parameter type of the values in AtomVec::data_vel(int, values): `char **` in 29Sep2021,
// `const std::vector<std::string> &` in later releases.
template <class F> struct SecondParameter;
template <class C, class R, class A, class B> struct SecondParameter<R (C::*)(A, B)> {
  using type = B;
};
using DataVelValues = SecondParameter<decltype(&AtomVec::data_vel)>::type;

// Point the per-atom table entry `name` at new storage, or add it if there is none.
namespace detail {
  template <class AtomT> auto peratom_count(AtomT *atom, Preferred) -> decltype((int) atom->peratom.size())
  {
    return (int) atom->peratom.size();
  }
  template <class AtomT> auto peratom_count(AtomT *atom, Fallback) -> decltype((int) atom->nperatom)
  {
    return atom->nperatom;
  }
}    // namespace detail

template <class AtomT>
void set_peratom(AtomT *atom, const std::string &name, void *address, int datatype, int cols)
{
  const int n = detail::peratom_count(atom, Preferred());
  for (int i = 0; i < n; i++) {
    auto &entry = atom->peratom[i];
    if (name == entry.name) {
      entry.address = address;
      entry.datatype = datatype;
      entry.cols = cols;
      return;
    }
  }
  atom->add_peratom(name.c_str(), address, datatype, cols);
}

/* ---------------------------------------------------------------------- */
// A pair style's own communication

namespace detail {
  template <class C, class P> auto forward_comm(C *comm, P *pair, Preferred) -> decltype(comm->forward_comm(pair))
  {
    comm->forward_comm(pair);
  }
  template <class C, class P> void forward_comm(C *comm, P *pair, Fallback) { comm->forward_comm_pair(pair); }
  template <class C, class P> auto reverse_comm(C *comm, P *pair, Preferred) -> decltype(comm->reverse_comm(pair))
  {
    comm->reverse_comm(pair);
  }
  template <class C, class P> void reverse_comm(C *comm, P *pair, Fallback) { comm->reverse_comm_pair(pair); }
}    // namespace detail

// Comm::forward_comm(Pair *) / reverse_comm(Pair *); forward_comm_pair() / reverse_comm_pair()
// before (whether the Pair overload compiles)
template <class C> void forward_comm_pair(C *comm, Pair *pair) { detail::forward_comm(comm, pair, Preferred()); }
template <class C> void reverse_comm_pair(C *comm, Pair *pair) { detail::reverse_comm(comm, pair, Preferred()); }

/* ---------------------------------------------------------------------- */
// A fix's own communication

namespace detail {
  template <class C, class F> auto forward_comm_fix(C *comm, F *fix, Preferred) -> decltype(comm->forward_comm(fix))
  {
    comm->forward_comm(fix);
  }
  template <class C, class F> void forward_comm_fix(C *comm, F *fix, Fallback) { comm->forward_comm_fix(fix); }
  template <class C, class F> auto reverse_comm_fix(C *comm, F *fix, Preferred) -> decltype(comm->reverse_comm(fix))
  {
    comm->reverse_comm(fix);
  }
  template <class C, class F> void reverse_comm_fix(C *comm, F *fix, Fallback) { comm->reverse_comm_fix(fix); }
}    // namespace detail

// Comm::forward_comm(Fix *) / reverse_comm(Fix *); forward_comm_fix() / reverse_comm_fix() before
template <class C> void forward_comm_fix(C *comm, Fix *fix) { detail::forward_comm_fix(comm, fix, Preferred()); }
template <class C> void reverse_comm_fix(C *comm, Fix *fix) { detail::reverse_comm_fix(comm, fix, Preferred()); }

/* ---------------------------------------------------------------------- */
// Regions

namespace detail {
  template <class D>
  auto find_region(D *domain, const std::string &id, Preferred) -> decltype(domain->get_region_by_id(id))
  {
    return domain->get_region_by_id(id);
  }
  template <class D> Region *find_region(D *domain, const std::string &id, Fallback)
  {
    const int index = domain->find_region(id);
    return index < 0 ? nullptr : domain->regions[index];
  }
}    // namespace detail

// A region by its ID, nullptr if there is none.
inline Region *find_region(Domain *domain, const std::string &id)
{
  return detail::find_region(domain, id, Preferred());
}

/* ---------------------------------------------------------------------- */
// The command in hand

namespace detail {
  template <class I>
  auto is_read_restart(I *input, Preferred) -> decltype(input->command, bool())
  {
    return input->command && std::string(input->command) == "read_restart";
  }
  template <class I> bool is_read_restart(I *input, Fallback)
  {
    // an atom style is created by atom_style (its name first), read_restart (a file name
    // first) or replicate (with the stored arguments)
    return input->narg > 0 && std::string(input->arg[0]) != "sph/soil";
  }
}    // namespace detail

// Whether atom_style sph/soil is being created by read_restart (from its process_args()).
inline bool atom_style_from_restart(LAMMPS *lmp)
{
  return detail::is_read_restart(lmp->input, Preferred());
}

/* ---------------------------------------------------------------------- */
// Errors

namespace detail {
  // raise() throws (exceptions on) or exits; what LAMMPS wrote before is flushed first
  template <class Raise> [[noreturn]] void flushed(LAMMPS *lmp, Raise raise)
  {
    try {
      raise();
    } catch (...) {
      if (lmp->screen) fflush(lmp->screen);
      if (lmp->logfile) fflush(lmp->logfile);
      throw;
    }
    // without exceptions Error::one() and all() end the process; this is never reached
    throw;
  }
}    // namespace detail

// error->one(), but the message surely reaches this rank's screen and log in a batch run
template <typename... Args>
[[noreturn]] void error_one(LAMMPS *lmp, const std::string &file, int line,
                            const std::string &format, Args &&...args)
{
  detail::flushed(lmp, [&] {
    lmp->error->one(file, line, format, std::forward<Args>(args)...);
  });
}

// error->all(), but the message surely reaches the screen and the log of a batch run on any
// number of ranks
template <typename... Args>
[[noreturn]] void error_all(LAMMPS *lmp, const std::string &file, int line,
                            const std::string &format, Args &&...args)
{
  detail::flushed(lmp, [&] {
    lmp->error->all(file, line, format, std::forward<Args>(args)...);
  });
}

}    // namespace SPHSoilCompat
}    // namespace LAMMPS_NS

#endif
