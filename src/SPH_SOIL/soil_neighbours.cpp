/* ----------------------------------------------------------------------
   SPH_SOIL package: the pair style's own neighbour list (see the header)
------------------------------------------------------------------------- */

#include "soil_neighbours.h"

#include <algorithm>
#include <cmath>

namespace SPHSoil {

void SmoothingClassGrids::build(const double *const *x, const double *h_, const std::vector<int> &members,
                                int dimension, double support, double cell_per_h)
{
  h = h_;
  dims = dimension == 2 ? 2 : 3;
  support2 = support * support;
  classes.clear();
  double h_max = 0.0;
  for (int j : members) h_max = std::max(h_max, h[j]);
  if (!(h_max > 0.0)) return;
  // class c holds h in (h_max / 2^(c+1), h_max / 2^c]; at most 64 classes (the last takes
  // the rest)
  constexpr int MAX_CLASSES = 64;
  std::vector<int> class_of(members.size());
  int nclasses = 0;
  for (std::size_t k = 0; k < members.size(); k++) {
    const double ratio = h_max / h[members[k]];
    int c = ratio > 1.0 ? (int) std::floor(std::log2(ratio)) : 0;
    c = std::min(std::max(c, 0), MAX_CLASSES - 1);
    class_of[k] = c;
    nclasses = std::max(nclasses, c + 1);
  }
  std::vector<Class> all(nclasses);
  for (auto &c : all) c.h_max = 0.0;
  for (std::size_t k = 0; k < members.size(); k++) {
    Class &c = all[class_of[k]];
    const int j = members[k];
    c.members.push_back(j);
    c.positions.push_back(x[j]);
    c.h_max = std::max(c.h_max, h[j]);
  }
  for (auto &c : all) {
    if (c.members.empty()) continue;
    c.reach = support * c.h_max;
    c.grid.build(c.positions.data(), (int) c.members.size(), dimension,
                 cell_per_h > 0.0 ? cell_per_h * c.h_max : c.reach);
    classes.push_back(std::move(c));
  }
}

std::size_t SmoothingClassGrids::memory_bytes() const
{
  std::size_t bytes = 0;
  for (const auto &c : classes)
    bytes += sizeof(int) * c.members.capacity() + sizeof(const double *) * c.positions.capacity() +
        c.grid.memory_bytes();
  return bytes;
}

/* ---------------------------------------------------------------------- */

void CellGrid::build(const double *const *x, int n, int dimension, double cell)
{
  dims = dimension == 2 ? 2 : 3;
  double hi[3] = {0.0, 0.0, 0.0};
  for (int a = 0; a < 3; a++) {
    lo_corner[a] = 0.0;
    ncells[a] = 1;
  }
  if (n > 0)
    for (int a = 0; a < dims; a++) lo_corner[a] = hi[a] = x[0][a];
  for (int i = 0; i < n; i++)
    for (int a = 0; a < dims; a++) {
      lo_corner[a] = std::min(lo_corner[a], x[i][a]);
      hi[a] = std::max(hi[a], x[i][a]);
    }
  // a sparse spread of atoms (few atoms in a large box) would ask for more cells than atoms:
  // coarser cells then
  for (;;) {
    double total = 1.0;
    for (int a = 0; a < dims; a++) total *= std::floor((hi[a] - lo_corner[a]) / cell) + 1.0;
    if (total <= 8.0 * n + 64.0) break;
    cell *= 2.0;
  }
  for (int a = 0; a < dims; a++) ncells[a] = (int) std::floor((hi[a] - lo_corner[a]) / cell) + 1;
  inverse_cell = 1.0 / cell;

  const std::size_t total_cells = (std::size_t) ncells[0] * ncells[1] * ncells[2];
  std::vector<int> cell_of(n);
  start.assign(total_cells + 1, 0);
  atoms.resize(n);
  for (int i = 0; i < n; i++) {
    int c = 0;
    for (int a = dims - 1; a >= 0; a--) c = c * ncells[a] + coordinate(x[i][a], a);
    cell_of[i] = c;
    start[c + 1]++;
  }
  for (std::size_t c = 0; c < total_cells; c++) start[c + 1] += start[c];
  std::vector<int> fill(start.begin(), start.end() - 1);
  for (int i = 0; i < n; i++) atoms[fill[cell_of[i]]++] = i;
}

std::size_t CellGrid::memory_bytes() const
{
  return sizeof(int) * (start.capacity() + atoms.capacity());
}

void NeighbourList::build(const NeighbourInput &in)
{
  const int nlocal = in.nlocal, nall = in.nall;
  const bool three = in.dimension == 3;
  dims = three ? 3 : 2;
  offsets.assign(nlocal + 1, 0);
  extrapolated_begins.assign(nlocal, 0);
  plain_ends.assign(nlocal, 0);
  partners.clear();
  x_at_build.resize((std::size_t) dims * nlocal);
  move_limit2.resize(nlocal);
  for (int i = 0; i < nlocal; i++) {
    for (int a = 0; a < dims; a++) x_at_build[(std::size_t) dims * i + a] = in.x[i][a];
    const double half_skin = 0.5 * (in.skin + in.skin_per_h * in.h[i]);
    move_limit2[i] = half_skin * half_skin;
  }
  if (nlocal == 0) return;

  // a pair's cutoff is reach_per_h (h_i + h_j) + skin
  const double reach_per_h = 0.5 * (in.support + in.skin_per_h);
  // each class of h in cells of half its own pairs' cutoff (without the absolute skin): a search
  // of two cells each way checks (5/2)^D of the cutoff's volume against 3^D for cells of the
  // whole cutoff. Soil and walls apart: walls never pair with each other, and the layers of a
  // wall under the soil outnumber it. With Newton's third law for ghost pairs a soil-wall pair
  // belongs to the soil particle (on the rank that owns it, whatever the order of the two), and
  // wall particles do not search at all; without it, each rank keeps the pairs of its owned
  // particles with ghosts, and wall particles search the soil.
  soil_atoms.clear();
  wall_atoms.clear();
  for (int j = 0; j < nall; j++)
    (in.kind_of_type[in.type[j]] == NEIGHBOUR_SOIL ? soil_atoms : wall_atoms).push_back(j);
  soil_classes.build(in.x, in.h, soil_atoms, in.dimension, in.support, reach_per_h);
  wall_classes.build(in.x, in.h, wall_atoms, in.dimension, in.support, reach_per_h);

  // each owned atom's partners: plain ones straight into the list, mirror-wall ones after them
  for (int i = 0; i < nlocal; i++) {
    offsets[i] = (int) partners.size();
    extrapolated_scratch.clear();
    mirror_scratch.clear();
    const int kind_i = in.kind_of_type[in.type[i]];
    if (kind_i != NEIGHBOUR_SOIL && in.newton) {
      extrapolated_begins[i] = plain_ends[i] = offsets[i];
      continue;
    }
    const double *xi = in.x[i];
    const double hi_skin = reach_per_h * in.h[i] + in.skin;
    const auto reach = [&](double h_class) { return hi_skin + reach_per_h * h_class; };
    // whether pair (i, j) is i's to keep by the half list's order: an owned pair where j > i, a
    // ghost pair (with Newton's third law) on the one of its two ranks where j lies above i
    const auto in_order = [&](int j) {
      if (j < nlocal) return j > i;
      if (!in.newton) return true;
      const double *xj = in.x[j];
      if (three && xj[2] != xi[2]) return xj[2] > xi[2];
      if (xj[1] != xi[1]) return xj[1] > xi[1];
      return xj[0] >= xi[0];
    };
    const auto visit = [&](int j, bool ordered) {
      if (ordered && !in_order(j)) return;
      const int kind_j = in.kind_of_type[in.type[j]];
      const double *xj = in.x[j];
      const double dx = xi[0] - xj[0], dy = xi[1] - xj[1], dz = three ? xi[2] - xj[2] : 0.0;
      const double cut = hi_skin + reach_per_h * in.h[j];
      if (dx * dx + dy * dy + dz * dz >= cut * cut) return;
      if (kind_i == NEIGHBOUR_MIRROR_WALL || kind_j == NEIGHBOUR_MIRROR_WALL)
        mirror_scratch.push_back(j);
      else if (kind_j == NEIGHBOUR_EXTRAPOLATED_WALL)
        extrapolated_scratch.push_back(j);
      else
        partners.push_back(j);
    };
    soil_classes.for_each_near(xi, reach, [&](int j) { visit(j, true); });
    if (kind_i == NEIGHBOUR_SOIL) wall_classes.for_each_near(xi, reach, [&](int j) { visit(j, !in.newton); });
    // (an extrapolating wall's partners are all soil: the pairs with it begin at its first)
    extrapolated_begins[i] = kind_i == NEIGHBOUR_EXTRAPOLATED_WALL ? offsets[i] : (int) partners.size();
    partners.insert(partners.end(), extrapolated_scratch.begin(), extrapolated_scratch.end());
    plain_ends[i] = (int) partners.size();
    partners.insert(partners.end(), mirror_scratch.begin(), mirror_scratch.end());
  }
  offsets[nlocal] = (int) partners.size();
}

bool NeighbourList::moved_beyond_skin(const double *const *x, int nlocal) const
{
  if (nlocal != size()) return true;
  for (int i = 0; i < nlocal; i++) {
    const double *built = &x_at_build[(std::size_t) dims * i];
    double moved2 = 0.0;
    for (int a = 0; a < dims; a++) moved2 += (x[i][a] - built[a]) * (x[i][a] - built[a]);
    // (a NaN position is the integrator's to report: not a reason to reneighbour)
    if (moved2 >= move_limit2[i]) return true;
  }
  return false;
}

std::size_t NeighbourList::memory_bytes() const
{
  return sizeof(int) * (offsets.capacity() + extrapolated_begins.capacity() + plain_ends.capacity() +
                        partners.capacity() + extrapolated_scratch.capacity() + mirror_scratch.capacity()) +
      sizeof(double) * (x_at_build.capacity() + move_limit2.capacity()) + sizeof(int) * (soil_atoms.capacity() + wall_atoms.capacity()) +
      soil_classes.memory_bytes() + wall_classes.memory_bytes();
}

}    // namespace SPHSoil
