// The registries are the one source of their names: a criterion or a model registered here,
// with nothing else written for it, is taken by the commands and listed in their errors'
// "allowed" lists. (The kernels' registry is a type list: test_kernel.cpp registers a dummy.)
#include "sph_soil_testing.h"

#include "atom_vec_sph_soil.h"
#include "compute_sph_soil_atom.h"
#include "soil_models.h"
#include "sph_soil_refine_criteria.h"

#include <cmath>

using namespace LAMMPS_NS;
using namespace SPHSoilTesting;

namespace {

// splits the particles at x <= edge (its own keyword), as a region block INF edge would hold
class DummyCriterion : public SPHSoilRefineCriterion {
 public:
  static constexpr const char *WORD = "dummy", *SHOWN = "dummy", *KEYWORDS = "edge";
  DummyCriterion(LAMMPS *lmp, const std::string &) : SPHSoilRefineCriterion(lmp), edge(0.0) {}
  bool parse_keyword(const std::string &, const std::string &keyword, const char *value) override
  {
    if (keyword != "edge") return false;
    edge = std::stod(value);
    return true;
  }
  bool wants(int i) const override { return atom->x[i][0] <= edge; }
  std::string describe() const override { return "the dummy's"; }

 private:
  double edge;
};

// Drucker-Prager under another keyword
std::unique_ptr<SPHSoil::ConstitutiveModel> make_dummy(const std::vector<std::string> &words,
                                                      std::string &error)
{
  return SPHSoil::make_model("drucker_prager", words, error);
}

class Registries : public SoilTest {
 protected:
  static void SetUpTestSuite()
  {
    register_refine_criterion(refine_criterion_entry<DummyCriterion>());
    SPHSoil::register_model({"dummy_model", "K nu phi psi c", &make_dummy});
  }
};

TEST_F(Registries, ADummyCriterionIsTakenAndListed)
{
  EXPECT_EQ(refine_criterion_names(), "strain, all, v_name, dummy");
  HIDE_OUTPUT([&] {
    for (const auto &line : periodic_patch_commands()) command(line);
    command("pair_style sph/soil");
    command("pair_coeff 1 1 soil 2650 0.7e6 0.3 19.8 0 0");
    command("run 0 post no");    // (wraps the disordered lattice's atoms into the box)
    command("variable left equal count(all,left)");
    command("region left block INF 0.05 INF INF INF INF units box");
    command("group left region left");
  });
  const bigint parents = (bigint) get_variable_value("left");
  ASSERT_GT(parents, 0);
  HIDE_OUTPUT([&] { command("sph_soil/refine all criterion dummy edge 0.05"); });
  // each parent left of x = 0.05 becomes 4 daughters
  EXPECT_EQ(lmp->atom->natoms, 320 + 3 * parents);
  EXPECT_LAMMPS_ERROR(".*Illegal fix sph/soil/refine criterion nothing \\(allowed: strain, all, "
                      "v_name, dummy\\).*",
                      command("fix r all sph/soil/refine 10 criterion nothing"));
  EXPECT_LAMMPS_ERROR(".*Illegal fix sph/soil/refine keyword height \\(allowed: criterion, region, "
                      "buffer, threshold, since, edge, separation, smoothing, dref, maxlevel, merge, ease\\).*",
                      command("fix r all sph/soil/refine 10 height 2"));
}

TEST_F(Registries, ADummyModelIsTakenAndListed)
{
  EXPECT_EQ(SPHSoil::model_keywords(), "drucker_prager, mohr_coulomb, dummy_model");
  HIDE_OUTPUT([&] {
    for (const auto &line : periodic_patch_commands()) command(line);
    command("pair_style sph/soil");
    command("pair_coeff 1 1 soil 2650 dummy_model 0.7e6 0.3 19.8 0 0");
  });
  EXPECT_LAMMPS_ERROR(".*unknown model 'plastic' \\(allowed: drucker_prager, mohr_coulomb, "
                      "dummy_model\\).*",
                      command("pair_coeff 1 1 soil 2650 plastic 0.7e6 0.3 19.8 0 0"));
}

// the compute's values are one table: the "allowed" list is its first names
TEST_F(Registries, ComputeValuesAreListedFromTheirTable)
{
  std::string names;
  for (const auto &value : ComputeSPHSoilAtom::values()) names += (names.empty() ? "" : " ") + value.names[0];
  EXPECT_EQ(ComputeSPHSoilAtom::value_names(), names);
  HIDE_OUTPUT([&] {
    for (const auto &line : periodic_patch_commands()) command(line);
  });
  EXPECT_LAMMPS_ERROR(".*Illegal compute sph/soil/atom value colour \\(allowed: " + names + "\\).*",
                      command("compute c all sph/soil/atom colour"));
}

}    // namespace
