// Helpers shared by the SPH_SOIL tests that run LAMMPS in-process (1 or more MPI ranks).
#ifndef SPH_SOIL_TESTING_H
#define SPH_SOIL_TESTING_H

#include "atom.h"
#include "atom_vec_sph_soil.h"
#include "core.h"
#include "exceptions.h"

#include <cmath>
#include <map>
#include <mpi.h>
#include <string>
#include <vector>

// Expect that the statements throw a LAMMPS error whose message matches `regex`, on every rank.
// (LAMMPS's TEST_FAILURE reads the message from rank 0's screen; this reads the exception.)
#define EXPECT_LAMMPS_ERROR(regex, ...)                                                   \
  do {                                                                                    \
    std::string sph_soil_message;                                                         \
    bool sph_soil_thrown = false;                                                         \
    ::testing::internal::CaptureStdout();                                                 \
    try {                                                                                 \
      __VA_ARGS__;                                                                        \
    } catch (LAMMPS_NS::LAMMPSException & e) {                                            \
      sph_soil_thrown = true;                                                             \
      sph_soil_message = e.what();                                                        \
    }                                                                                     \
    auto sph_soil_output = ::testing::internal::GetCapturedStdout();                      \
    EXPECT_TRUE(sph_soil_thrown) << "no LAMMPS error; output:\n" << sph_soil_output;      \
    EXPECT_THAT(sph_soil_message, ::testing::MatchesRegex(regex));                        \
  } while (0)

namespace SPHSoilTesting {

// the fixture of the package's LAMMPS tests: LAMMPSTest (unittest/testing/core.h) in SI units
class SoilTest : public LAMMPSTest {
 protected:
  void InitSystem() override { HIDE_OUTPUT([&] { command("units si"); }); }
};

// The commands that make an empty periodic 2D box of one atom type on a square lattice of
// 1 cm, its x and y extents in lattice spacings ("xlo xhi ylo yhi").
inline std::vector<std::string> periodic_box_commands(const std::string &extent)
{
  return {"dimension 2", "boundary p p p", "atom_style sph/soil", "atom_modify map array",
          "lattice sq 0.01", "region box block " + extent + " -0.5 0.5", "create_box 1 box"};
}

// The commands that make a periodic 2D patch of soil, 20 x 16 particles at 1 cm on a lattice
// disordered by `disorder` (m, 1 mm by default: a tenth of the spacing), with stresses that vary
// in space and no velocity (the caller sets it). Atom IDs depend on the number of ranks
// (create_atoms), positions do not.
inline std::vector<std::string> periodic_patch_commands(const std::string &disorder = "0.001")
{
  auto commands = periodic_box_commands("0 20 0 16");
  const std::vector<std::string> patch = {
      "create_atoms 1 box", "variable xnew atom x+" + disorder + "*sin(1299*x+7823*y)",
      "variable ynew atom y+" + disorder + "*sin(3711*x-4557*y)", "set group all x v_xnew y v_ynew",
      "variable sxx atom -2000.0-300.0*sin(300*x)", "variable syy atom -1500.0+200.0*cos(250*y)",
      "variable sxy atom 100.0*sin(200*(x+y))",
      "sph_soil/set all mass 0.265 h 0.012 density 2650 stress v_sxx v_syy v_sxx v_sxy 0 0"};
  commands.insert(commands.end(), patch.begin(), patch.end());
  return commands;
}

// The pair style of soil_and_water_patch_commands() (`pair_style`: its line) and its two
// materials: a saturated sand (type 1) and free water (type 2)
inline std::vector<std::string> soil_and_water_pair_commands(
    const std::string &pair_style = "pair_style sph/soil")
{
  return {pair_style,
          "pair_coeff 1 1 soil 2650 drucker_prager 0.7e6 0.3 19.8 0 0 porosity 0.4 permeability "
          "1e-4 water_modulus 2e7",
          "pair_coeff 2 2 water 1000 2e6"};
}

// The periodic patch (periodic_patch_commands()) as saturated soil below y = 8 cm (type 1, group
// soil, its pore pressure varying so that the pore water flows) and free water above it (type 2,
// group water, at rest at its reference density), with soil_and_water_pair_commands(pair_style);
// no integrator, no velocity
inline std::vector<std::string> soil_and_water_patch_commands(
    const std::string &pair_style = "pair_style sph/soil")
{
  auto commands = periodic_patch_commands();
  for (auto &line : commands)
    if (line == "create_box 1 box") line = "create_box 2 box";
  const std::vector<std::string> water = {
      "region upper block INF INF 8 INF INF INF", "set region upper type 2", "group water type 2",
      "group soil type 1", "variable pore atom 300.0+100.0*sin(400*x)*cos(300*y)",
      "sph_soil/set soil pore_pressure v_pore",
      "sph_soil/set water density 1000 mass 0.1 stress 0 0 0 0 0 0"};
  commands.insert(commands.end(), water.begin(), water.end());
  const auto pair = soil_and_water_pair_commands(pair_style);
  commands.insert(commands.end(), pair.begin(), pair.end());
  return commands;
}

// A 0.1 m x 0.1 m 2D column of soil particles (type 1, 4 mm spacing, h 4.8 mm, rho 1850) in a
// box of wall particles (type 2: groups floor, left, right, with their planes), no pair style
inline const std::vector<std::string> &walled_column_commands()
{
  static const std::vector<std::string> commands = {
      "dimension 2", "boundary f f p", "atom_style sph/soil", "atom_modify map array",
      "lattice sq 0.004 origin 0.5 0.5 0",
      "region box block -0.02 0.12 -0.02 0.14 -0.001 0.001 units box", "create_box 2 box",
      "region soil block 0 0.1 0 0.1 INF INF units box",
      "region floor block -0.012 0.112 -0.012 0 INF INF units box",
      "region left block -0.012 0 0 0.12 INF INF units box",
      "region right block 0.1 0.112 0 0.12 INF INF units box",
      "create_atoms 1 region soil", "create_atoms 2 region floor", "create_atoms 2 region left",
      "create_atoms 2 region right", "group soil type 1", "group floor region floor",
      "group left region left", "group right region right",
      "sph_soil/set all mass $(1850*0.004*0.004) h 0.0048 density 1850",
      "sph_soil/set floor wall 0 0 0 0 1 0", "sph_soil/set left wall 0 0 0 1 0 0",
      "sph_soil/set right wall 0.1 0 0 -1 0 0"};
  return commands;
}

inline int nprocs()
{
  int n;
  MPI_Comm_size(MPI_COMM_WORLD, &n);
  return n;
}

inline int rank()
{
  int r;
  MPI_Comm_rank(MPI_COMM_WORLD, &r);
  return r;
}

inline LAMMPS_NS::AtomVecSPHSoil *soil_avec(LAMMPS_NS::LAMMPS *lmp)
{
  return dynamic_cast<LAMMPS_NS::AtomVecSPHSoil *>(lmp->atom->style_match("sph/soil"));
}

// Every per-atom state value of atom_style sph/soil, in a fixed order, for atom i.
// Order: type x(3) v(3) mass h rho level stress(6) strain(6) wall_normal(3) wall_distance vest(3)
// pore_pressure
inline std::vector<double> atom_state(LAMMPS_NS::LAMMPS *lmp, int i)
{
  auto atom = lmp->atom;
  auto avec = soil_avec(lmp);
  std::vector<double> s;
  s.push_back(atom->type[i]);
  for (int k = 0; k < 3; k++) s.push_back(atom->x[i][k]);
  for (int k = 0; k < 3; k++) s.push_back(atom->v[i][k]);
  s.push_back(atom->rmass[i]);
  s.push_back(avec->smoothing_length[i]);
  s.push_back(atom->rho[i]);
  s.push_back(avec->level[i]);
  for (int k = 0; k < 6; k++) s.push_back(avec->stress[i][k]);
  for (int k = 0; k < 6; k++) s.push_back(avec->total_strain[i][k]);
  for (int k = 0; k < 3; k++) s.push_back(avec->wall_normal[i][k]);
  s.push_back(avec->wall_distance[i]);
  for (int k = 0; k < 3; k++) s.push_back(atom->vest[i][k]);
  s.push_back(avec->pore_pressure[i]);
  return s;
}
inline const std::vector<std::string> &state_names()
{
  static const std::vector<std::string> names = {
      "type", "x", "y", "z", "vx", "vy", "vz", "mass", "h", "rho", "level",
      "sxx", "syy", "szz", "sxy", "sxz", "syz", "exx", "eyy", "ezz", "exy", "exz", "eyz",
      "wall_nx", "wall_ny", "wall_nz", "wall_d", "vestx", "vesty", "vestz", "pore_pressure"};
  return names;
}

// The state of all atoms on all ranks, keyed by atom ID (identical on every rank).
inline std::map<LAMMPS_NS::tagint, std::vector<double>> gather_state(LAMMPS_NS::LAMMPS *lmp)
{
  const int nvalues = state_names().size();
  const int nlocal = lmp->atom->nlocal;
  std::vector<double> mine;
  for (int i = 0; i < nlocal; i++) {
    mine.push_back(lmp->atom->tag[i]);
    auto s = atom_state(lmp, i);
    mine.insert(mine.end(), s.begin(), s.end());
  }
  const int n = nprocs();
  int count = mine.size();
  std::vector<int> counts(n), displs(n, 0);
  MPI_Allgather(&count, 1, MPI_INT, counts.data(), 1, MPI_INT, MPI_COMM_WORLD);
  for (int r = 1; r < n; r++) displs[r] = displs[r - 1] + counts[r - 1];
  std::vector<double> all(displs[n - 1] + counts[n - 1] + 1);
  MPI_Allgatherv(mine.data(), count, MPI_DOUBLE, all.data(), counts.data(), displs.data(),
                 MPI_DOUBLE, MPI_COMM_WORLD);
  std::map<LAMMPS_NS::tagint, std::vector<double>> state;
  const size_t total = displs[n - 1] + counts[n - 1];
  for (size_t k = 0; k < total; k += nvalues + 1)
    state[(LAMMPS_NS::tagint) all[k]] = std::vector<double>(all.begin() + k + 1, all.begin() + k + 1 + nvalues);
  return state;
}

// Every value (or those of the state_names() columns `columns`) of every atom of `state`
// (gather_state()) within `relative` of the `reference`'s plus `absolute` (the round-off of a
// change of summation order, or of a scheme's variant)
inline void expect_same_state(const std::map<LAMMPS_NS::tagint, std::vector<double>> &state,
                              const std::map<LAMMPS_NS::tagint, std::vector<double>> &reference,
                              double relative, double absolute, std::vector<int> columns = {})
{
  ASSERT_EQ(state.size(), reference.size());
  const auto &names = state_names();
  if (columns.empty())
    for (size_t k = 1; k < names.size(); k++) columns.push_back((int) k);
  for (const auto &entry : reference) {
    const auto &s = state.at(entry.first);
    for (int k : columns)
      ASSERT_NEAR(s[k], entry.second[k], relative * std::fabs(entry.second[k]) + absolute)
          << "atom " << entry.first << " " << names[k];
  }
}

// the owned atoms of all ranks for which pred(i) holds
template <class Predicate> inline LAMMPS_NS::bigint count_atoms(LAMMPS_NS::LAMMPS *lmp, Predicate pred)
{
  LAMMPS_NS::bigint mine = 0, all = 0;
  for (int i = 0; i < lmp->atom->nlocal; i++)
    if (pred(i)) mine++;
  MPI_Allreduce(&mine, &all, 1, MPI_LMP_BIGINT, MPI_SUM, MPI_COMM_WORLD);
  return all;
}

}    // namespace SPHSoilTesting

#endif
