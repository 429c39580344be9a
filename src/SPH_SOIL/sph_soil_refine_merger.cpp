/* ----------------------------------------------------------------------
   SPH_SOIL package for LAMMPS: merging (derefinement) for fix sph/soil/refine.
   doc/theory.rst section 5.11.

   Siblings (the 4 or 8 daughters of one split) merge back into one particle
   when all of them have been quiet (their criterion's quiet(), e.g. a strain
   rate that would take more than twice the hold time to reach the threshold)
   for the hold time T, lie within their parent's smoothing length of their
   centre of mass, and have no neighbour finer than themselves (the merged
   particle is one level coarser: the 2:1 balance holds). The owner of
   daughter 0 (which kept the parent's ID) decides, from its own and the
   ghosts' values, and writes the merged particle into daughter 0's slot; the
   others' owners delete them (a reverse communication of flags).
------------------------------------------------------------------------- */

#include "sph_soil_refine_merger.h"

#include "fix.h"

#include "atom.h"
#include "atom_vec_sph_soil.h"
#include "comm.h"
#include "domain.h"
#include "memory.h"
#include "pair.h"
#include "soil_constitutive.h"
#include "soil_kernels.h"
#include "soil_refine_split.h"
#include "sph_soil_compat.h"
#include "sph_soil_fixes.h"
#include "sph_soil_materials.h"
#include "sph_soil_refine_balance.h"
#include "sph_soil_refine_selection.h"
#include "sph_soil_refine_splitter.h"
#include "update.h"

#include <cmath>
#include <map>

using namespace LAMMPS_NS;

namespace {
// a row of the merge's per-atom buffer (owned atoms fill theirs, ghosts get theirs by forward
// communication): ready, family at its level, level, force, velocity, the averaged values
enum { READY = 0, FAMILY = 1, LEVEL = 2, FORCE = 3, VELOCITY = 6, VALUES = 9 };
}    // namespace

SPHSoilRefineMerger::~SPHSoilRefineMerger()
{
  memory->destroy(merge_buffer);
}

/* ----------------------------------------------------------------------
   the values a merge mass-averages: stress, total strain, strain at birth, stress rate,
   strain rate, spin, the density rate per density (so that the merged particle's volume
   changes at the rate of the siblings' together)
------------------------------------------------------------------------- */

void SPHSoilRefineMerger::merge_values(int i, double *values) const
{
  auto avec = static_cast<AtomVecSPHSoil *>(atom->style_match("sph/soil"));
  int m = 0;
  for (int k = 0; k < 6; k++) values[m++] = avec->stress[i][k];
  for (int k = 0; k < 6; k++) values[m++] = avec->total_strain[i][k];
  for (int k = 0; k < 6; k++) values[m++] = state.strain_at_birth[i][k];
  for (int k = 0; k < 6; k++) values[m++] = avec->stress_rate[i][k];
  for (int k = 0; k < 6; k++) values[m++] = avec->strain_rate[i][k];
  for (int k = 0; k < 3; k++) values[m++] = avec->spin[i][k];
  values[m++] = atom->drho[i] / atom->rho[i];
}

/* ----------------------------------------------------------------------
   merge the families that may; the ghosts must be current (after a reneighbouring).
   Returns the families merged on all ranks; if any, the ghosts are gone (the caller
   reneighbours). Collective.
------------------------------------------------------------------------- */

bigint SPHSoilRefineMerger::merge(Fix *fix, const RefineHistory &history, int groupbit, int maxlevel,
                                  int nevery)
{
  state = history;
  double **family = state.family, *quiet_since = state.quiet_since, **strain_at_birth = state.strain_at_birth;
  auto avec = static_cast<AtomVecSPHSoil *>(atom->style_match("sph/soil"));
  const int nlocal = atom->nlocal;
  const double now = SPHSoilFixes::elapsed_time(update);

  // a family must have been quiet for the hold time: looking four times per hold time is
  // enough (a merge comes at most a quarter of it late), and spares the checks in between. The
  // looks are at the first check after each multiple of a quarter of the hold time (a rule of
  // the time alone: a restarted run looks when the uninterrupted one does)
  const double quarter = 0.25 * merge_time, since_last_check = nevery * update->dt;
  if (std::floor(now / quarter) == std::floor((now - since_last_check) / quarter)) return 0;

  // candidates: quiet for the hold time, of a known family
  std::vector<char> ready(nlocal, 0);
  int candidates = 0, any = 0;
  for (int i = 0; i < nlocal; i++) {
    const int level = avec->level[i];
    if (!(atom->mask[i] & groupbit) || level < 1 || level > maxlevel) continue;
    if (family[i][level - 1] == 0.0 || quiet_since[i] < 0.0) continue;
    if (now - quiet_since[i] < merge_time * (1.0 - 1.0e-12)) continue;
    ready[i] = 1;
    candidates++;
  }
  MPI_Allreduce(&candidates, &any, 1, MPI_INT, MPI_MAX, world);
  if (!any) return 0;

  // Daughters 0 (which kept their parent's ID) search their neighbourhood: the siblings, and
  // whether a particle finer than the family lies within the reach of the particle it would
  // merge into (one level coarser: the 2:1 balance must hold, and the balance must not split
  // it again at once). That reach, B kappa h_p about the centre of mass, which lies within
  // about 0.3 h_p of daughter 0, is within (B kappa + 0.3) h_p = (1 + 0.1) B kappa h_p.
  std::vector<char> searching(nlocal, 0);
  for (int i = 0; i < nlocal; i++)
    searching[i] = ready[i] && (double) atom->tag[i] == family[i][avec->level[i] - 1];
  const double parent_scale = 1.1 / splitter.smoothing_ratio;
  balance.prepare(groupbit, SPHSoil::kernel_support(splitter.kernel_kind()), parent_scale, &searching);

  // every atom's row: the owned ones here, the ghosts' by forward communication
  if (atom->nmax > merge_rows) {
    merge_rows = atom->nmax;
    memory->destroy(merge_buffer);
    memory->create(merge_buffer, merge_rows, MERGE_ROW, "sph/soil/refine:merge_buffer");
  }
  for (int i = 0; i < nlocal; i++) {
    double *row = merge_buffer[i];
    const int level = avec->level[i];
    row[READY] = ready[i];
    row[FAMILY] = level >= 1 && level <= maxlevel ? family[i][level - 1] : 0.0;
    row[LEVEL] = level;
    for (int a = 0; a < 3; a++) {
      row[FORCE + a] = atom->f[i][a];
      row[VELOCITY + a] = atom->v[i][a];
    }
    merge_values(i, row + VALUES);
  }
  SPHSoilCompat::forward_comm_fix(comm, fix);

  // the owners of daughter 0 decide and merge
  const int nall = nlocal + atom->nghost;
  std::vector<char> to_delete(nall, 0);
  const int count = SPHSoil::daughter_count(domain->dimension);
  int merged = 0;
  double **x = atom->x;
  for (int i = 0; i < nlocal; i++) {
    const double *own = merge_buffer[i];
    const int level = avec->level[i];
    if (!searching[i] || balance.finest_neighbour(i) > level) continue;
    // the siblings among the neighbours, one image each (the nearest)
    std::map<tagint, int> siblings;
    bool complete = true;
    auto distance2 = [&](int k, const double *p) {
      double r2 = 0.0;
      for (int a = 0; a < domain->dimension; a++) r2 += (x[k][a] - p[a]) * (x[k][a] - p[a]);
      return r2;
    };
    balance.for_each_neighbour(i, [&](int j) {
      const double *row = merge_buffer[j];
      if ((int) row[LEVEL] != level || row[FAMILY] != own[FAMILY]) return;
      if (row[READY] == 0.0) complete = false;
      const auto found = siblings.find(atom->tag[j]);
      if (found == siblings.end() || distance2(j, x[i]) < distance2(found->second, x[i]))
        siblings[atom->tag[j]] = j;
    });
    siblings.erase(atom->tag[i]);
    if (!complete || (int) siblings.size() != count - 1) continue;

    SPHSoil::MergeSum<MERGE_VALUES> sum;
    auto add = [&](int k) {
      const double *row = merge_buffer[k];
      sum.add(atom->rmass[k], atom->rho[k], x[k], row + VELOCITY, row + FORCE, row + VALUES);
    };
    add(i);
    for (const auto &s : siblings) add(s.second);
    // a family torn apart by the flow does not merge: every sibling within the parent's
    // smoothing length of the centre of mass
    double centre[3];
    sum.position(centre);
    const double parent_h = avec->smoothing_length[i] / splitter.smoothing_ratio;
    bool together = distance2(i, centre) <= parent_h * parent_h;
    for (const auto &s : siblings) together = together && distance2(s.second, centre) <= parent_h * parent_h;
    if (!together) continue;

    // the merged particle in daughter 0's slot
    for (int a = 0; a < 3; a++) x[i][a] = centre[a];
    sum.velocity(atom->v[i]);
    for (int a = 0; a < 3; a++) {
      atom->vest[i][a] = atom->v[i][a];
      atom->f[i][a] = sum.force[a];
    }
    atom->rmass[i] = sum.mass;
    atom->rho[i] = sum.density();
    double values[MERGE_VALUES];
    sum.averages(values);
    int m = 0;
    for (int k = 0; k < 6; k++) avec->stress[i][k] = values[m++];
    for (int k = 0; k < 6; k++) avec->total_strain[i][k] = values[m++];
    for (int k = 0; k < 6; k++) strain_at_birth[i][k] = values[m++];
    for (int k = 0; k < 6; k++) avec->stress_rate[i][k] = values[m++];
    for (int k = 0; k < 6; k++) avec->strain_rate[i][k] = values[m++];
    for (int k = 0; k < 3; k++) avec->spin[i][k] = values[m++];
    atom->drho[i] = values[m++] * atom->rho[i];
    splitter.return_to_admissible(i);
    avec->smoothing_length[i] = parent_h;
    avec->level[i] = level - 1;
    family[i][level - 1] = 0.0;
    quiet_since[i] = now;
    for (const auto &s : siblings) to_delete[s.second] = 1;
    merged++;
  }

  bigint mine = merged, all = 0;
  MPI_Allreduce(&mine, &all, 1, MPI_LMP_BIGINT, MPI_SUM, world);
  if (all == 0) return 0;

  // the siblings' owners delete them (the flags of ghosts travel back to their owners)
  for (int j = 0; j < nall; j++) merge_buffer[j][0] = to_delete[j];
  SPHSoilCompat::reverse_comm_fix(comm, fix);
  std::vector<char> gone(nlocal);
  for (int i = 0; i < nlocal; i++) gone[i] = merge_buffer[i][0] != 0.0;
  atom->nghost = 0;
  int n = nlocal, i = 0;
  while (i < n) {
    if (gone[i]) {
      // (AtomVec::copy moves no force: the next step's first half kick needs it)
      atom->avec->copy(n - 1, i, 1);
      for (int a = 0; a < 3; a++) atom->f[i][a] = atom->f[n - 1][a];
      gone[i] = gone[n - 1];
      n--;
    } else {
      i++;
    }
  }
  atom->nlocal = n;
  SPHSoilFixes::recount_atoms(atom, world);
  return all;
}

/* ----------------------------------------------------------------------
   the merge's communication: rows to the ghosts, deletion flags back to the owners
------------------------------------------------------------------------- */

int SPHSoilRefineMerger::pack_forward_comm(int n, int *list, double *buf)
{
  int m = 0;
  for (int k = 0; k < n; k++)
    for (int c = 0; c < MERGE_ROW; c++) buf[m++] = merge_buffer[list[k]][c];
  return m;
}

void SPHSoilRefineMerger::unpack_forward_comm(int n, int first, double *buf)
{
  int m = 0;
  for (int i = first; i < first + n; i++)
    for (int c = 0; c < MERGE_ROW; c++) merge_buffer[i][c] = buf[m++];
}

int SPHSoilRefineMerger::pack_reverse_comm(int n, int first, double *buf)
{
  int m = 0;
  for (int i = first; i < first + n; i++) buf[m++] = merge_buffer[i][0];
  return m;
}

void SPHSoilRefineMerger::unpack_reverse_comm(int n, int *list, double *buf)
{
  for (int k = 0; k < n; k++)
    if (buf[k] != 0.0) merge_buffer[list[k]][0] = 1.0;
}
