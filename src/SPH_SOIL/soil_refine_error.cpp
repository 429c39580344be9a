/* ----------------------------------------------------------------------
   SPH_SOIL package: kernel gradient error of a split, instability conditions
------------------------------------------------------------------------- */

#include "soil_refine_error.h"


#include <algorithm>
#include <cmath>

using namespace SPHSoil;

namespace {

// 4-point Gauss-Legendre on [-1, 1]
const double GAUSS_X[4] = {-0.8611363115940526, -0.3399810435848563, 0.3399810435848563,
                           0.8611363115940526};
const double GAUSS_W[4] = {0.3478548451374538, 0.6521451548625461, 0.6521451548625461,
                           0.3478548451374538};

struct Split {
  KernelKind kernel;
  int dimension;
  double eps, alpha, ra;
  double h_parent, h_daughter;    // symmetrized with h(x)
  int ndaughters;
  double daughters[8][3];
};

Split make_split(int dimension, double eps, double alpha, double ra, NeighbourSmoothing neighbours,
                 KernelKind kernel)
{
  Split s;
  s.kernel = kernel;
  s.dimension = dimension;
  s.eps = eps;
  s.alpha = alpha;
  s.ra = ra;
  const double hp = ra, hd = alpha * ra;
  const double hx = neighbours == NeighbourSmoothing::UNREFINED ? hp : hd;
  s.h_parent = 0.5 * (hp + hx);
  s.h_daughter = 0.5 * (hd + hx);
  s.ndaughters = dimension == 3 ? 8 : 4;
  for (int d = 0; d < s.ndaughters; d++)
    for (int k = 0; k < 3; k++)
      s.daughters[d][k] = k < dimension ? ((d >> k) & 1 ? 0.5 : -0.5) * eps : 0.0;
  return s;
}

// the parent's kernel gradient at x minus its daughters' (each of 1/M of its volume)
void gradient_difference(const Split &s, const double *x, double *diff)
{
  const int D = s.dimension;
  const double r0 = std::sqrt(x[0] * x[0] + x[1] * x[1] + (D == 3 ? x[2] * x[2] : 0.0));
  const double fp = kernel_gradient_factor(s.kernel, D, r0, s.h_parent);
  for (int a = 0; a < 3; a++) diff[a] = a < D ? fp * x[a] : 0.0;
  const double lambda = 1.0 / s.ndaughters;
  for (int d = 0; d < s.ndaughters; d++) {
    double dx[3], r2 = 0.0;
    for (int a = 0; a < D; a++) {
      dx[a] = x[a] - s.daughters[d][a];
      r2 += dx[a] * dx[a];
    }
    const double fd = lambda * kernel_gradient_factor(s.kernel, D, std::sqrt(r2), s.h_daughter);
    for (int a = 0; a < D; a++) diff[a] -= fd * dx[a];
  }
}

double difference_squared(const Split &s, const double *x)
{
  double diff[3];
  gradient_difference(s, x, diff);
  return diff[0] * diff[0] + diff[1] * diff[1] + diff[2] * diff[2];
}

// the pattern is symmetric under x^a -> -x^a for each a: integrate over [0, L]^D, times 2^D
double integrate(const Split &s, int cells)
{
  const double L = std::max(2.0 * s.h_parent, 0.5 * s.eps + 2.0 * s.h_daughter);
  const double width = L / cells;
  const int D = s.dimension;
  double total = 0.0;
  double x[3] = {0.0, 0.0, 0.0};
  const int nz = D == 3 ? cells : 1, gz = D == 3 ? 4 : 1;
  for (int ci = 0; ci < cells; ci++)
    for (int gi = 0; gi < 4; gi++) {
      x[0] = (ci + 0.5 + 0.5 * GAUSS_X[gi]) * width;
      for (int cj = 0; cj < cells; cj++)
        for (int gj = 0; gj < 4; gj++) {
          x[1] = (cj + 0.5 + 0.5 * GAUSS_X[gj]) * width;
          const double wij = GAUSS_W[gi] * GAUSS_W[gj];
          for (int ck = 0; ck < nz; ck++)
            for (int gk = 0; gk < gz; gk++) {
              double w = wij;
              if (D == 3) {
                x[2] = (ck + 0.5 + 0.5 * GAUSS_X[gk]) * width;
                w *= GAUSS_W[gk];
              }
              total += w * difference_squared(s, x);
            }
        }
    }
  const double jacobian = std::pow(0.5 * width, D);
  return total * jacobian * std::pow(2.0, D);
}

}    // namespace

double SPHSoil::gradient_difference_squared(int dimension, double separation,
                                            double smoothing_ratio, double r_a,
                                            NeighbourSmoothing neighbours, const double *x,
                                            KernelKind kernel)
{
  return difference_squared(make_split(dimension, separation, smoothing_ratio, r_a, neighbours, kernel), x);
}

double SPHSoil::kernel_gradient_error_fixed(int dimension, double separation, double smoothing_ratio,
                                            double r_a, NeighbourSmoothing neighbours, int cells,
                                            KernelKind kernel)
{
  return integrate(make_split(dimension, separation, smoothing_ratio, r_a, neighbours, kernel), cells);
}

KernelGradientError SPHSoil::kernel_gradient_error(int dimension, double separation,
                                                   double smoothing_ratio, double r_a,
                                                   NeighbourSmoothing neighbours,
                                                   double relative_tolerance, int max_cells,
                                                   KernelKind kernel)
{
  const Split s = make_split(dimension, separation, smoothing_ratio, r_a, neighbours, kernel);
  // the integrand has kinks (W''' jumps) on spheres around every particle: the composite rule
  // converges algebraically, so the change under doubling the cells bounds the error
  int cells = dimension == 3 ? 8 : 16;
  double previous = integrate(s, cells);
  KernelGradientError result{previous, HUGE_VAL, cells};
  while (cells < max_cells) {
    cells *= 2;
    const double current = integrate(s, cells);
    result = {current, std::fabs(current - previous), cells};
    // E = 0 exactly for coinciding daughters: stop on an absolute floor too
    if (result.error_estimate <= relative_tolerance * std::fabs(current) ||
        result.error_estimate < 1.0e-14)
      break;
    previous = current;
  }
  return result;
}

InstabilityConditions SPHSoil::instability_conditions(double separation, double smoothing_ratio,
                                                      double r_a, double neighbour_distance,
                                                      double inflection)
{
  InstabilityConditions c;
  const double unstable_radius = inflection * smoothing_ratio * r_a;    // q* h_d in d_ref
  c.daughters_too_close = unstable_radius - separation > 0.0;
  c.refined_neighbours = neighbour_distance < unstable_radius + separation;
  // a daughter (h_d) and an unrefined neighbour (h_p): h_ij = (1 + alpha_r) h_p / 2
  c.unrefined_neighbour =
      neighbour_distance < inflection * (1.0 + smoothing_ratio) * r_a / 2.0 + 0.5 * separation;
  return c;
}

SplitStressDefect SPHSoil::split_stress_defect(int dimension, double separation, double smoothing_ratio,
                                               double r_a, KernelKind kernel)
{
  const int D = dimension;
  const double hp = r_a, hd = smoothing_ratio * r_a;
  // the lattice sites within reach of the split (their supports see a daughter)
  const int reach = (int) std::ceil(kernel_support(kernel) * hp + 0.5 * separation) + 1;
  const int kmax = D == 3 ? reach : 0;
  SplitStressDefect result{0.0, 0.0};
  // A coarse neighbour at x: its lattice sum vanished with the parent in it; the split replaces
  // the parent's gradient by the daughters' at (h_p + alpha_r h_p)/2, which is the
  // kernel-gradient difference of case (a), h(x) = h_p
  const Split unrefined = make_split(D, separation, smoothing_ratio, r_a, NeighbourSmoothing::UNREFINED, kernel);
  for (int i = -reach; i <= reach; i++)
    for (int j = -reach; j <= reach; j++)
      for (int k = -kmax; k <= kmax; k++) {
        if (i == 0 && j == 0 && k == 0) continue;
        const double x[3] = {(double) i, (double) j, (double) k};
        result.neighbours = std::max(result.neighbours, std::sqrt(difference_squared(unrefined, x)));
      }
  // A daughter (all are alike by symmetry: the first): the whole lattice, the parent's site
  // included, seen with (alpha_r h_p + h_p)/2, minus the difference of case (b), h(x) = alpha_r
  // h_p (the parent's term taken out, its siblings' put in)
  const Split refined = make_split(D, separation, smoothing_ratio, r_a, NeighbourSmoothing::REFINED, kernel);
  const double *x = refined.daughters[0];
  double sum[3] = {0.0, 0.0, 0.0};
  for (int i = -reach; i <= reach; i++)
    for (int j = -reach; j <= reach; j++)
      for (int k = -kmax; k <= kmax; k++) {
        const double dx[3] = {x[0] - i, x[1] - j, D == 3 ? x[2] - k : 0.0};
        const double r = std::sqrt(dx[0] * dx[0] + dx[1] * dx[1] + dx[2] * dx[2]);
        const double f = kernel_gradient_factor(kernel, D, r, 0.5 * (hd + hp));
        for (int a = 0; a < D; a++) sum[a] += f * dx[a];
      }
  double diff[3];
  gradient_difference(refined, x, diff);
  for (int a = 0; a < D; a++) sum[a] -= diff[a];
  result.daughters = std::sqrt(sum[0] * sum[0] + sum[1] * sum[1] + sum[2] * sum[2]);
  // a = -(2 p / rho) sum_j V_j grad W: in units of p / (rho h_p)
  result.neighbours *= 2.0 * hp;
  result.daughters *= 2.0 * hp;
  return result;
}

SplitStressDefect SPHSoil::level_edge_defect(int dimension, double separation, double smoothing_ratio,
                                             double r_a, KernelKind kernel)
{
  const int D = dimension, normal = D - 1;
  const double hp = r_a, hd = smoothing_ratio * r_a;
  const int reach = (int) std::ceil(kernel_support(kernel) * hp) + 2;
  const int kmax = D == 3 ? reach : 0;
  // the daughters' offsets from their site and their volume (the split's pattern; its
  // symmetrised smoothing lengths are not used: each pair below takes its own)
  const Split split = make_split(D, separation, smoothing_ratio, r_a, NeighbourSmoothing::REFINED, kernel);
  const double vd = 1.0 / split.ndaughters;
  // sum_j V_j grad W(r_ij, (h_i + h_j)/2) at x (smoothing length hi), over the coarse sites below
  // the edge (normal coordinate < 0) and the daughters above it, x itself left out
  auto lattice_sum = [&](const double x[3], double hi) {
    double sum[3] = {0.0, 0.0, 0.0};
    auto add = [&](const double y[3], double volume, double hj) {
      const double dx[3] = {x[0] - y[0], x[1] - y[1], x[2] - y[2]};
      const double r = std::sqrt(dx[0] * dx[0] + dx[1] * dx[1] + dx[2] * dx[2]);
      if (r < 1e-12) return;
      const double f = volume * kernel_gradient_factor(kernel, D, r, 0.5 * (hi + hj));
      for (int a = 0; a < D; a++) sum[a] += f * dx[a];
    };
    for (int i = -reach; i <= reach; i++)
      for (int j = -reach; j <= reach; j++)
        for (int k = -kmax; k <= kmax; k++) {
          const double site[3] = {(double) i, (double) j, (double) k};
          if (site[normal] < 0.0) {
            add(site, 1.0, hp);
          } else {
            for (int d = 0; d < split.ndaughters; d++) {
              const double *o = split.daughters[d];
              const double y[3] = {site[0] + o[0], site[1] + o[1], site[2] + o[2]};
              add(y, vd, hd);
            }
          }
        }
    return std::sqrt(sum[0] * sum[0] + sum[1] * sum[1] + sum[2] * sum[2]);
  };
  SplitStressDefect result{0.0, 0.0};
  const double coarse[3] = {0.0, D == 2 ? -1.0 : 0.0, D == 3 ? -1.0 : 0.0};
  result.neighbours = lattice_sum(coarse, hp);
  for (int d = 0; d < split.ndaughters; d++)
    result.daughters = std::max(result.daughters, lattice_sum(split.daughters[d], hd));
  // a = -(2 p / rho) sum_j V_j grad W: in units of p / (rho h_p)
  result.neighbours *= 2.0 * hp;
  result.daughters *= 2.0 * hp;
  return result;
}
