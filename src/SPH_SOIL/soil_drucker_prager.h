/* -*- c++ -*- ----------------------------------------------------------
   SPH_SOIL package: Drucker-Prager soil model (pure, no LAMMPS).

   Non-associated, perfectly plastic, in rate form (Bui et al. 2008;
   doc/theory.rst section 3):
     f = sqrt(J2) + alpha_phi I1 - k_c,   g = sqrt(J2) + 3 I1 sin(psi)
   alpha_phi and k_c come from a plane-strain fit to Mohr-Coulomb's phi and c
   (DruckerPragerFit):
     exact (the default): the fit under which plane-strain plastic flow with
       this g fails exactly at Mohr-Coulomb's strength. With beta = 3 sin(psi)
       (the I1 coefficient of g):
         alpha_phi = sin(phi) / (3 (sqrt(1 - 3 beta^2) + beta sin(phi))),
         k_c = c cos(phi) (1 - 3 alpha_phi beta) / sqrt(1 - 3 beta^2);
       psi = 0 gives sin(phi)/3 and c cos(phi). It exists for beta^2 < 1/3,
       i.e. psi < 11.1 degrees: beyond, g dilates so much that no plastic
       flow is possible in plane strain, and the fit must be chosen;
     associated (Bui 2008; the same formula with beta = alpha_phi, i.e. exact
       for a flow potential with g = f):
         alpha_phi = tan(phi)/sqrt(9 + 12 tan^2 phi), k_c = 3c/sqrt(9 + 12 tan^2 phi);
     nonassociated (exact for psi = 0): alpha_phi = sin(phi)/3, k_c = c cos(phi).
   phi = 0 gives a pressure-independent (von Mises-like) surface sqrt(J2) <= c
   with no tension cap (all fits agree there).
   Tension cut-off (Bui 2008's tension cracking, generalized): the mean stress
   I1/3 never exceeds the tensile strength T; by default T is the apex of the
   cone, k_c / (3 alpha_phi) (c cot(phi) for psi = 0), and infinite for
   phi = 0; 'tension T' sets a lower one, 0 <= T <= the apex (T = 0: soil
   that carries no mean tension, a cohesive soil that cracks).

   Material line:
     drucker_prager K nu phi psi c [fit exact|associated|nonassociated] [tension T]
------------------------------------------------------------------------- */

#ifndef LMP_SOIL_DRUCKER_PRAGER_H
#define LMP_SOIL_DRUCKER_PRAGER_H

#include "soil_constitutive.h"

#include <limits>
#include <memory>

namespace SPHSoil {

enum class DruckerPragerFit { exact, associated, nonassociated };

struct DruckerPragerParameters : FrictionalParameters {
  DruckerPragerFit fit = DruckerPragerFit::exact;    // plane-strain fit to Mohr-Coulomb
  // the tension cut-off: largest mean stress I1/3 (Pa); infinity: the cone's apex
  double tension = std::numeric_limits<double>::infinity();

  DruckerPragerParameters() = default;
  DruckerPragerParameters(const FrictionalParameters &frictional,
                          DruckerPragerFit fit = DruckerPragerFit::exact) :
      FrictionalParameters(frictional), fit(fit)
  {
  }
};

class DruckerPrager final : public ConstitutiveModel {
 public:
  static constexpr const char *KEYWORD = "drucker_prager";
  static constexpr const char *USAGE =
      "K nu phi psi c [fit exact|associated|nonassociated] [tension T]";
  // relative distance to the yield surface below which a stress counts as on it,
  // in units of sqrt(J2) + alpha_phi |I1| + k_c (see soil_drucker_prager.cpp)
  static constexpr double YIELD_TOLERANCE = 1.0e-10;
  // J2 below (1 - SQUARED_MARGIN) r^2 means sqrt(J2) < r whatever the rounding of the square
  // root (0.5 ulp): the tests that decide "inside" skip the square root with no change of result
  static constexpr double SQUARED_MARGIN = 1.0e-12;
  // the exact fit exists below this dilatancy angle: 3 sin(psi) < 1/sqrt(3)
  static double largest_exact_dilatancy();

  // the parameters must pass check(); throws std::invalid_argument otherwise
  explicit DruckerPrager(const DruckerPragerParameters &parameters);

  // empty if the parameters are admissible, else which one is wrong and its allowed range
  static std::string check(const DruckerPragerParameters &parameters);
  // from the words of a material line after the keyword; nullptr and `error` if they are wrong
  static std::unique_ptr<ConstitutiveModel> create(const std::vector<std::string> &words,
                                                   std::string &error);

  const char *keyword() const override { return KEYWORD; }
  void stress_rate(const double stress[6], const double strain_rate[6], const double spin[3],
                   double rate[6]) const override;
  bool return_to_admissible(double stress[6]) const override;
  double yield_function(const double stress[6]) const override;
  bool on_yield_surface(const double stress[6]) const override;
  double p_wave_modulus() const override { return p_modulus; }
  double tensile_strength() const override { return largest_i1 / 3.0; }

  const DruckerPragerParameters &parameters() const { return params; }
  double bulk_modulus() const { return bulk; }
  double shear_modulus() const { return shear; }
  double alpha_phi() const { return alpha; }
  double k_c() const { return kc; }

 private:
  DruckerPragerParameters params;
  double bulk, shear;          // K, G
  double alpha, kc;            // alpha_phi, k_c
  double largest_i1;           // the tension cut-off: 3 T, at most the apex k_c / alpha_phi
  double flow_volumetric;      // 9 K sin(psi): volumetric part of the plastic stress rate
  double plastic_denominator;  // 27 alpha_phi K sin(psi) + G, > 0
  double p_modulus;            // K + 4G/3
};

}    // namespace SPHSoil

#endif
