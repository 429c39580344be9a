/* -*- c++ -*- ----------------------------------------------------------
   SPH_SOIL package: Mohr-Coulomb soil model (pure, no LAMMPS).

   Perfectly plastic Mohr-Coulomb in principal stresses (tension positive,
   sigma_1 >= sigma_2 >= sigma_3; doc/theory.rst section 3.10):
     f = (sigma_1 - sigma_3)/2 + (sigma_1 + sigma_3)/2 sin(phi) - c cos(phi)
     g = (sigma_1 - sigma_3)/2 + (sigma_1 + sigma_3)/2 sin(psi)
   No fit is needed: in plane strain sigma_zz is one of the three principal
   stresses, and when it is the intermediate one (as in plane-strain flow)
   the in-plane strength is exactly tau = c cos(phi) - sigma_m sin(phi), with
   sigma_m the in-plane mean stress. In 3D the surface is Mohr-Coulomb's
   hexagonal pyramid.

   Integration: the stress rate is elastic (Jaumann + Hooke); the plastic
   correction is the closest-point return of return_to_admissible(), exact
   for a linear surface with perfect plasticity (one backward-Euler step):
   to the face, or, when that return would reorder the principal stresses,
   to one of the two edges (sigma_1 = sigma_2 or sigma_2 = sigma_3), or to
   the apex c cot(phi) (de Souza Neto, Peric & Owen 2008, section 8.2).

   Tension cut-off (Rankine): with 'tension T' no principal stress exceeds T
   (0 <= T <= the apex c cot(phi)); after the Mohr-Coulomb return, a principal
   stress above T is set to T, the others kept (an opening crack normal to it).
   T = 0 is a soil that carries no tension in any direction: at a footing's
   corner, where Mohr-Coulomb alone returns to its apex in tension.

   Material line: mohr_coulomb K nu phi psi c [tension T]
------------------------------------------------------------------------- */

#ifndef LMP_SOIL_MOHR_COULOMB_H
#define LMP_SOIL_MOHR_COULOMB_H

#include "soil_constitutive.h"

#include <algorithm>
#include <limits>
#include <memory>

namespace SPHSoil {

class MohrCoulomb final : public ConstitutiveModel {
 public:
  static constexpr const char *KEYWORD = "mohr_coulomb";
  static constexpr const char *USAGE = "K nu phi psi c [tension T]";
  // relative distance to the surface below which a stress counts as on it, in units of
  // (sigma_1 - sigma_3)/2 + |sigma_1 + sigma_3|/2 sin(phi) + c cos(phi)
  static constexpr double YIELD_TOLERANCE = 1.0e-10;

  // the parameters must pass check(); throws std::invalid_argument otherwise. `tension`: the
  // largest principal stress (Pa), infinity for none
  explicit MohrCoulomb(const FrictionalParameters &parameters,
                       double tension = std::numeric_limits<double>::infinity());
  static std::string check(const FrictionalParameters &parameters, double tension);
  // from the words of a material line after the keyword; nullptr and `error` if they are wrong
  static std::unique_ptr<ConstitutiveModel> create(const std::vector<std::string> &words,
                                                   std::string &error);

  const char *keyword() const override { return KEYWORD; }
  void stress_rate(const double stress[6], const double strain_rate[6], const double spin[3],
                   double rate[6]) const override;
  bool return_to_admissible(double stress[6]) const override;
  double yield_function(const double stress[6]) const override;
  bool on_yield_surface(const double stress[6]) const override;
  double p_wave_modulus() const override { return bulk + 4.0 * shear / 3.0; }
  // the apex c cot(phi), or the cut-off below it; no limit for phi = 0 with c > 0 and no cut-off
  double tensile_strength() const override
  {
    const double cone = sin_phi > 0.0 || params.cohesion == 0.0 ? apex : std::numeric_limits<double>::infinity();
    return std::min(cone, tension);
  }
  double tension_cutoff() const { return tension; }

  const FrictionalParameters &parameters() const { return params; }
  double shear_modulus() const { return shear; }

  // where the last call of return_principal() went (for tests)
  enum class Return { none, face, edge_12, edge_23, apex };
  // the return in principal stresses (descending on entry and on exit)
  Return return_principal(double principal[3]) const;

 private:
  FrictionalParameters params;
  double bulk, shear;              // K, G
  double sin_phi, sin_psi, cohesion_term;    // sin(phi), sin(psi), 2 c cos(phi)
  double lame;                     // K - 2G/3
  double apex;                     // c cot(phi), each principal stress at the apex (phi > 0)
  double tension;                  // the cut-off of every principal stress (infinity: none)
  // twice f and twice g: yield_twice(s) = (s1 - s3) + (s1 + s3) sin(phi) - 2 c cos(phi)
  double yield_twice(const double s[3]) const
  {
    return (s[0] - s[2]) + (s[0] + s[2]) * sin_phi - cohesion_term;
  }
  double face_stiffness;           // a = (df/ds) : D : (dg/ds) on a face
  double edge_coupling_12, edge_coupling_23;    // the cross terms of the two faces of an edge
};

}    // namespace SPHSoil

#endif
