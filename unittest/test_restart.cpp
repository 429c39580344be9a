// Restart files of SPH_SOIL: the materials travel in them (no pair_coeff after read_restart), a
// run continues exactly whenever the file was written (before the first run, between runs,
// during a run) and under whichever fix sph/soil ID, and a file of another format stops with a
// message naming both formats.
#include "sph_soil_testing.h"

#include "fix.h"
#include "fix_sph_soil.h"
#include "force.h"
#include "modify.h"
#include "pair_sph_soil.h"

#include <cmath>
#include <fstream>
#include <sstream>

using namespace LAMMPS_NS;
using namespace SPHSoilTesting;

namespace {

class Restart : public SoilTest {
 protected:

  // a soil column in a box of walls (floor no-slip, sides mirror, frictional right wall), under
  // gravity, refined where it strains: the state a restart must carry; with the continuity
  // equation that is not the default, which the file must carry too
  void walled_refining_column()
  {
    HIDE_OUTPUT([&] {
      for (const auto &line : walled_column_commands()) command(line);
      command("sph_soil/set soil geostatic 0.1 1850 9.81 0.5");
      command("pair_style sph/soil alpha 0.2 continuity mass");
      command("pair_coeff 1 1 soil 1850 1.5e6 0.3 30 0 0");
      command("pair_coeff 2 2 wall friction 0.4");
      command("variable push atom 0.3*(x>0.05)");
      command("velocity soil set v_push 0 0 units box");
      command("neighbor 0.001 bin");
      command("timestep 2e-5");
      command("thermo 0");
    });
  }
  const std::vector<std::string> column_fixes = {
      "fix integrate soil sph/soil cfl 0.1", "fix down soil gravity 9.81 vector 0 -1 0",
      "fix refine soil sph/soil/refine 10 threshold 1e-6 maxlevel 1"};

  // a periodic patch with pair style and coefficients, no fix
  void patch()
  {
    HIDE_OUTPUT([&] {
      for (const auto &line : periodic_patch_commands()) command(line);
      command("variable vx atom 0.02*sin(2*PI*y/0.16)");
      command("velocity all set v_vx NULL NULL units box");
      command("pair_style sph/soil");
      command("pair_coeff 1 1 soil 2650 0.7e6 0.3 19.8 0 0");
      command("neighbor 0.002 bin");
      command("timestep 2e-5");
      command("thermo 0");
    });
  }

  void commands(const std::vector<std::string> &lines)
  {
    HIDE_OUTPUT([&] {
      for (const auto &line : lines) command(line);
    });
  }

  // every value of every atom within the round-off of a change of summation order
  static void expect_same_state(const std::map<tagint, std::vector<double>> &restarted,
                                const std::map<tagint, std::vector<double>> &reference)
  {
    SPHSoilTesting::expect_same_state(restarted, reference, 1e-11, 1e-15);
  }
};

// The materials and the pair style's settings are in the restart file: a refined run with
// walls continues after read_restart with its fixes only, as if uninterrupted.
TEST_F(Restart, ARefinedRunWithWallsContinuesWithoutPairCoeff)
{
  walled_refining_column();
  commands(column_fixes);
  commands({"run 200 post no", "write_restart column.restart", "run 200 post no"});
  const auto uninterrupted = gather_state(lmp);
  const double splits = lmp->modify->fix[lmp->modify->find_fix("refine")]->compute_vector(1);
  ASSERT_GT(splits, 0.0) << "the column should have refined";
  commands({"clear", "read_restart column.restart", "neighbor 0.001 bin", "thermo 0"});
  commands(column_fixes);
  commands({"run 200 post no"});
  expect_same_state(gather_state(lmp), uninterrupted);
}

// A run with three levels, the 2:1 balance and merging continues exactly after a restart in
// its middle: the levels, each particle's strain at birth, since when it is quiet and its
// families travel with the atoms.
TEST_F(Restart, DeepRefinementWithMergingContinuesExactly)
{
  const std::vector<std::string> fixes = {
      "fix integrate all sph/soil cfl 0.1",
      "variable zone atom ((x-0.1)^2+(y-0.08)^2<0.02^2)*(step<60)",
      "fix refine all sph/soil/refine 10 criterion v_zone maxlevel 3 merge 3e-4"};
  patch();
  commands(fixes);
  commands({"run 80 post no", "write_restart merging.restart", "run 150 post no"});
  const auto uninterrupted = gather_state(lmp);
  auto refine = lmp->modify->fix[lmp->modify->find_fix("refine")];
  ASSERT_GT(refine->compute_vector(7), 0.0) << "families should have merged";
  commands({"clear", "read_restart merging.restart", "neighbor 0.002 bin", "thermo 0"});
  commands(fixes);
  commands({"run 150 post no"});
  expect_same_state(gather_state(lmp), uninterrupted);
}

// Orphans (families short of a sibling) keep their state across a restart in the middle of
// their merging in clusters: the continued run merges the same clusters. The soil is elastic
// (phi = 0, a huge cohesion), as in the parallel tests: the holes the deletion leaves set off
// waves, and whether a soil particle is on its yield surface flips at round-off, which a change
// of summation order (the atoms' order after read_restart on 2 ranks) brings about.
TEST_F(Restart, OrphansMergingContinueExactly)
{
  const std::vector<std::string> fixes = {
      "pair_coeff 1 1 soil 2650 0.7e6 0.3 0 0 1e12",
      "fix integrate all sph/soil cfl 0.1",
      "variable zone atom ((x-0.1)^2+(y-0.08)^2<0.05^2)*(step<20)",
      "fix refine all sph/soil/refine 10 criterion v_zone maxlevel 1 merge 1e-3"};
  patch();
  commands(fixes);
  commands({"run 20 post no", "variable first atom id>320&&(id-321)%3==0", "group first variable first",
            "delete_atoms group first compress no", "run 60 post no", "write_restart orphans.restart",
            "run 200 post no"});
  const auto uninterrupted = gather_state(lmp);
  auto refine = lmp->modify->fix[lmp->modify->find_fix("refine")];
  ASSERT_GT(refine->compute_vector(6), 0.0) << "orphans should have merged";
  commands({"clear", "read_restart orphans.restart", "neighbor 0.002 bin", "thermo 0"});
  commands(fixes);
  commands({"run 200 post no"});
  refine = lmp->modify->fix[lmp->modify->find_fix("refine")];
  EXPECT_GT(refine->compute_vector(6), 0.0) << "orphans should merge after the restart too";
  expect_same_state(gather_state(lmp), uninterrupted);
}

// A restart file written before the first run holds no rates of a last step (none was
// computed): the continued run starts from its set-up's rates, as the uninterrupted one does.
TEST_F(Restart, AFileWrittenBeforeTheFirstRunContinuesExactly)
{
  patch();
  commands({"fix integrate all sph/soil", "write_restart first.restart", "run 100 post no"});
  const auto uninterrupted = gather_state(lmp);
  commands({"clear", "read_restart first.restart", "neighbor 0.002 bin", "thermo 0",
            "fix integrate all sph/soil", "run 100 post no"});
  expect_same_state(gather_state(lmp), uninterrupted);
}

// The rates of the last step travel with the atoms, not with the fix's ID: fix sph/soil under
// another ID after read_restart continues exactly. And a file written during a run (restart
// command) carries the rates of its step.
TEST_F(Restart, AnotherFixIDAndAFileWrittenDuringARunContinueExactly)
{
  patch();
  commands({"fix integrate all sph/soil", "run 50 post no", "restart 70 during.*.restart",
            "write_restart between.restart", "run 100 post no"});
  const auto uninterrupted = gather_state(lmp);
  commands({"clear", "read_restart between.restart", "neighbor 0.002 bin", "thermo 0",
            "fix another_id all sph/soil", "run 100 post no"});
  expect_same_state(gather_state(lmp), uninterrupted);
  commands({"clear", "read_restart during.140.restart", "neighbor 0.002 bin", "thermo 0",
            "fix integrate all sph/soil", "run 10 post no"});
  expect_same_state(gather_state(lmp), uninterrupted);
}

// Saturated soil under free water, with the full gradient correction: the pore pressure, its flow of
// the last step, the materials with their pore water and the pair style's gradient_correction
// travel in the file; the run continues exactly
TEST_F(Restart, SaturatedSoilAndWaterContinueExactly)
{
  commands(soil_and_water_patch_commands("pair_style sph/soil gradient_correction full"));
  commands({"variable vx atom 0.02*sin(2*PI*y/0.16)", "velocity all set v_vx NULL NULL units box",
            "neighbor 0.002 bin", "thermo 0", "fix integrate all sph/soil cfl 0.1",
            "run 50 post no", "write_restart saturated.restart", "run 100 post no"});
  const auto uninterrupted = gather_state(lmp);
  commands({"clear", "read_restart saturated.restart", "neighbor 0.002 bin", "thermo 0",
            "fix integrate all sph/soil cfl 0.1", "run 100 post no"});
  expect_same_state(gather_state(lmp), uninterrupted);
}

// A restart file of another layout stops read_restart with both format numbers. The files are
// made from a current one: the atom style's arguments "format 3" (LAMMPS stores them after the
// style's name) changed to "format 7", or removed (a file from before formats had numbers).
TEST_F(Restart, AFileOfAnotherFormatStopsWithBothFormats)
{
  patch();
  commands({"fix integrate all sph/soil", "run 5 post no", "write_restart current.restart"});
  std::string bytes;
  if (rank() == 0) {
    std::ifstream in("current.restart", std::ios::binary);
    std::ostringstream buffer;
    buffer << in.rdbuf();
    bytes = buffer.str();
    // int 2 (arguments), int 7, "format\0", int 2, "3\0"
    const std::string format("format\0", 7);
    const size_t at = bytes.find(format);
    ASSERT_NE(at, std::string::npos);
    const size_t start = at - 2 * sizeof(int), value = at + 7 + sizeof(int);
    ASSERT_EQ(bytes.substr(value, 2), std::string("3\0", 2));
    std::string other = bytes;
    other[value] = '7';
    std::ofstream("other.restart", std::ios::binary) << other;
    const int none = 0;
    std::string old = bytes.substr(0, start) + std::string((const char *) &none, sizeof(int)) +
        bytes.substr(value + 2);
    std::ofstream("old.restart", std::ios::binary) << old;
  }
  MPI_Barrier(MPI_COMM_WORLD);
  commands({"clear"});
  EXPECT_LAMMPS_ERROR(".*Restart file holds atom_style sph/soil data of format 7; this build of "
                      "SPH_SOIL reads format 3: read it with the build that wrote it and save the "
                      "state with write_data.*",
                      command("read_restart other.restart"));
  commands({"clear"});
  EXPECT_LAMMPS_ERROR(".*Restart file holds atom_style sph/soil data without a format number, "
                      "written before 2026-12-03 \\(format 1\\); this build of SPH_SOIL reads "
                      "format 3.*",
                      command("read_restart old.restart"));
}

// fix sph/soil's own record: the elapsed time behind -(its format); an older record began with
// the time itself (>= 0)
TEST_F(Restart, AnOlderFixRecordStopsWithBothFormats)
{
  patch();
  commands({"fix integrate all sph/soil"});
  auto fix = lmp->modify->fix[lmp->modify->find_fix("integrate")];
  double older[2] = {0.001, 50.0};
  EXPECT_LAMMPS_ERROR(".*Fix sph/soil integrate: the restart file holds its data in format 1; "
                      "this build of SPH_SOIL reads format 2.*",
                      fix->restart(reinterpret_cast<char *>(older)));
}

}    // namespace

// pair_style sph/soil's settings of format 1, written before the continuity keyword by runs of
// the mass form, are read and go on with the mass form; the settings written now are of the
// current format.
TEST_F(Restart, PairSettingsOfTheFormatBeforeContinuityGoOnWithTheMassForm)
{
  patch();    // the default, the volume form
  auto pair = dynamic_cast<PairSPHSoil *>(lmp->force->pair);
  ASSERT_NE(pair, nullptr);
  FILE *old = tmpfile();
  const int format = 1, flags[2] = {0, 0};
  const double numbers[4] = {1.0, 1.0, 0.0, 0.3};
  fwrite(&format, sizeof(int), 1, old);
  fwrite(flags, sizeof(int), 2, old);
  fwrite(numbers, sizeof(double), 4, old);
  rewind(old);
  pair->read_restart_settings(old);
  fclose(old);
  FILE *now = tmpfile();
  pair->write_restart_settings(now);
  rewind(now);
  int written_format = 0, written_flags[3] = {-1, -1, -1};
  ASSERT_EQ(fread(&written_format, sizeof(int), 1, now), 1u);
  ASSERT_EQ(fread(written_flags, sizeof(int), 3, now), 3u);
  fclose(now);
  EXPECT_EQ(written_format, PairSPHSoil::RESTART_FORMAT);
  EXPECT_EQ(written_flags[2], 0) << "the mass form";
}
