/* -*- c++ -*- ----------------------------------------------------------
   SPH_SOIL package: the pair style's own neighbour list (pure, no LAMMPS).

   Each pair is listed with its own cutoff, the kernel's support at the mean
   smoothing length h_ij = (h_i + h_j)/2 plus the pair's skin, so that a refined
   particle lists the neighbours of its own h, not those of the largest h in
   the system. (LAMMPS's lists by size would do this through the atoms'
   radius, but fix rigid takes particles with a radius for spheres.) A half list: every pair
   once, on the rank that owns i, and for a ghost j with Newton's third law on
   only on one of the two ranks (the one where j lies above i in z, then y,
   then x, as LAMMPS's own half lists decide). Wall particles never pair with
   each other, and with Newton's third law a soil-wall pair is listed at the
   soil particle, on the rank that owns it (wall particles list nothing). A particle's partners come sorted by kind: first those whose
   pair is a plain SPH pair (soil, then walls that extrapolate the soil's
   state), then those whose pair goes through a mirror wall's image, so that
   the pair loop and the walls' extrapolation need no test of the partner's
   kind (doc/theory.rst 5.8).

   The skin may follow h too: a pair's skin is skin + skin_per_h h_ij, and the
   list stays valid while every atom i has moved less than half of its own
   skin, skin + skin_per_h h_i (the two halves of a pair add up to the pair's
   skin). moved_beyond_skin() tells when that no longer holds.
------------------------------------------------------------------------- */

#ifndef LMP_SOIL_NEIGHBOURS_H
#define LMP_SOIL_NEIGHBOURS_H

#include <cstddef>
#include <vector>

namespace SPHSoil {

// a particle's kind for the list: soil, a wall with mirror images, a wall that extrapolates
enum NeighbourKind {
  NEIGHBOUR_SOIL = 0,
  NEIGHBOUR_MIRROR_WALL = 1,
  NEIGHBOUR_EXTRAPOLATED_WALL = 2
};

struct NeighbourInput {
  const double *const *x;    // positions of owned (0..nlocal-1) and ghost atoms (..nall-1)
  const double *h;           // smoothing lengths, > 0
  const int *type;           // atom types
  const int *kind_of_type;   // NeighbourKind per type
  int nlocal, nall;
  int dimension;             // 2 (z ignored) or 3
  double support;            // the kernel's support radius in units of h
  double skin;               // added to every pair's cutoff support * h_ij ...
  double skin_per_h = 0.0;   // ... and so is skin_per_h * h_ij
  bool newton;               // Newton's third law for pairs with ghosts
};

// Atoms binned in cells (a counting sort), for searches within a distance of a point
class CellGrid {
 public:
  // bin atoms 0..n-1 (the first `dimension` coordinates) in cells of about `cell` or larger
  void build(const double *const *x, int n, int dimension, double cell);
  // call f(j) for every atom j in the cells within `reach` of point p (a superset of the
  // atoms within `reach`, in cell order)
  std::size_t memory_bytes() const;
  template <class F> void for_each_near(const double *p, double reach, F &&f) const
  {
    int lo[3] = {0, 0, 0}, hi[3] = {0, 0, 0};
    for (int a = 0; a < dims; a++) {
      lo[a] = coordinate(p[a] - reach, a);
      hi[a] = coordinate(p[a] + reach, a);
    }
    for (int cz = lo[2]; cz <= hi[2]; cz++)
      for (int cy = lo[1]; cy <= hi[1]; cy++) {
        // the cells of a row are contiguous in `atoms`
        const int row = (cz * ncells[1] + cy) * ncells[0];
        for (int k = start[row + lo[0]]; k < start[row + hi[0] + 1]; k++) f(atoms[k]);
      }
  }

 private:
  int dims = 2;
  int ncells[3] = {1, 1, 1};
  double lo_corner[3] = {0.0, 0.0, 0.0}, inverse_cell = 1.0;
  std::vector<int> start, atoms;
  int coordinate(double value, int a) const
  {
    const double c = (value - lo_corner[a]) * inverse_cell;
    if (!(c > 0.0)) return 0;    // (NaN too)
    return c >= ncells[a] - 1 ? ncells[a] - 1 : (int) c;
  }
};

// Atoms binned by their smoothing length: one CellGrid per class of h within a factor of two
// (powers of two below the largest h), each in cells of its own reach, so that a search for
// the atoms whose support reaches a point costs what the atoms near it need, not what the
// largest h of the run would (a refined particle among level-0 soil and walls).
class SmoothingClassGrids {
 public:
  // bin the atoms `members` (indices into x and h) of x: `support` h is an atom's reach; each
  // class in cells of `cell_per_h` times its largest h (0: of its reach)
  void build(const double *const *x, const double *h, const std::vector<int> &members,
             int dimension, double support, double cell_per_h = 0.0);
  // call f(j, r2) for every member j with |p - x_j| < max(reach, support h_j) (exactly those:
  // the distance is tested here), r2 = |p - x_j|^2
  template <class F> void for_each_within(const double *p, double reach, F &&f) const
  {
    for (const auto &c : classes) {
      const double r = reach > c.reach ? reach : c.reach;
      const double r2 = r * r;
      c.grid.for_each_near(p, r, [&](int k) {
        const int j = c.members[k];
        const double *xj = c.positions[k];
        double d2 = 0.0;
        for (int a = 0; a < dims; a++) d2 += (p[a] - xj[a]) * (p[a] - xj[a]);
        if (d2 < r2 && (d2 < reach * reach || d2 < support2 * h[j] * h[j])) f(j, d2);
      });
    }
  }
  // call f(j) for every member j in the cells within reach_of(h_max) of p, h_max the largest h
  // of j's class (a superset of the members within that distance: the caller tests it)
  template <class Reach, class F> void for_each_near(const double *p, Reach &&reach_of, F &&f) const
  {
    for (const auto &c : classes)
      c.grid.for_each_near(p, reach_of(c.h_max), [&](int k) { f(c.members[k]); });
  }
  std::size_t memory_bytes() const;

 private:
  struct Class {
    double h_max;                          // the largest h of the class
    double reach;                          // support times h_max
    std::vector<int> members;              // atom indices
    std::vector<const double *> positions;
    CellGrid grid;
  };
  std::vector<Class> classes;
  const double *h = nullptr;
  double support2 = 0.0;
  int dims = 2;
};

class NeighbourList {
 public:
  // build the list of the owned atoms (an empty list for nlocal = 0)
  void build(const NeighbourInput &in);

  // owned atom i's partners are partners[first(i) .. end(i)); the plain ones up to
  // plain_end(i), then the mirror-wall ones. The plain pairs of a soil particle and a wall that
  // extrapolates are [extrapolated_begin(i) .. plain_end(i)): for a soil particle its partners
  // of that kind, which come after its soil partners; for such a wall particle all its plain
  // partners (soil).
  int first(int i) const { return offsets[i]; }
  int extrapolated_begin(int i) const { return extrapolated_begins[i]; }
  int size() const { return (int) plain_ends.size(); }    // the owned atoms at the build
  int plain_end(int i) const { return plain_ends[i]; }
  int end(int i) const { return offsets[i + 1]; }
  const int *partner_data() const { return partners.data(); }
  std::size_t pairs() const { return partners.size(); }
  std::size_t memory_bytes() const;
  // whether some owned atom has moved half its own skin or more since the build (then a pair
  // may have come within the support unlisted), or the owned atoms are not those of the build
  bool moved_beyond_skin(const double *const *x, int nlocal) const;

 private:
  std::vector<int> offsets, extrapolated_begins, plain_ends, partners;
  int dims = 2;
  std::vector<double> x_at_build;    // owned atoms' positions, dims per atom
  std::vector<double> move_limit2;   // (half the atom's skin)^2
  // the owned and ghost atoms binned by their h, soil and walls apart: a particle searches each
  // class of h within its pair cutoff with the class's largest h, so that a refined particle's
  // search costs what its neighbours need, not what the largest h of the run would, and a wall
  // particle searches the soil alone (doc/theory.rst 5.8)
  SmoothingClassGrids soil_classes, wall_classes;
  std::vector<int> soil_atoms, wall_atoms;
  std::vector<int> extrapolated_scratch, mirror_scratch;
};

}    // namespace SPHSoil

#endif
