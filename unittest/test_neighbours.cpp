// The pair style's own neighbour list (soil_neighbours.h) against a brute-force search: every
// pair within its own cutoff support * h_ij + skin (+ skin_per_h * h_ij) listed once, wall pairs
// never, plain partners before mirror-wall partners (and among them soil before extrapolating
// walls), ghosts on one of their two ranks; a list
// whose atoms have each moved less than half their own skin still holds every pair within the
// support.

#include "soil_neighbours.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <set>
#include <utility>
#include <vector>

using namespace SPHSoil;

namespace {

struct Particles {
  std::vector<std::vector<double>> coordinates;
  std::vector<const double *> rows;
  std::vector<double> h;
  std::vector<int> type;
  int nlocal = 0;
};

// atoms of types 1 (soil), 2 (mirror wall), 3 (extrapolated wall) with smoothing lengths of three
// refinement levels at random places; the last `ghosts` of them are ghosts
Particles random_particles(int n, int ghosts, int dimension, unsigned seed)
{
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> place(0.0, 1.0);
  std::uniform_int_distribution<int> level(0, 2), kind(1, 3);
  Particles p;
  for (int i = 0; i < n; i++) {
    p.coordinates.push_back({place(random), place(random), dimension == 3 ? place(random) : 0.0});
    p.h.push_back(0.06 / (1 << level(random)));
    p.type.push_back(kind(random));
  }
  for (auto &c : p.coordinates) p.rows.push_back(c.data());
  p.nlocal = n - ghosts;
  return p;
}

const int KIND_OF_TYPE[4] = {0, NEIGHBOUR_SOIL, NEIGHBOUR_MIRROR_WALL, NEIGHBOUR_EXTRAPOLATED_WALL};

NeighbourInput input_of(const Particles &p, int dimension, double skin, bool newton,
                        double skin_per_h = 0.0)
{
  NeighbourInput in;
  in.x = p.rows.data();
  in.h = p.h.data();
  in.type = p.type.data();
  in.kind_of_type = KIND_OF_TYPE;
  in.nlocal = p.nlocal;
  in.nall = (int) p.h.size();
  in.dimension = dimension;
  in.support = 2.0;
  in.skin = skin;
  in.skin_per_h = skin_per_h;
  in.newton = newton;
  return in;
}

bool within(const Particles &p, int i, int j, int dimension, double skin, double skin_per_h = 0.0)
{
  double r2 = 0.0;
  for (int a = 0; a < dimension; a++) {
    const double d = p.coordinates[i][a] - p.coordinates[j][a];
    r2 += d * d;
  }
  const double hij = 0.5 * (p.h[i] + p.h[j]);
  const double cut = 2.0 * hij + skin + skin_per_h * hij;
  return r2 < cut * cut;
}

void check_list(int dimension, bool newton, unsigned seed, double skin_per_h = 0.0)
{
  const double skin = skin_per_h > 0.0 ? 0.0 : 0.01;
  const Particles p = random_particles(600, 150, dimension, seed);
  NeighbourList list;
  list.build(input_of(p, dimension, skin, newton, skin_per_h));
  ASSERT_EQ(list.size(), p.nlocal);

  std::set<std::pair<int, int>> listed;
  for (int i = 0; i < p.nlocal; i++) {
    for (int jj = list.first(i); jj < list.end(i); jj++) {
      const int j = list.partner_data()[jj];
      const int kind_i = KIND_OF_TYPE[p.type[i]], kind_j = KIND_OF_TYPE[p.type[j]];
      EXPECT_TRUE(kind_i == NEIGHBOUR_SOIL || kind_j == NEIGHBOUR_SOIL) << "a wall-wall pair";
      if (newton) EXPECT_EQ(kind_i, NEIGHBOUR_SOIL) << "a wall particle's list with Newton's third law";
      EXPECT_TRUE(within(p, i, j, dimension, skin, skin_per_h))
          << i << " " << j << " beyond the cutoff";
      const bool mirror = kind_i == NEIGHBOUR_MIRROR_WALL || kind_j == NEIGHBOUR_MIRROR_WALL;
      EXPECT_EQ(mirror, jj >= list.plain_end(i)) << "partners not sorted by kind";
      const bool extrapolated = kind_i == NEIGHBOUR_EXTRAPOLATED_WALL || kind_j == NEIGHBOUR_EXTRAPOLATED_WALL;
      if (!mirror)
        EXPECT_EQ(extrapolated, jj >= list.extrapolated_begin(i)) << "extrapolated walls not after the soil";
      EXPECT_TRUE(listed.insert({std::min(i, j), std::max(i, j)}).second) << "listed twice";
    }
  }

  // every owned-owned pair within the cutoff once; a pair with a ghost: with Newton's third
  // law a soil pair where the ghost lies above (z, then y, then x), which holds on exactly one of
  // the two ranks (the other sees the mirrored separation), and a soil-wall pair where the soil
  // is owned (under the soil particle: a wall lists no partners); without, always
  const int nall = (int) p.h.size();
  std::size_t expected = 0;
  for (int i = 0; i < p.nlocal; i++)
    for (int j = i + 1; j < nall; j++) {
      const int kind_i = KIND_OF_TYPE[p.type[i]], kind_j = KIND_OF_TYPE[p.type[j]];
      if (kind_i != NEIGHBOUR_SOIL && kind_j != NEIGHBOUR_SOIL) continue;
      if (!within(p, i, j, dimension, skin, skin_per_h)) continue;
      bool keep = true;
      if (j >= p.nlocal && newton && kind_i != NEIGHBOUR_SOIL) {
        keep = false;
      } else if (j >= p.nlocal && newton && kind_j == NEIGHBOUR_SOIL) {
        const auto &xi = p.coordinates[i], &xj = p.coordinates[j];
        if (xj[2] != xi[2]) keep = xj[2] > xi[2];
        else if (xj[1] != xi[1]) keep = xj[1] > xi[1];
        else keep = xj[0] >= xi[0];
      }
      if (!keep) continue;
      expected++;
      EXPECT_TRUE(listed.count({i, j})) << "pair " << i << " " << j << " missing";
    }
  EXPECT_EQ(listed.size(), expected);
  EXPECT_EQ(list.pairs(), expected);
}

}    // namespace

TEST(NeighbourList, MatchesBruteForceIn2DWithNewton) { check_list(2, true, 1); }
TEST(NeighbourList, MatchesBruteForceIn2DWithoutNewton) { check_list(2, false, 2); }
TEST(NeighbourList, MatchesBruteForceIn3DWithNewton) { check_list(3, true, 3); }
TEST(NeighbourList, MatchesBruteForceIn3DWithoutNewton) { check_list(3, false, 4); }
TEST(NeighbourList, MatchesBruteForceWithASkinThatFollowsH)
{
  check_list(2, true, 5, 0.3);
  check_list(3, false, 6, 0.3);
}

// the skin that follows h: every atom moved (in a random direction) by just under half its own
// skin, every pair now within the support is still listed, and moved_beyond_skin() says no;
// one atom moved by half its skin, it says yes
TEST(NeighbourList, AtomsWithinHalfTheirSkinKeepEveryPairWithinTheSupport)
{
  for (int dimension = 2; dimension <= 3; dimension++) {
    const double skin_per_h = 0.3;
    Particles p = random_particles(800, 0, dimension, 10 + dimension);
    NeighbourList list;
    list.build(input_of(p, dimension, 0.0, true, skin_per_h));
    std::set<std::pair<int, int>> listed;
    for (int i = 0; i < p.nlocal; i++)
      for (int jj = list.first(i); jj < list.end(i); jj++) {
        const int j = list.partner_data()[jj];
        listed.insert({std::min(i, j), std::max(i, j)});
      }

    const auto original = p.coordinates;
    std::mt19937 random(99);
    std::normal_distribution<double> direction(0.0, 1.0);
    for (int i = 0; i < p.nlocal; i++) {
      double step[3] = {direction(random), direction(random), dimension == 3 ? direction(random) : 0.0};
      const double norm = std::sqrt(step[0] * step[0] + step[1] * step[1] + step[2] * step[2]);
      for (int a = 0; a < dimension; a++)
        p.coordinates[i][a] += 0.4999 * skin_per_h * p.h[i] * step[a] / norm;
    }
    EXPECT_FALSE(list.moved_beyond_skin(p.rows.data(), p.nlocal));
    int within_support = 0;
    for (int i = 0; i < p.nlocal; i++)
      for (int j = i + 1; j < p.nlocal; j++) {
        const int kind_i = KIND_OF_TYPE[p.type[i]], kind_j = KIND_OF_TYPE[p.type[j]];
        if (kind_i != NEIGHBOUR_SOIL && kind_j != NEIGHBOUR_SOIL) continue;
        if (!within(p, i, j, dimension, 0.0)) continue;
        within_support++;
        EXPECT_TRUE(listed.count({i, j})) << "pair " << i << " " << j << " lost within the support";
      }
    EXPECT_GT(within_support, 200);

    for (int a = 0; a < 3; a++) p.coordinates[7][a] = original[7][a];    // (rows point in)
    p.coordinates[7][1] += 0.5001 * skin_per_h * p.h[7];
    EXPECT_TRUE(list.moved_beyond_skin(p.rows.data(), p.nlocal));
    EXPECT_TRUE(list.moved_beyond_skin(p.rows.data(), p.nlocal - 1)) << "other atoms than built";
  }
}

// a refined particle lists about the neighbours of its own smoothing length: in a lattice of
// spacing d/2 and h/2 next to one of spacing d and h, the fine particles away from the coarse
// ones have the partners of a uniform fine lattice
TEST(NeighbourList, FineParticlesListTheNeighboursOfTheirOwnSmoothingLength)
{
  Particles p;
  const double d = 0.01, h = 1.2 * d, skin = 0.1 * d;
  for (int ix = 0; ix < 40; ix++)
    for (int iy = 0; iy < 40; iy++) {
      const bool fine = ix >= 20;
      if (fine) {
        for (int k = 0; k < 4; k++) {
          p.coordinates.push_back({(ix + 0.25 + 0.5 * (k % 2)) * d, (iy + 0.25 + 0.5 * (k / 2)) * d, 0.0});
          p.h.push_back(0.5 * h);
          p.type.push_back(1);
        }
      } else {
        p.coordinates.push_back({(ix + 0.5) * d, (iy + 0.5) * d, 0.0});
        p.h.push_back(h);
        p.type.push_back(1);
      }
    }
  for (auto &c : p.coordinates) p.rows.push_back(c.data());
  p.nlocal = (int) p.h.size();
  NeighbourList list;
  list.build(input_of(p, 2, skin, true));
  // interior atoms: each pair once, so half the partners within the cutoff per atom
  double fine_sum = 0.0, coarse_sum = 0.0;
  int fine_count = 0, coarse_count = 0;
  for (int i = 0; i < p.nlocal; i++) {
    const double x = p.coordinates[i][0], y = p.coordinates[i][1];
    if (y < 10 * d || y > 30 * d) continue;
    const int n = list.end(i) - list.first(i);
    if (x > 26 * d && x < 34 * d) {
      fine_sum += n;
      fine_count++;
    } else if (x > 6 * d && x < 14 * d) {
      coarse_sum += n;
      coarse_count++;
    }
  }
  const double fine_mean = fine_sum / fine_count, coarse_mean = coarse_sum / coarse_count;
  // a cutoff of 2.4 spacings plus the skin (in spacings) holds pi (2.4 + s)^2 / 2 partners
  const double pi = 3.14159265358979;
  EXPECT_NEAR(coarse_mean, pi * std::pow(2.4 + 0.1, 2) / 2, 1.5);
  EXPECT_NEAR(fine_mean, pi * std::pow(2.4 + 0.2, 2) / 2, 1.5);

  // a skin that follows h, 0.1 d for the coarse: the fine particles' reach in their spacings is
  // the coarse ones' in theirs, and so is their partner count
  list.build(input_of(p, 2, 0.0, true, 0.1 * d / h));
  double counts[2] = {0.0, 0.0};
  for (int i = 0; i < p.nlocal; i++) {
    const double x = p.coordinates[i][0], y = p.coordinates[i][1];
    if (y < 10 * d || y > 30 * d) continue;
    if (x > 26 * d && x < 34 * d) counts[0] += list.end(i) - list.first(i);
    if (x > 6 * d && x < 14 * d) counts[1] += list.end(i) - list.first(i);
  }
  EXPECT_NEAR(counts[0] / fine_count, pi * std::pow(2.4 + 0.1, 2) / 2, 1.5);
  EXPECT_NEAR(counts[1] / coarse_count, pi * std::pow(2.4 + 0.1, 2) / 2, 1.5);
}

// The atoms binned by smoothing length: a search returns exactly the atoms within the given
// reach or within their own support, with their squared distance, whatever the mix of h
TEST(Neighbours, SmoothingClassGridsFindExactlyTheAtomsThatReach)
{
  std::mt19937 random(11);
  std::uniform_real_distribution<double> position(0.0, 1.0);
  const int n = 600;
  std::vector<std::vector<double>> xs(n, std::vector<double>(3, 0.0));
  std::vector<const double *> x(n);
  std::vector<double> h(n);
  std::vector<int> members;
  for (int i = 0; i < n; i++) {
    xs[i][0] = position(random);
    xs[i][1] = position(random);
    x[i] = xs[i].data();
    h[i] = 0.02 * std::ldexp(1.0, -(i % 4));    // four levels
    if (i % 5 != 0) members.push_back(i);       // not every atom is a member
  }
  SPHSoil::SmoothingClassGrids grids;
  const double support = 2.0;
  grids.build(x.data(), h.data(), members, 2, support);
  for (int p = 0; p < 50; p++) {
    const double *point = x[p];
    const double reach = (p % 3) * 0.01;
    std::set<int> found, expected;
    grids.for_each_within(point, reach, [&](int j, double r2) {
      const double dx = point[0] - x[j][0], dy = point[1] - x[j][1];
      EXPECT_NEAR(r2, dx * dx + dy * dy, 1e-15);
      found.insert(j);
    });
    for (int j : members) {
      const double r = std::hypot(point[0] - x[j][0], point[1] - x[j][1]);
      if (r < std::max(reach, support * h[j])) expected.insert(j);
    }
    EXPECT_EQ(found, expected) << "point " << p;
  }
}
