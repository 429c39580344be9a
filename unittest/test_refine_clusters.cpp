// The clusters of orphans that merge by proximity (soil_refine_clusters.h): pure, no LAMMPS.

#include "soil_refine_clusters.h"

#include "gtest/gtest.h"

#include <algorithm>
#include <cmath>
#include <set>
#include <vector>

using namespace SPHSoil;

namespace {

struct Orphan {
  double x, y, tag;
};

// a square lattice of n x n orphans of spacing 1, disordered by a tenth of it, with IDs along
// the rows, as create_atoms numbers a lattice (IDs that follow space must not make the
// clusters grow from one corner, a few per look)
std::vector<Orphan> lattice(int n)
{
  std::vector<Orphan> o;
  for (int i = 0; i < n; i++)
    for (int j = 0; j < n; j++) {
      const int k = i * n + j;
      o.push_back({i + 0.1 * std::sin(1299.0 * k), j + 0.1 * std::sin(3711.0 * k),
                   (double) (1 + k)});
    }
  return o;
}

// one look of the merger on one rank: the three rounds over the orphans still there; the
// clusters found (the leader first)
std::vector<std::vector<int>> look(const std::vector<Orphan> &o, const std::vector<char> &there, double reach,
                                   int count, uint64_t salt = 0)
{
  const int n = (int) o.size();
  auto near = [&](int i, const std::vector<char> *only) {
    std::vector<NearOrphan> within;
    for (int j = 0; j < n; j++) {
      if (j == i || !there[j] || (only && !(*only)[j])) continue;
      const double r2 = (o[j].x - o[i].x) * (o[j].x - o[i].x) + (o[j].y - o[i].y) * (o[j].y - o[i].y);
      if (r2 <= reach * reach) within.push_back({o[j].tag, r2, j});
    }
    return within;
  };
  std::vector<char> leader(n, 0);
  for (int i = 0; i < n; i++) leader[i] = there[i] && leads_cluster(o[i].tag, near(i, nullptr), salt);
  std::vector<double> joined(n, 0.0);
  for (int i = 0; i < n; i++)
    if (there[i] && !leader[i]) joined[i] = joined_leader(near(i, &leader));
  std::vector<std::vector<int>> clusters;
  for (int i = 0; i < n; i++) {
    if (!leader[i]) continue;
    std::vector<NearOrphan> mine;
    for (const auto &c : near(i, nullptr))
      if (joined[c.index] == o[i].tag) mine.push_back(c);
    const auto members = cluster_members(mine, count - 1);
    if (members.empty()) continue;
    clusters.push_back({i});
    for (const auto &m : members) clusters.back().push_back(m.index);
  }
  return clusters;
}

}    // namespace

// Orphans of a 12 x 12 lattice, merged look after look (each look's clusters leave): no
// orphan in two clusters at a look, every cluster four orphans within the reach of its
// leader (the parent's h, 2.4 spacings), and in the end few orphans left over.
TEST(RefineClusters, EveryOrphanMergesOnceAndFewAreLeft)
{
  const auto o = lattice(12);
  const double reach = 2.4;
  std::vector<char> there(o.size(), 1);
  int looks = 0, merged = 0;
  for (;; looks++) {
    const auto clusters = look(o, there, reach, 4);
    if (clusters.empty()) break;
    std::set<int> seen;
    for (const auto &c : clusters) {
      ASSERT_EQ(c.size(), 4u);
      for (int k : c) {
        EXPECT_TRUE(seen.insert(k).second) << "orphan " << k << " in two clusters";
        EXPECT_TRUE(there[k]);
        const double r = std::hypot(o[k].x - o[c[0]].x, o[k].y - o[c[0]].y);
        EXPECT_LE(r, reach);
      }
    }
    for (const auto &c : clusters)
      for (int k : c) there[k] = 0;
    merged += (int) clusters.size();
  }
  const int left = (int) o.size() - 4 * merged;
  EXPECT_LE(looks, 8);
  // 144 orphans: at least 32 of the 36 possible clusters (at most 16 orphans left)
  EXPECT_GE(merged, 32) << left << " orphans left after " << looks << " looks";
}

// The rounds' rules and ties: a leader has the least priority within reach; an orphan joins the nearer leader, the smaller ID at equal distance; a
// leader takes the nearest joined orphans; fewer than it needs, none.
TEST(RefineClusters, Ties)
{
  EXPECT_TRUE(leads_cluster(3.0, {{4.0, 1.0, 0}, {7.0, 0.5, 1}}) ==
              (cluster_priority(3.0) < std::min(cluster_priority(4.0), cluster_priority(7.0))));
  EXPECT_NE(cluster_priority(1.0), cluster_priority(2.0));
  EXPECT_EQ(joined_leader({{9.0, 1.0, 0}, {4.0, 2.0, 1}}), 9.0);
  EXPECT_EQ(joined_leader({{9.0, 1.0, 0}, {4.0, 1.0, 1}}), 4.0);
  EXPECT_EQ(joined_leader({}), 0.0);
  const auto m = cluster_members({{5.0, 3.0, 0}, {6.0, 1.0, 1}, {2.0, 2.0, 2}, {8.0, 1.0, 3}}, 3);
  ASSERT_EQ(m.size(), 3u);
  EXPECT_EQ(m[0].tag, 6.0);
  EXPECT_EQ(m[1].tag, 8.0);
  EXPECT_EQ(m[2].tag, 2.0);
  EXPECT_TRUE(cluster_members({{5.0, 3.0, 0}, {6.0, 1.0, 1}}, 3).empty());
}

// Orphans with gaps (eight in ten of a 24 x 24 lattice's): with one priority for all looks, a
// leader that lacks members leads at every look while the orphans near it stay the same, and
// they wait for ever; with the look in the priority the leaders change. Measured over 16
// looks: 52 of 460 orphans left with fixed priorities, 24 with salted ones.
TEST(RefineClusters, LeadersChangeFromLookToLook)
{
  std::vector<Orphan> o;
  for (const auto &orphan : lattice(24))
    if (((int) orphan.tag * 7919) % 10 < 8) o.push_back(orphan);
  const double reach = 2.4;
  auto left_after = [&](int looks, bool salted) {
    std::vector<char> there(o.size(), 1);
    for (int k = 0; k < looks; k++)
      for (const auto &c : look(o, there, reach, 4, salted ? (uint64_t) k : 0))
        for (int i : c) there[i] = 0;
    return (int) std::count(there.begin(), there.end(), 1);
  };
  const int fixed = left_after(16, false), salted = left_after(16, true);
  EXPECT_LE(2 * salted, fixed) << salted << " orphans left with salted priorities, " << fixed << " with fixed ones";
  EXPECT_LE(salted, (int) (0.06 * o.size()));
  // a leader among three orphans within reach of each other: each leads at some look
  std::set<double> leaders;
  for (uint64_t k = 0; k < 32; k++)
    for (double tag : {3.0, 17.0, 40.0}) {
      std::vector<NearOrphan> others;
      for (double other : {3.0, 17.0, 40.0})
        if (other != tag) others.push_back({other, 1.0, 0});
      if (leads_cluster(tag, others, k)) leaders.insert(tag);
    }
  EXPECT_EQ(leaders.size(), 3u);
}
