// Soil against wall particles moved by LAMMPS fixes: the image of a moving wall moves with it,
// and the soil's force on the wall particles is the opposite of the wall's force on the soil.
#include "sph_soil_testing.h"

#include "atom_vec_sph_soil.h"

#include <algorithm>
#include <cmath>

using namespace LAMMPS_NS;
using namespace SPHSoilTesting;

namespace {

class Walls : public SoilTest {
 protected:

  // a 2D block of soil (20 x 10 particles) on a floor against a left wall
  void soil_in_a_corner(const std::string &newton = "on", const std::string &wall = "wall")
  {
    HIDE_OUTPUT([&] {
      command("newton " + newton);
      command("dimension 2");
      command("boundary f f p");
      command("atom_style sph/soil");
      command("atom_modify map array");
      command("lattice sq 0.002 origin 0.5 0.5 0");
      command("region box block -0.01 0.06 -0.01 0.04 -0.001 0.001 units box");
      command("create_box 2 box");
      command("region soil block 0 0.04 0 0.02 INF INF units box");
      command("region floor block -0.006 0.046 -0.006 0 INF INF units box");
      command("region left block -0.006 0 0 0.03 INF INF units box");
      command("create_atoms 1 region soil");
      command("create_atoms 2 region floor");
      command("create_atoms 2 region left");
      command("group soil type 1");
      command("group floor region floor");
      command("group left region left");
      command("group wall type 2");
      command("sph_soil/set all mass $(2650*0.002*0.002) h 0.0024 density 2650");
      command("sph_soil/set floor wall 0 0 0 0 1 0");
      command("sph_soil/set left wall 0 0 0 1 0 0");
      command("pair_style sph/soil alpha 1 beta 1");
      command("pair_coeff 1 1 soil 2650 0.7e6 0.3 19.8 0 0");
      command("pair_coeff 2 2 " + wall);
      command("fix integrate soil sph/soil");
      command("neighbor 0.0005 bin");
      command("neigh_modify every 1 delay 0 check yes");
      command("timestep 1.0e-5");
      command("thermo 0");
    });
  }

  // the largest |strain rate| component over the soil particles of all ranks
  double max_soil_strain_rate()
  {
    auto avec = soil_avec(lmp);
    double local = 0.0, global = 0.0;
    for (int i = 0; i < lmp->atom->nlocal; i++)
      if (lmp->atom->type[i] == 1)
        for (int k = 0; k < 6; k++) local = std::max(local, std::fabs(avec->strain_rate[i][k]));
    MPI_Allreduce(&local, &global, 1, MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD);
    return global;
  }

  // sum of f over the atoms of `type` (0: all), and the sum of |f| over all atoms
  std::vector<double> force_sums(int type)
  {
    std::vector<double> local(4, 0.0), global(4, 0.0);
    auto atom = lmp->atom;
    for (int i = 0; i < atom->nlocal; i++) {
      for (int a = 0; a < 2; a++) {
        if (type == 0 || atom->type[i] == type) local[a] += atom->f[i][a];
        local[2 + a] += std::fabs(atom->f[i][a]);
      }
    }
    MPI_Allreduce(local.data(), global.data(), 4, MPI_DOUBLE, MPI_SUM, MPI_COMM_WORLD);
    return global;
  }
};

}    // namespace

// Everything translating at the same velocity, the walls moved by fix move, the soil by fix
// sph/soil, no stress and no gravity: the soil sees walls at rest relative to it and stays
// unstrained. (With the image of a wall at rest, -(d_w/d_s) v_s, the soil next to the walls
// would shear at about beta v / h = 80 /s.)
TEST_F(Walls, RigidTranslationWithMovingWallsLeavesTheSoilUnstrained)
{
  soil_in_a_corner();
  HIDE_OUTPUT([&] {
    // the walls move from the start: fix move sets their velocity from its first step on,
    // the force evaluation of the set-up needs it too
    command("velocity all set 0.1 0.05 0 units box");
    command("fix slide wall move linear 0.1 0.05 NULL units box");
    command("run 100 post no");
  });
  EXPECT_LE(max_soil_strain_rate(), 1.0e-12);
  auto state = gather_state(lmp);
  for (const auto &entry : state) {
    const auto &s = entry.second;
    EXPECT_NEAR(s[4], 0.1, 1.0e-14) << "atom " << entry.first;
    EXPECT_NEAR(s[5], 0.05, 1.0e-14) << "atom " << entry.first;
  }
}

// Without body forces the force on soil plus walls sums to zero (Newton's third law: the wall
// particles take the opposite of the soil's share of every soil-wall pair), and the walls'
// share is the soil's force on them, with and without newton_pair.
TEST_F(Walls, SoilAndWallForcesObeyNewtonsThirdLaw)
{
  bool first = true;
  for (const std::string wall : {"wall", "wall boundary extrapolate", "wall friction 0.3"})
    for (const std::string newton : {"on", "off"}) {
      if (!first) HIDE_OUTPUT([&] { command("clear"); command("units si"); });
      first = false;
      soil_in_a_corner(newton, wall);
      HIDE_OUTPUT([&] {
        command("variable vx atom 0.05*sin(2*PI*y/0.02)");
        command("velocity soil set v_vx -0.02 0 units box");
        command("sph_soil/set soil stress -1000 -1500 -1000 100 0 0");
        command("run 20 post no");
      });
      const auto all = force_sums(0), soil = force_sums(1), walls = force_sums(2);
      const double scale = all[2] + all[3];
      ASSERT_GT(scale, 0.0);
      for (int a = 0; a < 2; a++) {
        EXPECT_NEAR(all[a], 0.0, 1.0e-13 * scale) << wall << ", newton " << newton << " component " << a;
        EXPECT_NEAR(walls[a], -soil[a], 1.0e-13 * scale) << wall << ", newton " << newton << " component " << a;
      }
      // the soil pushes the floor down and the left wall to the left
      EXPECT_LT(walls[1], -0.01 * scale) << wall << ", newton " << newton;
      EXPECT_LT(walls[0], -0.001 * scale) << wall << ", newton " << newton;
    }
}

// A column of soil in its at-rest state between smooth (free-slip) walls stays at rest: the
// image behind a free-slip wall has the mirrored stress, so the wall carries no shear traction
// and the horizontal force on a side wall stays at 0.5 K0 gamma H^2. (With the soil's own stress
// on the image, as behind a no-slip wall, the walls' shear traction drove the column away from
// rest: the side force rose to 1.7 times the at-rest value within 0.2 s.)
TEST_F(Walls, AtRestColumnBetweenFreeSlipWallsStaysAtRest)
{
  HIDE_OUTPUT([&] {
    for (const auto &line : walled_column_commands()) command(line);
    command("sph_soil/set soil geostatic 0.1 1850 9.81 0.5");
    command("pair_style sph/soil alpha 1 beta 1 wall freeslip");
    command("pair_coeff 1 1 soil 1850 1.5e6 0.3 30 0 0");
    command("pair_coeff 2 2 wall");
    command("fix gravity soil gravity 9.81 vector 0 -1 0");
    command("fix integrate soil sph/soil");
    command("timestep 1.0e-5");
    command("thermo 0");
    command("run 5000 post no");
  });
  const double at_rest = 0.5 * 0.5 * 1850 * 9.81 * 0.1 * 0.1;    // 0.5 K0 gamma H^2
  auto walls = force_sums(2);
  // the right wall alone: sum over its atoms
  double local = 0.0, global = 0.0;
  for (int i = 0; i < lmp->atom->nlocal; i++)
    if (lmp->atom->type[i] == 2 && lmp->atom->x[i][0] > 0.1) local += lmp->atom->f[i][0];
  MPI_Allreduce(&local, &global, 1, MPI_DOUBLE, MPI_SUM, MPI_COMM_WORLD);
  EXPECT_NEAR(global / at_rest, 1.0, 0.05);    // measured 1.03 at 25 particles per H
  // the floor carries the weight
  const double weight = 1850 * 9.81 * 0.1 * 0.1;
  EXPECT_NEAR(-walls[1] / weight, 1.0, 0.02);
  double vmax = 0.0;
  for (const auto &entry : gather_state(lmp))
    if (entry.second[0] == 1)
      vmax = std::max(vmax, std::hypot(entry.second[4], entry.second[5]));
  EXPECT_LT(vmax, 5.0e-3);
}

// Coulomb friction (pair_coeff 2 2 wall friction mu): a strong block of soil on a floor, under
// gravity tilted by the slope angle theta, sticks for tan(theta) < mu (the floor then carries
// the tilt's shear, tan(theta) times the weight) and slides for tan(theta) > mu, with a rigid
// block's acceleration g (sin(theta) - mu cos(theta)) and the floor's shear force mu times its
// normal force; a very large mu holds it as a no-slip wall does; a smooth wall lets it slide
// with g sin(theta). (doc/theory.rst 4.4; the friction of the earlier, stress-driven law was
// 0.71 of the normal force while sliding, and the block accelerated at 0.33 m/s^2 instead of
// 1.68.)
namespace {
// mean x velocity of the soil (type 1) of all ranks
double mean_soil_velocity_x(LAMMPS_NS::LAMMPS *lmp)
{
  double local[2] = {0.0, 0.0}, global[2];
  for (int i = 0; i < lmp->atom->nlocal; i++)
    if (lmp->atom->type[i] == 1) {
      local[0] += lmp->atom->v[i][0];
      local[1] += 1.0;
    }
  MPI_Allreduce(local, global, 2, MPI_DOUBLE, MPI_SUM, MPI_COMM_WORLD);
  return global[0] / global[1];
}
}    // namespace

TEST_F(Walls, BlockOnAFrictionalSlopeSticksBelowAndSlidesAboveTheFrictionAngle)
{
  const double g = 9.81, mu = 0.4, dt = 1.0e-5;
  struct Case {
    double tan_theta;
    std::string slip;
    double adhesion;    // c_a with mu = 0: the interface holds c_a L, L the block's length
  };
  // the block's mass and length (per unit thickness), and the adhesion that holds its weight's
  // tangential part at tan(theta) = 1.5 mu
  const double mass = 160 * 2000 * 0.002 * 0.002, length = 0.08;
  const double holding = mass * g * std::sin(std::atan(1.5 * mu)) / length;
  // tan(theta) = 0.8 mu and 1.5 mu with friction; free slip, no slip and mu = 1000 at 1.5 mu;
  // mu = 0 with twice and half the adhesion that holds the block
  const std::string friction = "friction " + std::to_string(mu);
  for (const Case &c : {Case{0.8 * mu, friction, 0.0}, Case{1.5 * mu, friction, 0.0},
                        Case{1.5 * mu, "freeslip", 0.0}, Case{1.5 * mu, "noslip", 0.0},
                        Case{1.5 * mu, "friction 1000", 0.0}, Case{1.5 * mu, "", 2.0 * holding},
                        Case{1.5 * mu, "", 0.5 * holding}}) {
    const double theta = std::atan(c.tan_theta);
    const std::string slip =
        c.adhesion > 0.0 ? fmt::format("friction 0 adhesion {}", c.adhesion) : c.slip;
    std::vector<double> velocity;
    std::vector<double> wall_force;
    HIDE_OUTPUT([&] {
      command("clear");
      command("units si");
      command("dimension 2");
      command("boundary f f p");
      command("atom_style sph/soil");
      command("atom_modify map array");
      command("lattice sq 0.002 origin 0.5 0.5 0");
      command("region box block -0.01 0.2 -0.01 0.03 -0.001 0.001 units box");
      command("create_box 2 box");
      // a flat block, 40 x 4 particles
      command("region soil block 0 0.08 0 0.008 INF INF units box");
      command("region floor block -0.006 0.196 -0.006 0 INF INF units box");
      command("create_atoms 1 region soil");
      command("create_atoms 2 region floor");
      command("group soil type 1");
      command("group floor type 2");
      command("sph_soil/set all mass $(2000*0.002*0.002) h 0.0024 density 2000");
      // the normal stress of the block's weight, no shear: the tilt loads the contact
      command(fmt::format("sph_soil/set soil geostatic 0.008 2000 {} 0.5", g * std::cos(theta)));
      command("sph_soil/set floor wall 0 0 0 0 1 0");
      command("pair_style sph/soil alpha 1 beta 1 artificial_stress 0");
      // elastic: a cohesion far above the block's stresses, and no artificial stress (which the
      // cohesion switches on; with it this block at 1.5 mu slows down instead of sliding:
      // doc/theory.rst section 2.5)
      command("pair_coeff 1 1 soil 2000 2e6 0.3 30 0 1e5");
      command("pair_coeff 2 2 wall " + slip);
      command(fmt::format("fix gravity soil gravity {} vector {} {} 0", g, std::sin(theta),
                          -std::cos(theta)));
      command("fix integrate soil sph/soil");
      command("neighbor 0.0005 bin");
      command("neigh_modify every 1 delay 0 check yes");
      command(fmt::format("timestep {}", dt));
      command("thermo 0");
      for (int k = 0; k < 5; k++) {
        command("run 2000 post no");
        velocity.push_back(mean_soil_velocity_x(lmp));
      }
      const auto walls = force_sums(2);
      wall_force = {walls[0], walls[1]};
    });
    const double smooth = g * std::sin(theta), rigid_sliding = g * (std::sin(theta) - mu * std::cos(theta));
    // the mean acceleration over the last 0.08 s
    const double acceleration = (velocity[4] - velocity[0]) / (8000 * dt);
    if (rank() == 0)
      std::cerr << slip << " tan(theta)/mu " << c.tan_theta / mu << ": acceleration "
              << acceleration << " (rigid block sliding " << rigid_sliding << ", smooth " << smooth
              << "), v(0.1 s) " << velocity[4] << ", wall force ratio "
              << -wall_force[0] / wall_force[1] << "\n";
    if (c.slip == "freeslip") {
      EXPECT_NEAR(acceleration / smooth, 1.0, 1.0e-3);
    } else if (c.adhesion > 0.0 && c.adhesion < holding) {
      // sliding against the adhesion alone: the floor's shear is c_a L (the pairs' contact
      // areas add up to the block's length)
      EXPECT_NEAR(acceleration / (smooth - c.adhesion * length / mass), 1.0, 0.02);
      EXPECT_NEAR(wall_force[0] / (c.adhesion * length), 1.0, 0.02);
    } else if (c.slip == friction && c.tan_theta > mu) {
      // sliding: a rigid block's acceleration, the floor's shear mu times its normal force
      EXPECT_NEAR(acceleration / rigid_sliding, 1.0, 0.01);
      EXPECT_NEAR(-wall_force[0] / wall_force[1], mu, 0.02 * mu);
    } else {
      // sticking: at rest to 1e-6 m/s, the floor carries the tilt's shear
      EXPECT_LT(std::fabs(velocity[4]), 1.0e-6) << slip << " tan " << c.tan_theta;
      EXPECT_NEAR(-wall_force[0] / wall_force[1], c.tan_theta, 1.0e-3 * c.tan_theta);
    }
  }
}

// mu = 0 is the smooth wall to the bit: a block pushed along a floor of friction 0 and the same
// block on a free-slip floor end in the same state (positions, velocities, stresses).
TEST_F(Walls, FrictionZeroIsTheFreeSlipWall)
{
  std::vector<std::map<tagint, std::vector<double>>> states;
  for (const std::string slip : {"freeslip", "friction 0"}) {
    HIDE_OUTPUT([&] {
      command("clear");
      command("units si");
    });
    soil_in_a_corner("on", "wall " + slip);
    HIDE_OUTPUT([&] {
      command("fix gravity soil gravity 9.81 vector 0.5 -1 0");
      command("velocity soil set 0.02 0 0 units box");
      command("run 500 post no");
    });
    states.push_back(gather_state(lmp));
  }
  ASSERT_EQ(states[0].size(), states[1].size());
  for (const auto &entry : states[0]) {
    const auto &other = states[1].at(entry.first);
    for (size_t k = 0; k < entry.second.size(); k++)
      EXPECT_EQ(entry.second[k], other[k]) << "atom " << entry.first << " value " << k;
  }
}

// Wall normals turn with the wall: a wall particle's normal is its dipole orientation mu, which
// the fixes that rotate atoms with their orientation turn with them. A plate of wall particles
// (normal +y) next to a block of soil turns about the z axis, by fix move rotate (update
// dipole) and as a free rigid body (fix rigid); its normals stay the analytic ones to 1e-12.
class TurningWalls : public Walls {
 protected:
  // a 20 x 4 plate of wall particles centred at the origin, its upper face y = 0.003 facing +y,
  // and a block of soil above it, clear of the plate's sweep
  void plate_and_soil()
  {
    command("dimension 2");
    command("boundary f f p");
    command("atom_style sph/soil");
    command("atom_modify map array");
    command("lattice sq 0.002 origin 0.5 0.5 0");
    command("region box block -0.04 0.04 -0.04 0.06 -0.001 0.001 units box");
    command("create_box 2 box");
    command("region plate block -0.02 0.02 -0.003 0.003 INF INF units box");
    command("region soil block -0.01 0.01 0.03 0.04 INF INF units box");
    command("create_atoms 2 region plate");
    command("create_atoms 1 region soil");
    command("group plate type 2");
    command("group soil type 1");
    command("sph_soil/set all mass $(2650*0.002*0.002) h 0.0024 density 2650");
    command("sph_soil/set plate wall 0 0.003 0 0 1 0");
    command("pair_style sph/soil");
    command("pair_coeff 1 1 soil 2650 0.7e6 0.3 19.8 0 0");
    command("pair_coeff 2 2 wall");
    command("fix integrate soil sph/soil");
    command("neighbor 0.0005 bin");
    command("neigh_modify every 1 delay 0 check yes");
    command("comm_modify vel yes");
    command("timestep 1.0e-5");
    command("thermo 0");
  }
  // every wall particle's normal is (-sin(angle), cos(angle), 0)
  void expect_normals_turned_by(double angle)
  {
    const auto state = gather_state(lmp);
    const auto &names = state_names();
    const int nx = std::find(names.begin(), names.end(), "wall_nx") - names.begin();
    int walls = 0;
    for (const auto &entry : state) {
      if (entry.second[0] != 2) continue;
      walls++;
      EXPECT_NEAR(entry.second[nx], -std::sin(angle), 1.0e-12) << "atom " << entry.first;
      EXPECT_NEAR(entry.second[nx + 1], std::cos(angle), 1.0e-12) << "atom " << entry.first;
      EXPECT_NEAR(entry.second[nx + 2], 0.0, 1.0e-12) << "atom " << entry.first;
    }
    EXPECT_EQ(walls, 80);    // 20 x 4: the rows at y = -0.003 and 0.003 included
  }
};

TEST_F(TurningWalls, FixMoveRotateTurnsTheNormals)
{
  bool has_update_dipole = true;
  HIDE_OUTPUT([&] {
    plate_and_soil();
    try {
      command("fix turn plate move rotate 0 0 0 0 0 1 0.05 units box update dipole");
    } catch (LAMMPS_NS::LAMMPSException &) {
      has_update_dipole = false;
    }
  });
  // LAMMPS of 2025 and later: fix move's 'update dipole'
  if (!has_update_dipole) GTEST_SKIP() << "this LAMMPS's fix move has no 'update dipole'";
  HIDE_OUTPUT([&] { command("run 1300 post no"); });
  // 0.013 s of a 0.05 s period
  expect_normals_turned_by(2.0 * M_PI * 0.013 / 0.05);
}

TEST_F(TurningWalls, FixRigidTurnsTheNormals)
{
  const double omega = 3.0;    // rad/s about z
  HIDE_OUTPUT([&] {
    plate_and_soil();
    command(fmt::format("variable vx atom -{}*y", omega));
    command(fmt::format("variable vy atom {}*x", omega));
    command("velocity plate set v_vx v_vy 0 units box");
    command("fix body plate rigid single");
    command("run 5000 post no");
  });
  // the body's angle from its atoms: the direction of the plate's long axis, from the first to
  // the last particle of its first row (create_atoms numbers them first, x fastest)
  const auto state = gather_state(lmp);
  const auto &first = state.at(1), &last = state.at(20);
  const double angle = std::atan2(last[2] - first[2], last[1] - first[1]);
  EXPECT_NEAR(angle, omega * 0.05, 0.02 * omega * 0.05);    // a free body turns at omega
  expect_normals_turned_by(angle);
}

// fix rigid/small turns the plate as fix rigid does (the walls find the fixes that may turn them
// by what they do, not by their style's name): the normals turn with the body, and the soil
// next to the plate sees the same turned walls, on every rank, as with fix rigid.
TEST_F(TurningWalls, FixRigidSmallTurnsTheNormalsAsFixRigid)
{
  const double omega = 3.0;    // rad/s about z
  auto turned = [&](const std::string &rigid) {
    HIDE_OUTPUT([&] {
      command("clear");
      command("units si");
      plate_and_soil();
      command("fix molecules all property/atom mol ghost yes");
      command("set group plate mol 1");
      command("comm_modify vel yes cutoff 0.03");
      command(fmt::format("variable vx atom -{}*y", omega));
      command(fmt::format("variable vy atom {}*x", omega));
      command("velocity plate set v_vx v_vy 0 units box");
      command("velocity soil set 0 -1.0 0 units box");
      command(rigid);
      command("run 3000 post no");
    });
    return gather_state(lmp);
  };
  const auto rigid = turned("fix body plate rigid single");
  const auto small = turned("fix body plate rigid/small molecule");
  const auto &first = small.at(1), &last = small.at(20);
  const double angle = std::atan2(last[2] - first[2], last[1] - first[1]);
  EXPECT_GT(angle, 0.05);
  expect_normals_turned_by(angle);
  // the soil (which has struck the turning plate) moves as with fix rigid, to the round-off of
  // two integrators that the impact amplifies (1e-5 of the velocity measured; a stale normal on
  // a ghost would change the contact's force by its whole size)
  for (const auto &entry : rigid) {
    if (entry.second[0] != 1) continue;
    const auto &s = small.at(entry.first);
    for (int k = 1; k <= 5; k++)
      EXPECT_NEAR(s[k], entry.second[k], 1e-3 * (0.1 + std::fabs(entry.second[k])))
          << "atom " << entry.first << " " << state_names()[k];
  }
}

// Soil striking a free rigid body: the block of soil falls (no gravity, 1 m/s) onto the plate,
// a free body under fix rigid, and pushes it away: the momentum of soil plus body is
// conserved to round-off through the impact (the body takes the soil's reaction, Newton's
// third law, and fix rigid integrates it), while the body gains a good part of it.
TEST_F(TurningWalls, SoilAndAFreeRigidBodyConserveMomentum)
{
  auto momentum = [&](int type) {
    double local[2] = {0.0, 0.0}, global[2];
    for (int i = 0; i < lmp->atom->nlocal; i++)
      if (type == 0 || lmp->atom->type[i] == type)
        for (int a = 0; a < 2; a++) local[a] += lmp->atom->rmass[i] * lmp->atom->v[i][a];
    MPI_Allreduce(local, global, 2, MPI_DOUBLE, MPI_SUM, MPI_COMM_WORLD);
    return std::vector<double>{global[0], global[1]};
  };
  HIDE_OUTPUT([&] {
    plate_and_soil();
    command("velocity soil set 0.2 -1.0 0 units box");
    command("fix body plate rigid single");
    command("run 0 post no");
  });
  const auto before = momentum(0);
  HIDE_OUTPUT([&] { command("run 4000 post no"); });
  const auto after = momentum(0), body = momentum(2);
  const double scale = std::hypot(before[0], before[1]);
  for (int a = 0; a < 2; a++) EXPECT_NEAR(after[a], before[a], 1.0e-12 * scale) << "component " << a;
  // the impact happened: the body moves down with a tenth or more of the momentum
  EXPECT_LT(body[1], 0.1 * before[1]);
}
