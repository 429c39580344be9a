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
   others' owners delete them (a reverse communication of flags). A quiet
   member that does not find all its siblings within the parent's smoothing
   length becomes an orphan; orphans merge in clusters by proximity
   (soil_refine_clusters.h), each cluster's leader deciding as daughter 0 does.
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
#include "soil_refine_clusters.h"
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
// communication): ready, family at its level, level, a cluster's leader, the leader joined,
// density (a ghost's own is a step old here: fix sph/soil steps it after the ghosts' update),
// force, velocity, the averaged values
enum { READY = 0, FAMILY = 1, LEVEL = 2, LEADER = 3, JOINED = 4, DENSITY = 5, FORCE = 6, VELOCITY = 9, VALUES = 12 };
static_assert(VALUES + SPHSoilRefineMerger::MERGE_VALUES == SPHSoilRefineMerger::MERGE_ROW,
              "the merge row: its columns and the averaged values");

// squared distance of two points in `dimension` dimensions
double distance2(const double *a, const double *b, int dimension)
{
  double r2 = 0.0;
  for (int k = 0; k < dimension; k++) r2 += (a[k] - b[k]) * (a[k] - b[k]);
  return r2;
}
}    // namespace

SPHSoilRefineMerger::~SPHSoilRefineMerger()
{
  memory->destroy(merge_buffer);
}

/* ----------------------------------------------------------------------
   the values a merge mass-averages: stress, total strain, stress rate,
   strain rate, spin, the density rate per density (so that the merged particle's volume
   changes at the rate of the siblings' together), the pore pressure and its flow
------------------------------------------------------------------------- */

void SPHSoilRefineMerger::merge_values(int i, double *values) const
{
  auto avec = static_cast<AtomVecSPHSoil *>(atom->style_match("sph/soil"));
  int m = 0;
  for (int k = 0; k < 6; k++) values[m++] = avec->stress[i][k];
  for (int k = 0; k < 6; k++) values[m++] = avec->total_strain[i][k];
  for (int k = 0; k < 6; k++) values[m++] = avec->stress_rate[i][k];
  for (int k = 0; k < 6; k++) values[m++] = avec->strain_rate[i][k];
  for (int k = 0; k < 3; k++) values[m++] = avec->spin[i][k];
  values[m++] = atom->drho[i] / atom->rho[i];
  values[m++] = avec->pore_pressure[i];
  values[m++] = avec->pore_flow[i];
}

/* ----------------------------------------------------------------------
   merge the families and clusters of orphans that may; the ghosts must be current (after a
   reneighbouring). Returns the merges on all ranks; if any, the ghosts are gone (the caller
   reneighbours). Collective.
------------------------------------------------------------------------- */

bigint SPHSoilRefineMerger::merge(Fix *fix, const RefineHistory &history, int groupbit, int maxlevel,
                                  int nevery)
{
  state = history;
  double **family = state.family, *quiet_since = state.quiet_since;
  auto avec = static_cast<AtomVecSPHSoil *>(atom->style_match("sph/soil"));
  const int nlocal = atom->nlocal;
  const double now = SPHSoilFixes::elapsed_time(update);
  last_clusters = 0;

  // a family must have been quiet for the hold time: looking four times per hold time is
  // enough (a merge comes at most a quarter of it late), and spares the checks in between. The
  // looks are at the first check after each multiple of a quarter of the hold time (a rule of
  // the time alone: a restarted run looks when the uninterrupted one does)
  const double quarter = 0.25 * merge_time, since_last_check = nevery * update->dt;
  if (std::floor(now / quarter) == std::floor((now - since_last_check) / quarter)) return 0;
  // the looks' count, which salts the clusters' leaders (soil_refine_clusters.h)
  const uint64_t look = (uint64_t) std::floor(now / quarter);

  // candidates: quiet for the hold time, of a known family or orphans
  // orphan: an orphan that takes part in this look's clusters
  std::vector<char> ready(nlocal, 0), orphan(nlocal, 0);
  int candidates = 0, any = 0;
  for (int i = 0; i < nlocal; i++) {
    const int level = avec->level[i];
    if (!(atom->mask[i] & groupbit) || level < 1 || level > maxlevel) continue;
    if (family[i][level - 1] == 0.0 || !held_quiet(quiet_since[i], now)) continue;
    ready[i] = 1;
    candidates++;
  }
  MPI_Allreduce(&candidates, &any, 1, MPI_INT, MPI_MAX, world);
  if (!any) return 0;

  // The candidates search their neighbourhood: the siblings (daughters 0, which kept their
  // parent's ID, decide) or the other orphans, and whether a particle finer than they are lies
  // within the reach of the particle they would merge into (one level coarser: the 2:1 balance
  // must hold, and the balance must not split it again at once). That reach, B kappa h_p about
  // the centre of mass, which lies within about 0.3 h_p of daughter 0 and within h_p of a
  // cluster's leader (below), is within (B kappa + 1) h_p of either; a cluster's orphans lie
  // within h_p of their leader, inside it.
  const double support = SPHSoil::kernel_support(splitter.kernel_kind());
  const double reach = SPHSoilRefineBalance::BUFFER * support;
  balance.prepare(groupbit, support, (reach + 1.0) / reach / splitter.smoothing_ratio, &ready);

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
    row[LEADER] = row[JOINED] = 0.0;
    row[DENSITY] = atom->rho[i];
    for (int a = 0; a < 3; a++) {
      row[FORCE + a] = atom->f[i][a];
      row[VELOCITY + a] = atom->v[i][a];
    }
    merge_values(i, row + VALUES);
  }
  SPHSoilCompat::forward_comm_fix(comm, fix);

  // A candidate that does not find all its siblings within its parent's smoothing length (the
  // flow has torn the family apart, or a sibling is gone) leaves the family: an orphan. Where
  // every sibling finds every other within h_p, all lie within h_p of their centre of mass
  // (the family's merge below); where one does not, it leaves, its family cannot merge, and the
  // others leave at a later look. The orphans' new family goes to the ghosts before anything
  // is decided, so that a family's search (daughter 0's) and the clusters' see the same.
  const int count = SPHSoil::daughter_count(domain->dimension);
  double **x = atom->x;
  std::vector<char> searching(nlocal, 0);
  int orphans = 0, any_orphans = 0, changed = 0, any_changed = 0;    // changed: rows
  for (int i = 0; i < nlocal; i++) {
    if (!ready[i]) continue;
    const int level = avec->level[i];
    double &own_family = family[i][level - 1];
    // one with a finer neighbour waits for that to merge first (a sibling that split again is
    // one, and no longer of this level)
    const bool waits = balance.finest_neighbour(i) > level;
    if (own_family > 0.0 && !waits) {
      const double parent_h = avec->smoothing_length[i] / splitter.smoothing_ratio;
      std::map<tagint, bool> siblings;
      balance.for_each_neighbour(i, [&](int j) {
        const double *row = merge_buffer[j];
        if ((int) row[LEVEL] != level || row[FAMILY] != own_family || atom->tag[j] == atom->tag[i]) return;
        if (distance2(x[j], x[i], domain->dimension) <= parent_h * parent_h) siblings[atom->tag[j]] = true;
      });
      // (the rows keep the families of before until all have decided: the same on any ranks)
      if ((int) siblings.size() < count - 1) {
        own_family = ORPHAN;
        changed++;
      }
    }
    orphan[i] = own_family == ORPHAN && !waits;
    orphans += orphan[i];
    searching[i] = (orphan[i] || (double) atom->tag[i] == own_family) && !waits;
    // an orphan that waits takes no part in the clusters (its row is not ready)
    if (own_family == ORPHAN && waits) changed++;
  }
  for (int i = 0; i < nlocal; i++) {
    const int level = avec->level[i];
    if (!ready[i] || family[i][level - 1] != ORPHAN) continue;
    merge_buffer[i][FAMILY] = ORPHAN;
    if (!orphan[i]) merge_buffer[i][READY] = 0.0;
  }
  MPI_Allreduce(&changed, &any_changed, 1, MPI_INT, MPI_MAX, world);
  if (any_changed) SPHSoilCompat::forward_comm_fix(comm, fix);
  MPI_Allreduce(&orphans, &any_orphans, 1, MPI_INT, MPI_MAX, world);
  if (any_orphans) find_clusters(fix, orphan, look);

  // the owners of daughter 0 and the clusters' leaders decide and merge
  const int nall = nlocal + atom->nghost;
  std::vector<char> to_delete(nall, 0);
  int merged = 0, clusters = 0;
  std::vector<int> members;
  for (int i = 0; i < nlocal; i++) {
    const double *own = merge_buffer[i];
    const int level = avec->level[i];
    if (!searching[i]) continue;
    // the siblings (or the orphans that joined this leader) among the neighbours, one image
    // each (the nearest)
    std::map<tagint, std::pair<int, double>> found;
    bool complete = true;
    const double tag = (double) atom->tag[i];
    balance.for_each_neighbour(i, [&](int j) {
      const double *row = merge_buffer[j];
      if ((int) row[LEVEL] != level || atom->tag[j] == atom->tag[i]) return;
      if (orphan[i] ? row[JOINED] != tag : row[FAMILY] != own[FAMILY]) return;
      if (row[READY] == 0.0) complete = false;
      const double r2 = distance2(x[j], x[i], domain->dimension);
      const auto seen = found.find(atom->tag[j]);
      if (seen == found.end() || r2 < seen->second.second) found[atom->tag[j]] = {j, r2};
    });
    members.clear();
    if (orphan[i]) {
      if (own[LEADER] == 0.0) continue;
      std::vector<SPHSoil::NearOrphan> joined;
      for (const auto &f : found) joined.push_back({(double) f.first, f.second.second, f.second.first});
      for (const auto &m : SPHSoil::cluster_members(joined, count - 1)) members.push_back(m.index);
    } else {
      if (!complete) continue;
      for (const auto &f : found) members.push_back(f.second.first);
    }
    if ((int) members.size() != count - 1 || !merge_into(i, members, now)) continue;
    for (int j : members) to_delete[j] = 1;
    merged++;
    clusters += orphan[i];
  }

  bigint mine[2] = {merged, clusters}, all[2] = {0, 0};
  MPI_Allreduce(mine, all, 2, MPI_LMP_BIGINT, MPI_SUM, world);
  last_clusters = all[1];
  if (all[0] == 0) return 0;

  // the members' owners delete them (the flags of ghosts travel back to their owners)
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
  return all[0];
}

/* ----------------------------------------------------------------------
   the clusters of orphans (soil_refine_clusters.h): the leaders, then whom each orphan
   joins, each round's values to the ghosts. Reach: the parent's smoothing length.
------------------------------------------------------------------------- */

void SPHSoilRefineMerger::find_clusters(Fix *fix, const std::vector<char> &orphan, uint64_t look)
{
  auto avec = static_cast<AtomVecSPHSoil *>(atom->style_match("sph/soil"));
  const int nlocal = atom->nlocal;
  double **x = atom->x;
  auto near = [&](int i, int column) {
    // the orphans of i's level within its reach (column: any, or leaders only)
    std::vector<SPHSoil::NearOrphan> within;
    const double reach = avec->smoothing_length[i] / splitter.smoothing_ratio;
    balance.for_each_neighbour(i, [&](int j) {
      const double *row = merge_buffer[j];
      if (row[READY] == 0.0 || row[FAMILY] != ORPHAN || (int) row[LEVEL] != avec->level[i]) return;
      if (atom->tag[j] == atom->tag[i] || atom->type[j] != atom->type[i] || (column >= 0 && row[column] == 0.0))
        return;
      const double r2 = distance2(x[j], x[i], domain->dimension);
      if (r2 <= reach * reach) within.push_back({(double) atom->tag[j], r2, j});
    });
    return within;
  };
  for (int i = 0; i < nlocal; i++)
    if (orphan[i]) merge_buffer[i][LEADER] = SPHSoil::leads_cluster((double) atom->tag[i], near(i, -1), look);
  SPHSoilCompat::forward_comm_fix(comm, fix);
  for (int i = 0; i < nlocal; i++)
    if (orphan[i] && merge_buffer[i][LEADER] == 0.0) merge_buffer[i][JOINED] = SPHSoil::joined_leader(near(i, LEADER));
  SPHSoilCompat::forward_comm_fix(comm, fix);
}

/* ----------------------------------------------------------------------
   merge owned particle i and `members` (owned or ghosts) into i's slot, one level coarser:
   mass, momentum and volume conserved, the rest mass-averaged, the stress returned to the
   admissible set. Not if the flow has torn them apart: every one within the parent's
   smoothing length of their centre of mass. Whether it merged.
------------------------------------------------------------------------- */

bool SPHSoilRefineMerger::merge_into(int i, const std::vector<int> &members, double now)
{
  auto avec = static_cast<AtomVecSPHSoil *>(atom->style_match("sph/soil"));
  double **x = atom->x;
  SPHSoil::MergeSum<MERGE_VALUES> sum;
  auto add = [&](int k) {
    const double *row = merge_buffer[k];
    sum.add(atom->rmass[k], row[DENSITY], x[k], row + VELOCITY, row + FORCE, row + VALUES);
  };
  add(i);
  for (int j : members) add(j);
  double centre[3];
  sum.position(centre);
  const double parent_h = avec->smoothing_length[i] / splitter.smoothing_ratio;
  auto within = [&](int k) {
    return distance2(x[k], centre, domain->dimension) <= parent_h * parent_h;
  };
  if (!within(i)) return false;
  for (int j : members)
    if (!within(j)) return false;

  const int level = avec->level[i];
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
  // born now: a criterion of the strain since the split judges it from here. (The mass
  // average of its members' strains at birth would hand it the strain they gathered since
  // their split, above the threshold wherever they sat at maxlevel: it would split again at
  // the next check, and merge again, and so on.)
  for (int k = 0; k < 6; k++) state.strain_reference[i][k] = avec->total_strain[i][k];
  for (int k = 0; k < 6; k++) avec->stress_rate[i][k] = values[m++];
  for (int k = 0; k < 6; k++) avec->strain_rate[i][k] = values[m++];
  for (int k = 0; k < 3; k++) avec->spin[i][k] = values[m++];
  atom->drho[i] = values[m++] * atom->rho[i];
  avec->pore_pressure[i] = values[m++];
  avec->pore_flow[i] = values[m++];
  splitter.return_to_admissible(i);
  avec->smoothing_length[i] = parent_h;
  avec->level[i] = level - 1;
  state.family[i][level - 1] = 0.0;
  state.quiet_since[i] = now;
  return true;
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
