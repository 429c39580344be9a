/* ----------------------------------------------------------------------
   SPH_SOIL package for LAMMPS: fix sph/soil/refine
------------------------------------------------------------------------- */

#include "fix_sph_soil_refine.h"

#include "atom.h"
#include "atom_vec_sph_soil.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "fix_sph_soil.h"
#include "group.h"
#include "force.h"
#include "memory.h"
#include "modify.h"
#include "neighbor.h"
#include "pair_sph_soil.h"
#include "region.h"
#include "soil_constitutive.h"
#include "soil_refine_error.h"
#include "soil_refine_split.h"
#include "sph_soil_refine_balance.h"
#include "sph_soil_refine_merger.h"
#include "sph_soil_compat.h"
#include "sph_soil_fixes.h"
#include "sph_soil_input.h"
#include "sph_soil_refine_selection.h"
#include "sph_soil_memory.h"
#include "sph_soil_refine_splitter.h"
#include "update.h"
#include "utils.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <vector>

using namespace LAMMPS_NS;
using namespace FixConst;

namespace {
const char *const STYLE = "Fix sph/soil/refine";
}

/* ---------------------------------------------------------------------- */

FixSPHSoilRefine::FixSPHSoilRefine(LAMMPS *lmp, int narg, char **arg) :
    Fix(lmp, narg, arg), maxlevel(1),
    strain_reference(nullptr), quiet_since(nullptr), family(nullptr), merge_time(0.0),
    total_merged(0), integrator(nullptr), schedule(nullptr), parameters_reported(false),
    bytes_per_particle(0.0), last_split(0), last_split_step(-1), total_split(0),
    last_unbalanced(0), run_unbalanced(0), run_split(0), run_forced(0)
{
  if (narg < 4)
    SPHSoilCompat::error_all(lmp, FLERR,
                             "Illegal fix sph/soil/refine command: expected 'fix ID group "
                             "sph/soil/refine N keyword value ...'");
  if (!atom->style_match("sph/soil"))
    SPHSoilCompat::error_all(lmp, FLERR, "Fix sph/soil/refine requires atom_style sph/soil");

  nevery = SPHSoilInput::integer(FLERR, lmp, "fix sph/soil/refine N", arg[3], 1);

  // a keyword's time > 0, or no (0)
  auto time_or_no = [&](const std::string &keyword, const char *value, const char *what) {
    if (std::string(value) == "no") return 0.0;
    if (!utils::is_double(value))
      SPHSoilCompat::error_all(lmp, FLERR,
                               "Illegal fix sph/soil/refine {} {}: must be {} > 0 or no", keyword,
                               value, what);
    return SPHSoilInput::number(FLERR, lmp, "fix sph/soil/refine " + keyword, value, SPHSoilInput::above(0.0));
  };
  splitter.reset(new SPHSoilRefineSplitter(lmp, STYLE));
  selection.reset(new SPHSoilRefineSelection(lmp, "fix sph/soil/refine", "strain"));
  for (int iarg = 4; iarg < narg; iarg += 2) {
    const std::string keyword = arg[iarg];
    if (iarg + 1 >= narg)
      SPHSoilCompat::error_all(
          lmp, FLERR, "Illegal fix sph/soil/refine command: keyword {} needs a value", keyword);
    const char *value = arg[iarg + 1];
    if (selection->parse_keyword(keyword, value) ||
        splitter->parse_keyword("fix sph/soil/refine", keyword, value)) {
      continue;
    } else if (keyword == "maxlevel") {
      maxlevel = SPHSoilInput::integer(FLERR, lmp, "fix sph/soil/refine maxlevel", value, 1,
                                       SPHSoil::MAX_LEVEL);
    } else if (keyword == "ease") {
      ease_time = time_or_no(keyword, value, "a time");
    } else if (keyword == "merge") {
      merge_time = time_or_no(keyword, value, "a hold time");
    } else {
      SPHSoilCompat::error_all(lmp, FLERR,
                               "Illegal fix sph/soil/refine keyword {} (allowed: {}, {}, "
                               "maxlevel, merge, ease)",
                               keyword, SPHSoilRefineSelection::keywords(),
                               SPHSoilRefineSplitter::KEYWORDS);
    }
  }

  // global output: split this step, total split, particles of the group per level
  // 0..maxlevel, pairs more than one level apart at the last check, merges, of them clusters
  vector_flag = 1;
  size_vector = 2 + maxlevel + 1 + 3;
  global_freq = 1;
  extvector = 0;
  restart_global = 1;
  force_reneighbor = 1;
  next_reneighbor = -1;
  balance.reset(new SPHSoilRefineBalance(lmp));
  if (merge_time > 0.0) {
    merger.reset(new SPHSoilRefineMerger(lmp, merge_time, *balance, *splitter));
    comm_forward = SPHSoilRefineMerger::MERGE_ROW;
    comm_reverse = 1;
  }
  if (ease_time > 0.0) comm_forward = MAX(comm_forward, 1);
  SPHSoilFixes::keep_per_atom(this, atom);
}

/* ---------------------------------------------------------------------- */

FixSPHSoilRefine::~FixSPHSoilRefine()
{
  SPHSoilFixes::keep_per_atom_end(this, atom);
  memory->destroy(strain_reference);
  memory->destroy(quiet_since);
  memory->destroy(family);
  memory->destroy(ease_since);
  memory->destroy(ease_target);
}

int FixSPHSoilRefine::setmask()
{
  // (easing in post_integrate: the forces and the adaptive step of the step's end see one h)
  return END_OF_STEP | (ease_time > 0.0 ? POST_INTEGRATE : 0);
}

void FixSPHSoilRefine::post_integrate()
{
  ease();
}

/* ---------------------------------------------------------------------- */

void FixSPHSoilRefine::init()
{
  splitter->init();
  selection->init(SPHSoil::kernel_support(splitter->kernel_kind()), splitter->smoothing_ratio);

  integrator = nullptr;
  for (int ifix = 0; ifix < modify->nfix && !integrator; ifix++)
    integrator = dynamic_cast<FixSPHSoil *>(modify->fix[ifix]);
  if (!integrator)
    SPHSoilCompat::error_all(lmp, FLERR, "Fix sph/soil/refine requires fix sph/soil");
  // with a time step per level, splits and merges happen where every level ends a step: the
  // multiples of the largest period, 2^maxlevel for particles that began at one level
  schedule = &integrator->step_schedule();
  if (schedule->per_level && nevery % (1 << maxlevel) != 0)
    SPHSoilCompat::error_all(
        lmp, FLERR,
        "Fix sph/soil/refine N {}: with fix sph/soil stepping level, N must be a "
        "multiple of 2^maxlevel = {}, the steps at which all levels are synchronised",
        nevery, 1 << maxlevel);

  // wall particles carry the wall geometry; splitting them would break it
  auto pair = dynamic_cast<PairSPHSoil *>(force->pair_match("sph/soil", 1));
  bigint walls = 0, all_walls = 0;
  int wall_type = 0;
  for (int i = 0; i < atom->nlocal; i++)
    if ((atom->mask[i] & groupbit) && pair->is_wall_type(atom->type[i])) {
      walls++;
      wall_type = atom->type[i];
    }
  MPI_Allreduce(&walls, &all_walls, 1, MPI_LMP_BIGINT, MPI_SUM, world);
  if (all_walls > 0) {
    int any_type = 0;
    MPI_Allreduce(&wall_type, &any_type, 1, MPI_INT, MPI_MAX, world);
    SPHSoilCompat::error_all(
        lmp, FLERR,
        "Fix sph/soil/refine: group {} contains {} wall particles (e.g. type {}); "
        "refine soil particles only",
        group->names[igroup], all_walls, any_type);
  }
}

/* ---------------------------------------------------------------------- */

void FixSPHSoilRefine::setup(int)
{
  // (after a restart each rank knows its own atoms' easing: ease() needs all ranks to agree)
  MPI_Allreduce(MPI_IN_PLACE, &easing_until, 1, MPI_DOUBLE, MPI_MAX, world);
  if (!parameters_reported) {
    report_parameters();
    report_capacity();
  }
  parameters_reported = true;
}

/* ----------------------------------------------------------------------
   what refinement down to maxlevel can cost: warn (once) when the group split down to maxlevel
   would not fit in the memory that the ranks and nodes of the run may have
   (sph_soil_memory.h). A particle's share of the pair style's list follows its own h
   (doc/theory.rst 5.8), so the bytes per particle stay about those of now at every level.
------------------------------------------------------------------------- */

void FixSPHSoilRefine::report_capacity()
{
  const int dimension = domain->dimension;
  const double daughters = SPHSoil::daughter_count(dimension);
  auto avec = static_cast<AtomVecSPHSoil *>(atom->style_match("sph/soil"));
  double worst_count = 0.0;    // as a double: 4^30 fits
  bigint members = 0;
  for (int i = 0; i < atom->nlocal; i++) {
    if (!(atom->mask[i] & groupbit)) continue;
    worst_count += std::pow(daughters, MAX(0, maxlevel - avec->level[i]));
    members++;
  }
  worst_count += (double) (atom->nlocal - members);
  double worst_all;
  bigint members_all;
  MPI_Allreduce(&worst_count, &worst_all, 1, MPI_DOUBLE, MPI_SUM, world);
  MPI_Allreduce(&members, &members_all, 1, MPI_LMP_BIGINT, MPI_SUM, world);
  if (members_all == 0) return;
  measure_bytes_per_particle();
  const auto verdict = SPHSoilMemory::check(world, growth_bytes(worst_count));
  if (!verdict.fits && comm->me == 0)
    error->warning(FLERR, "Fix sph/soil/refine: the group split down to level {} would hold {:.3g} "
                          "particles, about {:.3g} GB at {:.0f} bytes each, more than {}; lower "
                          "maxlevel or limit the refinement to a region",
                   maxlevel, worst_all, worst_all * bytes_per_particle / 1e9, bytes_per_particle,
                   verdict.limit);
}

/* ----------------------------------------------------------------------
   the bytes a particle costs now, per slot of the per-atom arrays (owned and ghost atoms), the
   most of any rank: LAMMPS's accounting of the arrays of the atoms, the fixes and the pair style
   (its rows and its list), and what that accounting misses (SPHSoilMemory::UNCOUNTED). Measured
   at each split: the pair list per particle grows as refined particles crowd. Collective.
------------------------------------------------------------------------- */

void FixSPHSoilRefine::measure_bytes_per_particle()
{
  const double counted =
      (atom->memory_usage() + modify->memory_usage() + force->pair->memory_usage()) / MAX(atom->nmax, 1);
  const double mine = counted * (1.0 + SPHSoilMemory::UNCOUNTED);
  MPI_Allreduce(&mine, &bytes_per_particle, 1, MPI_DOUBLE, MPI_MAX, world);
}

/* ----------------------------------------------------------------------
   the bytes this rank would allocate to hold `owned` owned atoms: its ghosts grow with them,
   and the slots of the per-atom arrays it has now are allocated already
------------------------------------------------------------------------- */

double FixSPHSoilRefine::growth_bytes(double owned) const
{
  const double growth = atom->nlocal > 0 ? owned / atom->nlocal : 1.0;
  const double slots = growth * (atom->nlocal + atom->nghost);
  return MAX(0.0, slots - atom->nmax) * bytes_per_particle;
}

/* ----------------------------------------------------------------------
   log the kernel-gradient error of one split and warn about unstable parameters
   (doc/refinement_parameters.rst)
------------------------------------------------------------------------- */

void FixSPHSoilRefine::report_parameters()
{
  // r_a = h / d of the group (largest: the conditions are strictest for it), with the h that
  // easing daughters (after a restart) are going to
  const double *h = static_cast<AtomVecSPHSoil *>(atom->style_match("sph/soil"))->smoothing_length;
  double ra = 0.0, ra_all = 0.0;
  for (int i = 0; i < atom->nlocal; i++)
    if (atom->mask[i] & groupbit) {
      const double eased = ease_since[i] >= 0.0 ? ease_target[i] / h[i] : 1.0;
      ra = MAX(ra, eased * splitter->smoothing_over_spacing(i));
    }
  MPI_Allreduce(&ra, &ra_all, 1, MPI_DOUBLE, MPI_MAX, world);
  birth_ratio = splitter->smoothing_ratio;
  if (ease_time > 0.0 && ra_all > 0.0) choose_birth_ratio(ra_all);
  if (comm->me != 0 || !(ra_all > 0.0)) return;

  using namespace SPHSoil;
  const double eps = splitter->separation, alpha = splitter->smoothing_ratio;
  const int dimension = domain->dimension;
  const KernelKind kernel = splitter->kernel_kind();
  const double inflection = kernel_inflection(kernel);
  const double error_a =
      kernel_gradient_error(dimension, eps, alpha, ra_all, NeighbourSmoothing::UNREFINED, 1.0e-5, 256, kernel).value;
  const double error_b =
      kernel_gradient_error(dimension, eps, alpha, ra_all, NeighbourSmoothing::REFINED, 1.0e-5, 256, kernel).value;
  auto describe = [&](double distance) {
    const auto c = instability_conditions(eps, alpha, ra_all, distance, inflection);
    if (!c.any()) return std::string("stable");
    std::string s = "unstable (Cond.";
    if (c.daughters_too_close) s += " 1";
    if (c.refined_neighbours) s += " 2";
    if (c.unrefined_neighbour) s += " 3";
    return s + ")";
  };
  utils::logmesg(lmp, "fix sph/soil/refine: splits {} up to level {}\n", selection->describe(),
                 maxlevel);
  if (ease_time > 0.0) {
    const auto born = split_stress_defect(dimension, eps, birth_ratio, ra_all, kernel);
    const auto eased = split_stress_defect(dimension, eps, alpha, ra_all, kernel);
    utils::logmesg(lmp, "fix sph/soil/refine: daughters born with smoothing {:.2f} (a split's push on "
                        "its neighbours and daughters at most {:.3g} p/(rho h), against {:.3g} with "
                        "{}), eased to {} over {} time units\n", birth_ratio,
                   MAX(born.neighbours, born.daughters), MAX(eased.neighbours, eased.daughters),
                   alpha, alpha, ease_time);
  }
  utils::logmesg(lmp, "fix sph/soil/refine: separation {} smoothing {} with h/d = {:.4g}: kernel "
                      "gradient error E_a = {:.4g}, E_b = {:.4g} (1/d^{}); d_ij/d_ref = 1.0: {}, "
                      "0.85: {}{}\n", eps, alpha, ra_all, error_a, error_b, dimension,
                 describe(1.0), describe(0.85),
                 kernel == KernelKind() ? "" : std::string(" (kernel ") + kernel_name(kernel) + ")");
  if (!stable_refinement(eps, alpha, ra_all, 1.0, inflection))
    error->warning(FLERR, "Fix sph/soil/refine: separation {} and smoothing {} (h/d = {:.4g}) are "
                          "in the unstable region for d_ij/d_ref = 1.0 ({}): expect clumps and "
                          "cracks under compression; see doc/refinement_parameters.rst",
                   eps, alpha, ra_all, describe(1.0));
}

/* ---------------------------------------------------------------------- */

void FixSPHSoilRefine::end_of_step()
{
  // (particles that began at different levels may have a longer period: wait for its multiple)
  if (schedule->per_level && update->ntimestep % schedule->largest_period != 0) return;

  last_split_step = update->ntimestep;
  last_split = 0;
  std::vector<char> may_split;
  // a criterion of a variable may use computes: made current now, and ready at the next check
  // (LAMMPS re-evaluates a compute in a variable only after clearstep_compute(); without it
  // the criterion saw the values of the last output, up to a thermo interval old)
  modify->clearstep_compute();
  std::vector<int> parents = selection->parents(groupbit, maxlevel, history(), &may_split);
  modify->addstep_compute(update->ntimestep + nevery);
  if (merge_time > 0.0) {
    mark_quiet();
    // with merging, a particle that has been quiet for the hold time (one that may merge) rests:
    // it does not split, and the criterion counts its deformation from here (the band between
    // the split's and the merge's conditions, the hysteresis in value, holds in both
    // directions). Without the first, a quiet particle whose strain since its birth creeps past
    // the threshold (a deposit at rest settles about each merge near it) splits, merges back
    // after the hold time, and splits again; without the second, it splits on that old strain
    // as soon as a merge nearby kicks it out of its rest (doc/theory.rst 5.11).
    const double now = SPHSoilFixes::elapsed_time(update);
    for (int i = 0; i < atom->nlocal; i++)
      if ((atom->mask[i] & groupbit) && merger->held_quiet(quiet_since[i], now)) selection->rest(i);
    parents.erase(std::remove_if(parents.begin(), parents.end(),
                                 [&](int i) { return merger->held_quiet(quiet_since[i], now); }),
                  parents.end());
  }

  // the 2:1 balance: needed once a particle is refined and a level 2 can exist (at maxlevel 1,
  // or in a group of levels 0 and 1 only, every pair is balanced and the check costs nothing)
  auto avec = static_cast<AtomVecSPHSoil *>(atom->style_match("sph/soil"));
  int deepest = 0, deepest_all = 0;
  for (int i = 0; i < atom->nlocal; i++)
    if (atom->mask[i] & groupbit) deepest = MAX(deepest, avec->level[i]);
  MPI_Allreduce(&deepest, &deepest_all, 1, MPI_INT, MPI_MAX, world);
  last_unbalanced = 0;
  if (deepest_all >= 1 && (maxlevel > 1 || deepest_all > 1)) {
    balance->prepare(groupbit, SPHSoil::kernel_support(splitter->kernel_kind()));
    last_unbalanced = balance->unbalanced();
    run_unbalanced = MAX(run_unbalanced, last_unbalanced);
    bigint wanted = parents.size(), wanted_all = 0;
    MPI_Allreduce(&wanted, &wanted_all, 1, MPI_LMP_BIGINT, MPI_SUM, world);
    parents = balance->parents(parents, may_split);
    bigint now = parents.size(), now_all = 0;
    MPI_Allreduce(&now, &now_all, 1, MPI_LMP_BIGINT, MPI_SUM, world);
    run_forced += MAX(0, now_all - wanted_all);
  }

  bigint candidates = parents.size(), all_candidates = 0;
  MPI_Allreduce(&candidates, &all_candidates, 1, MPI_LMP_BIGINT, MPI_SUM, world);
  if (all_candidates == 0) {
    if (merge_time > 0.0) merge();
    return;
  }
  // a split that cannot fit stops here, not in an allocation somewhere in LAMMPS
  const int others = SPHSoil::daughter_count(domain->dimension) - 1;
  const double after = (double) atom->natoms + (double) all_candidates * others;
  measure_bytes_per_particle();
  const auto verdict = SPHSoilMemory::check(
      world, growth_bytes((double) atom->nlocal + (double) candidates * others));
  if (!verdict.fits)
    SPHSoilCompat::error_all(
        lmp, FLERR,
        "Fix sph/soil/refine: splitting {} particles at step {} would make {:.3g} "
        "particles, about {:.3g} GB at {:.0f} bytes each, more than {}; lower maxlevel "
        "or limit the refinement to a region",
        all_candidates, update->ntimestep, after, after * bytes_per_particle / 1e9,
        bytes_per_particle, verdict.limit);

  const int nlocal_before = atom->nlocal;
  last_split = splitter->split(parents);
  born(parents, nlocal_before);
  total_split += last_split;
  run_split += last_split;
  reneighbour();
  next_reneighbor = update->ntimestep + 1;
  integrator->particles_refined(STYLE);
  if (merge_time > 0.0) merge();
}

/* ----------------------------------------------------------------------
   the daughters of `parents` are born now: the parent's slot and, after the owned atoms of
   before the split, the others, parent by parent. Their strain at birth, quiet from now, and
   their family: the parent's ID, which daughter 0 keeps
------------------------------------------------------------------------- */

void FixSPHSoilRefine::born(const std::vector<int> &parents, int nlocal_before)
{
  auto avec = static_cast<AtomVecSPHSoil *>(atom->style_match("sph/soil"));
  const int others = SPHSoil::daughter_count(domain->dimension) - 1;
  const double now = SPHSoilFixes::elapsed_time(update);
  // (with ease T: born with the smoothing ratio of the least defect, eased from now on; the
  // neighbour lists built after the split see the birth h, which only shrinks from there)
  auto set = [&](int j, tagint parent_tag) {
    for (int k = 0; k < 6; k++) strain_reference[j][k] = avec->total_strain[j][k];
    quiet_since[j] = now;
    const int level = avec->level[j];
    if (level >= 1 && level <= maxlevel) family[j][level - 1] = (double) parent_tag;
    if (ease_time > 0.0) {
      ease_target[j] = avec->smoothing_length[j];
      avec->smoothing_length[j] = eased_smoothing_length(ease_target[j], 1.0);
      ease_since[j] = now;
    }
  };
  if (ease_time > 0.0) easing_until = now + ease_time;
  for (size_t n = 0; n < parents.size(); n++) {
    const int i = parents[n];
    set(i, atom->tag[i]);
    for (int k = 0; k < others; k++) set(nlocal_before + (int) n * others + k, atom->tag[i]);
  }
}

/* ----------------------------------------------------------------------
   what the run did, in the log: splits, those for the balance, pairs out of balance
------------------------------------------------------------------------- */

void FixSPHSoilRefine::post_run()
{
  if (comm->me == 0)
    utils::logmesg(lmp, "fix sph/soil/refine: {} particles split in this run ({} for the 2:1 "
                        "balance), {} merges ({} of them clusters of orphans); the most pairs more "
                        "than one level apart at a check: {}\n",
                   run_split, run_forced, run_merged, run_clusters, run_unbalanced);
  run_split = run_forced = run_unbalanced = run_merged = run_clusters = 0;
}

/* ----------------------------------------------------------------------
   After a split the ghosts are gone (the daughters took their slots). Output at this step
   (dumps, and computes that build a neighbour list of their own: rdf, pair/local,
   property/local) would see that state, and LAMMPS's neighbour lists would point at atoms that
   are no longer there (an occasional list built on it crashed). So the ghosts are rebuilt and
   LAMMPS's lists too. The owned atoms stay where they are: the daughters lie within a quarter
   spacing of their parents, inside the ghost region, as atoms drift between reneighbourings;
   an exchange now would move atoms without their forces and rates, which the next step's first
   half needs. The next step reneighbours anyway (next_reneighbor): the run is the same.
------------------------------------------------------------------------- */

void FixSPHSoilRefine::reneighbour()
{
  if (domain->triclinic) domain->x2lamda(atom->nlocal);
  comm->borders();
  if (domain->triclinic) domain->lamda2x(atom->nlocal + atom->nghost);
  if (modify->n_pre_neighbor) modify->pre_neighbor();
  neighbor->build(1);
  if (modify->n_post_neighbor) modify->post_neighbor();
}

/* ----------------------------------------------------------------------
   1: particles split at this step, 2: split since the fix was defined,
   3..: particles of the group at level 0, 1, ..., maxlevel (the last counts deeper levels too),
   then the pairs more than one level apart at the last check (before its splits), the merges
   since the fix was defined (families and clusters of orphans), of which clusters of orphans
------------------------------------------------------------------------- */

double FixSPHSoilRefine::compute_vector(int n)
{
  if (n == 0) return last_split_step == update->ntimestep ? (double) last_split : 0.0;
  if (n == 1) return (double) total_split;
  if (n == size_vector - 3) return (double) last_unbalanced;
  if (n == size_vector - 2) return (double) total_merged;
  if (n == size_vector - 1) return (double) total_clusters;
  const int wanted = n - 2;
  auto avec = static_cast<AtomVecSPHSoil *>(atom->style_match("sph/soil"));
  bigint count = 0, all = 0;
  for (int i = 0; i < atom->nlocal; i++)
    if (atom->mask[i] & groupbit) {
      const int level = MIN(avec->level[i], maxlevel);
      if (level == wanted) count++;
    }
  MPI_Allreduce(&count, &all, 1, MPI_LMP_BIGINT, MPI_SUM, world);
  return (double) all;
}

/* ---------------------------------------------------------------------- */

void FixSPHSoilRefine::write_restart(FILE *fp)
{
  if (comm->me != 0) return;
  double data[1] = {(double) total_split};
  int size = sizeof(data);
  fwrite(&size, sizeof(int), 1, fp);
  fwrite(data, sizeof(double), 1, fp);
}

// (the merges are counted from the fix's definition in this input, not kept: files
// from before merging hold the total split alone, and LAMMPS does not pass the size)
void FixSPHSoilRefine::restart(char *buf)
{
  total_split = (bigint) reinterpret_cast<double *>(buf)[0];
}

/* ----------------------------------------------------------------------
   per atom: the total strain at the particle's birth (0 for one never split, or created),
   quiet since (-1: not quiet), families (0: unknown)
------------------------------------------------------------------------- */

void FixSPHSoilRefine::grow_arrays(int nmax)
{
  memory->grow(strain_reference, nmax, 6, "sph/soil/refine:strain_reference");
  memory->grow(quiet_since, nmax, "sph/soil/refine:quiet_since");
  memory->grow(family, nmax, maxlevel, "sph/soil/refine:family");
  memory->grow(ease_since, nmax, "sph/soil/refine:ease_since");
  memory->grow(ease_target, nmax, "sph/soil/refine:ease_target");
}

void FixSPHSoilRefine::copy_arrays(int i, int j, int /*delflag*/)
{
  for (int k = 0; k < 6; k++) strain_reference[j][k] = strain_reference[i][k];
  quiet_since[j] = quiet_since[i];
  for (int l = 0; l < maxlevel; l++) family[j][l] = family[i][l];
  ease_since[j] = ease_since[i];
  ease_target[j] = ease_target[i];
}

void FixSPHSoilRefine::set_arrays(int i)
{
  for (int k = 0; k < 6; k++) strain_reference[i][k] = 0.0;
  quiet_since[i] = -1.0;
  for (int l = 0; l < maxlevel; l++) family[i][l] = 0.0;
  ease_since[i] = -1.0;
  ease_target[i] = 0.0;
}

int FixSPHSoilRefine::pack_exchange(int i, double *buf)
{
  int m = 0;
  for (int k = 0; k < 6; k++) buf[m++] = strain_reference[i][k];
  buf[m++] = quiet_since[i];
  for (int l = 0; l < maxlevel; l++) buf[m++] = family[i][l];
  buf[m++] = ease_since[i];
  buf[m++] = ease_target[i];
  return m;
}

int FixSPHSoilRefine::unpack_exchange(int nlocal, double *buf)
{
  int m = 0;
  for (int k = 0; k < 6; k++) strain_reference[nlocal][k] = buf[m++];
  quiet_since[nlocal] = buf[m++];
  for (int l = 0; l < maxlevel; l++) family[nlocal][l] = buf[m++];
  ease_since[nlocal] = buf[m++];
  ease_target[nlocal] = buf[m++];
  return m;
}

// restart files: the same values; a file of another maxlevel gives the families it has
int FixSPHSoilRefine::pack_restart(int i, double *buf)
{
  buf[0] = 1 + per_atom_columns();
  return 1 + pack_exchange(i, buf + 1);
}

void FixSPHSoilRefine::unpack_restart(int nlocal, int nth)
{
  double **extra = atom->extra;
  int m = 0;
  for (int i = 0; i < nth; i++) m += static_cast<int>(extra[nlocal][m]);
  const double *buf = &extra[nlocal][m];
  // (the layout of pack_exchange() after the count: strain at birth, quiet since, families,
  // ease since and target; files of before easing (2026-12-06) end with the families: with the
  // same maxlevel they are told by their count)
  const int values = static_cast<int>(buf[0]) - 1;
  const bool with_easing = values != 7 + maxlevel;
  const int stored_levels = values - 7 - (with_easing ? 2 : 0);
  for (int k = 0; k < 6; k++) strain_reference[nlocal][k] = buf[1 + k];
  quiet_since[nlocal] = buf[1 + 6];
  for (int l = 0; l < maxlevel; l++) family[nlocal][l] = l < stored_levels ? buf[1 + 7 + l] : 0.0;
  ease_since[nlocal] = with_easing ? buf[1 + 7 + stored_levels] : -1.0;
  ease_target[nlocal] = with_easing ? buf[1 + 7 + stored_levels + 1] : 0.0;
  if (ease_since[nlocal] >= 0.0) easing_until = MAX(easing_until, ease_since[nlocal] + ease_time);
}

int FixSPHSoilRefine::maxsize_restart()
{
  return 1 + per_atom_columns();
}

int FixSPHSoilRefine::size_restart(int /*nlocal*/)
{
  return 1 + per_atom_columns();
}

double FixSPHSoilRefine::memory_usage()
{
  return (double) atom->nmax * per_atom_columns() * sizeof(double) + (merger ? merger->memory_usage() : 0.0);
}

/* ----------------------------------------------------------------------
   merging (merge T, sph_soil_refine_merger.h): at a check, before its splits, since when each
   particle of the group is quiet; after them, the merges
------------------------------------------------------------------------- */

void FixSPHSoilRefine::mark_quiet()
{
  const double now = SPHSoilFixes::elapsed_time(update);
  for (int i = 0; i < atom->nlocal; i++) {
    if (!(atom->mask[i] & groupbit)) continue;
    // (a daughter still easing is not: the merge takes its h for alpha_r times its parent's)
    if (!selection->quiet(i, merge_time) || ease_since[i] >= 0.0)
      quiet_since[i] = -1.0;
    else if (quiet_since[i] < 0.0)
      quiet_since[i] = now;
  }
}

void FixSPHSoilRefine::merge()
{
  const bigint merged = merger->merge(this, history(), groupbit, maxlevel, nevery);
  if (merged == 0) return;
  reneighbour();
  next_reneighbor = update->ntimestep + 1;
  // the smallest h may have grown: with a time step per level, the hierarchy follows now, at
  // the synchronised step (with one global step, the adaptive step follows at the next step)
  if (schedule->per_level) integrator->particles_refined(STYLE);
  total_merged += merged;
  run_merged += merged;
  total_clusters += merger->clusters_merged();
  run_clusters += merger->clusters_merged();
}

int FixSPHSoilRefine::pack_forward_comm(int n, int *list, double *buf, int /*pbc_flag*/, int * /*pbc*/)
{
  if (forwarding_h) {
    const double *h = static_cast<AtomVecSPHSoil *>(atom->style_match("sph/soil"))->smoothing_length;
    for (int k = 0; k < n; k++) buf[k] = h[list[k]];
    return n;
  }
  return merger->pack_forward_comm(n, list, buf);
}

void FixSPHSoilRefine::unpack_forward_comm(int n, int first, double *buf)
{
  if (forwarding_h) {
    double *h = static_cast<AtomVecSPHSoil *>(atom->style_match("sph/soil"))->smoothing_length;
    for (int k = 0; k < n; k++) h[first + k] = buf[k];
    return;
  }
  merger->unpack_forward_comm(n, first, buf);
}

int FixSPHSoilRefine::pack_reverse_comm(int n, int first, double *buf)
{
  return merger->pack_reverse_comm(n, first, buf);
}

void FixSPHSoilRefine::unpack_reverse_comm(int n, int *list, double *buf)
{
  merger->unpack_reverse_comm(n, list, buf);
}

/* ----------------------------------------------------------------------
   ease T: each step (after the positions' update, before the forces), the smoothing length of
   the daughters born within the last T goes
   linearly from birth_ratio h_parent (at birth) to alpha_r h_parent (at T), and the ghosts
   follow. The split's defect (doc/theory.rst 5.11) then grows from its least to its value over T,
   as a load applied slowly, instead of at once. Collective: easing_until is the same on all
   ranks (splits happen at the same steps everywhere); -1 once all have eased.
------------------------------------------------------------------------- */

void FixSPHSoilRefine::ease()
{
  if (ease_time <= 0.0 || easing_until < 0.0) return;
  const double now = SPHSoilFixes::elapsed_time(update);
  auto avec = static_cast<AtomVecSPHSoil *>(atom->style_match("sph/soil"));
  for (int i = 0; i < atom->nlocal; i++) {
    if (ease_since[i] < 0.0) continue;
    const double remaining = 1.0 - (now - ease_since[i]) / ease_time;
    avec->smoothing_length[i] = eased_smoothing_length(ease_target[i], remaining);
    if (remaining <= 0.0) ease_since[i] = -1.0;
  }
  forwarding_h = true;
  SPHSoilCompat::forward_comm_fix(comm, this);
  forwarding_h = false;
  // all eased (the last births' T is over): the time step must now suit the final h (a fixed
  // step that does not stops here, as at a split without easing)
  if (now >= easing_until) {
    easing_until = -1.0;
    integrator->particles_refined(STYLE);
  }
}

double FixSPHSoilRefine::eased_smoothing_length(double final_h, double remaining) const
{
  const double widen = birth_ratio / splitter->smoothing_ratio;
  return remaining <= 0.0 ? final_h : final_h * (1.0 + (widen - 1.0) * remaining);
}

/* ----------------------------------------------------------------------
   the smoothing ratio at birth with ease T: in [alpha_r, 1], the one whose split is the least
   felt by a soil at rest (split_stress_defect(): the larger of the pushes on the coarse
   neighbours and on the daughters), on a grid of 0.01; the same on all ranks
------------------------------------------------------------------------- */

void FixSPHSoilRefine::choose_birth_ratio(double ra)
{
  const double eps = splitter->separation, alpha = splitter->smoothing_ratio;
  double best = HUGE_VAL;
  birth_ratio = alpha;
  for (int k = 0; alpha + 0.01 * k <= 1.0 + 1e-12; k++) {
    const double ratio = alpha + 0.01 * k;
    const auto d = SPHSoil::split_stress_defect(domain->dimension, eps, ratio, ra, splitter->kernel_kind());
    const double worst = MAX(d.neighbours, d.daughters);
    if (worst < best) {
      best = worst;
      birth_ratio = ratio;
    }
  }
}
