/* ----------------------------------------------------------------------
   SPH_SOIL package: the registry of constitutive models (pure, no LAMMPS)
------------------------------------------------------------------------- */

#include "soil_models.h"

#include "soil_drucker_prager.h"
#include "soil_mohr_coulomb.h"

using namespace SPHSoil;

namespace {
// the registry: one line per model
std::vector<ModelEntry> &registry()
{
  static std::vector<ModelEntry> models = {
      {DruckerPrager::KEYWORD, DruckerPrager::USAGE, &DruckerPrager::create},
      {MohrCoulomb::KEYWORD, MohrCoulomb::USAGE, &MohrCoulomb::create},
  };
  return models;
}
}    // namespace

const std::vector<ModelEntry> &SPHSoil::constitutive_models()
{
  return registry();
}

void SPHSoil::register_model(const ModelEntry &entry)
{
  registry().push_back(entry);
}

const ModelEntry *SPHSoil::find_model(const std::string &keyword)
{
  for (const auto &entry : constitutive_models())
    if (keyword == entry.keyword) return &entry;
  return nullptr;
}

std::string SPHSoil::model_keywords()
{
  std::string list;
  for (const auto &entry : constitutive_models()) list += (list.empty() ? "" : ", ") + std::string(entry.keyword);
  return list;
}

std::string SPHSoil::model_usages()
{
  std::string list;
  for (const auto &entry : constitutive_models())
    list += (list.empty() ? "" : "; ") + std::string(entry.keyword) + " " + entry.usage;
  return list;
}

std::unique_ptr<ConstitutiveModel> SPHSoil::make_model(const std::string &keyword,
                                                       const std::vector<std::string> &words,
                                                       std::string &error)
{
  const ModelEntry *entry = find_model(keyword);
  if (!entry) {
    error = "unknown model '" + keyword + "' (allowed: " + model_keywords() + ")";
    return nullptr;
  }
  return entry->create(words, error);
}
