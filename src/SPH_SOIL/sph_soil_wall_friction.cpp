/* ----------------------------------------------------------------------
   SPH_SOIL package for LAMMPS: the Coulomb interface of frictional walls (see the header)
------------------------------------------------------------------------- */

#include "sph_soil_wall_friction.h"

#include "atom.h"
#include "comm.h"
#include "force.h"
#include "memory.h"
#include "update.h"
#include "sph_soil_compat.h"

#include <cstring>

using namespace LAMMPS_NS;
using SPHSoil::CONTACT_SUMS;

/* ---------------------------------------------------------------------- */

SPHSoilWallFriction::SPHSoilWallFriction(LAMMPS *lmp, Pair *owner_) :
    Pointers(lmp), owner(owner_), nmax(0), contact(nullptr), ratio(nullptr), reaction(nullptr),
    step_periods(nullptr), exchange(CONTACTS)
{
}

SPHSoilWallFriction::~SPHSoilWallFriction()
{
  memory->destroy(contact);
  memory->destroy(ratio);
  memory->destroy(reaction);
}

void SPHSoilWallFriction::begin_step()
{
  const int nall = atom->nlocal + atom->nghost;
  if (atom->nmax > nmax) {
    nmax = atom->nmax;
    memory->destroy(contact);
    memory->destroy(ratio);
    memory->destroy(reaction);
    memory->create(contact, (size_t) nmax * CONTACT_SUMS, "pair:contact");
    memory->create(ratio, (size_t) nmax * 3, "pair:friction_ratio");
    memory->create(reaction, (size_t) nmax * 3, "pair:friction_reaction");
  }
  if (nall > 0) memset(contact, 0, sizeof(double) * CONTACT_SUMS * nall);
  pairs.clear();
}

/* ----------------------------------------------------------------------
   the friction forces (soil_wall_friction.h): f of owned atoms holds every other force of the
   step; v is the half-step velocity (the integrator's second half kick follows)
------------------------------------------------------------------------- */

void SPHSoilWallFriction::apply(const double *h, double *pressures)
{
  if (!contact) return;
  const int nlocal = atom->nlocal, nall = nlocal + atom->nghost;
  const bool newton = force->newton_pair != 0;
  if (newton) {
    exchange = CONTACTS;
    SPHSoilCompat::reverse_comm_pair(comm, owner);
  }
  double **f = atom->f, **v = atom->v;
  const double *rmass = atom->rmass;
  const int *type = atom->type;
  const double dt = update->dt;
  for (int i = 0; i < nlocal; i++) {
    double *r = ratio + (size_t) 3 * i;
    const double *c = contact + (size_t) i * CONTACT_SUMS;
    if (step_periods && step_periods[i] < 0.0) {
      r[0] = r[1] = r[2] = 0.0;    // between its step's ends: no wall pair, the state kept
      continue;
    }
    if (!(c[SPHSoil::C_NORMAL_FORCE] > 0.0)) {
      r[0] = r[1] = r[2] = 0.0;
      pressures[i] = SPHSoil::NO_CONTACT;
      continue;
    }
    SPHSoil::contact_friction(c, rmass[i], f[i], v[i], h[i], wave_speed_of_type[type[i]], dt,
                              pressures[i], r, step_periods ? step_periods[i] : 1.0);
    for (int a = 0; a < 3; a++) f[i][a] += r[a] * c[SPHSoil::C_NORMAL_FORCE];
  }
  exchange = RATIOS;
  SPHSoilCompat::forward_comm_pair(comm, owner);

  // each kept pair's wall particle: the opposite of its share
  if (nall > 0) memset(reaction, 0, sizeof(double) * 3 * nall);
  for (const KeptPair &p : pairs) {
    const double *r = ratio + (size_t) 3 * p.soil;
    double *w = reaction + (size_t) 3 * p.wall;
    for (int a = 0; a < 3; a++) w[a] -= r[a] * p.normal_force;
  }
  if (newton) {
    exchange = REACTIONS;
    SPHSoilCompat::reverse_comm_pair(comm, owner);
  }
  // (newton off: only owned walls have shares; they hold them all)
  for (int i = 0; i < nlocal; i++) {
    const double *w = reaction + (size_t) 3 * i;
    for (int a = 0; a < 3; a++) f[i][a] += w[a];
  }
}

/* ---------------------------------------------------------------------- */

int SPHSoilWallFriction::pack_forward_comm(int n, int *list, double *buf)
{
  int m = 0;
  for (int k = 0; k < n; k++)
    for (int a = 0; a < 3; a++) buf[m++] = ratio[(size_t) 3 * list[k] + a];
  return m;
}

void SPHSoilWallFriction::unpack_forward_comm(int n, int first, double *buf)
{
  int m = 0;
  for (int i = first; i < first + n; i++)
    for (int a = 0; a < 3; a++) ratio[(size_t) 3 * i + a] = buf[m++];
}

int SPHSoilWallFriction::pack_reverse_comm(int n, int first, double *buf)
{
  const int size = exchange == CONTACTS ? CONTACT_SUMS : 3;
  const double *data = exchange == CONTACTS ? contact : reaction;
  int m = 0;
  for (int i = first; i < first + n; i++)
    for (int k = 0; k < size; k++) buf[m++] = data[(size_t) i * size + k];
  return m;
}

void SPHSoilWallFriction::unpack_reverse_comm(int n, int *list, double *buf)
{
  const int size = exchange == CONTACTS ? CONTACT_SUMS : 3;
  double *data = exchange == CONTACTS ? contact : reaction;
  int m = 0;
  for (int k = 0; k < n; k++)
    for (int c = 0; c < size; c++) data[(size_t) list[k] * size + c] += buf[m++];
}

double SPHSoilWallFriction::memory_usage() const
{
  return (double) nmax * (CONTACT_SUMS + 6) * sizeof(double) + pairs.capacity() * sizeof(KeptPair);
}
