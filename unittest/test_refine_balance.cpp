// The 2:1 level balance of refinement (soil_refine_balance.h): pure, no LAMMPS.

#include "soil_refine_balance.h"

#include "gtest/gtest.h"

#include <random>
#include <vector>

using namespace SPHSoil;

namespace {

// a graph of `n` particles, all owned, from undirected edges
struct Graph {
  std::vector<int> offsets, partners;
  LevelGraph graph;
  Graph(int n, const std::vector<std::pair<int, int>> &edges)
  {
    std::vector<std::vector<int>> adjacent(n);
    for (const auto &e : edges) {
      adjacent[e.first].push_back(e.second);
      adjacent[e.second].push_back(e.first);
    }
    offsets.push_back(0);
    for (const auto &a : adjacent) {
      partners.insert(partners.end(), a.begin(), a.end());
      offsets.push_back((int) partners.size());
    }
    graph = LevelGraph{n, offsets.data(), partners.data()};
  }
};

// the whole check of sph_soil_refine_balance.cpp on one rank: limit, the wanted splits, raise
std::vector<int> check(const Graph &g, const std::vector<int> &level, const std::vector<int> &wanted,
                       const std::vector<char> &may_split)
{
  const int n = (int) level.size();
  std::vector<int> deepest(n), new_level(level);
  for (int i = 0; i < n; i++) deepest[i] = level[i] + (may_split[i] ? 1 : 0);
  while (limit_new_levels(g.graph, level.data(), deepest.data()) > 0) {}
  for (int i : wanted)
    if (deepest[i] > level[i]) new_level[i] = level[i] + 1;
  while (raise_coarse_neighbours(g.graph, level.data(), new_level.data(), may_split.data()) > 0) {}
  return new_level;
}

}    // namespace

// a level-1 particle that splits next to a level-0 one makes it split first (in the same check)
TEST(RefineBalance, CoarseNeighbourSplitsWithTheFineOne)
{
  const Graph g(3, {{0, 1}, {1, 2}, {0, 2}});
  EXPECT_EQ(check(g, {0, 1, 1}, {2}, {1, 1, 1}), (std::vector<int>{1, 1, 2}));
  EXPECT_EQ(count_unbalanced(g.graph, std::vector<int>{1, 1, 2}.data()), 0);
}

// forced splits cascade down a chain of ever coarser neighbours
TEST(RefineBalance, ForcedSplitsCascade)
{
  const Graph g(4, {{0, 1}, {1, 2}, {2, 3}});
  EXPECT_EQ(check(g, {0, 1, 2, 3}, {3}, {1, 1, 1, 1}), (std::vector<int>{1, 2, 3, 4}));
}

// a split that a neighbour could not follow (outside the region, at maxlevel, another group)
// is called off, and forces nothing: a particle two links away stays as it is
TEST(RefineBalance, SplitANeighbourCannotFollowIsCalledOff)
{
  const Graph g(4, {{0, 1}, {1, 2}, {2, 3}});
  EXPECT_EQ(check(g, {0, 1, 1, 0}, {1}, {0, 1, 1, 1}), (std::vector<int>{0, 1, 1, 0}));
  // the other way round, it splits and drags its coarse neighbour along
  EXPECT_EQ(check(g, {0, 1, 1, 0}, {2}, {0, 1, 1, 1}), (std::vector<int>{0, 1, 2, 1}));
}

// pairs that motion has unbalanced are mended where the coarse particle may split, and counted
// once, from the coarse side
TEST(RefineBalance, MotionsImbalanceIsMendedAndCounted)
{
  const Graph g(3, {{0, 1}, {1, 2}});
  const std::vector<int> level{0, 2, 0};
  EXPECT_EQ(count_unbalanced(g.graph, level.data()), 2);
  EXPECT_EQ(check(g, level, {}, {1, 1, 0}), (std::vector<int>{1, 2, 0}));
  // it cannot be mended all at once (one split per check), and the fine particle does not split
  // further meanwhile
  const Graph pair(2, {{0, 1}});
  EXPECT_EQ(check(pair, {0, 3}, {1}, {1, 1}), (std::vector<int>{1, 3}));
}

// nothing wanted, nothing unbalanced: nothing changes
TEST(RefineBalance, BalancedLevelsStayAsTheyAre)
{
  const Graph g(5, {{0, 1}, {1, 2}, {2, 3}, {3, 4}});
  const std::vector<int> level{0, 1, 2, 1, 0};
  EXPECT_EQ(check(g, level, {}, {1, 1, 1, 1, 1}), level);
  EXPECT_EQ(count_unbalanced(g.graph, level.data()), 0);
}

// pairs of one level constrain nothing (the header): on random graphs, levels, wishes and
// permissions, leaving them out changes no check's outcome and no count
TEST(RefineBalance, PairsOfOneLevelMayBeLeftOut)
{
  std::mt19937 random(29);
  for (int trial = 0; trial < 200; trial++) {
    const int n = 30;
    std::vector<int> level(n);
    std::vector<char> may_split(n);
    std::vector<int> wanted;
    for (int i = 0; i < n; i++) {
      level[i] = (int) (random() % 4);
      may_split[i] = random() % 5 != 0;
      if (random() % 3 == 0) wanted.push_back(i);
    }
    std::vector<std::pair<int, int>> all, across;
    for (int i = 0; i < n; i++)
      for (int j = i + 1; j < n; j++)
        if (random() % 6 == 0) {
          all.push_back({i, j});
          if (level[i] != level[j]) across.push_back({i, j});
        }
    const Graph full(n, all), reduced(n, across);
    EXPECT_EQ(check(full, level, wanted, may_split), check(reduced, level, wanted, may_split));
    EXPECT_EQ(count_unbalanced(full.graph, level.data()), count_unbalanced(reduced.graph, level.data()));
  }
}
