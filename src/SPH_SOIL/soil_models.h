/* -*- c++ -*- ----------------------------------------------------------
   SPH_SOIL package: the registry of constitutive models (pure, no LAMMPS).

   A material line names its model by keyword and gives its parameters; the
   model's own create() reads and checks them (as GRANULAR's sub-models do).
   A new model is one file with its class and one line in soil_models.cpp.
------------------------------------------------------------------------- */

#ifndef LMP_SOIL_MODELS_H
#define LMP_SOIL_MODELS_H

#include "soil_constitutive.h"

#include <memory>
#include <string>
#include <vector>

namespace SPHSoil {

struct ModelEntry {
  const char *keyword;    // drucker_prager
  const char *usage;      // its words, for messages (model_usages()): "K nu phi psi c [fit ...]"
  std::unique_ptr<ConstitutiveModel> (*create)(const std::vector<std::string> &words,
                                               std::string &error);
};

// every model, in the order of the documentation (the registry: soil_models.cpp)
const std::vector<ModelEntry> &constitutive_models();
// add a model to the registry (for a model outside the package, and the tests' dummy model)
void register_model(const ModelEntry &entry);

// the entry of `keyword`, nullptr if there is none
const ModelEntry *find_model(const std::string &keyword);

// the keywords, comma-separated, for messages
std::string model_keywords();
// each keyword with its words ("drucker_prager K nu phi psi c ...; mohr_coulomb ..."), for
// messages that show how a model is written
std::string model_usages();

// the model of `keyword` built from `words` (the parameters after the keyword), or nullptr
// with the reason (naming the model, the parameter and its range) in `error`
std::unique_ptr<ConstitutiveModel> make_model(const std::string &keyword,
                                              const std::vector<std::string> &words,
                                              std::string &error);

// the model of a material line written before models had keywords (five numbers)
constexpr const char *DEFAULT_MODEL = "drucker_prager";

}    // namespace SPHSoil

#endif
