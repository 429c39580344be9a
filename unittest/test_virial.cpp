// The pair style's virial: compute pressure and compute stress/atom see the SPH forces. For
// uniform particle stresses sigma the pair forces' virial is sum_ij x_ij (x) F_ij = -sum_i V_i
// M sigma, with M = -sum_j V_j x_ij (x) grad W_ij the kernel's discrete second moment (I for an
// exact kernel sum; mu I on a square lattice, mu = 0.9908 for the cubic spline at h = 1.2 d), so
// the pressure tensor is -mu sigma and the per-atom stress V_i mu sigma. With newton on LAMMPS takes
// x . f over owned and ghost atoms; with newton off, and per atom, the pairs are tallied one
// by one: both are tested.
#include "sph_soil_testing.h"

#include "force.h"
#include "soil_kernel_cubic.h"

#include <cmath>

using namespace LAMMPS_NS;
using namespace SPHSoilTesting;

namespace {

// Voigt xx yy zz xy xz yz
const double STRESS[6] = {-2000.0, -3000.0, -1000.0, 500.0, 0.0, 0.0};

class Virial : public SoilTest, public ::testing::WithParamInterface<const char *> {
 protected:

  // a periodic square lattice (20 x 16 at 1 cm, h = 1.2 d) of uniform stress, at rest
  void uniform_patch(const std::string &newton)
  {
    HIDE_OUTPUT([&] {
      command("newton " + newton);
      command("dimension 2");
      command("boundary p p p");
      command("atom_style sph/soil");
      command("atom_modify map array");
      command("lattice sq 0.01");
      command("region box block 0 20 0 16 -0.5 0.5");
      command("create_box 1 box");
      command("create_atoms 1 box");
      command(fmt::format("sph_soil/set all mass 0.265 h 0.012 density 2650 stress {} {} {} {} 0 0",
                          STRESS[0], STRESS[1], STRESS[2], STRESS[3]));
      command("pair_style sph/soil");
      command("pair_coeff 1 1 soil 2650 0.7e6 0.3 19.8 0 0");
      command("neighbor 0.002 bin");
      command("compute p all pressure NULL virial");
      command("compute s all stress/atom NULL virial");
      command("compute sum all reduce sum c_s[1] c_s[2] c_s[4]");
      command("thermo_style custom step c_p[1] c_p[2] c_p[4] c_sum[1] c_sum[2] c_sum[3]");
      command("run 0 post no");
    });
  }
  // compute `id`'s element k (from 1) after the last run
  double element(const std::string &id, int k)
  {
    HIDE_OUTPUT([&] { command(fmt::format("variable element equal c_{}[{}]", id, k)); });
    return get_variable_value("element");
  }
};

// mu = -sum_j V_j dx^2 (1/r) dW/dr over the square lattice of spacing d, h = 1.2 d
double lattice_moment(double d, double h)
{
  double mu = 0.0;
  for (int a = -5; a <= 5; a++)
    for (int b = -5; b <= 5; b++) {
      const double dx = a * d, dy = b * d, r = std::sqrt(dx * dx + dy * dy);
      if (r > 0.0 && r < 2.0 * h) mu -= d * d * dx * dx * SPHSoil::CubicSpline::gradient_factor(2, r, h);
    }
  return mu;
}

TEST_P(Virial, PressureIsMinusTheParticleStressAndStressAtomItsVolumeShare)
{
  uniform_patch(GetParam());
  const double area = 0.2 * 0.16;
  const double mu = lattice_moment(0.01, 0.012);
  EXPECT_NEAR(mu, 1.0, 0.01);
  const int components[3] = {0, 1, 3};
  for (int k = 0; k < 3; k++) {
    const double sigma = STRESS[components[k]];
    const double pressure = element("p", components[k] + 1);
    EXPECT_NEAR(pressure, -mu * sigma, 1e-9 * std::fabs(STRESS[1])) << "component " << k;
    // per atom: compute stress/atom is minus the per-atom virial, in stress x volume
    const double per_atom_sum = element("sum", k + 1);
    EXPECT_NEAR(per_atom_sum / area, mu * sigma, 1e-9 * std::fabs(STRESS[1])) << "component " << k;
    // and the two agree to round-off: the same pairs, tallied two ways
    EXPECT_NEAR(per_atom_sum / area, -pressure, 1e-9 * std::fabs(STRESS[1])) << "component " << k;
  }
}

INSTANTIATE_TEST_SUITE_P(SPHSoil, Virial, ::testing::Values("on", "off"));

// The disordered patch with stresses that vary in space: the pressure tensor is minus the
// volume average of the particle stresses to the kernel's consistency on that lattice.
TEST_F(Virial, PressureFollowsTheAverageStressOfADisorderedPatch)
{
  HIDE_OUTPUT([&] {
    for (const auto &line : periodic_patch_commands()) command(line);
    command("pair_style sph/soil");
    command("pair_coeff 1 1 soil 2650 0.7e6 0.3 19.8 0 0");
    command("neighbor 0.002 bin");
    command("compute p all pressure NULL virial");
    command("compute v all property/atom rho mass sxx syy sxy");
    command("variable vsxx atom c_v[2]/c_v[1]*c_v[3]");
    command("variable vsyy atom c_v[2]/c_v[1]*c_v[4]");
    command("variable vsxy atom c_v[2]/c_v[1]*c_v[5]");
    command("compute avg all reduce sum v_vsxx v_vsyy v_vsxy");
    command("thermo_style custom step c_p[1] c_p[2] c_p[4] c_avg[1] c_avg[2] c_avg[3]");
    command("run 0 post no");
  });
  const double area = 0.2 * 0.16;
  const int components[3] = {1, 2, 4};
  for (int k = 0; k < 3; k++) {
    const double pressure = element("p", components[k]);
    const double average = element("avg", k + 1) / area;
    EXPECT_NEAR(pressure, -average, 0.02 * 1500.0) << "component " << k;
  }
}

}    // namespace
