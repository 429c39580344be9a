/* ----------------------------------------------------------------------
   SPH_SOIL package for LAMMPS: pair_style sph/soil: input, init, restart
   (the loop: pair_sph_soil_loop.cpp; the checks: pair_sph_soil_checks.cpp)
------------------------------------------------------------------------- */

#include "pair_sph_soil.h"

#include "atom.h"
#include "atom_vec_sph_soil.h"
#include "comm.h"
#include "error.h"
#include "fix_sph_soil_skin.h"
#include "force.h"
#include "memory.h"
#include "modify.h"
#include "neighbor.h"
#include "soil_artificial_stress.h"
#include "soil_packed_rows.h"
#include "soil_pair_terms.h"
#include "sph_soil_compat.h"
#include "sph_soil_fixes.h"
#include "sph_soil_gradient_correction.h"
#include "sph_soil_input.h"
#include "sph_soil_offenders.h"
#include "sph_soil_pore_water.h"
#include "sph_soil_stress_diffusion.h"
#include "sph_soil_walls.h"
#include "utils.h"

#include <algorithm>
#include <cstring>
#include <functional>

using namespace LAMMPS_NS;
using SPHSoil::SoilMaterial;

// (a definition for C++11, where LAMMPS 29Sep2021 compiles: the value is passed by reference)
constexpr int PairSPHSoil::RESTART_FORMAT;

/* ---------------------------------------------------------------------- */

PairSPHSoil::PairSPHSoil(LAMMPS *lmp) :
    Pair(lmp), has_artificial_stress(false), multiphase(false), materials(lmp),
    walls(new SPHSoilWalls(lmp, this)), pore_water(new SPHSoilPoreWater(lmp, this)), sound_speed_ij(nullptr), max_h(0.0), avec(nullptr),
    warned_density(false), warned_spacing(false), warned_coinciding(false), nmax_packed(0),
    packed(nullptr), sums(nullptr), schedule(nullptr), nmax_periods(0), step_periods(nullptr), atom_periods(nullptr),
    periods_finest_h(-1.0),
    nmax_artificial(0), artificial(nullptr), skin_fix(nullptr)
{
  set_defaults();
  single_enable = 0;
  restartinfo = 1;
  one_coeff = 0;
  manybody_flag = 0;
  // the forces are pairwise and reach the ghosts (Newton's third law): x . f over owned and
  // ghost atoms is the virial (LAMMPS asks for it with newton on); pair by pair otherwise
  no_virial_fdotr_compute = 0;
  // (the pore water sends one number per atom, the gradient correction up to its COMM_SIZE)
  comm_forward = MAX(MAX(walls->forward_size(), SPHSoilGradientCorrection::COMM_SIZE),
                     SPHSoilStressDiffusion::COMM_SIZE);
  comm_reverse = MAX(MAX(walls->reverse_size(), SPHSoilGradientCorrection::COMM_SIZE),
                     MAX(SPHSoilStressDiffusion::COMM_SIZE, SPHSoilPoreWater::FLOW_COMM_SIZE));
  skin_fix_id = "SPH_SOIL_SKIN_" + std::to_string(instance_me);
}

/* ---------------------------------------------------------------------- */

PairSPHSoil::~PairSPHSoil()
{
  memory->destroy(packed);
  memory->destroy(sums);
  memory->destroy(step_periods);
  memory->destroy(atom_periods);
  memory->destroy(artificial);
  if (allocated) {
    memory->destroy(setflag);
    memory->destroy(cutsq);
    memory->destroy(sound_speed_ij);
  }
  if (modify && modify->find_fix(skin_fix_id) >= 0) modify->delete_fix(skin_fix_id);
}

/* ---------------------------------------------------------------------- */

void PairSPHSoil::allocate()
{
  allocated = 1;
  const int n = atom->ntypes;
  memory->create(setflag, n + 1, n + 1, "pair:setflag");
  memory->create(cutsq, n + 1, n + 1, "pair:cutsq");
  memory->create(sound_speed_ij, n + 1, n + 1, "pair:sound_speed_ij");
  for (int i = 0; i <= n; i++)
    for (int j = 0; j <= n; j++) setflag[i][j] = 0;
  materials.allocate(n);
}

// a repeated pair_style command starts again from these
void PairSPHSoil::set_defaults()
{
  viscosity_alpha = viscosity_beta = 0.1;
  viscosity_h0 = 0.0;
  artificial_stress_epsilon = SPHSoil::ARTIFICIAL_STRESS_EPSILON;
  free_slip = false;
  continuity_volume = true;
  gradient_correction = CORRECTION_NONE;
  density_diffusion = DEFAULT_DIFFUSION;
  stress_diffusion = AUTO_DIFFUSION;
  kernel = SPHSoil::KernelKind();
}

/* ----------------------------------------------------------------------
   pair_style sph/soil [alpha A] [beta B] [viscosity_h0 H] [wall noslip|freeslip]
                       [kernel cubic|wendland2] [artificial_stress epsilon]
                       [continuity volume|mass] [gradient_correction no|yes|full]
                       [density_diffusion delta] [stress_diffusion delta]
------------------------------------------------------------------------- */

void PairSPHSoil::settings(int narg, char **arg)
{
  using namespace SPHSoilInput;
  set_defaults();
  auto number_of = [&](const char *keyword, const char *text, const Range &range) {
    return number(FLERR, lmp, std::string("pair_style sph/soil ") + keyword, text, range);
  };
  // a keyword of two values: whether it is `first`
  auto one_of_two = [&](const char *keyword, const char *v, const char *first, const char *second) {
    if (strcmp(v, first) != 0 && strcmp(v, second) != 0)
      SPHSoilCompat::error_all(lmp, FLERR, "Illegal pair_style sph/soil {} {}: must be {} or {}",
                               keyword, v, first, second);
    return strcmp(v, first) == 0;
  };
  // the keywords: one line each, and the "allowed" list of the error from them
  const std::vector<std::pair<const char *, std::function<void(const char *)>>> keywords = {
      {"alpha", [&](const char *v) { viscosity_alpha = number_of("alpha", v, at_least(0.0)); }},
      {"beta", [&](const char *v) { viscosity_beta = number_of("beta", v, at_least(0.0)); }},
      {"viscosity_h0",
       [&](const char *v) { viscosity_h0 = number_of("viscosity_h0", v, at_least(0.0)); }},
      {"wall", [&](const char *v) { free_slip = !one_of_two("wall", v, "noslip", "freeslip"); }},
      {"kernel",
       [&](const char *v) {
         if (!SPHSoil::kernel_kind(v, kernel))
           SPHSoilCompat::error_all(lmp, FLERR,
                                    "Illegal pair_style sph/soil kernel {}: must be one of {}", v,
                                    SPHSoil::kernel_names());
       }},
      {"artificial_stress",
       [&](const char *v) {
         artificial_stress_epsilon =
             number_of("artificial_stress", v, between(0.0, 1.0, false, false));
       }},
      {"continuity",
       [&](const char *v) { continuity_volume = one_of_two("continuity", v, "volume", "mass"); }},
      {"gradient_correction",
       [&](const char *v) {
         // (in the order of CORRECTION_NONE, _SCALAR, _FULL)
         const char *names[3] = {"no", "yes", "full"};
         const auto found =
             std::find_if(names, names + 3, [&](const char *n) { return strcmp(n, v) == 0; });
         if (found == names + 3)
           SPHSoilCompat::error_all(lmp, FLERR,
                                    "Illegal pair_style sph/soil gradient_correction {}: must be "
                                    "{}, {} or {}",
                                    v, names[0], names[1], names[2]);
         gradient_correction = (int) (found - names);
       }},
      {"density_diffusion",
       [&](const char *v) { density_diffusion = number_of("density_diffusion", v, between(0.0, 1.0, false, false)); }},
      {"stress_diffusion",
       [&](const char *v) { stress_diffusion = number_of("stress_diffusion", v, between(0.0, 1.0, false, false)); }},
  };
  for (int iarg = 0; iarg < narg; iarg += 2) {
    if (iarg + 1 >= narg)
      SPHSoilCompat::error_all(
          lmp, FLERR, "Illegal pair_style sph/soil command: keyword {} needs a value", arg[iarg]);
    if (strcmp(arg[iarg], "fit") == 0)
      // moved in 2026-12: say where to, rather than "unknown keyword"
      SPHSoilCompat::error_all(
          lmp, FLERR,
          "Illegal pair_style sph/soil keyword fit: the Drucker-Prager fit is now a "
          "parameter of the material ('soil rho0 drucker_prager K nu phi psi c fit {}' "
          "in pair_coeff or a material file); by default it is the fit exact for the "
          "dilatancy angle",
          arg[iarg + 1]);
    bool known = false;
    for (const auto &k : keywords)
      if (strcmp(arg[iarg], k.first) == 0) {
        k.second(arg[iarg + 1]);
        known = true;
      }
    if (!known) {
      std::string allowed;
      for (const auto &k : keywords) allowed += (allowed.empty() ? "" : ", ") + std::string(k.first);
      SPHSoilCompat::error_all(lmp, FLERR, "Illegal pair_style sph/soil keyword {} (allowed: {})",
                               arg[iarg], allowed);
    }
  }
}

/* ----------------------------------------------------------------------
   pair_coeff: the materials (sph_soil_materials.h); a pair is set once both types have one
------------------------------------------------------------------------- */

void PairSPHSoil::coeff(int narg, char **arg)
{
  if (!allocated) allocate();
  materials.coeff(narg, arg);
  for (int i = 1; i <= atom->ntypes; i++)
    for (int j = 1; j <= atom->ntypes; j++) setflag[i][j] = materials.has(i) && materials.has(j);
}

/* ---------------------------------------------------------------------- */

void PairSPHSoil::init_style()
{
  avec = dynamic_cast<AtomVecSPHSoil *>(atom->style_match("sph/soil"));
  if (!avec)
    SPHSoilCompat::error_all(lmp, FLERR, "Pair style sph/soil requires atom_style sph/soil");

  // the cutoff follows the largest smoothing length; every particle needs h > 0
  const int nlocal = atom->nlocal;
  const int *type = atom->type;
  const double *h = avec->smoothing_length;
  const auto no_h = SPHSoilOffenders::find_offenders(
      lmp, [&](int i) { return materials.has(type[i]) && !(h[i] > 0.0); }, [](int, double *) {});
  if (no_h)
    SPHSoilCompat::error_all(lmp, FLERR,
                             "Pair sph/soil: atom {} has smoothing length h <= 0; set it with "
                             "'sph_soil/set <group> h <value>'",
                             no_h.first);
  double local_max = 0.0;
  for (int i = 0; i < nlocal; i++)
    if (materials.has(type[i])) local_max = MAX(local_max, h[i]);
  MPI_Allreduce(&local_max, &max_h, 1, MPI_DOUBLE, MPI_MAX, world);
  if (max_h <= 0.0)
    SPHSoilCompat::error_all(lmp, FLERR, "Pair sph/soil: no particle with a material and h > 0");
  check_list_fits();

  // every type has a material here (init_one stops otherwise)
  walls->classify(materials.all(), materials.set_flags(), free_slip);
  check_particles();

  // the artificial stress, for soils that can carry tension
  type_artificial_stress.assign(atom->ntypes + 1, 0);
  has_artificial_stress = false;
  for (int t = 1; t <= atom->ntypes; t++) {
    const SPHSoil::ConstitutiveModel *soil = materials.model(t);
    if (soil && soil->tensile_strength() > 0.0 && artificial_stress_epsilon > 0.0) {
      type_artificial_stress[t] = 1;
      has_artificial_stress = true;
    }
  }

  walls->init();
  pore_water->init(materials.all(), materials.set_flags(), density_diffusion);
  // free water: the momentum sum's multiphase form (see the header)
  multiphase = pore_water->free_water();
  type_free_water.assign(atom->ntypes + 1, 0);
  type_soil_by_water.assign(atom->ntypes + 1, 0);
  for (int t = 1; t <= atom->ntypes; t++) {
    type_free_water[t] = materials.has(t) && materials.all()[t].water;
    type_soil_by_water[t] = materials.has(t) && !materials.all()[t].water && !materials.all()[t].is_wall();
  }
  init_stress_diffusion();
  const bool full = gradient_correction == CORRECTION_FULL;
  if (gradient_correction == CORRECTION_NONE || (correction && correction->full() != full))
    correction.reset();
  if (gradient_correction != CORRECTION_NONE && !correction)
    correction.reset(new SPHSoilGradientCorrection(lmp, this, full));
  schedule = SPHSoilFixes::step_schedule(lmp);
  // the fix that keeps our list valid between LAMMPS's reneighbourings (created once, as
  // pair_granular creates its history fix)
  if (modify->find_fix(skin_fix_id) < 0) modify->add_fix(skin_fix_id + " all SPH_SOIL_SKIN");
  skin_fix = dynamic_cast<FixSPHSoilSkin *>(modify->fix[modify->find_fix(skin_fix_id)]);

  // no request of a LAMMPS neighbour list: the pair style builds its own (build_neighbours())
  // on LAMMPS's reneighbouring, whose ghost atoms and skin it uses; LAMMPS's exclusions apply
  // to LAMMPS's lists only
  // (the exclusion lists themselves: Neighbor::init(), which sets `exclude`, runs after this)
  if ((neighbor->nex_type || neighbor->nex_group || neighbor->nex_mol) && comm->me == 0)
    error->warning(FLERR, "Pair sph/soil builds its own neighbour list: neigh_modify exclude "
                          "has no effect on it");
}

/* ---------------------------------------------------------------------- */

double PairSPHSoil::init_one(int i, int j)
{
  if (setflag[i][j] == 0)
    SPHSoilCompat::error_all(lmp, FLERR,
                             "All pair coeffs are not set: pair sph/soil needs a material for atom "
                             "types {} and {}",
                             i, j);
  const SoilMaterial &mi = materials.of(i), &mj = materials.of(j);
  if (mi.is_wall() && mj.is_wall()) {
    // wall particles never interact with each other: only within the skin
    sound_speed_ij[i][j] = sound_speed_ij[j][i] = 0.0;
    return 0.0;
  }
  const double ci = mi.is_wall() ? mj.wave_speed() : mi.wave_speed();
  const double cj = mj.is_wall() ? mi.wave_speed() : mj.wave_speed();
  sound_speed_ij[i][j] = sound_speed_ij[j][i] = 0.5 * (ci + cj);
  return SPHSoil::kernel_support(kernel) * max_h;
}

/* ----------------------------------------------------------------------
   the pair list of the owned and ghost atoms, every pair within the kernel's support at h_ij
   plus its skin, in proportion to h_ij (soil_neighbours.h): neighbor's skin is that of the
   largest h, which with the support sets the ghost cutoff; a daughter's skin is in proportion
   to its spacing, as its parent's (doc/theory.rst 5.8). fix SPH_SOIL_SKIN watches the list
   while some particle has a smaller h (else LAMMPS's own check is the list's)
------------------------------------------------------------------------- */

void PairSPHSoil::build_neighbours()
{
  SPHSoil::NeighbourInput input;
  input.x = atom->x;
  input.h = avec->smoothing_length;
  input.type = atom->type;
  input.kind_of_type = walls->kinds();
  input.nlocal = atom->nlocal;
  input.nall = atom->nlocal + atom->nghost;
  input.dimension = domain->dimension;
  input.support = SPHSoil::kernel_support(kernel);
  input.skin = 0.0;
  input.skin_per_h = neighbor->skin / max_h;
  input.newton = force->newton_pair != 0;
  neighbours.build(input);

  int smaller_h = 0, anywhere = 0;
  for (int i = 0; i < input.nlocal && !smaller_h; i++)
    if (input.h[i] < max_h) smaller_h = 1;
  MPI_Allreduce(&smaller_h, &anywhere, 1, MPI_INT, MPI_MAX, world);
  skin_fix->watch(&neighbours, anywhere != 0);
}

/* ----------------------------------------------------------------------
   bytes of the per-atom rows and of the pair list (LAMMPS adds them to its memory report)
------------------------------------------------------------------------- */

double PairSPHSoil::memory_usage()
{
  double bytes = Pair::memory_usage();
  bytes += (double) nmax_packed * (SPHSoil::PACKED + SUMS) * sizeof(double);
  bytes += (double) nmax_artificial * ARTIFICIAL * sizeof(double);
  bytes += walls->memory_usage();
  bytes += (double) neighbours.memory_bytes();
  return bytes;
}

/* ---------------------------------------------------------------------- */

void *PairSPHSoil::extract(const char *name, int &dim)
{
  dim = 0;
  if (strcmp(name, "viscosity_alpha") == 0) return (void *) &viscosity_alpha;
  if (strcmp(name, "viscosity_beta") == 0) return (void *) &viscosity_beta;
  if (strcmp(name, "viscosity_h0") == 0) return (void *) &viscosity_h0;
  // for the package's own code (the refinement), which needs no more of the pair style
  if (strcmp(name, "sph_soil_materials") == 0) return (void *) &materials;
  if (strcmp(name, "sph_soil_kernel") == 0) return (void *) &kernel;
  return nullptr;
}

/* ----------------------------------------------------------------------
   the stress diffusion: its coefficient delta c per soil type (c its wave speed, undrained for
   a saturated soil); by default on in runs with pore water or free water (a submerged soil's
   effective stress near its surface is a few pascals, which the zigzag swamps), off in dry
   runs (whose validated answers it would move, and whose step it would slow)
------------------------------------------------------------------------- */

void PairSPHSoil::init_stress_diffusion()
{
  const double delta = stress_diffusion == AUTO_DIFFUSION
      ? (pore_water->pressures() ? DEFAULT_DIFFUSION : 0.0)
      : stress_diffusion;
  std::vector<double> coefficient(atom->ntypes + 1, 0.0);
  for (int t = 1; t <= atom->ntypes; t++) {
    const SPHSoil::SoilMaterial &m = materials.all()[t];
    // (the skeleton's own wave speed: its stress is what diffuses; a saturated soil's undrained
    // speed, several times larger, smeared Mandel's consolidation)
    if (materials.has(t) && !m.is_wall() && !m.water)
      coefficient[t] = delta * m.model->wave_speed(m.density);
  }
  if (delta <= 0.0) {
    diffusion.reset();
    return;
  }
  if (!diffusion) diffusion.reset(new SPHSoilStressDiffusion(lmp, this));
  diffusion->init(coefficient);
}

double PairSPHSoil::drained_inflow(int i) const
{
  return pore_water->drained_inflow(i);
}

bool PairSPHSoil::carries_pressures() const
{
  return pore_water->pressures();
}

/* ----------------------------------------------------------------------
   the communication belongs to the pore water while it sends, else to the walls
------------------------------------------------------------------------- */

int PairSPHSoil::pack_forward_comm(int n, int *list, double *buf, int /*pbc_flag*/, int * /*pbc*/)
{
  if (pore_water->communicating()) return pore_water->pack_forward_comm(n, list, buf);
  if (correction && correction->communicating()) return correction->pack_forward_comm(n, list, buf);
  if (diffusion && diffusion->communicating()) return diffusion->pack_forward_comm(n, list, buf);
  return walls->pack_forward_comm(n, list, buf);
}

void PairSPHSoil::unpack_forward_comm(int n, int first, double *buf)
{
  if (pore_water->communicating()) return pore_water->unpack_forward_comm(n, first, buf);
  if (correction && correction->communicating()) return correction->unpack_forward_comm(n, first, buf);
  if (diffusion && diffusion->communicating()) return diffusion->unpack_forward_comm(n, first, buf);
  walls->unpack_forward_comm(n, first, buf);
}

int PairSPHSoil::pack_reverse_comm(int n, int first, double *buf)
{
  if (pore_water->communicating()) return pore_water->pack_reverse_comm(n, first, buf);
  if (correction && correction->communicating()) return correction->pack_reverse_comm(n, first, buf);
  if (diffusion && diffusion->communicating()) return diffusion->pack_reverse_comm(n, first, buf);
  return walls->pack_reverse_comm(n, first, buf);
}

void PairSPHSoil::unpack_reverse_comm(int n, int *list, double *buf)
{
  if (pore_water->communicating()) return pore_water->unpack_reverse_comm(n, list, buf);
  if (correction && correction->communicating()) return correction->unpack_reverse_comm(n, list, buf);
  if (diffusion && diffusion->communicating()) return diffusion->unpack_reverse_comm(n, list, buf);
  walls->unpack_reverse_comm(n, list, buf);
}

double PairSPHSoil::viscosity_step_factor(double h) const
{
  return SPHSoil::viscosity_step_factor(viscosity_alpha, viscosity_h0, h);
}

/* ----------------------------------------------------------------------
   restart files: the format number and the settings, then every type's material, so that a
   restarted run needs no pair_style or pair_coeff
------------------------------------------------------------------------- */

void PairSPHSoil::write_restart_settings(FILE *fp)
{
  const int format = RESTART_FORMAT;
  const int flags[4] = {free_slip ? 1 : 0, kernel.index, continuity_volume ? 1 : 0,
                        gradient_correction};
  const double numbers[6] = {viscosity_alpha, viscosity_beta, viscosity_h0,
                             artificial_stress_epsilon, density_diffusion, stress_diffusion};
  fwrite(&format, sizeof(int), 1, fp);
  fwrite(flags, sizeof(int), 4, fp);
  fwrite(numbers, sizeof(double), 6, fp);
}

void PairSPHSoil::read_restart_settings(FILE *fp)
{
  // format 1 (before the continuity keyword) was written by runs of the mass form: they go on
  // with it; format 2 (before gradient_correction) by runs without the correction; format 3
  // (before the diffusions) by runs without them
  int format = 0, flags[4] = {0, 0, 0, 0};
  double numbers[6] = {0.0, 0.0, 0.0, 0.0, 0.0, 0.0};
  if (comm->me == 0) utils::sfread(FLERR, &format, sizeof(int), 1, fp, nullptr, error);
  MPI_Bcast(&format, 1, MPI_INT, 0, world);
  if (format < 1 || format > RESTART_FORMAT)
    SPHSoilCompat::error_all(
        lmp, FLERR,
        "Restart file holds pair_style sph/soil data of format {}; this build of "
        "SPH_SOIL reads formats 1 to {}",
        format, RESTART_FORMAT);
  const int nflags = std::min(format + 1, 4);
  const int nnumbers = format >= 4 ? 6 : 4;
  if (comm->me == 0) {
    utils::sfread(FLERR, flags, sizeof(int), nflags, fp, nullptr, error);
    utils::sfread(FLERR, numbers, sizeof(double), nnumbers, fp, nullptr, error);
  }
  MPI_Bcast(flags, 4, MPI_INT, 0, world);
  MPI_Bcast(numbers, 6, MPI_DOUBLE, 0, world);
  free_slip = flags[0] != 0;
  kernel.index = flags[1];
  continuity_volume = flags[2] != 0;
  gradient_correction = flags[3];
  viscosity_alpha = numbers[0];
  viscosity_beta = numbers[1];
  viscosity_h0 = numbers[2];
  artificial_stress_epsilon = numbers[3];
  density_diffusion = numbers[4];
  stress_diffusion = numbers[5];
}

void PairSPHSoil::write_restart(FILE *fp)
{
  write_restart_settings(fp);
  materials.write_restart(fp);
}

void PairSPHSoil::read_restart(FILE *fp)
{
  read_restart_settings(fp);
  allocate();
  materials.read_restart(fp);
  for (int i = 1; i <= atom->ntypes; i++)
    for (int j = 1; j <= atom->ntypes; j++) setflag[i][j] = materials.has(i) && materials.has(j);
}
