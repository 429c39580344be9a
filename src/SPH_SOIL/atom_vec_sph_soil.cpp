/* ----------------------------------------------------------------------
   SPH_SOIL package for LAMMPS: atom_style sph/soil
------------------------------------------------------------------------- */

#include "atom_vec_sph_soil.h"

#include "atom.h"
#include "error.h"
#include "utils.h"
#include "soil_refine_split.h"
#include "sph_soil_compat.h"

#include <cmath>
#include <cstring>
#include <map>
#include <memory>
#include <mutex>

using namespace LAMMPS_NS;

namespace {

// Names under which our own arrays are registered in Atom's per-atom table. They carry a
// prefix so that they cannot collide with another style's fields under atom_style hybrid.
const char *const H_NAME = "sph_soil_h";
const char *const STRESS_NAME = "sph_soil_stress";
const char *const STRESS_RATE_NAME = "sph_soil_stress_rate";
const char *const STRAIN_NAME = "sph_soil_strain";
const char *const STRAIN_RATE_NAME = "sph_soil_strain_rate";
const char *const SPIN_NAME = "sph_soil_spin";
const char *const LEVEL_NAME = "sph_soil_level";
const char *const WALL_DISTANCE_NAME = "sph_soil_wall_distance";
const char *const SAVED_RATES_NAME = "sph_soil_saved_rates";
const char *const PORE_PRESSURE_NAME = "sph_soil_pore_pressure";
const char *const PORE_FLOW_NAME = "sph_soil_pore_flow";

// What compute property/atom can read: name, array, column (-1 for a vector).
enum Field { H, RHO, DRHO, STRESS, STRESS_RATE, STRAIN, STRAIN_RATE, SPIN, LEVEL, WALL_N, WALL_D, VEST,
             PORE_PRESSURE, PORE_FLOW };
struct Property {
  const char *name;
  Field field;
  int col;
};
const Property properties[] = {
    {"h", H, -1},          {"rho", RHO, -1},         {"drho", DRHO, -1},
    {"sxx", STRESS, 0},    {"syy", STRESS, 1},       {"szz", STRESS, 2},
    {"sxy", STRESS, 3},    {"sxz", STRESS, 4},       {"syz", STRESS, 5},
    {"dsxx", STRESS_RATE, 0}, {"dsyy", STRESS_RATE, 1}, {"dszz", STRESS_RATE, 2},
    {"dsxy", STRESS_RATE, 3}, {"dsxz", STRESS_RATE, 4}, {"dsyz", STRESS_RATE, 5},
    {"exx", STRAIN, 0},    {"eyy", STRAIN, 1},       {"ezz", STRAIN, 2},
    {"exy", STRAIN, 3},    {"exz", STRAIN, 4},       {"eyz", STRAIN, 5},
    {"edotxx", STRAIN_RATE, 0}, {"edotyy", STRAIN_RATE, 1}, {"edotzz", STRAIN_RATE, 2},
    {"edotxy", STRAIN_RATE, 3}, {"edotxz", STRAIN_RATE, 4}, {"edotyz", STRAIN_RATE, 5},
    {"wxy", SPIN, 0},      {"wxz", SPIN, 1},         {"wyz", SPIN, 2},
    {"level", LEVEL, -1},
    {"wall_nx", WALL_N, 0}, {"wall_ny", WALL_N, 1},  {"wall_nz", WALL_N, 2},
    {"wall_d", WALL_D, -1},
    {"vestx", VEST, 0},    {"vesty", VEST, 1},       {"vestz", VEST, 2},
    {"pore_pressure", PORE_PRESSURE, -1}, {"pore_flow", PORE_FLOW, -1},
};
constexpr int NPROPERTIES = sizeof(properties) / sizeof(properties[0]);

// LAMMPS finds a per-atom array of an atom style through the address of its pointer, and the
// base AtomVec destroys the arrays through these addresses. Under atom_style hybrid the hybrid
// style does so only after it has deleted its sub-styles: pointers that were members of this
// style would then be read from freed memory. They live in a block per Atom instead, which
// outlives the style; the block is replaced (and the old one freed) when that Atom gets a new
// sph/soil style, by which time the previous style and its hybrid are gone, and freed at exit.
std::mutex arrays_mutex;
std::map<const Atom *, std::unique_ptr<AtomVecSPHSoil::Arrays>> arrays_by_atom;

AtomVecSPHSoil::Arrays *arrays_of(const Atom *atom)
{
  std::lock_guard<std::mutex> lock(arrays_mutex);
  auto &block = arrays_by_atom[atom];
  block.reset(new AtomVecSPHSoil::Arrays());
  return block.get();
}

}    // namespace

// (a definition for C++11, where LAMMPS 29Sep2021 compiles: the value is passed by reference)
constexpr int AtomVecSPHSoil::RESTART_FORMAT;

/* ---------------------------------------------------------------------- */

AtomVecSPHSoil::AtomVecSPHSoil(LAMMPS *lmp) :
    AtomVec(lmp), smoothing_length(nullptr), stress(nullptr), stress_rate(nullptr),
    total_strain(nullptr), strain_rate(nullptr), spin(nullptr), level(nullptr),
    wall_normal(nullptr), wall_distance(nullptr), saved_rates(nullptr), pore_pressure(nullptr), pore_flow(nullptr), rmass(nullptr), rho(nullptr), drho(nullptr),
    vest(nullptr), arrays(arrays_of(atom))
{
  molecular = Atom::ATOMIC;
  mass_type = PER_ATOM;
  forceclearflag = 1;

  atom->rmass_flag = 1;
  atom->rho_flag = 1;
  atom->vest_flag = 1;
  // a wall particle's normal is its dipole orientation mu (unit length, mu[3] = 1; 0 for soil):
  // the fixes that turn orientations with their atoms (fix rigid, fix rigid/small, fix move
  // rotate/transrot with 'update dipole') then turn the normal with the wall
  atom->mu_flag = 1;

  // read_restart and a second atom_style command re-create the AtomVec: an entry of the
  // previous instance then follows the new arrays
  using SPHSoilCompat::set_peratom;
  set_peratom(atom, H_NAME, &arrays->smoothing_length, Atom::DOUBLE, 0);
  set_peratom(atom, STRESS_NAME, &arrays->stress, Atom::DOUBLE, NVOIGT);
  set_peratom(atom, STRESS_RATE_NAME, &arrays->stress_rate, Atom::DOUBLE, NVOIGT);
  set_peratom(atom, STRAIN_NAME, &arrays->total_strain, Atom::DOUBLE, NVOIGT);
  set_peratom(atom, STRAIN_RATE_NAME, &arrays->strain_rate, Atom::DOUBLE, NVOIGT);
  set_peratom(atom, SPIN_NAME, &arrays->spin, Atom::DOUBLE, NSPIN);
  set_peratom(atom, LEVEL_NAME, &arrays->level, Atom::INT, 0);
  set_peratom(atom, WALL_DISTANCE_NAME, &arrays->wall_distance, Atom::DOUBLE, 0);
  set_peratom(atom, SAVED_RATES_NAME, &arrays->saved_rates, Atom::DOUBLE, NSAVED);
  set_peratom(atom, PORE_PRESSURE_NAME, &arrays->pore_pressure, Atom::DOUBLE, 0);
  set_peratom(atom, PORE_FLOW_NAME, &arrays->pore_flow, Atom::DOUBLE, 0);

  // Which fields travel where (why):
  //  comm (every step):  rho, stress, vest   - the pair sum needs them from ghosts (and the
  //                      wall normal mu when a fix may turn walls: the pair style sends it)
  //  reverse (every step): drho, strain rate, spin - ghosts' shares of the pair sums
  //                      (the pore pressure and its flow: the pair style communicates them
  //                      itself, in runs with saturated soil only)
  //  border:             + mass, h, wall data - constant between reneighborings; the pore
  //                      pressure
  //  exchange:           the whole state and the stress rate: atoms migrate between the
  //                      predictor and the force evaluation, which recomputes the other
  //                      rates, while the corrector still needs the stress rate of the
  //                      step's start (fix sph/soil carries its own saved rates)
  //  restart:            the whole state with the rates saved at the end of the last run
  //  data file:          the whole state, see doc/atom_style_sph_soil.rst
  const std::vector<std::string> rates = {"drho", STRESS_RATE_NAME, STRAIN_RATE_NAME, SPIN_NAME,
                                          PORE_FLOW_NAME};
  const std::vector<std::string> state = {"rmass",     "rho",       H_NAME,     "vest",
                                          STRESS_NAME, STRAIN_NAME, LEVEL_NAME, "mu",
                                          WALL_DISTANCE_NAME, PORE_PRESSURE_NAME};
  std::vector<std::string> all = state;
  all.insert(all.end(), rates.begin(), rates.end());
  all.push_back(SAVED_RATES_NAME);
  const std::vector<std::string> comm = {"rho", STRESS_NAME, "vest"};
  const std::vector<std::string> border = {"rmass", "rho", STRESS_NAME,       "vest",
                                           H_NAME,  "mu",  WALL_DISTANCE_NAME, PORE_PRESSURE_NAME};

  using SPHSoilCompat::assign_fields;
  assign_fields(fields_grow, all, field_storage[0]);
  assign_fields(fields_copy, all, field_storage[1]);
  assign_fields(fields_comm, comm, field_storage[2]);
  assign_fields(fields_comm_vel, comm, field_storage[3]);
  // the pair style accumulates rates on ghosts (Newton's third law): they go back to owners
  assign_fields(fields_reverse, {"drho", STRAIN_RATE_NAME, SPIN_NAME}, field_storage[4]);
  assign_fields(fields_border, border, field_storage[5]);
  assign_fields(fields_border_vel, border, field_storage[6]);
  std::vector<std::string> exchange = state;
  exchange.push_back(STRESS_RATE_NAME);
  exchange.push_back(SAVED_RATES_NAME);
  assign_fields(fields_exchange, exchange, field_storage[7]);
  std::vector<std::string> restart = state;
  restart.push_back(SAVED_RATES_NAME);
  assign_fields(fields_restart, restart, field_storage[8]);
  assign_fields(fields_create, all, field_storage[9]);
  // Data files: LAMMPS 29Sep2021 reads lines of at most 255 characters, room for about ten
  // full-precision numbers. The particle definition goes to Atoms, the stress (the state a
  // user prepares, e.g. geostatic) rides with the velocity in Velocities. Total strain and
  // wall data are in restart files only (doc/atom_style_sph_soil.rst).
  assign_fields(fields_data_atom, {"id", "type", "rmass", H_NAME, "rho", LEVEL_NAME, "x"},
                field_storage[10]);
  assign_fields(fields_data_vel, {"id", "v", STRESS_NAME}, field_storage[11]);

  setup_fields();
}

/* ---------------------------------------------------------------------- */

/* ----------------------------------------------------------------------
   the style takes no arguments from a user; its own 'format N' rides in the restart file (LAMMPS
   stores an atom style's arguments there), so that read_restart, which re-creates the style from
   them, learns the layout of the file's per-atom data before it reads any. Under atom_style
   hybrid the hybrid style's arguments are stored instead, and the check is not made.
------------------------------------------------------------------------- */

void AtomVecSPHSoil::process_args(int narg, char **arg)
{
  const bool sub_style = atom->avec != this;    // of atom_style hybrid
  if (narg == 2 && strcmp(arg[0], "format") == 0) {
    const int format = utils::inumeric(FLERR, arg[1], false, lmp);
    if (format != RESTART_FORMAT)
      SPHSoilCompat::error_all(
          lmp, FLERR,
          "Restart file holds atom_style sph/soil data of format {}; this build of "
          "SPH_SOIL reads format {}: read it with the build that wrote it and save "
          "the state with write_data",
          format, RESTART_FORMAT);
  } else if (narg > 0) {
    SPHSoilCompat::error_all(
        lmp, FLERR, "Illegal atom_style sph/soil command: it takes no arguments, got '{}'", arg[0]);
  } else if (!sub_style && SPHSoilCompat::atom_style_from_restart(lmp)) {
    SPHSoilCompat::error_all(
        lmp, FLERR,
        "Restart file holds atom_style sph/soil data without a format number, "
        "written before 2026-12-03 (format 1); this build of SPH_SOIL reads format {}: "
        "read it with the build that wrote it and save the state with write_data",
        RESTART_FORMAT);
  }
  if (!sub_style) store_format_args();
}

// the arguments that write_restart stores with the style's name: "format N"
void AtomVecSPHSoil::store_format_args()
{
  const std::string format = std::to_string(RESTART_FORMAT);
  char *args[2] = {const_cast<char *>("format"), const_cast<char *>(format.c_str())};
  for (int i = 0; i < nargcopy; i++) delete[] argcopy[i];
  delete[] argcopy;
  argcopy = nullptr;
  nargcopy = 0;
  store_args(2, args);
}

/* ----------------------------------------------------------------------
   our own arrays are grown in place through their registered addresses;
   the core ones live in Atom
------------------------------------------------------------------------- */

void AtomVecSPHSoil::grow_pointers()
{
  smoothing_length = arrays->smoothing_length;
  stress = arrays->stress;
  stress_rate = arrays->stress_rate;
  total_strain = arrays->total_strain;
  strain_rate = arrays->strain_rate;
  spin = arrays->spin;
  level = arrays->level;
  wall_normal = atom->mu;
  wall_distance = arrays->wall_distance;
  saved_rates = arrays->saved_rates;
  pore_pressure = arrays->pore_pressure;
  pore_flow = arrays->pore_flow;
  rmass = atom->rmass;
  rho = atom->rho;
  drho = atom->drho;
  vest = atom->vest;
}

/* ----------------------------------------------------------------------
   clear the rates that the pair style accumulates, starting at atom n
------------------------------------------------------------------------- */

void AtomVecSPHSoil::force_clear(int n, size_t nbytes)
{
  memset(&drho[n], 0, nbytes);
  memset(&strain_rate[n][0], 0, NVOIGT * nbytes);
  memset(&spin[n][0], 0, NSPIN * nbytes);
}

/* ----------------------------------------------------------------------
   defaults for create_atoms: unit mass and density, everything else zero
   (h must be set, e.g. with sph_soil/set, before a pair style can use it)
------------------------------------------------------------------------- */

void AtomVecSPHSoil::create_atom_post(int ilocal)
{
  rmass[ilocal] = 1.0;
  rho[ilocal] = 1.0;
}

/* ----------------------------------------------------------------------
   check what AtomVec::data_atom() just read and reset the rates
------------------------------------------------------------------------- */

void AtomVecSPHSoil::data_atom_post(int ilocal)
{
  const tagint id = atom->tag[ilocal];
  if (!(rmass[ilocal] > 0.0) || !std::isfinite(rmass[ilocal]))
    SPHSoilCompat::error_one(lmp, FLERR,
               "Invalid mass {} of atom {} in Atoms section of data file: must be finite and > 0",
               rmass[ilocal], id);
  if (!(smoothing_length[ilocal] >= 0.0) || !std::isfinite(smoothing_length[ilocal]))
    SPHSoilCompat::error_one(lmp, FLERR,
               "Invalid smoothing length h {} of atom {} in Atoms section of data file: must be >= 0",
               smoothing_length[ilocal], id);
  if (!(rho[ilocal] > 0.0) || !std::isfinite(rho[ilocal]))
    SPHSoilCompat::error_one(lmp, FLERR, "Invalid density {} of atom {} in Atoms section of data file: must be > 0",
               rho[ilocal], id);
  if (level[ilocal] < 0 || level[ilocal] > SPHSoil::MAX_LEVEL)
    SPHSoilCompat::error_one(lmp, FLERR,
               "Invalid refinement level {} of atom {} in Atoms section of data file: must be in 0 "
               "to {}", level[ilocal], id, SPHSoil::MAX_LEVEL);
  drho[ilocal] = 0.0;
  for (int k = 0; k < 3; k++) vest[ilocal][k] = 0.0;
  for (int k = 0; k < 4; k++) wall_normal[ilocal][k] = 0.0;
  wall_distance[ilocal] = 0.0;
  pore_pressure[ilocal] = pore_flow[ilocal] = 0.0;
  for (int k = 0; k < NVOIGT; k++)
    stress[ilocal][k] = stress_rate[ilocal][k] = total_strain[ilocal][k] = strain_rate[ilocal][k] = 0.0;
  for (int k = 0; k < NSPIN; k++) spin[ilocal][k] = 0.0;
  for (int k = 0; k < NSAVED; k++) saved_rates[ilocal][k] = 0.0;
}

/* ----------------------------------------------------------------------
   a line of the Velocities section: velocity and stress, which must be finite
------------------------------------------------------------------------- */

void AtomVecSPHSoil::data_vel(int ilocal, SPHSoilCompat::DataVelValues values)
{
  AtomVec::data_vel(ilocal, values);
  double sum = 0.0;
  for (int k = 0; k < NVOIGT; k++) sum += stress[ilocal][k];
  for (int k = 0; k < 3; k++) sum += atom->v[ilocal][k];
  if (!std::isfinite(sum))
    SPHSoilCompat::error_one(lmp, FLERR,
               "Invalid velocity or stress of atom {} in Velocities section of data file: must be "
               "finite (got velocity {} {} {}, stress {} {} {} {} {} {})", atom->tag[ilocal],
               atom->v[ilocal][0], atom->v[ilocal][1], atom->v[ilocal][2], stress[ilocal][0],
               stress[ilocal][1], stress[ilocal][2], stress[ilocal][3], stress[ilocal][4],
               stress[ilocal][5]);
}

/* ----------------------------------------------------------------------
   index of a named per-atom property for compute property/atom, or -1
------------------------------------------------------------------------- */

int AtomVecSPHSoil::property_atom(SPHSoilCompat::PropertyAtomName name)
{
  const std::string wanted(name);
  for (int i = 0; i < NPROPERTIES; i++)
    if (wanted == properties[i].name) return i;
  return -1;
}

/* ---------------------------------------------------------------------- */

void AtomVecSPHSoil::pack_property_atom(int index, double *buf, int nvalues, int groupbit)
{
  if (index < 0 || index >= NPROPERTIES) return;
  const Property &p = properties[index];
  const int *mask = atom->mask;
  const int nlocal = atom->nlocal;

  double *vector = nullptr;
  double **array = nullptr;
  switch (p.field) {
    case H: vector = smoothing_length; break;
    case RHO: vector = rho; break;
    case DRHO: vector = drho; break;
    case WALL_D: vector = wall_distance; break;
    case STRESS: array = stress; break;
    case STRESS_RATE: array = stress_rate; break;
    case STRAIN: array = total_strain; break;
    case STRAIN_RATE: array = strain_rate; break;
    case SPIN: array = spin; break;
    case WALL_N: array = wall_normal; break;
    case VEST: array = vest; break;
    case PORE_PRESSURE: vector = pore_pressure; break;
    case PORE_FLOW: vector = pore_flow; break;
    case LEVEL: break;
  }

  for (int i = 0, n = 0; i < nlocal; i++, n += nvalues) {
    if (!(mask[i] & groupbit)) {
      buf[n] = 0.0;
    } else if (p.field == LEVEL) {
      buf[n] = level[i];
    } else if (vector) {
      buf[n] = vector[i];
    } else {
      buf[n] = array[i][p.col];
    }
  }
}
