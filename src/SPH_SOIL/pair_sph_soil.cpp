/* ----------------------------------------------------------------------
   SPH_SOIL package for LAMMPS: pair_style sph/soil
------------------------------------------------------------------------- */

#include "pair_sph_soil.h"

#include "atom.h"
#include "atom_vec_sph_soil.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "fix_sph_soil.h"
#include "force.h"
#include "memory.h"
#include "modify.h"
#include "neigh_list.h"
#include "neighbor.h"
#include "soil_artificial_stress.h"
#include "soil_kernels.h"
#include "soil_models.h"
#include "soil_neighbours.h"
#include "soil_split.h"
#include "sph_soil_pair_term.h"
#include "sph_soil_compat.h"
#include "sph_soil_input.h"
#include "sph_soil_offenders.h"
#include "utils.h"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdlib>
#include <cstring>

using namespace LAMMPS_NS;
using SPHSoil::SoilMaterial;

// kept out of line (GCC and Clang would inline it into the pair loop)
#if defined(__GNUC__)
#define SPH_SOIL_NOINLINE __attribute__((noinline))
#else
#define SPH_SOIL_NOINLINE
#endif

/* ---------------------------------------------------------------------- */

PairSPHSoil::PairSPHSoil(LAMMPS *lmp) :
    Pair(lmp), viscosity_alpha(0.1), viscosity_beta(0.1), viscosity_h0(0.0),
    artificial_stress_epsilon(SPHSoil::ARTIFICIAL_STRESS_EPSILON), has_artificial_stress(false),
    nmax_artificial(0), artificial(nullptr), free_slip(false),
    kernel(SPHSoil::KernelKind::cubic),
    sound_speed_ij(nullptr), max_h(0.0), avec(nullptr), warned_density(false),
    warned_spacing(false), warned_coinciding(false), smaller_h_anywhere(false), nmax_packed(0),
    packed(nullptr), sums(nullptr), has_extrapolated_walls(false), nmax_extrapolation(0),
    extrapolation_sums(nullptr), extrapolated_state(nullptr), walls_may_turn(false),
    integrator(nullptr)
{
  single_enable = 0;
  restartinfo = 0;
  one_coeff = 0;
  manybody_flag = 0;
  no_virial_fdotr_compute = 1;
  // extrapolated walls: their sums go back to the owners, their state out to the ghosts
  comm_forward = WSTATE;
  comm_reverse = XSUMS;
}

/* ---------------------------------------------------------------------- */

PairSPHSoil::~PairSPHSoil()
{
  memory->destroy(packed);
  memory->destroy(sums);
  memory->destroy(artificial);
  memory->destroy(extrapolation_sums);
  memory->destroy(extrapolated_state);
  if (allocated) {
    memory->destroy(setflag);
    memory->destroy(cutsq);
    memory->destroy(sound_speed_ij);
  }
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
  materials.assign(n + 1, SoilMaterial());
  type_set.assign(n + 1, 0);
}

/* ----------------------------------------------------------------------
   pair_style sph/soil [alpha A] [beta B] [viscosity_h0 H] [wall noslip|freeslip]
                       [kernel cubic|wendland2] [artificial_stress epsilon]
------------------------------------------------------------------------- */

void PairSPHSoil::settings(int narg, char **arg)
{
  // a repeated pair_style command starts again from the defaults
  viscosity_alpha = viscosity_beta = 0.1;
  viscosity_h0 = 0.0;
  artificial_stress_epsilon = SPHSoil::ARTIFICIAL_STRESS_EPSILON;
  free_slip = false;
  kernel = SPHSoil::KernelKind::cubic;
  for (int iarg = 0; iarg < narg; iarg += 2) {
    if (iarg + 1 >= narg)
      error->all(FLERR, "Illegal pair_style sph/soil command: keyword {} needs a value", arg[iarg]);
    if (strcmp(arg[iarg], "alpha") == 0) {
      viscosity_alpha = SphSoilInput::number(FLERR, lmp, "pair_style sph/soil alpha", arg[iarg + 1],
                                             SphSoilInput::at_least(0.0));
    } else if (strcmp(arg[iarg], "beta") == 0) {
      viscosity_beta = SphSoilInput::number(FLERR, lmp, "pair_style sph/soil beta", arg[iarg + 1],
                                            SphSoilInput::at_least(0.0));
    } else if (strcmp(arg[iarg], "viscosity_h0") == 0) {
      viscosity_h0 = SphSoilInput::number(FLERR, lmp, "pair_style sph/soil viscosity_h0",
                                          arg[iarg + 1], SphSoilInput::at_least(0.0));
    } else if (strcmp(arg[iarg], "artificial_stress") == 0) {
      artificial_stress_epsilon =
          SphSoilInput::number(FLERR, lmp, "pair_style sph/soil artificial_stress", arg[iarg + 1],
                               SphSoilInput::between(0.0, 1.0, false, false));
    } else if (strcmp(arg[iarg], "wall") == 0) {
      if (strcmp(arg[iarg + 1], "noslip") == 0) free_slip = false;
      else if (strcmp(arg[iarg + 1], "freeslip") == 0) free_slip = true;
      else
        error->all(FLERR, "Illegal pair_style sph/soil wall {}: must be noslip or freeslip",
                   arg[iarg + 1]);
    } else if (strcmp(arg[iarg], "fit") == 0) {
      // moved in 2026-12: say where to, rather than "unknown keyword"
      error->all(FLERR, "Illegal pair_style sph/soil keyword fit: the Drucker-Prager fit is now a "
                        "parameter of the material ('soil rho0 drucker_prager K nu phi psi c fit {}' "
                        "in pair_coeff or a material file); by default it is the fit exact for the "
                        "dilatancy angle", arg[iarg + 1]);
    } else if (strcmp(arg[iarg], "kernel") == 0) {
      if (!SPHSoil::kernel_kind(arg[iarg + 1], kernel))
        error->all(FLERR, "Illegal pair_style sph/soil kernel {}: must be one of {}", arg[iarg + 1],
                   SPHSoil::KERNEL_NAMES);
    } else {
      error->all(FLERR, "Illegal pair_style sph/soil keyword {} (allowed: alpha, beta, "
                        "viscosity_h0, wall, kernel, artificial_stress)", arg[iarg]);
    }
  }
}

/* ----------------------------------------------------------------------
   pair_coeff * * file.soil name1 ... nameN     (NULL: type not handled)
   pair_coeff I I soil rho0 [model] parameters...
   pair_coeff I I wall
------------------------------------------------------------------------- */

void PairSPHSoil::coeff(int narg, char **arg)
{
  if (!allocated) allocate();
  const int ntypes = atom->ntypes;
  if (narg < 3)
    error->all(FLERR, "Incorrect args for pair_coeff sph/soil: expected 'I I soil rho0 model "
                      "parameters' (models: {}), 'I I wall' or '* * file name1 ... name{}'",
               SPHSoil::model_keywords(), ntypes);

  if (strcmp(arg[2], "soil") == 0 || strcmp(arg[2], "wall") == 0) {
    int ilo, ihi, jlo, jhi;
    utils::bounds(FLERR, arg[0], 1, ntypes, ilo, ihi, error);
    utils::bounds(FLERR, arg[1], 1, ntypes, jlo, jhi, error);
    if (ilo != jlo || ihi != jhi)
      error->all(FLERR, "Incorrect args for pair_coeff sph/soil: a material belongs to atom types, "
                        "so both type arguments must be the same (got {} {})", arg[0], arg[1]);
    std::vector<std::string> words(arg + 2, arg + narg);
    SoilMaterial material;
    std::string problem;
    const std::string name = fmt::format("of type(s) {}", arg[0]);
    if (!SPHSoil::material_from_words(name, words, material, problem))
      error->all(FLERR, "Incorrect args for pair_coeff sph/soil: {}", problem);
    for (int type = ilo; type <= ihi; type++) set_type_material(type, material);
    return;
  }

  if (strcmp(arg[0], "*") != 0 || strcmp(arg[1], "*") != 0)
    error->all(FLERR, "Incorrect args for pair_coeff sph/soil: unknown material kind '{}' for "
                      "types {} {} (allowed: soil, wall; a material file takes '* * file name1 ... "
                      "name{}')", arg[2], arg[0], arg[1], ntypes);
  if (narg != 3 + ntypes)
    error->all(FLERR, "Incorrect args for pair_coeff sph/soil: a material file needs one name (or "
                      "NULL) per atom type, {} expected, {} given", ntypes, narg - 3);
  std::vector<SoilMaterial> list;
  read_material_file(arg[2], list);
  for (int type = 1; type <= ntypes; type++) {
    const char *name = arg[2 + type];
    if (strcmp(name, "NULL") == 0) continue;
    const SoilMaterial *found = nullptr;
    for (const auto &m : list)
      if (m.name == name) found = &m;
    if (!found)
      error->all(FLERR, "pair_coeff sph/soil: material {} for atom type {} is not in file {}",
                 name, type, arg[2]);
    set_type_material(type, *found);
  }
}

/* ---------------------------------------------------------------------- */

void PairSPHSoil::set_type_material(int type, const SoilMaterial &material)
{
  materials[type] = material;
  type_set[type] = 1;
  for (int other = 1; other <= atom->ntypes; other++)
    if (type_set[other]) setflag[type][other] = setflag[other][type] = 1;
}

/* ----------------------------------------------------------------------
   read a material file on rank 0 (through LAMMPS's potential-file search)
------------------------------------------------------------------------- */

void PairSPHSoil::read_material_file(const char *file, std::vector<SoilMaterial> &list)
{
  std::string text;
  int ok = 1;
  if (comm->me == 0) {
    // LAMMPS's search (current directory, then its potentials directory), then
    // $LAMMPS_POTENTIALS (which Debian's LAMMPS build no longer consults), then the
    // package's own potentials/ directory when the build knows it
    std::string path = utils::get_potential_file_path(file);
    std::vector<std::string> fallbacks;
    if (const char *env = getenv("LAMMPS_POTENTIALS")) fallbacks.emplace_back(env);
#ifdef SPH_SOIL_POTENTIALS_DIR
    fallbacks.emplace_back(SPH_SOIL_POTENTIALS_DIR);
#endif
    for (const auto &dir : fallbacks) {
      if (!path.empty()) break;
      const std::string candidate = dir + "/" + file;
      if (FILE *probe = fopen(candidate.c_str(), "r")) {
        fclose(probe);
        path = candidate;
      }
    }
    FILE *fp = path.empty() ? nullptr : fopen(path.c_str(), "r");
    if (!fp) {
      ok = 0;
    } else {
      char buffer[4096];
      size_t n;
      while ((n = fread(buffer, 1, sizeof(buffer), fp)) > 0) text.append(buffer, n);
      fclose(fp);
    }
  }
  MPI_Bcast(&ok, 1, MPI_INT, 0, world);
  if (!ok) error->all(FLERR, "Cannot open material file {} for pair_coeff sph/soil", file);
  int length = text.size();
  MPI_Bcast(&length, 1, MPI_INT, 0, world);
  text.resize(length);
  MPI_Bcast(&text[0], length, MPI_CHAR, 0, world);
  std::string problem;
  if (!SPHSoil::parse_material_file(text, list, problem))
    error->all(FLERR, "Invalid material file {} for pair_coeff sph/soil: {}", file, problem);
}

/* ---------------------------------------------------------------------- */

void PairSPHSoil::init_style()
{
  avec = dynamic_cast<AtomVecSPHSoil *>(atom->style_match("sph/soil"));
  if (!avec) error->all(FLERR, "Pair style sph/soil requires atom_style sph/soil");

  // the cutoff follows the largest smoothing length; every particle needs h > 0
  const int nlocal = atom->nlocal;
  const int *type = atom->type;
  const double *h = avec->smoothing_length;
  const auto no_h = SphSoilOffenders::find_offenders(
      lmp, [&](int i) { return type_set[type[i]] && !(h[i] > 0.0); }, [](int, double *) {});
  if (no_h)
    error->all(FLERR, "Pair sph/soil: atom {} has smoothing length h <= 0; set it with "
                      "'sph_soil/set <group> h <value>'", no_h.first);
  double local_max = 0.0;
  for (int i = 0; i < nlocal; i++)
    if (type_set[type[i]]) local_max = MAX(local_max, h[i]);
  MPI_Allreduce(&local_max, &max_h, 1, MPI_DOUBLE, MPI_MAX, world);
  if (max_h <= 0.0) error->all(FLERR, "Pair sph/soil: no particle with a material and h > 0");

  // every type has a material here (init_one stops otherwise): a plain flag for the pair loop
  type_wall_kind.assign(atom->ntypes + 1, 0);
  type_wall_slip.assign(atom->ntypes + 1, SLIP_NONE);
  type_wall_friction.assign(atom->ntypes + 1, 0.0);
  has_extrapolated_walls = false;
  bool has_mirror_walls = false;
  for (int t = 1; t <= atom->ntypes; t++) {
    const SoilMaterial &m = materials[t];
    if (!m.is_wall()) continue;
    using SPHSoil::WallSlip;
    const WallSlip slip = m.slip == WallSlip::pair_default
        ? (free_slip ? WallSlip::freeslip : WallSlip::noslip)
        : m.slip;
    const bool extrapolated = m.boundary == SPHSoil::WallBoundary::extrapolate;
    type_wall_kind[t] = extrapolated ? WALL_EXTRAPOLATE : WALL_MIRROR;
    has_extrapolated_walls = has_extrapolated_walls || extrapolated;
    has_mirror_walls = has_mirror_walls || !extrapolated;
    // free slip and friction act across a plane; an extrapolated wall has none
    if (extrapolated && slip != WallSlip::noslip)
      error->all(FLERR, "Pair sph/soil: wall type {} has boundary extrapolate with {}: an "
                        "extrapolated wall is no-slip (free slip and friction need the plane of "
                        "'boundary mirror')", t, slip == WallSlip::freeslip ? "freeslip" : "friction");
    type_wall_slip[t] = slip == WallSlip::noslip ? SLIP_NONE
        : slip == WallSlip::freeslip             ? SLIP_FREE
                                                 : SLIP_FRICTION;
    type_wall_friction[t] = m.friction;
  }
  check_particles();

  // the artificial stress, for soils that can carry tension
  type_artificial_stress.assign(atom->ntypes + 1, 0);
  has_artificial_stress = false;
  for (int t = 1; t <= atom->ntypes; t++) {
    const SPHSoil::ConstitutiveModel *soil = materials[t].model.get();
    if (soil && soil->tensile_strength() > 0.0 && artificial_stress_epsilon > 0.0) {
      type_artificial_stress[t] = 1;
      has_artificial_stress = true;
    }
  }

  // extrapolated walls: the soil's body force (fix gravity) and the walls' acceleration
  // walls that turn: the fixes that may turn atoms' orientation (fix rigid and its variants,
  // fix move) turn the owners' normals; ghosts get them every step, only then
  gravity_fixes.clear();
  integrator = nullptr;
  bool turning_fix = false;
  for (int ifix = 0; ifix < modify->nfix; ifix++) {
    Fix *fix = modify->fix[ifix];
    if (strcmp(fix->style, "gravity") == 0) gravity_fixes.push_back(fix);
    if (!integrator && strcmp(fix->style, "sph/soil") == 0)
      integrator = dynamic_cast<FixSPHSoil *>(fix);
    if (strncmp(fix->style, "rigid", 5) == 0 || strcmp(fix->style, "move") == 0) turning_fix = true;
  }
  walls_may_turn = has_mirror_walls && turning_fix;

  // no request of a LAMMPS neighbour list: the pair style builds its own (build_neighbours())
  // on LAMMPS's reneighbouring, whose ghost atoms and skin it uses; LAMMPS's exclusions apply
  // to LAMMPS's lists only
  // (the exclusion lists themselves: Neighbor::init(), which sets `exclude`, runs after this)
  if ((neighbor->nex_type || neighbor->nex_group || neighbor->nex_mol) && comm->me == 0)
    error->warning(FLERR, "Pair sph/soil builds its own neighbour list: neigh_modify exclude "
                          "has no effect on it");
}

/* ----------------------------------------------------------------------
   the pair list of the owned and ghost atoms, every pair within the kernel's support at h_ij
   plus its skin (soil_neighbours.h). neighbor's skin is that of the largest h, which with the
   support sets the ghost cutoff. With fix sph/soil, which asks for a reneighbouring when a
   particle has moved half its own skin, a pair's skin is in proportion to h_ij (a daughter's
   skin in proportion to its spacing, as its parent's); without it, LAMMPS's check decides
   alone and knows one skin, for all pairs (doc/theory.rst 5.8)
------------------------------------------------------------------------- */

void PairSPHSoil::build_neighbours()
{
  SPHSoil::NeighbourInput input;
  input.x = atom->x;
  input.h = avec->smoothing_length;
  input.type = atom->type;
  input.kind_of_type = type_wall_kind.data();
  input.nlocal = atom->nlocal;
  input.nall = atom->nlocal + atom->nghost;
  input.dimension = domain->dimension;
  input.support = SPHSoil::kernel_support(kernel);
  input.skin = skin_follows_h() ? 0.0 : neighbor->skin;
  input.skin_per_h = skin_follows_h() ? neighbor->skin / max_h : 0.0;
  input.newton = force->newton_pair != 0;
  neighbours.build(input);

  int smaller_h = 0, anywhere = 0;
  for (int i = 0; i < input.nlocal && !smaller_h; i++)
    if (input.h[i] < max_h) smaller_h = 1;
  MPI_Allreduce(&smaller_h, &anywhere, 1, MPI_INT, MPI_MAX, world);
  smaller_h_anywhere = anywhere != 0;
}

bool PairSPHSoil::neighbours_outdated() const
{
  return neighbours.moved_beyond_skin(atom->x, atom->nlocal);
}

/* ----------------------------------------------------------------------
   the particles' state against their materials: wall particles need their plane (an error
   otherwise); a density far from the material's or an h far from the spacing that mass and
   density give is legal but most likely a set-up mistake (a warning, once)
------------------------------------------------------------------------- */

void PairSPHSoil::check_particles()
{
  using SphSoilOffenders::find_offenders;
  const int *type = atom->type;
  double **x = atom->x;
  double **normal = avec->wall_normal;
  const double *distance = avec->wall_distance, *h = avec->smoothing_length;
  const double *rho = atom->rho, *rmass = atom->rmass;
  auto position = [&](int i, double *values) {
    for (int a = 0; a < 3; a++) values[a] = x[i][a];
    values[3] = type[i];
  };

  const auto no_plane = find_offenders(
      lmp,
      [&](int i) {
        return type_set[type[i]] && type_wall_kind[type[i]] == WALL_MIRROR &&
            normal[i][0] * normal[i][0] + normal[i][1] * normal[i][1] + normal[i][2] * normal[i][2] == 0.0;
      },
      position);
  if (no_plane)
    error->all(FLERR, "Pair sph/soil: {} wall particle(s) have no wall plane (atom {} of type {} at "
                      "{} {} {}); set it with 'sph_soil/set <group> wall px py pz nx ny nz'",
               no_plane.count, no_plane.first, (int) no_plane.values[3], no_plane.values[0],
               no_plane.values[1], no_plane.values[2]);
  // behind the plane: distance >= 0 (a round-off margin for particles on the plane)
  const auto in_front = find_offenders(
      lmp,
      [&](int i) {
        return type_set[type[i]] && type_wall_kind[type[i]] == WALL_MIRROR && distance[i] < -1.0e-9 * h[i];
      },
      [&](int i, double *values) {
        values[0] = distance[i];
        for (int a = 0; a < 3; a++) values[1 + a] = normal[i][a];
      });
  if (in_front)
    error->all(FLERR, "Pair sph/soil: {} wall particle(s) lie in front of their wall plane (atom "
                      "{}: distance {} along the normal {} {} {}); the normal given to "
                      "'sph_soil/set <group> wall' must point into the soil, with the wall "
                      "particles behind the plane", in_front.count, in_front.first,
               in_front.values[0], in_front.values[1], in_front.values[2], in_front.values[3]);

  // Warnings. Density within 10% of rho0: compression under soil's own weight changes it by
  // p/K, well below 1%. h/d within [0.9, 3], d = (m/rho)^(1/D) the spacing that mass and
  // density give: below, a particle has too few neighbours for SPH (none below 0.5), above,
  // the kernel smears over many spacings; runs use 1.2 to 2.
  if (!warned_density) {
    const auto off = find_offenders(
        lmp,
        [&](int i) {
          return type_set[type[i]] && !type_wall_kind[type[i]] &&
              std::fabs(rho[i] / materials[type[i]].density - 1.0) > 0.1;
        },
        [&](int i, double *values) {
          values[0] = rho[i];
          values[1] = materials[type[i]].density;
        });
    if (off && comm->me == 0)
      error->warning(FLERR, "Pair sph/soil: {} soil particle(s) have a density more than 10% away "
                            "from their material's rho0 (atom {}: {} against {}); is "
                            "'sph_soil/set <group> density' missing?", off.count, off.first,
                     off.values[0], off.values[1]);
    warned_density = true;
  }
  if (!warned_spacing) {
    const double dimension = domain->dimension;
    auto ratio = [&](int i) { return h[i] / SPHSoil::volume_spacing(rmass[i] / rho[i], dimension); };
    const auto off = find_offenders(
        lmp,
        [&](int i) {
          if (!type_set[type[i]]) return false;
          const double r = ratio(i);
          return !(r >= 0.9 && r <= 3.0);
        },
        [&](int i, double *values) {
          values[0] = ratio(i);
          values[1] = h[i];
          values[2] = rmass[i];
          values[3] = rho[i];
        });
    if (off && comm->me == 0)
      error->warning(FLERR, "Pair sph/soil: {} particle(s) have h/d outside [0.9, 3], with d = "
                            "(m/rho)^(1/{}) the spacing that their mass and density give (atom {}: "
                            "h/d = {:.3g} from h {}, m {}, rho {}); usual is 1.2 to 2: check "
                            "'sph_soil/set ... mass ... density ... h'", off.count,
                     domain->dimension, off.first, off.values[0], off.values[1], off.values[2],
                     off.values[3]);
    warned_spacing = true;
  }
}

/* ----------------------------------------------------------------------
   particles at the same place (created twice, or read twice): legal, the sums stay finite
   (the kernel gradient vanishes at r = 0), but most likely a mistake; warned once, at the
   first force evaluation, when the neighbour list exists
------------------------------------------------------------------------- */

void PairSPHSoil::warn_coinciding()
{
  warned_coinciding = true;
  double **x = atom->x;
  const double *h = avec->smoothing_length;
  const tagint *tag = atom->tag;
  bigint pairs = 0;
  int first = -1, partner = -1;
  const int *partners = neighbours.partner_data();
  for (int i = 0; i < atom->nlocal; i++) {
    const double tolerance = 1.0e-6 * h[i];
    for (int jj = neighbours.first(i); jj < neighbours.end(i); jj++) {
      const int j = partners[jj];
      const double dx = x[i][0] - x[j][0], dy = x[i][1] - x[j][1], dz = x[i][2] - x[j][2];
      if (dx * dx + dy * dy + dz * dz >= tolerance * tolerance) continue;
      pairs++;
      if (first < 0 || tag[i] < tag[first]) {
        first = i;
        partner = j;
      }
    }
  }
  const auto at_same_place = SphSoilOffenders::reduce_offenders(
      lmp, pairs, first, [&](int i, double *values) {
        values[0] = tag[partner];
        for (int a = 0; a < 3; a++) values[1 + a] = x[i][a];
      });
  if (at_same_place && comm->me == 0)
    error->warning(FLERR, "Pair sph/soil: {} pair(s) of particles closer than 1e-6 h (atoms {} and "
                          "{} at {} {} {}): particles at the same place, created or read twice?",
                   at_same_place.count, at_same_place.first, (tagint) at_same_place.values[0],
                   at_same_place.values[1], at_same_place.values[2], at_same_place.values[3]);
}

/* ---------------------------------------------------------------------- */

double PairSPHSoil::init_one(int i, int j)
{
  if (setflag[i][j] == 0)
    error->all(FLERR, "All pair coeffs are not set: pair sph/soil needs a material for atom "
                      "types {} and {}", i, j);
  const SoilMaterial &mi = materials[i], &mj = materials[j];
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

/* ---------------------------------------------------------------------- */

double PairSPHSoil::max_wave_speed() const
{
  double c = 0.0;
  for (int type = 1; type < (int) materials.size(); type++)
    if (type_set[type]) c = MAX(c, materials[type].wave_speed());
  return c;
}

/* ----------------------------------------------------------------------
   bytes of the per-atom rows and of the pair list (LAMMPS adds them to its memory report)
------------------------------------------------------------------------- */

double PairSPHSoil::memory_usage()
{
  double bytes = Pair::memory_usage();
  bytes += (double) nmax_packed * (PACKED + SUMS) * sizeof(double);
  bytes += (double) nmax_artificial * ARTIFICIAL * sizeof(double);
  bytes += (double) nmax_extrapolation * (XSUMS + WSTATE) * sizeof(double);
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
  return nullptr;
}

/* ---------------------------------------------------------------------- */

void PairSPHSoil::compute(int eflag, int vflag)
{
  ev_init(eflag, vflag);
  if (walls_may_turn) comm->forward_comm_array(4, atom->mu);
  // LAMMPS has just reneighboured (set-up, or the skin was used up, or atoms were added):
  // owned and ghost atoms are new, and so is our list
  if (neighbor->ago == 0) build_neighbours();
  if (!warned_coinciding) warn_coinciding();
  SPHSoil::with_kernel(kernel, Evaluate{this, domain->dimension, has_artificial_stress});
}

/* ----------------------------------------------------------------------
   per-atom inputs of the pair sums, once per step for owned and ghost atoms,
   packed into one row of PACKED doubles per atom (see the header): a
   neighbour then costs two cache lines instead of a load from each of
   eight arrays; and the accumulators of the sums, set to zero
------------------------------------------------------------------------- */

template <int DIMENSION> void PairSPHSoil::pack_atoms()
{
  const int nall = atom->nlocal + atom->nghost;
  if (nall > nmax_packed) {
    nmax_packed = atom->nmax;
    memory->destroy(packed);
    memory->destroy(sums);
    memory->create(packed, nmax_packed * PACKED, "pair:packed");
    memory->create(sums, nmax_packed * SUMS, "pair:sums");
  }
  double **x = atom->x, **vest = atom->vest, **stress = avec->stress;
  const double *rho = atom->rho, *rmass = atom->rmass, *h = avec->smoothing_length;
  for (int i = 0; i < nall; i++) {
    double *row = packed + (size_t) i * PACKED;
    const double inv_rho = 1.0 / rho[i];
    const double inv_rho2 = inv_rho * inv_rho;
    // soil: fix sph/soil's estimate of v(t + dt); a wall: its velocity (fix sph/soil copies it
    // there after the fixes that move walls have run)
    for (int a = 0; a < 3; a++) {
      row[P_X + a] = x[i][a];
      row[P_V + a] = vest[i][a];
    }
    for (int k = 0; k < 6; k++) row[P_STRESS + k] = stress[i][k] * inv_rho2;
    row[P_VOLUME] = rmass[i] * inv_rho;
    row[P_MASS] = rmass[i];
    row[P_RHO] = rho[i];
    row[P_H] = h[i];
  }
  if (nall > 0) memset(sums, 0, sizeof(double) * SUM_ROW<DIMENSION>() * nall);
}

/* ----------------------------------------------------------------------
   the artificial stress R of every owned and ghost atom (soil_artificial_stress.h), 0 for
   the types without it, and 1 / w(d / h) for the pair's weight (see the header)
------------------------------------------------------------------------- */

template <int DIMENSION, class Kernel> void PairSPHSoil::pack_artificial_stress()
{
  const int nall = atom->nlocal + atom->nghost;
  if (atom->nmax > nmax_artificial) {
    nmax_artificial = atom->nmax;
    memory->destroy(artificial);
    memory->create(artificial, nmax_artificial * ARTIFICIAL, "pair:artificial");
  }
  double **stress = avec->stress;
  const int *type = atom->type;
  const double *rho = atom->rho, *rmass = atom->rmass, *h = avec->smoothing_length;
  for (int i = 0; i < nall; i++) {
    double *row = artificial + (size_t) i * ARTIFICIAL;
    if (type_artificial_stress[type[i]]) {
      SPHSoil::artificial_stress<DIMENSION>(stress[i], rho[i], artificial_stress_epsilon,
                                            row + A_STRESS);
    } else {
      for (int k = 0; k < 6; k++) row[A_STRESS + k] = 0.0;
    }
    const double spacing = SPHSoil::volume_spacing(rmass[i] / rho[i], DIMENSION);
    row[A_INVERSE_SHAPE] = 1.0 / Kernel::shape(spacing / h[i]);
  }
}

/* ----------------------------------------------------------------------
   the sums into the atoms' arrays (owned and ghost: the atom style's reverse
   communication then brings the ghosts' shares to their owners)
------------------------------------------------------------------------- */

template <int DIMENSION> void PairSPHSoil::unpack_sums()
{
  // without Newton's third law for ghost pairs, ghost rows hold shares that their owners
  // compute themselves
  const int n = force->newton_pair ? atom->nlocal + atom->nghost : atom->nlocal;
  double **f = atom->f, **strain_rate = avec->strain_rate, **spin = avec->spin;
  double *drho = atom->drho;
  constexpr int D = DIMENSION;
  for (int i = 0; i < n; i++) {
    const double *sum = sums + (size_t) i * SUM_ROW<D>();
    for (int a = 0; a < D; a++) f[i][a] += sum[S_FORCE + a];
    drho[i] += sum[S_DRHO<D>()];
    // strain rate (Voigt) and spin (xy xz yz): the symmetric and antisymmetric parts
    const double *g = sum + S_GRADIENT<D>();
    for (int a = 0; a < D; a++) strain_rate[i][a] += g[a * D + a];
    for (int a = 0; a < D; a++)
      for (int b = a + 1; b < D; b++) {
        strain_rate[i][SPHSoil::voigt_index(a, b)] += 0.5 * (g[a * D + b] + g[b * D + a]);
        spin[i][a + b - 1] += 0.5 * (g[a * D + b] - g[b * D + a]);
      }
  }
}

/* ----------------------------------------------------------------------
   a pair's separation dx = x_i - x_j, r, h_ij and gradient factor (grad W = factor dx), from
   i's position and h and j's packed row; false beyond the support (the list has a skin)
------------------------------------------------------------------------- */

template <int DIMENSION, class Kernel>
inline bool PairSPHSoil::pair_geometry(const double *xi, double hi, const double *pj,
                                       PairGeometry &g)
{
  g.dx[0] = xi[0] - pj[P_X];
  g.dx[1] = xi[1] - pj[P_X + 1];
  g.dx[2] = DIMENSION == 3 ? xi[2] - pj[P_X + 2] : 0.0;
  g.r2 = g.dx[0] * g.dx[0] + g.dx[1] * g.dx[1] + g.dx[2] * g.dx[2];
  g.hij = 0.5 * (hi + pj[P_H]);
  constexpr double SUPPORT2 = Kernel::SUPPORT * Kernel::SUPPORT;
  if (g.r2 >= SUPPORT2 * g.hij * g.hij) return false;
  // the square root and the two divisions are independent of each other, so that the
  // processor overlaps them; at r = 0 (coinciding particles) q = 0 takes the kernel's inner
  // piece, and 1/max(r^2, DBL_MIN) keeps the unused h/r finite (0) without a branch
  g.r = sqrt(g.r2);
  g.inv_h = 1.0 / g.hij;
  const double inv_r2 = 1.0 / std::max(g.r2, DBL_MIN);
  g.factor = Kernel::template gradient_factor_inside<DIMENSION>(g.r, g.inv_h, g.hij * g.r * inv_r2);
  return true;
}

/* ----------------------------------------------------------------------
   soil particle s and the image of mirror wall particle w (Bui 2008; doc/theory.rst 4.3, 4.4):
   relative to the wall, the image moves with -(d_w/d_s) (v_s - v_w), limited so that
   v_s - v_image = beta (v_s - v_w), beta = min(1.5, 1 + d_w/d_s) (free slip: the normal part
   only), and has the density of s and its stress (no slip), the stress's mirror image (free
   slip) or between the two (friction). s takes its share, w the opposite force (Newton's third
   law: the soil's force on the structure); a wall moved by a fix (move, rigid) brings its
   velocity, a wall at rest has v_w = 0 and the terms of a static wall. `sign` dx = x_s - x_w.
------------------------------------------------------------------------- */

template <int DIMENSION>
SPH_SOIL_NOINLINE void PairSPHSoil::mirror_wall_pair(int soil, int wall, double sign,
                                                     const double dx[3], double r2, double hij,
                                                     double factor, double c_ij)
{
  constexpr int D = DIMENSION;
  const int newton_pair = force->newton_pair, nlocal = atom->nlocal;
  const bool update_soil = newton_pair || soil < nlocal;
  const bool update_wall = newton_pair || wall < nlocal;
  const double *ps = packed + (size_t) soil * PACKED;
  const double *pw = packed + (size_t) wall * PACKED;
  const double *normal = avec->wall_normal[wall];
  const double wall_distance = avec->wall_distance[wall];
  const int wall_type = atom->type[wall];

  // seen from the soil particle: x_s - x_w, and its distance beyond the wall plane
  double separation[3] = {0.0, 0.0, 0.0};
  double ds = -wall_distance;
  for (int a = 0; a < D; a++) {
    separation[a] = sign * dx[a];
    ds += separation[a] * normal[a];
  }
  const double beta = ds > 0.0 ? MIN(1.5, 1.0 + wall_distance / ds) : 1.5;
  // the image's stress: the soil particle's (no slip), its mirror image (free slip: no shear
  // traction), or the mirror image plus the share of the shear that Coulomb's law allows
  // (friction); its velocity: the whole relative velocity while the soil sticks, else the
  // normal part
  const int slip = type_wall_slip[wall_type];
  const double *ss = ps + P_STRESS;
  double stress_sum[6] = {0.0, 0.0, 0.0, 0.0, 0.0, 0.0};
  double share = 1.0;    // of the tangential velocity
  if (slip == SLIP_NONE) {
    for (int a = 0; a < D; a++)
      for (int b = a; b < D; b++)
        stress_sum[SPHSoil::voigt_index(a, b)] = 2.0 * ss[SPHSoil::voigt_index(a, b)];
  } else if (slip == SLIP_FREE) {
    SPHSoil::mirrored_stress_sum(ss, normal, stress_sum);
    share = 0.0;
  } else {
    share = SPHSoil::frictional_stress_sum(ss, normal, type_wall_friction[wall_type], stress_sum);
  }
  double relative[3], vn = 0.0;
  for (int a = 0; a < D; a++) {
    relative[a] = beta * (ps[P_V + a] - pw[P_V + a]);
    vn += relative[a] * normal[a];
  }
  double dv[3] = {0.0, 0.0, 0.0}, approach = 0.0;
  for (int a = 0; a < D; a++) {
    dv[a] = share == 1.0 ? relative[a] : vn * normal[a];
    approach += dv[a] * separation[a];
  }
  // friction: the artificial viscosity sees only the normal approach, so that the traction
  // across the wall stays the Coulomb-limited one (with the sticking velocity it would add a
  // viscous drag that mu does not bound: a rough gate lifted at 1 m/s got 6 times the at-rest
  // force in its first step)
  double viscous_approach = approach;
  if (slip == SLIP_FRICTION) {
    double normal_distance = 0.0;
    for (int a = 0; a < D; a++) normal_distance += separation[a] * normal[a];
    viscous_approach = vn * normal_distance;
  }
  const double rhos = ps[P_RHO];
  const double viscosity_h =
      SPHSoil::viscosity_length(viscosity_h0, SPHSoil::viscosity_h_weight(viscosity_h0), hij);
  SPHSoil::PairTerms<D> terms;
  SPHSoil::pair_terms<D>(separation, r2, hij, viscosity_h, factor, dv, approach, viscous_approach,
                         stress_sum, rhos, c_ij, viscosity_alpha, viscosity_beta, terms);

  const double mw = pw[P_MASS], mass_product = ps[P_MASS] * mw;
  if (update_wall) {
    double *ow = sums + (size_t) wall * SUM_ROW<D>();
    for (int a = 0; a < D; a++) ow[S_FORCE + a] -= mass_product * terms.force[a];
  }
  if (!update_soil) return;
  double *os = sums + (size_t) soil * SUM_ROW<D>();
  os[S_DRHO<D>()] += mw * terms.density_rate;
  for (int a = 0; a < D; a++) os[S_FORCE + a] += mass_product * terms.force[a];
  // the image's volume: the wall particle's mass at the soil's density
  const double volume = mw / rhos;
  for (int c = 0; c < D; c++)
    for (int d = 0; d < D; d++) os[S_GRADIENT<D>() + c * D + d] += volume * terms.gradient[c][d];
}

/* ----------------------------------------------------------------------
   the SPH sums of doc/theory.rst section 2 over a half neighbour list: every pair once,
   its contributions to both particles (Newton's third law: momentum is
   conserved exactly); ghosts' shares return to their owners by reverse
   communication (the atom style carries drho, strain rate and spin back)
------------------------------------------------------------------------- */

template <int DIMENSION, class Kernel, bool ARTIFICIAL_STRESS> void PairSPHSoil::eval()
{
  using SPHSoil::voigt_index;
  constexpr int D = DIMENSION;
  const int *type = atom->type;
  const int nlocal = atom->nlocal;
  // members as locals: the stores to the sums (double *) could otherwise alias the double
  // members, which the compiler would then reload for every pair
  const double alpha = viscosity_alpha, beta_viscosity = viscosity_beta, h0 = viscosity_h0;
  const double h0_weight = SPHSoil::viscosity_h_weight(viscosity_h0);
  double *const *const c_type = sound_speed_ij;
  const int *const wall_kind = type_wall_kind.data();

  pack_atoms<D>();    // (re)allocates the packed rows: take their addresses after it
  if (has_extrapolated_walls) extrapolate_to_walls<D, Kernel>();
  if (ARTIFICIAL_STRESS) pack_artificial_stress<D, Kernel>();
  const int *const artificial_type = type_artificial_stress.data();
  const double *const in = packed;
  double *const out = sums;
  constexpr int ROW = SUM_ROW<D>();
  constexpr int DRHO = S_DRHO<D>(), GRADIENT = S_GRADIENT<D>();
  const int *const partners = neighbours.partner_data();

  for (int i = 0; i < nlocal; i++) {
    const int itype = type[i];
    // i's inputs as local copies: the stores to j's sums (double *) could alias the packed
    // rows, and the compiler would reload them for every pair
    const double *pi = in + (size_t) i * PACKED;
    double xi[3], vi[3], si[6];
    for (int a = 0; a < 3; a++) {
      xi[a] = pi[P_X + a];
      vi[a] = pi[P_V + a];
    }
    for (int k = 0; k < 6; k++) si[k] = pi[P_STRESS + k];
    const double hi = pi[P_H];
    const double mi = pi[P_MASS], rhoi = pi[P_RHO], volume_i = pi[P_VOLUME];
    const double *c_i = c_type[itype];

    // i's shares, accumulated here and stored once after the j loop
    double drho_i = 0.0, force_i[D], gradient_i[D][D];
    for (int a = 0; a < D; a++) {
      force_i[a] = 0.0;
      for (int b = 0; b < D; b++) gradient_i[a][b] = 0.0;
    }

    // the plain pairs: soil-soil, or soil and an extrapolated wall particle (a partner like a
    // soil particle, with the soil's state extrapolated to it; its own rates are summed and
    // never used). Seen from i: grad = dW/dx_i; j gets the same terms with the opposite force
    // and dW/dx_j = -grad (Newton's third law). Without Newton's third law for ghost pairs,
    // a ghost j's row is written and never read (unpack_sums()).
    const int plain_end = neighbours.plain_end(i);
    for (int jj = neighbours.first(i); jj < plain_end; jj++) {
      const int j = partners[jj];
      const double *pj = in + (size_t) j * PACKED;
      PairGeometry g;
      if (!pair_geometry<D, Kernel>(xi, hi, pj, g)) continue;
      const int jtype = type[j];
      const double *sj = pj + P_STRESS;
      double dv[3], stress_sum[6];
      for (int a = 0; a < D; a++) {
        dv[a] = vi[a] - pj[P_V + a];
        for (int b = a; b < D; b++) {
          const int k = voigt_index(a, b);
          stress_sum[k] = si[k] + sj[k];
        }
      }
      if (ARTIFICIAL_STRESS && (artificial_type[itype] || artificial_type[jtype])) {
        // (R_i + R_j) (W(r) / W(spacing))^4
        const double *ai = artificial + (size_t) i * ARTIFICIAL;
        const double *aj = artificial + (size_t) j * ARTIFICIAL;
        const double weight = SPHSoil::artificial_stress_weight(
            Kernel::shape(g.r * g.inv_h) * 0.5 * (ai[A_INVERSE_SHAPE] + aj[A_INVERSE_SHAPE]));
        for (int a = 0; a < D; a++)
          for (int b = a; b < D; b++) {
            const int k = voigt_index(a, b);
            stress_sum[k] += weight * (ai[A_STRESS + k] + aj[A_STRESS + k]);
          }
      }
      double approach = 0.0;
      for (int a = 0; a < D; a++) approach += dv[a] * g.dx[a];
      SPHSoil::PairTerms<D> terms;
      const double viscosity_h = SPHSoil::viscosity_length(h0, h0_weight, g.hij);
      SPHSoil::pair_terms<D>(g.dx, g.r2, g.hij, viscosity_h, g.factor, dv, approach, approach,
                             stress_sum, 0.5 * (rhoi + pj[P_RHO]), c_i[jtype], alpha,
                             beta_viscosity, terms);

      const double mj = pj[P_MASS], volume_j = pj[P_VOLUME], mass_product = mi * mj;
      double *oj = out + (size_t) j * ROW;
      drho_i += mj * terms.density_rate;
      oj[DRHO] += mi * terms.density_rate;
      for (int a = 0; a < D; a++) {
        const double force = mass_product * terms.force[a];
        force_i[a] += force;
        oj[S_FORCE + a] -= force;
      }
      // g_i += V_j (v_j - v_i) x grad, and g_j += V_i (v_i - v_j) x (-grad): the same tensor
      for (int c = 0; c < D; c++)
        for (int d = 0; d < D; d++) {
          gradient_i[c][d] += volume_j * terms.gradient[c][d];
          oj[GRADIENT + c * D + d] += volume_i * terms.gradient[c][d];
        }
    }

    double *oi = out + (size_t) i * ROW;
    oi[DRHO] += drho_i;
    for (int a = 0; a < D; a++) oi[S_FORCE + a] += force_i[a];
    for (int c = 0; c < D; c++)
      for (int d = 0; d < D; d++) oi[GRADIENT + c * D + d] += gradient_i[c][d];

    // a soil particle and a mirror wall particle: out of line, so that the plain pair above
    // keeps its registers (inlined, the larger loop cost 15 instructions per pair)
    const bool wall_i = wall_kind[itype] == WALL_MIRROR;
    for (int jj = plain_end; jj < neighbours.end(i); jj++) {
      const int j = partners[jj];
      PairGeometry g;
      if (!pair_geometry<D, Kernel>(xi, hi, in + (size_t) j * PACKED, g)) continue;
      mirror_wall_pair<D>(wall_i ? j : i, wall_i ? i : j, wall_i ? -1.0 : 1.0, g.dx, g.r2, g.hij,
                          g.factor, c_i[type[j]]);
    }
  }

  unpack_sums<D>();
}

/* ----------------------------------------------------------------------
   walls with boundary extrapolate (Adami, Hu & Adams 2012, with the full stress; doc/theory.rst
   4.5): a wall particle w takes the soil's stress, density and velocity, interpolated to it
   with the kernel (Shepard: weights V_s W_ws over the soil particles s within its support),
     sigma_w = sum V W sigma_s / sum V W - (g - a_w) . sum V W rho_s (x_w - x_s) / sum V W  I
   (the weight of the soil between s and w, for soil under gravity g against a wall of
   acceleration a_w), and moves, as an image of the soil, with 2 v_w - v~ (no slip). The pair
   loop then treats it as a soil particle of that state. Its packed row is overwritten here.
------------------------------------------------------------------------- */

template <int DIMENSION, class Kernel> void PairSPHSoil::extrapolate_to_walls()
{
  const int nlocal = atom->nlocal, nall = nlocal + atom->nghost;
  if (atom->nmax > nmax_extrapolation) {
    nmax_extrapolation = atom->nmax;
    memory->destroy(extrapolation_sums);
    memory->destroy(extrapolated_state);
    memory->create(extrapolation_sums, nmax_extrapolation * XSUMS, "pair:extrapolation_sums");
    memory->create(extrapolated_state, nmax_extrapolation * WSTATE, "pair:extrapolated_state");
  }
  if (nall > 0) memset(extrapolation_sums, 0, sizeof(double) * XSUMS * nall);
  const int *type = atom->type;
  const int *wall_kind = type_wall_kind.data();
  const int newton_pair = force->newton_pair;
  double **stress = avec->stress;
  constexpr double SUPPORT2 = Kernel::SUPPORT * Kernel::SUPPORT;

  const int *partners = neighbours.partner_data();
  for (int i = 0; i < nlocal; i++) {
    const int wall_i = wall_kind[type[i]];
    for (int jj = neighbours.first(i); jj < neighbours.plain_end(i); jj++) {
      const int j = partners[jj];
      const int wall_j = wall_kind[type[j]];
      // a soil particle and an extrapolated wall particle
      if (!((wall_i == WALL_EXTRAPOLATE && wall_j == SOIL) ||
            (wall_i == SOIL && wall_j == WALL_EXTRAPOLATE)))
        continue;
      const int wall = wall_i ? i : j, soil = wall_i ? j : i;
      if (!newton_pair && wall >= nlocal) continue;
      const double *ps = packed + (size_t) soil * PACKED, *pw = packed + (size_t) wall * PACKED;
      double r2 = 0.0, rw[3] = {0.0, 0.0, 0.0};
      for (int a = 0; a < DIMENSION; a++) {
        rw[a] = pw[P_X + a] - ps[P_X + a];
        r2 += rw[a] * rw[a];
      }
      const double hij = 0.5 * (ps[P_H] + pw[P_H]);
      if (r2 >= SUPPORT2 * hij * hij) continue;
      const double weight = ps[P_VOLUME] * Kernel::value(DIMENSION, sqrt(r2), hij);
      double *sum = extrapolation_sums + (size_t) wall * XSUMS;
      sum[X_WEIGHT] += weight;
      for (int k = 0; k < 6; k++) sum[X_STRESS + k] += weight * stress[soil][k];
      sum[X_DENSITY] += weight * ps[P_RHO];
      for (int a = 0; a < DIMENSION; a++) {
        sum[X_HYDROSTATIC + a] += weight * ps[P_RHO] * rw[a];
        sum[X_VELOCITY + a] += weight * ps[P_V + a];
      }
    }
  }
  if (newton_pair) SphSoilCompat::reverse_comm_pair(comm, this);

  // the soil's body force: the gravity fixes' acceleration vectors
  double gravity[3] = {0.0, 0.0, 0.0};
  for (Fix *fix : gravity_fixes) {
    int dim;
    if (const double *g = static_cast<const double *>(fix->extract("gvec", dim)))
      for (int a = 0; a < 3; a++) gravity[a] += g[a];
  }
  const double *rho = atom->rho;
  for (int i = 0; i < nlocal; i++) {
    if (wall_kind[type[i]] != WALL_EXTRAPOLATE) continue;
    const double *sum = extrapolation_sums + (size_t) i * XSUMS;
    const double *vw = packed + (size_t) i * PACKED + P_V;
    double *state = extrapolated_state + (size_t) i * WSTATE;
    if (!(sum[X_WEIGHT] > 0.0)) {
      // no soil near: the wall particle is nobody's partner
      for (int k = 0; k < 6; k++) state[W_STRESS + k] = 0.0;
      for (int a = 0; a < 3; a++) state[W_VELOCITY + a] = vw[a];
      state[W_DENSITY] = rho[i];
      continue;
    }
    const double inv_weight = 1.0 / sum[X_WEIGHT];
    const double *acceleration = integrator ? integrator->wall_acceleration(i) : nullptr;
    double hydrostatic = 0.0;
    for (int a = 0; a < DIMENSION; a++)
      hydrostatic += (gravity[a] - (acceleration ? acceleration[a] : 0.0)) * sum[X_HYDROSTATIC + a];
    hydrostatic *= inv_weight;
    const double density = sum[X_DENSITY] * inv_weight;
    const double inv_density2 = 1.0 / (density * density);
    for (int k = 0; k < 6; k++)
      state[W_STRESS + k] = (sum[X_STRESS + k] * inv_weight - (k < 3 ? hydrostatic : 0.0)) * inv_density2;
    for (int a = 0; a < 3; a++)
      state[W_VELOCITY + a] = 2.0 * vw[a] - (a < DIMENSION ? sum[X_VELOCITY + a] * inv_weight : vw[a]);
    state[W_DENSITY] = density;
  }
  SphSoilCompat::forward_comm_pair(comm, this);

  for (int i = 0; i < nall; i++) {
    if (wall_kind[type[i]] != WALL_EXTRAPOLATE) continue;
    const double *state = extrapolated_state + (size_t) i * WSTATE;
    double *row = packed + (size_t) i * PACKED;
    for (int k = 0; k < 6; k++) row[P_STRESS + k] = state[W_STRESS + k];
    for (int a = 0; a < 3; a++) row[P_V + a] = state[W_VELOCITY + a];
    row[P_RHO] = state[W_DENSITY];
    row[P_VOLUME] = row[P_MASS] / state[W_DENSITY];
  }
}

/* ---------------------------------------------------------------------- */

int PairSPHSoil::pack_reverse_comm(int n, int first, double *buf)
{
  int m = 0;
  for (int i = first; i < first + n; i++)
    for (int k = 0; k < XSUMS; k++) buf[m++] = extrapolation_sums[(size_t) i * XSUMS + k];
  return m;
}

void PairSPHSoil::unpack_reverse_comm(int n, int *list, double *buf)
{
  int m = 0;
  for (int k = 0; k < n; k++)
    for (int c = 0; c < XSUMS; c++) extrapolation_sums[(size_t) list[k] * XSUMS + c] += buf[m++];
}

int PairSPHSoil::pack_forward_comm(int n, int *list, double *buf, int /*pbc_flag*/, int * /*pbc*/)
{
  int m = 0;
  for (int k = 0; k < n; k++)
    for (int c = 0; c < WSTATE; c++) buf[m++] = extrapolated_state[(size_t) list[k] * WSTATE + c];
  return m;
}

void PairSPHSoil::unpack_forward_comm(int n, int first, double *buf)
{
  int m = 0;
  for (int i = first; i < first + n; i++)
    for (int c = 0; c < WSTATE; c++) extrapolated_state[(size_t) i * WSTATE + c] = buf[m++];
}

template void PairSPHSoil::eval<2, SPHSoil::CubicSpline, false>();
template void PairSPHSoil::eval<3, SPHSoil::CubicSpline, false>();
template void PairSPHSoil::eval<2, SPHSoil::WendlandC2, false>();
template void PairSPHSoil::eval<3, SPHSoil::WendlandC2, false>();
template void PairSPHSoil::eval<2, SPHSoil::CubicSpline, true>();
template void PairSPHSoil::eval<3, SPHSoil::CubicSpline, true>();
template void PairSPHSoil::eval<2, SPHSoil::WendlandC2, true>();
template void PairSPHSoil::eval<3, SPHSoil::WendlandC2, true>();
