/* ----------------------------------------------------------------------
   SPH_SOIL package for LAMMPS: pair_style sph/soil
------------------------------------------------------------------------- */

#include "pair_sph_soil.h"

#include "atom.h"
#include "atom_vec_sph_soil.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "force.h"
#include "memory.h"
#include "neigh_list.h"
#include "neighbor.h"
#include "soil_kernel.h"
#include "sph_soil_compat.h"
#include "utils.h"

#include <cmath>
#include <cstdlib>
#include <cstring>

using namespace LAMMPS_NS;
using SPHSoil::CubicSpline;
using SPHSoil::SoilMaterial;

/* ---------------------------------------------------------------------- */

PairSPHSoil::PairSPHSoil(LAMMPS *lmp) :
    Pair(lmp), viscosity_alpha(0.1), viscosity_beta(0.1), free_slip(false),
    sound_speed_ij(nullptr), max_h(0.0), avec(nullptr)
{
  single_enable = 0;
  restartinfo = 0;
  one_coeff = 0;
  manybody_flag = 0;
  no_virial_fdotr_compute = 1;
}

/* ---------------------------------------------------------------------- */

PairSPHSoil::~PairSPHSoil()
{
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
   pair_style sph/soil [alpha A] [beta B] [wall noslip|freeslip]
------------------------------------------------------------------------- */

void PairSPHSoil::settings(int narg, char **arg)
{
  for (int iarg = 0; iarg < narg; iarg += 2) {
    if (iarg + 1 >= narg)
      error->all(FLERR, "Illegal pair_style sph/soil command: keyword {} needs a value", arg[iarg]);
    if (strcmp(arg[iarg], "alpha") == 0) {
      viscosity_alpha = utils::numeric(FLERR, arg[iarg + 1], false, lmp);
      if (viscosity_alpha < 0.0)
        error->all(FLERR, "Illegal pair_style sph/soil alpha {}: must be >= 0", viscosity_alpha);
    } else if (strcmp(arg[iarg], "beta") == 0) {
      viscosity_beta = utils::numeric(FLERR, arg[iarg + 1], false, lmp);
      if (viscosity_beta < 0.0)
        error->all(FLERR, "Illegal pair_style sph/soil beta {}: must be >= 0", viscosity_beta);
    } else if (strcmp(arg[iarg], "wall") == 0) {
      if (strcmp(arg[iarg + 1], "noslip") == 0) free_slip = false;
      else if (strcmp(arg[iarg + 1], "freeslip") == 0) free_slip = true;
      else
        error->all(FLERR, "Illegal pair_style sph/soil wall {}: must be noslip or freeslip",
                   arg[iarg + 1]);
    } else {
      error->all(FLERR, "Illegal pair_style sph/soil keyword {} (allowed: alpha, beta, wall)",
                 arg[iarg]);
    }
  }
}

/* ----------------------------------------------------------------------
   pair_coeff * * file.soil name1 ... nameN     (NULL: type not handled)
   pair_coeff I I soil rho0 K nu phi psi c
   pair_coeff I I wall
------------------------------------------------------------------------- */

void PairSPHSoil::coeff(int narg, char **arg)
{
  if (!allocated) allocate();
  const int ntypes = atom->ntypes;
  if (narg < 3)
    error->all(FLERR, "Incorrect args for pair_coeff sph/soil: expected 'I I soil rho0 K nu phi "
                      "psi c', 'I I wall' or '* * file name1 ... name{}'", ntypes);

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
    error->all(FLERR, "Incorrect args for pair_coeff sph/soil: a material file needs '* *'");
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
  double local_max = 0.0;
  tagint bad = MAXTAGINT;
  for (int i = 0; i < nlocal; i++) {
    if (!type_set[type[i]]) continue;
    const double h = avec->smoothing_length[i];
    if (!(h > 0.0)) bad = MIN(bad, atom->tag[i]);
    local_max = MAX(local_max, h);
  }
  tagint firstbad;
  MPI_Allreduce(&bad, &firstbad, 1, MPI_LMP_TAGINT, MPI_MIN, world);
  if (firstbad != MAXTAGINT)
    error->all(FLERR, "Pair sph/soil: atom {} has smoothing length h <= 0; set it with "
                      "'sph_soil/set <group> h <value>'", firstbad);
  MPI_Allreduce(&local_max, &max_h, 1, MPI_DOUBLE, MPI_MAX, world);
  if (max_h <= 0.0) error->all(FLERR, "Pair sph/soil: no particle with a material and h > 0");

  // every type has a material here (init_one stops otherwise): a plain flag for the pair loop
  type_is_wall.assign(atom->ntypes + 1, 0);
  for (int t = 1; t <= atom->ntypes; t++) type_is_wall[t] = materials[t].wall ? 1 : 0;

  // one constitutive model per soil type, built from its material (the factory decides which)
  models.clear();
  models.resize(atom->ntypes + 1);
  for (int t = 1; t <= atom->ntypes; t++)
    if (type_set[t] && !materials[t].wall) models[t] = SPHSoil::make_constitutive_model(materials[t]);

  SphSoilCompat::request_full_neighbor_list(neighbor, this, false, instance_me);
}

/* ---------------------------------------------------------------------- */

double PairSPHSoil::init_one(int i, int j)
{
  if (setflag[i][j] == 0)
    error->all(FLERR, "All pair coeffs are not set: pair sph/soil needs a material for atom "
                      "types {} and {}", i, j);
  const SoilMaterial &mi = materials[i], &mj = materials[j];
  if (mi.wall && mj.wall) {
    // wall particles never interact with each other: only within the skin
    sound_speed_ij[i][j] = sound_speed_ij[j][i] = 0.0;
    return 0.0;
  }
  const double ci = mi.wall ? mj.wave_speed() : mi.wave_speed();
  const double cj = mj.wall ? mi.wave_speed() : mj.wave_speed();
  sound_speed_ij[i][j] = sound_speed_ij[j][i] = 0.5 * (ci + cj);
  return CubicSpline::SUPPORT * max_h;
}

/* ---------------------------------------------------------------------- */

double PairSPHSoil::max_wave_speed() const
{
  double c = 0.0;
  for (int type = 1; type < (int) materials.size(); type++)
    if (type_set[type]) c = MAX(c, materials[type].wave_speed());
  return c;
}

/* ---------------------------------------------------------------------- */

void *PairSPHSoil::extract(const char *name, int &dim)
{
  dim = 0;
  if (strcmp(name, "viscosity_alpha") == 0) return (void *) &viscosity_alpha;
  if (strcmp(name, "viscosity_beta") == 0) return (void *) &viscosity_beta;
  return nullptr;
}

/* ---------------------------------------------------------------------- */

void PairSPHSoil::compute(int eflag, int vflag)
{
  ev_init(eflag, vflag);
  if (domain->dimension == 2) eval<2>();
  else eval<3>();
}

/* ----------------------------------------------------------------------
   the SPH sums of SPEC section 2 for every local soil particle i
   (full list: each particle sums over all its neighbours itself)
------------------------------------------------------------------------- */

template <int DIMENSION> void PairSPHSoil::eval()
{
  double **x = atom->x;
  double **f = atom->f;
  double **vest = atom->vest;
  const double *rho = atom->rho;
  double *drho = atom->drho;
  const double *rmass = atom->rmass;
  const int *type = atom->type;
  const double *h = avec->smoothing_length;
  double **stress = avec->stress;
  double **strain_rate = avec->strain_rate;
  double **spin = avec->spin;
  double **wall_normal = avec->wall_normal;
  const double *wall_distance = avec->wall_distance;

  const int inum = list->inum;
  const int *ilist = list->ilist;
  const int *numneigh = list->numneigh;
  int **firstneigh = list->firstneigh;

  // Voigt index of tensor component (a, b)
  static const int voigt[3][3] = {{0, 3, 4}, {3, 1, 5}, {4, 5, 2}};

  for (int ii = 0; ii < inum; ii++) {
    const int i = ilist[ii];
    const int itype = type[i];
    if (type_is_wall[itype]) continue;

    const double *xi = x[i];
    const double *vi = vest[i];
    const double rhoi = rho[i];
    const double hi = h[i];
    double stress_i[6];    // sigma_i / rho_i^2
    const double inv_rho2_i = 1.0 / (rhoi * rhoi);
    for (int k = 0; k < 6; k++) stress_i[k] = stress[i][k] * inv_rho2_i;

    double density_rate = 0.0;
    double acceleration[3] = {0.0, 0.0, 0.0};
    double gradient[3][3] = {{0.0, 0.0, 0.0}, {0.0, 0.0, 0.0}, {0.0, 0.0, 0.0}};    // dv^a/dx^b

    const int *jlist = firstneigh[i];
    const int jnum = numneigh[i];
    for (int jj = 0; jj < jnum; jj++) {
      const int j = jlist[jj] & NEIGHMASK;
      double dx[3] = {xi[0] - x[j][0], xi[1] - x[j][1], DIMENSION == 3 ? xi[2] - x[j][2] : 0.0};
      const double r2 = dx[0] * dx[0] + dx[1] * dx[1] + dx[2] * dx[2];
      const double hij = 0.5 * (hi + h[j]);
      if (r2 >= 4.0 * hij * hij) continue;
      const int jtype = type[j];

      const double r = sqrt(r2);
      const double factor = CubicSpline::gradient_factor(DIMENSION, r, hij);
      double gradW[3];
      for (int a = 0; a < DIMENSION; a++) gradW[a] = factor * dx[a];

      const double mj = rmass[j];
      double vij[3];
      double rhoj;
      const double *stress_j;    // sigma_j / rho_j^2
      double stress_j_storage[6];
      if (type_is_wall[jtype]) {
        // Bui 2008: the wall particle b moves with -(d_b/d_a) v_a, limited so that
        // v_a - v_b = beta v_a, beta = min(1.5, 1 + d_b/d_a); it takes a's stress and density
        const double *n = wall_normal[j];
        double da = -wall_distance[j];
        for (int a = 0; a < DIMENSION; a++) da += dx[a] * n[a];
        const double beta = da > 0.0 ? MIN(1.5, 1.0 + wall_distance[j] / da) : 1.5;
        if (free_slip) {
          double vn = 0.0;
          for (int a = 0; a < DIMENSION; a++) vn += vi[a] * n[a];
          for (int a = 0; a < 3; a++) vij[a] = beta * vn * n[a];
        } else {
          for (int a = 0; a < 3; a++) vij[a] = beta * vi[a];
        }
        rhoj = rhoi;
        stress_j = stress_i;
      } else {
        for (int a = 0; a < 3; a++) vij[a] = vi[a] - vest[j][a];
        rhoj = rho[j];
        const double inv_rho2_j = 1.0 / (rhoj * rhoj);
        for (int k = 0; k < 6; k++) stress_j_storage[k] = stress[j][k] * inv_rho2_j;
        stress_j = stress_j_storage;
      }

      double vdotgrad = 0.0, vdotx = 0.0;
      for (int a = 0; a < DIMENSION; a++) {
        vdotgrad += vij[a] * gradW[a];
        vdotx += vij[a] * dx[a];
      }
      density_rate += mj * vdotgrad;

      // Monaghan artificial viscosity, only for approaching pairs
      double viscosity = 0.0;
      if (vdotx < 0.0) {
        const double mu = hij * vdotx / (r2 + 0.01 * hij * hij);
        viscosity = (-viscosity_alpha * sound_speed_ij[itype][jtype] * mu +
                     viscosity_beta * mu * mu) / (0.5 * (rhoi + rhoj));
      }

      for (int a = 0; a < DIMENSION; a++) {
        double sum = -viscosity * gradW[a];
        for (int b = 0; b < DIMENSION; b++) {
          const int k = voigt[a][b];
          sum += (stress_i[k] + stress_j[k]) * gradW[b];
        }
        acceleration[a] += mj * sum;
      }

      // velocity gradient g^ab = sum (m_j/rho_j) (v_j^a - v_i^a) dW/dx_i^b
      const double volume = mj / rhoj;
      for (int a = 0; a < DIMENSION; a++)
        for (int b = 0; b < DIMENSION; b++) gradient[a][b] -= volume * vij[a] * gradW[b];
    }

    drho[i] += density_rate;
    const double mi = rmass[i];
    for (int a = 0; a < DIMENSION; a++) f[i][a] += mi * acceleration[a];
    strain_rate[i][0] = gradient[0][0];
    strain_rate[i][1] = gradient[1][1];
    strain_rate[i][2] = gradient[2][2];
    strain_rate[i][3] = 0.5 * (gradient[0][1] + gradient[1][0]);
    strain_rate[i][4] = 0.5 * (gradient[0][2] + gradient[2][0]);
    strain_rate[i][5] = 0.5 * (gradient[1][2] + gradient[2][1]);
    spin[i][0] = 0.5 * (gradient[0][1] - gradient[1][0]);
    spin[i][1] = 0.5 * (gradient[0][2] - gradient[2][0]);
    spin[i][2] = 0.5 * (gradient[1][2] - gradient[2][1]);
  }
}

template void PairSPHSoil::eval<2>();
template void PairSPHSoil::eval<3>();
