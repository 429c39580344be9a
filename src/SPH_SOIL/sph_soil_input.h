/* -*- c++ -*- ----------------------------------------------------------
   SPH_SOIL package for LAMMPS: numbers from input arguments.

   Every number a command of the package reads goes through number() or
   integer(), and every word from a list through choice(): an error names
   the command and keyword, the value as typed and the allowed range or
   words. A word that is no number ("nan", "inf", "abc") is ours to report
   too: LAMMPS's parser would say only that it expected a number, without
   the command. A number then goes through LAMMPS's own parser (text with
   UTF-8, which it substitutes, is left to it entirely), then the range
   check. LAMMPS's parser accepts "1e400", which becomes infinity and
   passes any "x > 0" test: number() rejects every non-finite value.
------------------------------------------------------------------------- */

#ifndef LMP_SPH_SOIL_INPUT_H
#define LMP_SPH_SOIL_INPUT_H

#include "lammps.h"
#include "sph_soil_compat.h"
#include "utils.h"

#include <climits>
#include <cmath>
#include <string>
#include <vector>

namespace LAMMPS_NS {
namespace SPHSoilInput {

// An allowed range of a number: a bound on either side (or none), open or closed.
struct Range {
  double lo = -HUGE_VAL, hi = HUGE_VAL;
  bool lo_open = false, hi_open = false;

  bool contains(double value) const
  {
    return std::isfinite(value) && (lo_open ? value > lo : value >= lo) &&
        (hi_open ? value < hi : value <= hi);
  }
  // "> 0", ">= 0", "in (0, 1)", "in [0, 10]"; empty for any finite number
  std::string describe() const
  {
    const bool has_lo = std::isfinite(lo), has_hi = std::isfinite(hi);
    if (has_lo && has_hi)
      return fmt::format("in {}{}, {}{}", lo_open ? "(" : "[", lo, hi, hi_open ? ")" : "]");
    if (has_lo) return fmt::format("{} {}", lo_open ? ">" : ">=", lo);
    if (has_hi) return fmt::format("{} {}", hi_open ? "<" : "<=", hi);
    return "";
  }
};

inline Range any() { return Range(); }
inline Range above(double lo)
{
  Range r;
  r.lo = lo;
  r.lo_open = true;
  return r;
}
inline Range at_least(double lo)
{
  Range r;
  r.lo = lo;
  return r;
}
inline Range between(double lo, double hi, bool lo_open, bool hi_open)
{
  Range r;
  r.lo = lo;
  r.hi = hi;
  r.lo_open = lo_open;
  r.hi_open = hi_open;
  return r;
}

// whether LAMMPS's parser would take `text` as it is (plain ASCII: text with UTF-8 is LAMMPS's
// to substitute and judge)
inline bool ascii(const char *text)
{
  for (const char *c = text; *c; c++)
    if ((unsigned char) *c > 127) return false;
  return true;
}

// "must be a finite number in (0, 1]", "must be a finite number": what `range` allows
inline std::string finite_number_in(const Range &range)
{
  const std::string allowed = range.describe();
  return "must be a finite number" + (allowed.empty() ? "" : " " + allowed);
}

// The number in `text` for `what` (the command and keyword, e.g. "pair_style sph/soil alpha"):
// finite and in `range`, else an error (on all ranks: input arguments are the same everywhere).
inline double number(const char *file, int line, LAMMPS *lmp, const std::string &what,
                     const char *text, const Range &range = Range())
{
  if (ascii(text) && !utils::is_double(text))
    SPHSoilCompat::error_all(lmp, file, line, "Illegal {} {}: {}", what, text, finite_number_in(range));
  const double value = utils::numeric(file, line, text, false, lmp);
  if (!range.contains(value)) {
    const std::string allowed = range.describe();
    if (std::isfinite(value))
      SPHSoilCompat::error_all(lmp, file, line, "Illegal {} {}: must be {}", what, text, allowed);
    SPHSoilCompat::error_all(lmp, file, line, "Illegal {} {}: {}", what, text, finite_number_in(range));
  }
  return value;
}

// The integer in `text` for `what`, in [lo, hi] (hi = INT_MAX: no upper bound).
inline int integer(const char *file, int line, LAMMPS *lmp, const std::string &what,
                   const char *text, int lo, int hi = INT_MAX)
{
  const std::string allowed =
      hi == INT_MAX ? fmt::format(">= {}", lo) : fmt::format("in {} to {}", lo, hi);
  if (ascii(text) && !utils::is_integer(text))
    SPHSoilCompat::error_all(lmp, file, line, "Illegal {} {}: must be an integer {}", what, text,
                             allowed);
  const int value = utils::inumeric(file, line, text, false, lmp);
  if (value < lo || value > hi)
    SPHSoilCompat::error_all(lmp, file, line, "Illegal {} {}: must be {}", what, text, allowed);
  return value;
}

// The index of `text` among `names` for `what` (e.g. "fix sph/soil stepping"), else an error
// that lists them: the list a keyword is parsed with is the one its message shows.
inline int choice(const char *file, int line, LAMMPS *lmp, const std::string &what,
                  const char *text, const std::vector<std::string> &names)
{
  std::string allowed;
  for (size_t k = 0; k < names.size(); k++) {
    if (names[k] == text) return (int) k;
    allowed += (k ? ", " : "") + names[k];
  }
  SPHSoilCompat::error_all(lmp, file, line, "Illegal {} {} (allowed: {})", what, text, allowed);
}

}    // namespace SPHSoilInput
}    // namespace LAMMPS_NS

#endif
