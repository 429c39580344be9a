/* -*- c++ -*- ----------------------------------------------------------
   SPH_SOIL package: constitutive models of the soil (pure, no LAMMPS).

   Conventions of tensors: soil_tensor.h.

   The integrator only talks to the abstract ConstitutiveModel. Models are
   chosen by keyword from the registry in soil_models.cpp: a new model is
   one file with its class (it parses and checks its own parameters and
   derives its constants once) and one line there. The models here:
   soil_drucker_prager.h, soil_mohr_coulomb.h.
------------------------------------------------------------------------- */

#ifndef LMP_SOIL_CONSTITUTIVE_H
#define LMP_SOIL_CONSTITUTIVE_H

#include "soil_numbers.h"
#include "soil_tensor.h"

#include <cmath>
#include <string>
#include <vector>

namespace SPHSoil {

/* ----------------------------------------------------------------------
   interface seen by the integrator
------------------------------------------------------------------------- */

class ConstitutiveModel {
 public:
  virtual ~ConstitutiveModel() = default;

  // the keyword that chose it (drucker_prager, mohr_coulomb)
  virtual const char *keyword() const = 0;

  // d(stress)/dt from the current stress, strain rate and spin: Jaumann terms + the
  // model's rate (elastic-plastic for a rate-form model, elastic for one whose plastic
  // correction is all in return_to_admissible())
  virtual void stress_rate(const double stress[6], const double strain_rate[6],
                           const double spin[3], double rate[6]) const = 0;

  // bring a stress back to the admissible set after an update;
  // returns true if it changed the stress
  virtual bool return_to_admissible(double stress[6]) const = 0;

  // > 0 outside the admissible set, 0 on its boundary (in stress units)
  virtual double yield_function(const double stress[6]) const = 0;

  // true if the stress is on (or outside) the yield surface within the model's
  // tolerance: the "yielded" flag of the output
  virtual bool on_yield_surface(const double stress[6]) const = 0;

  // P-wave modulus K + 4G/3 (Pa)
  virtual double p_wave_modulus() const = 0;
  // the largest mean stress I1/3 the model admits (Pa): 0 for a soil without cohesion,
  // infinity for one without a limit (phi = 0); > 0 means the soil can be in tension, where
  // SPH needs the artificial stress (pair_style sph/soil)
  virtual double tensile_strength() const = 0;

  // elastic P-wave speed sqrt((K + 4G/3)/rho0), for the time step and artificial viscosity
  double wave_speed(double reference_density) const
  {
    return std::sqrt(p_wave_modulus() / reference_density);
  }
};

/* ----------------------------------------------------------------------
   the parameters of a frictional soil, shared by the models that have them:
   linear elasticity (K, nu) and a Mohr-Coulomb strength (phi, c) with a
   dilatancy angle psi for the flow rule
------------------------------------------------------------------------- */

/* ----------------------------------------------------------------------
   a model's usage (its USAGE, e.g. "K nu phi psi c [fit exact|associated|nonassociated]
   [tension T]") is the one statement of its words: its parameters are the words before the
   first '[', its options the first word within each '[...]'. Messages list them from it.
------------------------------------------------------------------------- */

int usage_parameter_count(const std::string &usage);
// the options, comma-separated ("fit, tension"; empty if none)
std::string usage_options(const std::string &usage);
// whether `word` is one of the usage's options
bool usage_has_option(const std::string &usage, const std::string &word);

struct FrictionalParameters {
  double bulk_modulus = 0.0;       // K (Pa)
  double poisson_ratio = 0.0;      // nu
  double friction_angle = 0.0;     // phi (degrees)
  double dilatancy_angle = 0.0;    // psi (degrees)
  double cohesion = 0.0;           // c (Pa)

  // G = 3K (1 - 2nu) / (2 (1 + nu))
  double shear_modulus() const
  {
    return 3.0 * bulk_modulus * (1.0 - 2.0 * poisson_ratio) / (2.0 * (1.0 + poisson_ratio));
  }
  // empty if admissible, else which parameter is wrong, its value and its allowed range
  std::string check() const;

  // the same from Young's modulus: K = E / (3 (1 - 2 nu))
  static FrictionalParameters from_young_modulus(double young_modulus, double poisson_ratio,
                                                 double friction_angle, double dilatancy_angle,
                                                 double cohesion);
  // check() for parameters given as (E, nu, phi, psi, c): names E rather than K
  static std::string check_young_modulus(double young_modulus, double poisson_ratio,
                                         double friction_angle, double dilatancy_angle,
                                         double cohesion);

  // the order of the words of a material line, for messages
  static constexpr const char *WORDS = "K nu phi psi c";
  static constexpr int COUNT = 5;
  // K nu phi psi c from the first COUNT words (the model's keyword names it in errors); the
  // words after them go to `options`. False with the reason in `error` if a word is missing,
  // not a finite number, or the set fails check().
  static bool from_words(const std::string &model, const std::vector<std::string> &words,
                         FrictionalParameters &parameters, std::vector<std::string> &options,
                         std::string &error);

  // The tension cut-off T of the models that have one ('tension T'): the option's value as a
  // number (false with the reason, naming `model`, in `error`), and its range [0, apex], the
  // apex's mean stress (described by `apex_name`) limiting the tension already; empty if fine.
  static bool tension_from_word(const std::string &model, const std::string &value,
                                double &tension, std::string &error);
  static std::string check_tension(double tension, double apex, const char *apex_name);
};

}    // namespace SPHSoil

#endif
