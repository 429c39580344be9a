// Particle refinement in LAMMPS: the sph_soil/refine command and fix sph/soil/refine.
// Conservation of one split, the half lattice of a static refinement, CSPM of a constant
// state, criterion / maxlevel / region, rank independence, restart, bad input.
#include "sph_soil_testing.h"

#include "atom_vec_sph_soil.h"
#include "domain.h"
#include "fix.h"
#include "force.h"
#include "compute.h"
#include "modify.h"
#include "neighbor.h"
#include "pair_sph_soil.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <functional>
#include <set>

using namespace LAMMPS_NS;
using namespace SPHSoilTesting;

namespace {

const char *const SOIL = "pair_coeff 1 1 soil 2650 0.7e6 0.3 19.8 0 0";

class Refinement : public SoilTest {
 protected:

  // A periodic lattice of spacing 1 cm with mass rho0 d^D (so the derived d_p is 1 cm),
  // optionally disordered, with velocities and stresses that vary in space; with `types` 2,
  // half the atoms (at random) are of a second type of the same soil.
  void patch(int dimension, int n, bool disorder, const std::string &atom_style = "sph/soil", int types = 1)
  {
    HIDE_OUTPUT([&] {
      command("units si");    // (again after a clear)
      command(fmt::format("dimension {}", dimension));
      command("boundary p p p");
      command("atom_style " + atom_style);
      command("atom_modify map array");
      if (dimension == 2) {
        command("lattice sq 0.01 origin 0.5 0.5 0.0");
        command(fmt::format("region box block 0 {} 0 {} -0.5 0.5", n, n));
      } else {
        command("lattice sc 0.01 origin 0.5 0.5 0.5");
        command(fmt::format("region box block 0 {} 0 {} 0 {}", n, n, n));
      }
      command(fmt::format("create_box {} box", types));
      command("create_atoms 1 box");
      if (types == 2) command("set group all type/ratio 2 0.5 8123");
      if (disorder) {
        command("variable xnew atom x+0.001*sin(1299*x+7823*y)");
        command("variable ynew atom y+0.001*sin(3711*x-4557*y)");
        command("set group all x v_xnew y v_ynew");
      }
      command("variable vx atom 0.02*sin(2*PI*y/0.1)+0.01*cos(2*PI*x/0.1)");
      command("variable vy atom 0.015*sin(2*PI*x/0.1)");
      command("variable sxx atom -2000.0-300.0*sin(300*x)");
      command("variable syy atom -1500.0+200.0*cos(250*y)");
      command("variable sxy atom 100.0*sin(200*(x+y))");
      command(fmt::format("sph_soil/set all mass {} h 0.012 density 2650 stress v_sxx v_syy v_sxx v_sxy 0 0",
                          dimension == 2 ? 2650 * 1e-4 : 2650 * 1e-6));
      command("velocity all set v_vx v_vy NULL units box");
      command("pair_style sph/soil");
      command(SOIL);
      if (types == 2) command(std::string(SOIL).replace(0, std::strlen("pair_coeff 1 1"), "pair_coeff 2 2"));
      command("neighbor 0.003 bin");
      command("thermo 0");
    });
  }

  // a 12 x 12 patch (of `types` types) whose disc of particles split once at step 10 with
  // merging on (hold time 1e-3), then lost the first new daughter of every split: families
  // short of a sibling, whose members become orphans
  void orphans_patch(int types)
  {
    patch(2, 12, true, "sph/soil", types);
    HIDE_OUTPUT([&] {
      command("fix integrate all sph/soil cfl 0.1");
      command("variable on equal step<20");
      command("variable zone atom ((x-0.06)^2+(y-0.06)^2<0.045^2)*v_on");
      command("fix refine all sph/soil/refine 10 criterion v_zone maxlevel 1 merge 1e-3");
      command("run 20 post no");
      // the first of the three new daughters of every split (each split takes three IDs in a row)
      command("variable first atom id>144&&(id-145)%3==0");
      command("group first variable first");
      command("delete_atoms group first compress no");
      // (a step first: delete_atoms leaves the forces of the step before, which the first half
      // kick uses, with other atoms)
      command("run 1 post no");
    });
  }

  // mass, momentum (3), kinetic energy, angular momentum about the origin (3)
  std::vector<double> mass_and_momentum()
  {
    std::vector<double> local(8, 0.0), global(8, 0.0);
    auto atom = lmp->atom;
    for (int i = 0; i < atom->nlocal; i++) {
      const double m = atom->rmass[i], *x = atom->x[i], *v = atom->v[i];
      local[0] += m;
      for (int k = 0; k < 3; k++) local[1 + k] += m * v[k];
      local[4] += 0.5 * m * (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
      local[5] += m * (x[1] * v[2] - x[2] * v[1]);
      local[6] += m * (x[2] * v[0] - x[0] * v[2]);
      local[7] += m * (x[0] * v[1] - x[1] * v[0]);
    }
    MPI_Allreduce(local.data(), global.data(), 8, MPI_DOUBLE, MPI_SUM, MPI_COMM_WORLD);
    return global;
  }

  // split the particles left of x = `edge` once with (0.5, 0.5): a refined half
  void refine_left_of(double edge)
  {
    HIDE_OUTPUT([&] {
      command(fmt::format("region half block INF {} INF INF INF INF units box", edge));
      command("group half region half");
      command("sph_soil/refine half separation 0.5 smoothing 0.5");
    });
  }

  // Pairs closer than cutoff(i, j) over all ranks, twice: {in the pair style's list, by brute
  // force over owned and ghost atoms}. Each pair between owned atoms counts twice in both; a
  // pair with a ghost is listed on one of its ranks and seen from both, once each. With
  // `listed_beyond`, also the listed pairs at or beyond the cutoff (twice).
  template <class Cutoff>
  std::vector<bigint> pairs_within(Cutoff cutoff, bigint *listed_beyond = nullptr)
  {
    auto pair = dynamic_cast<PairSPHSoil *>(lmp->force->pair);
    double **x = lmp->atom->x;
    const int nlocal = lmp->atom->nlocal, nall = nlocal + lmp->atom->nghost;
    auto within = [&](int i, int j) {
      const double dx = x[i][0] - x[j][0], dy = x[i][1] - x[j][1], dz = x[i][2] - x[j][2];
      const double cut = cutoff(i, j);
      return dx * dx + dy * dy + dz * dz < cut * cut;
    };
    bigint local[3] = {0, 0, 0}, all[3];
    const auto &list = pair->neighbour_list();
    for (int i = 0; i < nlocal; i++) {
      for (int jj = list.first(i); jj < list.end(i); jj++)
        local[within(i, list.partner_data()[jj]) ? 0 : 2] += 2;
      for (int j = 0; j < nall; j++)
        if (j != i && within(i, j)) local[1]++;
    }
    MPI_Allreduce(local, all, 3, MPI_LMP_BIGINT, MPI_SUM, MPI_COMM_WORLD);
    if (listed_beyond) *listed_beyond = all[2];
    return {all[0], all[1]};
  }

  double fix_vector(const char *id, int n)
  {
    return lmp->modify->fix[lmp->modify->find_fix(id)]->compute_vector(n);
  }

  // from a cleared LAMMPS: the 2D 6 x 6 patch at rest with `state` (sph_soil/set keywords),
  // integrated with cfl 0.1 and refined by `refine` (the fix's arguments after its ID)
  void patch_at_rest(const std::string &state, const std::string &refine)
  {
    HIDE_OUTPUT([&] { command("clear"); });
    patch(2, 6, false);
    HIDE_OUTPUT([&] {
      command("velocity all set 0 0 0 units box");
      command("sph_soil/set all " + state);
      command("fix integrate all sph/soil cfl 0.1");
      command("fix refine all " + refine);
    });
  }

  // velocities on the 6 x 6 patch whose normal strain rates (of 6 m/s over a wavelength of 6
  // cm, 628/s at most) exceed 300/s at every site (the sites of one row or column sit at
  // phases 30 + 60 k degrees; y's shifted by 30 degrees): no particle is quiet for a hold time
  // of 1e-3 s (quiet below 112/s)
  void kick()
  {
    HIDE_OUTPUT([&] {
      command("variable kick_x atom 6.0*sin(2*PI*x/0.06)");
      command("variable kick_y atom 6.0*sin(2*PI*y/0.06+PI/6)");
      command("velocity all set v_kick_x v_kick_y NULL units box");
    });
  }

  // whether every atom's stress is on or inside its yield surface (to round-off), on all ranks
  bool stresses_admissible()
  {
    auto pair = dynamic_cast<PairSPHSoil *>(lmp->force->pair);
    auto avec = soil_avec(lmp);
    int bad = 0, all = 0;
    for (int i = 0; i < lmp->atom->nlocal; i++) {
      const double *s = avec->stress[i];
      const double scale = std::fabs(s[0]) + std::fabs(s[1]) + std::fabs(s[2]) + 1.0;
      if (pair->model(lmp->atom->type[i])->yield_function(s) > 1e-12 * scale) bad++;
    }
    MPI_Allreduce(&bad, &all, 1, MPI_INT, MPI_SUM, MPI_COMM_WORLD);
    return all == 0;
  }

  // The patch, written to a data file, then `lines` (from "units si" on) run here and, on rank
  // 0, alone in a LAMMPS of its own: the two final states, per atom ID, agree to `tolerance`
  // (relative) in the state_names() columns `columns`
  void expect_same_on_one_rank(const std::vector<std::string> &lines, const std::vector<int> &columns,
                               double tolerance)
  {
    HIDE_OUTPUT([&] {
      command("write_data refine.data");
      command("clear");
      for (const auto &line : lines) command(line);
    });
    auto parallel = gather_state(lmp);
    EXPECT_EQ((bigint) parallel.size(), lmp->atom->natoms);    // IDs unique
    EXPECT_GT(lmp->atom->natoms, 144);                          // something was split
    if (rank() != 0) return;
    const char *argv[] = {"serial", "-log", "none", "-echo", "none", "-screen", "none", "-nocite"};
    auto single = new LAMMPS(8, (char **) argv, MPI_COMM_SELF);
    for (const auto &line : lines) single->input->one(line);
    std::map<tagint, std::vector<double>> serial;
    for (int i = 0; i < single->atom->nlocal; i++) serial[single->atom->tag[i]] = atom_state(single, i);
    delete single;
    expect_same_state(parallel, serial, tolerance, 1e-15, columns);
  }

  // `fixes` on the patch: 40 steps, a restart file, 40 more; then the file read back with the
  // same fixes (`on_restart` sees the state read) and 40 steps: the same state to round-off
  void expect_restart_continues(const std::vector<std::string> &fixes,
                                const std::function<void()> &on_restart = {})
  {
    HIDE_OUTPUT([&] {
      for (const auto &line : fixes) command(line);
      command("run 40 post no");
      command("write_restart refine.restart");
      command("run 40 post no");
    });
    auto uninterrupted = gather_state(lmp);
    const double total_split = fix_vector("refine", 1);
    HIDE_OUTPUT([&] {
      command("clear");
      command("read_restart refine.restart");
      command("pair_style sph/soil");
      command(SOIL);
      command("neighbor 0.003 bin");
      for (const auto &line : fixes) command(line);
    });
    if (on_restart) on_restart();
    HIDE_OUTPUT([&] { command("run 40 post no"); });
    EXPECT_EQ(fix_vector("refine", 1), total_split);
    std::vector<int> columns;    // type to the strain (not the wall data, nor vest)
    for (int k = 1; k < 23; k++) columns.push_back(k);
    expect_same_state(gather_state(lmp), uninterrupted, 1e-12, 1e-18, columns);
  }
};

}    // namespace

TEST_F(Refinement, StaticRefinementOfASquareLatticeGivesTheHalfLattice)
{
  for (int dimension : {2, 3}) {
    HIDE_OUTPUT([&] { command("clear"); command("units si"); });
    const int n = dimension == 2 ? 10 : 4;
    patch(dimension, n, false);
    HIDE_OUTPUT([&] { command("sph_soil/refine all separation 0.5 smoothing 0.5"); });
    const int count = dimension == 2 ? 4 : 8;
    const bigint expected = count * (bigint) std::pow(n, dimension);
    ASSERT_EQ(lmp->atom->natoms, expected);
    auto state = gather_state(lmp);
    ASSERT_EQ((bigint) state.size(), expected);    // IDs unique
    EXPECT_EQ(state.rbegin()->first, expected);     // and consecutive
    std::set<std::vector<long>> sites;
    const double half = 0.005, mass = (dimension == 2 ? 2650e-4 : 2650e-6) / count;
    for (const auto &entry : state) {
      const auto &s = entry.second;
      std::vector<long> site;
      for (int a = 0; a < dimension; a++) {
        // the half lattice: x = (k + 1/2) d/2
        const double k = s[1 + a] / half - 0.5;
        EXPECT_NEAR(k, std::round(k), 1e-9) << "atom " << entry.first << " axis " << a;
        site.push_back(std::lround(k));
      }
      sites.insert(site);
      EXPECT_NEAR(s[8], 0.006, 1e-15) << "h = 0.6 d_ref";
      EXPECT_NEAR(s[7], mass, 1e-15 * mass);
      EXPECT_EQ(s[10], 1.0) << "level";
    }
    EXPECT_EQ((bigint) sites.size(), expected) << "every site of the half lattice once";
  }
}

// The pair style's list follows each pair's own h (doc/theory.rst 5.8): in a 3D lattice refined
// on one side, the daughters list about as many partners as the particles of a lattice refined
// everywhere (with one cutoff for all, 2 h_max + skin, they would list about eight times as many)
TEST_F(Refinement, RefinedParticlesListThePartnersOfTheirOwnSmoothingLength)
{
  // mean listed partners of the particles of `level` (over all ranks)
  auto mean_partners = [&](int level) {
    auto pair = dynamic_cast<PairSPHSoil *>(lmp->force->pair);
    auto avec = dynamic_cast<AtomVecSPHSoil *>(lmp->atom->avec);
    double local[2] = {0.0, 0.0}, global[2];
    for (int i = 0; i < lmp->atom->nlocal; i++)
      if (avec->level[i] == level) {
        local[0] += pair->listed_partners(i);
        local[1] += 1.0;
      }
    MPI_Allreduce(local, global, 2, MPI_DOUBLE, MPI_SUM, MPI_COMM_WORLD);
    return global[0] / global[1];
  };
  // the skin is that of the largest h, in proportion for the others (fix sph/soil present):
  // a quarter of the spacing for every particle in both set-ups
  auto setup = [&](const std::string &refined, double skin) {
    HIDE_OUTPUT([&] {
      command("clear");
      command("units si");
    });
    patch(3, 8, false);
    HIDE_OUTPUT([&] {
      command(fmt::format("neighbor {} bin", skin));
      command("region half block INF 0.04 INF INF INF INF units box");
      command("group half region half");
      command("sph_soil/refine " + refined + " separation 0.5 smoothing 0.5");
      command("fix integrate all sph/soil");
      command("run 0 post no");
    });
  };
  setup("all", 0.00125);
  const double uniformly_fine = mean_partners(1);
  setup("half", 0.0025);
  const double coarse = mean_partners(0), daughters = mean_partners(1);
  // compute sph/soil/atom neighbours gives the same count per particle
  HIDE_OUTPUT([&] {
    command("compute partners all sph/soil/atom neighbours");
    command("compute total all reduce sum c_partners");
    command("thermo_style custom step c_total");
    command("run 0 post no");
    command("variable total equal c_total");
  });
  double listed = 0.0, listed_all = 0.0;
  auto pair = dynamic_cast<PairSPHSoil *>(lmp->force->pair);
  for (int i = 0; i < lmp->atom->nlocal; i++) listed += pair->listed_partners(i);
  MPI_Allreduce(&listed, &listed_all, 1, MPI_DOUBLE, MPI_SUM, MPI_COMM_WORLD);
  EXPECT_EQ(get_variable_value("total"), listed_all);
  // a support of 2.4 spacings plus a skin of 0.25 spacings: about (4/3) pi 2.65^3 / 2 = 39
  EXPECT_NEAR(uniformly_fine, 39.0, 6.0);
  EXPECT_LT(daughters, 1.2 * uniformly_fine);
  EXPECT_GT(daughters, 0.8 * uniformly_fine);
  // the coarse particles next to the daughters list more (eight daughters where a coarse
  // particle was), but not eight times more
  EXPECT_LT(coarse, 4.0 * uniformly_fine);
}

// With fix sph/soil a daughter's skin is in proportion to its h, and LAMMPS reneighbours when
// a particle has moved half its own skin: at every step of a shearing flow of the daughters
// (the coarse half at rest, so that LAMMPS's own check, which knows the coarse skin only, would
// reneighbour too late: without the daughters' request this test fails at step 25), every pair
// within its support is in the list (counted over all ranks: pairs_within()).
TEST_F(Refinement, SkinsThatFollowHMissNoPairWithinTheSupport)
{
  patch(2, 12, true);
  HIDE_OUTPUT([&] {
    command("variable fast_x atom (x<0.06)*0.15*sin(2*PI*y/0.03)");
    command("variable fast_y atom (x<0.06)*0.15*sin(2*PI*x/0.03)");
    command("velocity all set v_fast_x v_fast_y NULL units box");
    command("neighbor 0.0001 bin");
  });
  refine_left_of(0.06);
  HIDE_OUTPUT([&] {
    command("fix integrate all sph/soil cfl 0.1");
    command("run 0 post no");
  });
  auto avec = dynamic_cast<AtomVecSPHSoil *>(lmp->atom->avec);
  const bigint builds_at_start = lmp->neighbor->ncalls;
  for (int step = 1; step <= 40; step++) {
    HIDE_OUTPUT([&] { command("run 1 pre no post no"); });
    const double *h = avec->smoothing_length;
    const auto counts = pairs_within([&](int i, int j) { return h[i] + h[j]; });
    ASSERT_EQ(counts[0], counts[1]) << "pairs within the support missing from the list at step " << step;
  }
  // the daughters reneighbour after moving a quarter of the coarse skin (8 times here in 40
  // steps), far less than at every step
  const bigint builds = lmp->neighbor->ncalls - builds_at_start;
  EXPECT_GT(builds, 5);
  EXPECT_LT(builds, 20);
}

// The list's skin policy belongs to the pair style (its internal fix SPH_SOIL_SKIN), not to
// the integrator: daughters moved by another integrator (fix nve) still get skins in proportion
// to their h, and LAMMPS reneighbours when one has moved half of it. At every step every pair
// within its support is listed, and nothing beyond h_i + h_j + the pair's own skin.
TEST_F(Refinement, WithoutFixSPHSoilSkinsFollowHAndMissNoPair)
{
  patch(2, 12, true);
  HIDE_OUTPUT([&] {
    command("variable fast_x atom (x<0.06)*0.15*sin(2*PI*y/0.03)");
    command("variable fast_y atom (x<0.06)*0.15*sin(2*PI*x/0.03)");
    command("velocity all set v_fast_x v_fast_y NULL units box");
    command("neighbor 0.0001 bin");
  });
  refine_left_of(0.06);
  HIDE_OUTPUT([&] {
    command("fix move_them all nve");
    command("timestep 2e-5");
    command("run 0 post no");
  });
  auto avec = dynamic_cast<AtomVecSPHSoil *>(lmp->atom->avec);
  const double skin = lmp->neighbor->skin;
  const double *h0 = avec->smoothing_length;
  double max_h = 0.0, max_all = 0.0;
  for (int i = 0; i < lmp->atom->nlocal; i++) max_h = std::max(max_h, h0[i]);
  MPI_Allreduce(&max_h, &max_all, 1, MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD);
  // at the build: the pair's own skin, skin h_ij / max(h), not the whole skin
  bigint listed_beyond = -1;
  const double *h = avec->smoothing_length;
  pairs_within([&](int i, int j) { return (h[i] + h[j]) * (1.0 + 0.5 * skin / max_all) * (1.0 + 1e-12); },
               &listed_beyond);
  EXPECT_EQ(listed_beyond, 0);
  const bigint builds_at_start = lmp->neighbor->ncalls;
  for (int step = 1; step <= 40; step++) {
    HIDE_OUTPUT([&] { command("run 1 pre no post no"); });
    const auto counts = pairs_within([&](int i, int j) { return h[i] + h[j]; });
    ASSERT_EQ(counts[0], counts[1]) << "pairs within the support missing from the list at step " << step;
  }
  EXPECT_GT(lmp->neighbor->ncalls - builds_at_start, 5);
}

TEST_F(Refinement, SplitsConserveMassMomentumEnergyAndAngularMomentum)
{
  for (int dimension : {2, 3}) {
    HIDE_OUTPUT([&] { command("clear"); command("units si"); });
    patch(dimension, dimension == 2 ? 10 : 4, true);
    if (dimension == 3) HIDE_OUTPUT([&] { command("velocity all set NULL NULL 0.01 units box"); });
    auto before = mass_and_momentum();
    HIDE_OUTPUT([&] { command("sph_soil/refine all separation 0.55 smoothing 0.6"); });
    auto once = mass_and_momentum();
    // a second level: two splits in a row
    HIDE_OUTPUT([&] { command("sph_soil/refine all"); });
    auto twice = mass_and_momentum();
    const double scale[8] = {before[0], before[0] * 0.02, before[0] * 0.02, before[0] * 0.02,
                             before[4], before[0] * 0.002, before[0] * 0.002, before[0] * 0.002};
    for (int k = 0; k < 8; k++) {
      EXPECT_NEAR(once[k], before[k], 1e-13 * scale[k]) << "dimension " << dimension << " total " << k;
      EXPECT_NEAR(twice[k], before[k], 1e-13 * scale[k]) << "dimension " << dimension << " total " << k;
    }
    EXPECT_EQ(lmp->atom->natoms, (dimension == 2 ? 100 * 16 : 64 * 64));
  }
}

// with every kernel of the pair style (the interpolation uses it)
TEST_F(Refinement, CspmKeepsAConstantStateExactly)
{
  for (const char *kernel : {"cubic", "wendland2"}) {
    HIDE_OUTPUT([&] {
      command("clear");
      command("units si");
    });
    patch(2, 10, true);
    HIDE_OUTPUT([&] {
      command(std::string("pair_style sph/soil kernel ") + kernel);
      command(SOIL);
      command("sph_soil/set all stress -3000 -2000 -2500 400 0 0 strain 0.01 -0.02 0 0.005 0 0 density 2700");
      command("sph_soil/refine all separation 0.55 smoothing 0.5");
    });
    ASSERT_EQ(lmp->atom->natoms, 400) << kernel;
    const double stress[6] = {-3000, -2000, -2500, 400, 0, 0}, strain[6] = {0.01, -0.02, 0, 0.005, 0, 0};
    for (const auto &entry : gather_state(lmp)) {
      const auto &s = entry.second;
      EXPECT_NEAR(s[9], 2700.0, 1e-12 * 2700.0) << kernel;
      for (int k = 0; k < 6; k++) {
        EXPECT_NEAR(s[11 + k], stress[k], 1e-12 * 3000.0) << kernel << " stress " << k;
        EXPECT_NEAR(s[17 + k], strain[k], 1e-15) << kernel << " strain " << k;
      }
    }
  }
}

// The paper's criterion (the strain since the start) splits the strained particles in the
// region, and their daughters again, up to maxlevel, within the 2:1 balance: no level 2 within
// 1.5 coarse supports (0.036) of a level-0 particle that may not split (outside the region),
// coarse neighbours of level-2 particles split too (also across the periodic boundary)
TEST_F(Refinement, FixSplitsStrainedParticlesInItsRegionUpToMaxlevel)
{
  patch(2, 10, false);
  HIDE_OUTPUT([&] {
    command("velocity all set 0 0 0 units box");
    command("sph_soil/set all stress 0 0 0 0 0 0");
    // strained (measure 0.09 > 0.05) in the left half only
    command("region left block 0 5 INF INF INF INF");
    command("group left region left");
    command("sph_soil/set left strain 0.3 0 0 0 0 0");
    command("region low block INF INF 0 8 INF INF");
    command("fix integrate all sph/soil cfl 0.1");
    command("fix refine all sph/soil/refine 1 maxlevel 2 region low since start");
    command("run 3 post no");
  });
  auto avec = soil_avec(lmp);
  int local_bad = 0, local_level2 = 0;
  for (int i = 0; i < lmp->atom->nlocal; i++) {
    const double x = lmp->atom->x[i][0], y = lmp->atom->x[i][1];
    const int level = avec->level[i];
    if (level > 2) local_bad++;
    // strained in the region: split at least once; outside the region: never
    if (x < 0.05 && y < 0.08 && level < 1) local_bad++;
    if (y > 0.08 && level != 0) local_bad++;
    // level 2: strained, and 0.036 from the level-0 particles outside (y = 0.085 and -0.005)
    if (level == 2) {
      local_level2++;
      if (x > 0.05 || y < 0.031 || y > 0.049) local_bad++;
    }
  }
  int bad = 0, level2 = 0;
  MPI_Allreduce(&local_bad, &bad, 1, MPI_INT, MPI_SUM, MPI_COMM_WORLD);
  MPI_Allreduce(&local_level2, &level2, 1, MPI_INT, MPI_SUM, MPI_COMM_WORLD);
  EXPECT_EQ(bad, 0);
  EXPECT_GT(level2, 0);
  // the thermo output: per-level counts add up to all atoms, the total split matches
  const double n0 = fix_vector("refine", 2), n1 = fix_vector("refine", 3), n2 = fix_vector("refine", 4);
  EXPECT_EQ(n0 + n1 + n2, (double) lmp->atom->natoms);
  EXPECT_EQ((double) lmp->atom->natoms, 100 + 3 * fix_vector("refine", 1));
  EXPECT_EQ(n2, level2);
  // balanced: no pair more than one level apart at the next check
  HIDE_OUTPUT([&] { command("run 1 post no"); });
  EXPECT_EQ(fix_vector("refine", 5), 0.0);
}

// A daughter is judged on the strain since its birth (the default, since split): strained
// particles that do not strain further split once, whatever maxlevel; with the paper's
// criterion (since start) they split at every check down to maxlevel. The strain at birth
// comes back from a restart file.
TEST_F(Refinement, DaughtersDoNotSplitAgainOnTheirParentsStrain)
{
  auto levels = [&](const std::string &since) {
    patch_at_rest("stress 0 0 0 0 0 0 strain 0.3 0 0 0 0 0", "sph/soil/refine 1 maxlevel 3 since " + since);
    HIDE_OUTPUT([&] { command("run 4 post no"); });
    return std::vector<double>{fix_vector("refine", 2), fix_vector("refine", 3), fix_vector("refine", 4),
                               fix_vector("refine", 5)};
  };
  EXPECT_EQ(levels("split"), (std::vector<double>{0, 144, 0, 0}));
  EXPECT_EQ(levels("start"), (std::vector<double>{0, 0, 0, 2304}));
  // the strain at birth travels with restart files: no split after a restart either
  levels("split");
  HIDE_OUTPUT([&] {
    command("write_restart refine.restart");
    command("clear");
    command("read_restart refine.restart");
    command("pair_style sph/soil");
    command(SOIL);
    command("neighbor 0.003 bin");
    command("fix integrate all sph/soil cfl 0.1");
    command("fix refine all sph/soil/refine 1 maxlevel 3");
    command("run 2 post no");
  });
  EXPECT_EQ(lmp->atom->natoms, 144);
}

// A merged particle is born at the merge: daughters at maxlevel that strained beyond the
// threshold since their split (they cannot split further) merge back, once quiet, into parents
// that do not split again when they move (an average of the daughters' strains at birth would
// hand the parents the daughters' strain since their split, and they would split at the first
// kick and merge again, for ever).
TEST_F(Refinement, MergedParticlesAreJudgedFromTheMerge)
{
  patch(2, 6, false);
  HIDE_OUTPUT([&] {
    command("sph_soil/set all stress 0 0 0 0 0 0 strain 0.3 0 0 0 0 0");
    command("fix integrate all sph/soil cfl 0.1");
    command("fix refine all sph/soil/refine 1 maxlevel 1 merge 1e-3");
  });
  kick();    // (a quiet particle does not split)
  HIDE_OUTPUT([&] { command("run 1 post no"); });
  ASSERT_EQ(lmp->atom->natoms, 144);
  HIDE_OUTPUT([&] {
    command("velocity all set 0 0 0 units box");
    command("sph_soil/set all strain 0.6 0 0 0 0 0");    // 0.3 since the split, at maxlevel
    command("run 200 post no");
  });
  EXPECT_EQ(lmp->atom->natoms, 36);
  EXPECT_EQ(fix_vector("refine", 5), 36.0);    // every family merged once
  kick();
  HIDE_OUTPUT([&] { command("run 2 post no"); });
  EXPECT_EQ(lmp->atom->natoms, 36);
  EXPECT_EQ(fix_vector("refine", 1), 36.0);    // the first split only
}

// With merging, a quiet particle does not split, whatever its strain since its birth: the
// hysteresis between splitting and merging holds both ways (no split, merge, split cycle in a
// deposit at rest). Without merging it splits.
TEST_F(Refinement, QuietParticlesDoNotSplitWhileMerging)
{
  auto splits_at_rest = [&](const std::string &merging) {
    patch_at_rest("stress 0 0 0 0 0 0", "sph/soil/refine 1 maxlevel 1 " + merging);
    HIDE_OUTPUT([&] {
      command("run 20 post no");                              // quiet for more than 1e-5 s
      command("sph_soil/set all strain 0.3 0 0 0 0 0");       // above the threshold
      command("run 2 post no");
    });
    return fix_vector("refine", 1);
  };
  EXPECT_EQ(splits_at_rest("merge 1e-5"), 0.0);
  EXPECT_EQ(splits_at_rest(""), 36.0);
}

// ... and when it moves again it is judged on its strain since it was last quiet: a patch at
// rest whose strain crept past the threshold (set here), then kicked above the quiet line, does
// not split (it did when the strain was counted from the split: in a collapse's deposit each
// merge's kick split such particles, their neighbours with them for the balance, and they
// merged back a hold time later, over and over). The paper's criterion, of the strain since the
// start, splits every kicked particle; and one that deforms by the threshold after its rest
// splits.
TEST_F(Refinement, ParticlesMovingAgainAreJudgedOnTheStrainSinceTheyWereQuiet)
{
  auto splits_after_kick = [&](const std::string &since, const std::string &then) {
    patch_at_rest("stress 0 0 0 0 0 0", "sph/soil/refine 1 maxlevel 1 merge 1e-3 since " + since);
    HIDE_OUTPUT([&] {
      command("run 40 post no");                              // quiet for more than 1e-3 s
      command("sph_soil/set all strain 0.3 0 0 0 0 0");       // crept past the threshold
      command("run 2 post no");
    });
    kick();
    HIDE_OUTPUT([&] {
      command(then);
      command("run 1 post no");
    });
    return fix_vector("refine", 1);
  };
  EXPECT_EQ(splits_after_kick("split", "print kicked"), 0.0);
  EXPECT_EQ(splits_after_kick("start", "print kicked"), 36.0);
  // deformed by the threshold again (0.6 - 0.3 since the rest): the kicked particles split
  EXPECT_EQ(splits_after_kick("split", "sph_soil/set all strain 0.6 0 0 0 0 0"), 36.0);
}

// Merge: a zone that wants particles down to level 3 for a while and then none; with 'merge',
// the families merge back once quiet for the hold time, one level at a time: mass and linear
// momentum are conserved to round-off, the stress stays admissible, the levels stay balanced,
// and the patch ends with its particles of the start (the same IDs). Split-merge cycles over
// 1000 checks lose no particle.
TEST_F(Refinement, SiblingsMergeBackConservingMassAndMomentum)
{
  patch(2, 12, true);
  HIDE_OUTPUT([&] {
    command("fix integrate all sph/soil cfl 0.1");
    command("variable on equal step<60");
    command("variable zone atom ((x-0.06)^2+(y-0.06)^2<0.02^2)*v_on");
    command("fix refine all sph/soil/refine 10 criterion v_zone maxlevel 3 merge 2e-4");
  });
  const auto before = mass_and_momentum();
  HIDE_OUTPUT([&] { command("run 60 post no"); });
  EXPECT_GT(lmp->atom->natoms, 144);
  EXPECT_GT(fix_vector("refine", 5), 0.0);    // level 3 reached
  HIDE_OUTPUT([&] { command("run 400 post no"); });
  const auto after = mass_and_momentum();
  EXPECT_EQ(lmp->atom->natoms, 144);
  EXPECT_NEAR(after[0], before[0], 1e-14 * before[0]);
  for (int a = 1; a < 3; a++) EXPECT_NEAR(after[a], before[a], 1e-13 * before[0] * 0.02);
  EXPECT_TRUE(stresses_admissible());
  EXPECT_EQ(fix_vector("refine", 6), 0.0);    // balanced
  EXPECT_GT(fix_vector("refine", 7), 0.0);    // families merged
  // the IDs of the start
  tagint local_max = 0, max_tag = 0;
  for (int i = 0; i < lmp->atom->nlocal; i++) local_max = std::max(local_max, lmp->atom->tag[i]);
  MPI_Allreduce(&local_max, &max_tag, 1, MPI_LMP_TAGINT, MPI_MAX, MPI_COMM_WORLD);
  EXPECT_EQ(max_tag, 144);

  // cycles: the zone wants for 20 steps of every 40, checks every 2 steps, 2000 steps
  HIDE_OUTPUT([&] {
    command("unfix refine");
    command("variable on equal (step%40)<20");
    command("fix refine all sph/soil/refine 2 criterion v_zone maxlevel 2 merge 1e-5");
    command("run 2000 post no");
  });
  EXPECT_GT(fix_vector("refine", 1), 1000.0);
  EXPECT_GT(fix_vector("refine", 6), 100.0);
  const auto cycled = mass_and_momentum();
  EXPECT_NEAR(cycled[0], before[0], 1e-13 * before[0]);
  // every particle is whole: the count is the start's plus 3 per split less 3 per merge
  const double splits = fix_vector("refine", 1), merges = fix_vector("refine", 6);
  EXPECT_EQ((double) lmp->atom->natoms, 144 + 3 * splits - 3 * merges);
}

// Orphans: families short of a sibling (one daughter of each deleted) never merge as families;
// their members merge in clusters of four by proximity, conserving
// mass and linear momentum to round-off, the stress admissible and the levels balanced, and
// few are left over.
TEST_F(Refinement, OrphansMergeInClusters)
{
  orphans_patch(1);
  const double families = fix_vector("refine", 1);
  ASSERT_GT(families, 40.0);
  const double orphans = fix_vector("refine", 3);
  EXPECT_EQ(orphans, 3.0 * families);
  const auto before = mass_and_momentum();
  HIDE_OUTPUT([&] { command("run 600 post no"); });
  const auto after = mass_and_momentum();
  EXPECT_EQ(fix_vector("refine", 5), fix_vector("refine", 6));    // every merge a cluster's
  EXPECT_NEAR(after[0], before[0], 1e-14 * before[0]);
  for (int a = 1; a < 3; a++) EXPECT_NEAR(after[a], before[a], 1e-13 * before[0] * 0.02);
  EXPECT_EQ(fix_vector("refine", 4), 0.0);    // balanced
  // every merge takes four orphans; at most a fifth of them is left
  EXPECT_EQ(fix_vector("refine", 3), orphans - 4.0 * fix_vector("refine", 6));
  EXPECT_LE(fix_vector("refine", 3), 0.2 * orphans);
  EXPECT_TRUE(stresses_admissible());
}

// Orphans of two types (two materials, here of the same soil) never share a cluster: the mass
// of each type is conserved to round-off while orphans merge.
TEST_F(Refinement, OrphansOfDifferentTypesDoNotMerge)
{
  orphans_patch(2);
  auto mass_of_type_2 = [&]() {
    double local = 0.0, global = 0.0;
    for (int i = 0; i < lmp->atom->nlocal; i++)
      if (lmp->atom->type[i] == 2) local += lmp->atom->rmass[i];
    MPI_Allreduce(&local, &global, 1, MPI_DOUBLE, MPI_SUM, MPI_COMM_WORLD);
    return global;
  };
  const double before = mass_of_type_2();
  HIDE_OUTPUT([&] { command("run 600 post no"); });
  EXPECT_GT(fix_vector("refine", 6), 0.0);    // clusters merged
  EXPECT_NEAR(mass_of_type_2(), before, 1e-14 * before);
}

TEST_F(Refinement, SameSplitsOnOneAndTwoRanks)
{
  patch(2, 12, true);
  expect_same_on_one_rank({"units si", "dimension 2", "atom_style sph/soil", "atom_modify map array",
                           "read_data refine.data", "pair_style sph/soil", SOIL, "neighbor 0.003 bin",
                           "thermo 0", "fix integrate all sph/soil cfl 0.1",
                           "fix refine all sph/soil/refine 5 threshold 1e-8", "run 60 post no"},
                          {1, 2, 7, 8, 10}, 1e-10);
}

// Under atom_style hybrid the splits go through the hybrid style: the other sub-style's fields
// (here the charge) are copied to the daughters, and nothing is lost or crashes.
TEST_F(Refinement, WorksUnderAtomStyleHybrid)
{
  patch(2, 6, false, "hybrid sph/soil charge");
  HIDE_OUTPUT([&] {
    command("set group all charge 0.25");
    command("sph_soil/refine all separation 0.5 smoothing 0.5");
  });
  ASSERT_EQ(lmp->atom->natoms, 4 * 36);
  for (int i = 0; i < lmp->atom->nlocal; i++) EXPECT_EQ(lmp->atom->q[i], 0.25) << "atom " << lmp->atom->tag[i];
  const double mass = mass_and_momentum()[0];
  EXPECT_NEAR(mass, 36 * 2650 * 1e-4, 1e-12);
  HIDE_OUTPUT([&] {
    command("fix integrate all sph/soil cfl 0.1");
    command("fix refine all sph/soil/refine 5 threshold 1e-12 maxlevel 2");
    command("run 10 post no");
  });
  ASSERT_EQ(lmp->atom->natoms, 16 * 36);
  for (int i = 0; i < lmp->atom->nlocal; i++) EXPECT_EQ(lmp->atom->q[i], 0.25) << "atom " << lmp->atom->tag[i];
  EXPECT_NEAR(mass_and_momentum()[0], mass, 1e-12);
}

// criterion v_name: exactly the particles where the atom-style variable is non-zero split, with
// the fix and with the command (the lattice sites x < 0.04, y < 0.03: 4 x 3 of them)
// A criterion of a variable that uses a compute sees the compute's values of the check's step:
// the fix makes LAMMPS's computes current before it evaluates the variable. (Before, LAMMPS
// re-evaluated a compute in a variable only after something cleared the computes' flags, e.g.
// the thermo output: the shear-rate criterion of the examples saw rates up to a thermo interval
// old, and a fix halt in the input, which clears them every step, changed the splits.)
TEST_F(Refinement, AVariableCriterionSeesItsComputesOfTheCheck)
{
  patch(2, 10, false);
  HIDE_OUTPUT([&] {
    command("compute rates all sph/soil/atom shear_strain_rate");
    command("variable never atom c_rates>1e30");
    command("fix integrate all sph/soil cfl 0.1");
    command("fix refine all sph/soil/refine 10 criterion v_never");
    command("thermo 1000");
    command("run 35 post no");
  });
  auto compute = lmp->modify->compute[lmp->modify->find_compute("rates")];
  EXPECT_EQ(compute->invoked_peratom, 30);    // the last check, not the first (10)
}

TEST_F(Refinement, VariableCriterionSplitsExactlyWhereNonZero)
{
  auto check = [&](const char *what) {
    int parents_local = 0, strays_local = 0;
    for (int i = 0; i < lmp->atom->nlocal; i++) {
      const double *x = lmp->atom->x[i];
      const bool inside = x[0] < 0.04 && x[1] < 0.03;    // daughters stay within d/4 of a site
      if (soil_avec(lmp)->level[i] == 1) {
        if (inside) parents_local++;
        else strays_local++;
      } else if (inside) {
        strays_local++;
      }
    }
    int parents, strays;
    MPI_Allreduce(&parents_local, &parents, 1, MPI_INT, MPI_SUM, MPI_COMM_WORLD);
    MPI_Allreduce(&strays_local, &strays, 1, MPI_INT, MPI_SUM, MPI_COMM_WORLD);
    EXPECT_EQ(parents, 4 * 12) << what;
    EXPECT_EQ(strays, 0) << what;
    EXPECT_EQ(lmp->atom->natoms, 100 + 3 * 12) << what;
  };
  patch(2, 10, false);
  HIDE_OUTPUT([&] {
    command("variable corner atom \"x < 0.04 && y < 0.03\"");
    command("fix integrate all sph/soil cfl 0.1");
    command("fix refine all sph/soil/refine 1 criterion v_corner");
    command("run 1 post no");
  });
  check("fix sph/soil/refine");

  HIDE_OUTPUT([&] {
    command("clear");
    command("units si");
  });
  patch(2, 10, false);
  HIDE_OUTPUT([&] {
    command("variable corner atom \"x < 0.04 && y < 0.03\"");
    command("sph_soil/refine all criterion v_corner");
  });
  check("sph_soil/refine");
}

// A buffer b splits, with a particle the criterion wants, the particles within b kernel supports
// (b 2h, cubic spline) of it: on the square lattice of spacing d = 1 cm and h = 1.2 cm, around
// the site (5.5, 5.5) cm, 4 sites within 0.5 support (1.2 cm), 20 within 1 support (2.4 cm).
// On two ranks the wanted particle is at the edge of its rank's half: the buffer crosses it.
TEST_F(Refinement, ABufferSplitsTheParticlesWithinItsReachOfAWantedParticle)
{
  auto count = [&](const char *what, double reach, int expected_sites) {
    // daughters lie within d/4 (each way) of their parent's site
    const bigint far = count_atoms(lmp, [&](int i) {
      const double *x = lmp->atom->x[i];
      return soil_avec(lmp)->level[i] == 1 && std::hypot(x[0] - 0.055, x[1] - 0.055) > reach + 0.0036;
    });
    EXPECT_EQ(lmp->atom->natoms, 100 + 3 * expected_sites) << what;
    EXPECT_EQ(far, 0) << what;
  };
  for (double buffer : {0.0, 0.5, 1.0}) {
    const double reach = buffer * 2.0 * 0.012;
    int sites = 1;
    for (int ix = -3; ix <= 3; ix++)
      for (int iy = -3; iy <= 3; iy++)
        if ((ix || iy) && std::hypot(ix, iy) * 0.01 < reach) sites++;
    ASSERT_EQ(sites, buffer == 0.0 ? 1 : buffer == 0.5 ? 5 : 21);
    for (const char *style : {"fix sph/soil/refine", "sph_soil/refine"}) {
      HIDE_OUTPUT([&] {
        command("clear");
        command("units si");
      });
      patch(2, 10, false);
      HIDE_OUTPUT([&] {
        command("variable centre atom \"abs(x-0.055) < 0.001 && abs(y-0.055) < 0.001\"");
        if (std::string(style) == "sph_soil/refine") {
          command(fmt::format("sph_soil/refine all criterion v_centre buffer {}", buffer));
        } else {
          command("fix integrate all sph/soil cfl 0.1");
          command(fmt::format("fix refine all sph/soil/refine 1 criterion v_centre buffer {}", buffer));
          command("run 1 post no");
        }
      });
      count(fmt::format("{} buffer {}", style, buffer).c_str(), reach, sites);
    }
  }
}

// A particle at maxlevel that the criterion wants still widens the refined zone: the coarser
// particles whose kernel reaches it split (a shear band at the finest level keeps fine
// particles around it). One site split first, its 4 daughters (level 1, d/4 from the site
// (5.5, 5.5) cm each way) wanted at maxlevel 1: the level-0 sites within one support of their
// own (2h = 2.4 cm) of a daughter split.
TEST_F(Refinement, ABufferWidensAroundWantedParticlesAtMaxlevel)
{
  patch(2, 10, false);
  HIDE_OUTPUT([&] {
    command("variable centre atom \"abs(x-0.055) < 0.001 && abs(y-0.055) < 0.001\"");
    command("sph_soil/refine all criterion v_centre");
    command("compute level all sph/soil/atom level");
    command("variable fine atom c_level>0");
    command("fix integrate all sph/soil cfl 0.1");
    command("fix refine all sph/soil/refine 1 maxlevel 1 criterion v_fine buffer 1");
    command("run 1 post no");
  });
  int sites = 0;
  for (int ix = -3; ix <= 3; ix++)
    for (int iy = -3; iy <= 3; iy++) {
      double nearest = 1.0;
      for (double dx : {-0.0025, 0.0025})
        for (double dy : {-0.0025, 0.0025}) nearest = std::min(nearest, std::hypot(ix * 0.01 - dx, iy * 0.01 - dy));
      if ((ix || iy) && nearest < 0.024) sites++;
    }
  ASSERT_EQ(sites, 20);    // (a reach of the daughters' own supports, 1.2 cm, would split 8)
  EXPECT_EQ(lmp->atom->natoms, 100 + 3 + 3 * sites);
  // the deepest level is 1: the wanted daughters at maxlevel did not split
  EXPECT_GT(count_atoms(lmp, [&](int i) { return soil_avec(lmp)->level[i] == 1; }), 0);
  EXPECT_EQ(count_atoms(lmp, [&](int i) { return soil_avec(lmp)->level[i] > 1; }), 0);
}

// With merge T, the daughters in the buffer of a wanted particle are not quiet while their
// parent's kernel would reach it (else they would merge back, and their parent, in the buffer
// again, split at the next check: a cycle of the hold time); once nothing is wanted they merge.
TEST_F(Refinement, BufferedDaughtersDoNotMergeWhileTheirParentWouldBeBuffered)
{
  patch(2, 10, false);
  HIDE_OUTPUT([&] {
    command("variable on equal 1");
    command("variable centre atom \"v_on && abs(x-0.055) < 0.003 && abs(y-0.055) < 0.003\"");
    command("fix integrate all sph/soil");
    command("timestep 1e-6");
    command("fix refine all sph/soil/refine 1 maxlevel 1 criterion v_centre buffer 1 merge 5e-6");
    command("run 30 post no");
  });
  EXPECT_EQ(lmp->atom->natoms, 100 + 3 * 21);
  EXPECT_EQ(fix_vector("refine", 5), 0.0);    // merges (after split, total, 2 levels, unbalanced)
  HIDE_OUTPUT([&] {
    command("variable on equal 0");
    command("run 30 post no");
  });
  EXPECT_EQ(lmp->atom->natoms, 100);
  EXPECT_EQ(fix_vector("refine", 5), 21.0);
}

// Computes that build a neighbour list of their own (rdf, property/local) at the steps where
// particles split: the split leaves the ghosts rebuilt and LAMMPS's lists valid (before, the
// occasional list's build crashed at such a step), and they see the daughters.
TEST_F(Refinement, LocalComputesRunAtSplitSteps)
{
  patch(2, 12, true);
  HIDE_OUTPUT([&] {
    command("fix integrate all sph/soil cfl 0.1");
    command("fix refine all sph/soil/refine 5 threshold 1e-9 maxlevel 2");
    command("compute rdf all rdf 20 cutoff 0.02");
    command("fix rdf all ave/time 5 1 5 c_rdf[*] mode vector");
  });
  // (LAMMPS 29Sep2021's property/local wants a pair style with single(), which this one has not)
  bool has_pairs = true;
  HIDE_OUTPUT([&] {
    try {
      command("compute pairs all property/local patom1 patom2");
      command("run 0 post no");
    } catch (LAMMPSException &) {
      has_pairs = false;
      command("uncompute pairs");
    }
    if (has_pairs) command("dump pairs all local 5 pairs.dump c_pairs[*]");
    command("run 10 post no");
  });
  // two checks split: 144 -> 576 -> most daughters again, and the pairs of the last split step
  EXPECT_GT(lmp->atom->natoms, 576);
  if (!has_pairs) return;
  auto pairs = lmp->modify->compute[lmp->modify->find_compute("pairs")];
  bigint rows = pairs->size_local_rows, all_rows = 0;
  MPI_Allreduce(&rows, &all_rows, 1, MPI_LMP_BIGINT, MPI_SUM, MPI_COMM_WORLD);
  EXPECT_GT(all_rows, lmp->atom->natoms);
}

TEST_F(Refinement, RestartAfterSplitsContinuesIdentically)
{
  patch(2, 12, true);
  expect_restart_continues({"fix integrate all sph/soil cfl 0.1", "fix refine all sph/soil/refine 5 threshold 1e-8"});
}

// ease T: daughters born with the smoothing ratio of the split's least defect (0.84 at
// separation 0.5, h/d = 1.2 in 2D: split_stress_defect()), their h then linear in time down to
// alpha_r h_p = 6 mm at T, exactly; the ghosts follow (on two ranks the run below is the same as on one,
// SameSplitsOnOneAndTwoRanks), and a restart in the middle of the easing continues it.
TEST_F(Refinement, EasedDaughtersGoFromTheBalancedToTheLevelsSmoothingLength)
{
  patch(2, 10, false);
  HIDE_OUTPUT([&] {
    command("variable centre atom \"abs(x-0.055) < 0.001 && abs(y-0.055) < 0.001\"");
    command("fix integrate all sph/soil");
    command("timestep 1e-6");
    command("fix refine all sph/soil/refine 1 criterion v_centre ease 9.5e-6 maxlevel 1");
    command("run 1 post no");    // split at the end of step 1 (t = 1e-6)
  });
  auto daughters_h = [&](double &lo, double &hi) {
    double mine[2] = {HUGE_VAL, -HUGE_VAL}, all[2];
    for (int i = 0; i < lmp->atom->nlocal; i++)
      if (soil_avec(lmp)->level[i] == 1) {
        mine[0] = std::min(mine[0], soil_avec(lmp)->smoothing_length[i]);
        mine[1] = std::max(mine[1], soil_avec(lmp)->smoothing_length[i]);
      }
    MPI_Allreduce(&mine[0], &all[0], 1, MPI_DOUBLE, MPI_MIN, MPI_COMM_WORLD);
    MPI_Allreduce(&mine[1], &all[1], 1, MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD);
    lo = all[0];
    hi = all[1];
  };
  double lo, hi;
  daughters_h(lo, hi);
  EXPECT_NEAR(lo, 0.012 * 0.84, 1e-12);
  EXPECT_NEAR(hi, 0.012 * 0.84, 1e-12);
  // 5 and 10 steps after the birth (eased at the start of each step, before its forces); T is
  // not a whole number of steps: the last step past it sets the final h exactly
  for (double remaining : {1.0 - 5.0 / 9.5, 0.0}) {
    HIDE_OUTPUT([&] { command("run 5 post no"); });
    daughters_h(lo, hi);
    EXPECT_NEAR(lo, 0.006 * (1.0 + (0.84 / 0.5 - 1.0) * remaining), 1e-12) << remaining;
    EXPECT_NEAR(hi, lo, 1e-15) << remaining;
  }
  // the ghosts carry the owners' h at every step
  for (int i = lmp->atom->nlocal; i < lmp->atom->nlocal + lmp->atom->nghost; i++) {
    const int owner = lmp->atom->map(lmp->atom->tag[i]);
    if (owner >= 0 && owner < lmp->atom->nlocal)
      EXPECT_EQ(soil_avec(lmp)->smoothing_length[i], soil_avec(lmp)->smoothing_length[owner]);
  }
}

// Easing on one and two ranks: the same h, positions and stress to round-off (compared while
// the daughters of the splits at steps 5 and 10 ease: the ghosts follow their owners' h). Over
// longer runs the two drift apart faster than without easing (5e-6 of the stress after 80
// steps, against under 1e-7): the daughters pass through a smoothing ratio where pairs are
// unstable (Cond. 1), which grows round-off.
TEST_F(Refinement, EasingIsTheSameOnOneAndTwoRanks)
{
  patch(2, 12, true);
  expect_same_on_one_rank({"units si", "dimension 2", "atom_style sph/soil", "atom_modify map array",
                           "read_data refine.data", "pair_style sph/soil", SOIL, "neighbor 0.003 bin",
                           "thermo 0", "fix integrate all sph/soil cfl 0.1",
                           "fix refine all sph/soil/refine 5 threshold 1e-8 maxlevel 2 ease 1e-3",
                           "run 14 post no"},
                          {1, 2, 7, 8, 10, 11, 12, 14}, 1e-10);
}

TEST_F(Refinement, RestartWhileDaughtersEaseContinuesIdentically)
{
  patch(2, 12, true);
  // some daughters are still easing at the restart: born in the last 1e-3 before it
  expect_restart_continues({"fix integrate all sph/soil cfl 0.1",
                            "fix refine all sph/soil/refine 5 threshold 1e-8 ease 1e-3"},
                           [&] {
                             EXPECT_GT(count_atoms(lmp, [&](int i) {
                                         return soil_avec(lmp)->level[i] == 1 &&
                                             soil_avec(lmp)->smoothing_length[i] > 0.006 * (1.0 + 1e-9);
                                       }), 0);
                           });
}

TEST_F(Refinement, UnstableParametersAreReported)
{
  patch(2, 6, false);
  HIDE_OUTPUT([&] {
    command("fix integrate all sph/soil cfl 0.1");
    command("fix refine all sph/soil/refine 10 separation 0.55 smoothing 0.7");
  });
  auto output = CAPTURE_OUTPUT([&] { command("run 0 post no"); });
  if (rank() != 0) return;
  EXPECT_THAT(output, testing::HasSubstr("E_a = 0.01137, E_b = 0.0139"));
  EXPECT_THAT(output, testing::HasSubstr("WARNING: Fix sph/soil/refine: separation 0.55 and smoothing "
                                         "0.7 (h/d = 1.2) are in the unstable region for d_ij/d_ref "
                                         "= 1.0 (unstable (Cond. 1 2))"));
}

