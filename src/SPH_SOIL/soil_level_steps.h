/* -*- c++ -*- ----------------------------------------------------------
   SPH_SOIL package: a time step per level (pure, no LAMMPS; doc/theory.rst 5.12).

   With fix sph/soil's 'stepping level', LAMMPS's time step dt is the step of
   the finest particles (those of the smallest h, h_min); a particle of
   smoothing length h steps with n dt, n = 2^floor(log2(h / h_min)) its period
   (a power of two: a daughter of ratio 1/2 steps twice as often as its parent,
   and n dt <= C h / c whenever dt <= C h_min / c). Its steps end at the LAMMPS
   steps that are multiples of n, so that all particles are synchronised at the
   multiples of the largest period.

   A pair is evaluated when one of its two particles ends a step, i.e. at the
   multiples of the finer one's period n_ij = min(n_i, n_j), and its force acts
   as an impulse n_ij dt F_ij, half before and half after the evaluation (the
   velocity Verlet kicks of the pair's own period): both particles receive the
   same impulse with opposite signs at the same instant, so that momentum is
   conserved to round-off at every step (n_ij is a power of two: the weights
   are exact). Density, strain and stress follow the Heun scheme over each
   particle's own step; between its step ends a particle shows its partners
   the states interpolated between the start of its step and the prediction
   at its end.
------------------------------------------------------------------------- */

#ifndef LMP_SOIL_LEVEL_STEPS_H
#define LMP_SOIL_LEVEL_STEPS_H

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace SPHSoil {

// the hierarchy fix sph/soil steps by, for the pair style and the computes (through
// extract("sph_soil_schedule")): off with one global step
struct StepSchedule {
  bool per_level = false;
  double finest_h = 0.0;     // smallest h of the integrated soil particles
  int largest_period = 1;    // all particles end a step at the multiples of it
};

// periods up to 2^MAX_PERIOD_EXPONENT LAMMPS steps (a ratio of h of a million)
constexpr int MAX_PERIOD_EXPONENT = 20;

// a particle's period in LAMMPS steps: the largest power of two not above h / h_min (1 for h at
// or below h_min, and for a non-positive h_min: no hierarchy)
inline int step_period(double h, double finest_h)
{
  if (!(finest_h > 0.0) || !(h > finest_h)) return 1;
  const int exponent = std::ilogb(h / finest_h);
  return 1 << std::min(std::max(exponent, 0), MAX_PERIOD_EXPONENT);
}

// whether a step of period n (a power of two) ends at LAMMPS step `step`: a multiple of n
inline bool ends_step(int64_t step, int period)
{
  return (step & (int64_t) (period - 1)) == 0;
}

// a step that begins at LAMMPS step `begin` ends at the next multiple of the period
inline int64_t step_end(int64_t begin, int period)
{
  return (begin / period + 1) * period;
}

// A pair's weight in the pair loop, from its two particles' signed periods (+n when the
// particle ends a step now, -n when not; a wall particle -INFINITY: it takes its partner's):
// 0 when neither ends a step (the pair is skipped), else the finer period; finer_period() the
// latter from i's unsigned period. (Comparisons, not std::fmin: this is the pair loop's, and
// fmin may be a library call.)
inline double finer_period(double period_i, double signed_period_j)
{
  const double period_j = signed_period_j < 0.0 ? -signed_period_j : signed_period_j;
  return period_i < period_j ? period_i : period_j;
}
inline double pair_step_weight(double signed_period_i, double signed_period_j)
{
  if (signed_period_i < 0.0 && signed_period_j < 0.0) return 0.0;
  return finer_period(signed_period_i < 0.0 ? -signed_period_i : signed_period_i, signed_period_j);
}

}    // namespace SPHSoil

#endif
