// The pair term's pieces that are not covered by the LAMMPS-level tests: the mirrored stress of
// a free-slip wall image, which wall particles stand for an image past a convex corner, the
// Coulomb interface of a frictional wall, and the density's step.
#include "soil_density_step.h"
#include "soil_kernel_cubic.h"
#include "soil_pair_terms.h"
#include "soil_wall_friction.h"
#include "soil_wall_images.h"

#include "gtest/gtest.h"

#include <algorithm>
#include <array>
#include <cmath>

using namespace SPHSoil;

// A wall along x (normal y): the image keeps the normal stresses and flips the shear stresses
// that couple y with x and z, so the sum has no shear traction on the wall: (sum n) x n = 0.
TEST(PairTerm, MirroredStressOfAFreeSlipWallHasNoShearTraction)
{
  const double stress[6] = {-3.0, -5.0, -4.0, 1.5, 0.7, -0.9};
  const double ny[3] = {0.0, 1.0, 0.0};
  double sum[6];
  mirrored_stress_sum(stress, ny, sum);
  const double expected[6] = {-6.0, -10.0, -8.0, 0.0, 1.4, 0.0};
  for (int k = 0; k < 6; k++) EXPECT_NEAR(sum[k], expected[k], 1e-15) << k;

  // any normal: the traction of the sum is normal to the wall, and twice the soil's normal stress
  const double angle = 0.3;
  const double n[3] = {std::cos(angle) * std::sin(1.1), std::sin(angle) * std::sin(1.1), std::cos(1.1)};
  mirrored_stress_sum(stress, n, sum);
  static const int voigt[3][3] = {{0, 3, 4}, {3, 1, 5}, {4, 5, 2}};
  double traction[3], soil_traction[3];
  for (int a = 0; a < 3; a++) {
    traction[a] = soil_traction[a] = 0.0;
    for (int b = 0; b < 3; b++) {
      traction[a] += sum[voigt[a][b]] * n[b];
      soil_traction[a] += stress[voigt[a][b]] * n[b];
    }
  }
  const double normal = traction[0] * n[0] + traction[1] * n[1] + traction[2] * n[2];
  const double soil_normal = soil_traction[0] * n[0] + soil_traction[1] * n[1] + soil_traction[2] * n[2];
  for (int a = 0; a < 3; a++) EXPECT_NEAR(traction[a], normal * n[a], 1e-14) << a;
  EXPECT_NEAR(normal, 2.0 * soil_normal, 1e-14);
  // and the trace is kept: the mirror is a rotation-like congruence
  EXPECT_NEAR(sum[0] + sum[1] + sum[2], 2.0 * (stress[0] + stress[1] + stress[2]), 1e-14);
}

// The Coulomb interface (soil_wall_friction.h), from a particle's contact sums: a wall of
// normal y at rest, normal force N = 10 on a contact area 0.01 (pressure 1000), mu = 0.3 (limit
// 3). Sticking, the trial force cancels the tangential force and the slip of the half step;
// sliding, it is mu N against the trial's direction; mu = 0 gives nothing; a moving wall's
// velocity is the reference of the slip.
// soil lifting off a drained wall (doc/theory.rst 7.3): the gap is 0 where a lattice touches the
// plane, the contact fades over CONTACT_RANGE of the spacing, and across the gap the image holds
// the wall's water
TEST(DrainedWall, GapIsMeasuredFromTheLatticePositionAndTheContactFadesWithIt)
{
  const double spacing = 0.004, volume = spacing * spacing;
  EXPECT_NEAR(gap_to_wall<2>(0.5 * spacing, volume), 0.0, 1e-15);
  EXPECT_NEAR(gap_to_wall<2>(0.6 * spacing, volume), 0.1 * spacing, 1e-15);
  EXPECT_NEAR(gap_to_wall<3>(0.7 * spacing, spacing * spacing * spacing), 0.2 * spacing, 1e-15);
  EXPECT_EQ(contact_share<2>(-0.01 * spacing, volume), 1.0);
  EXPECT_EQ(contact_share<2>(0.0, volume), 1.0);
  EXPECT_NEAR(contact_share<2>(0.5 * CONTACT_RANGE * spacing, volume), 0.5, 1e-12);
  EXPECT_EQ(contact_share<2>(CONTACT_RANGE * spacing, volume), 0.0);
  EXPECT_EQ(contact_share<2>(spacing, volume), 0.0);
}

// The wall's contact: nothing beyond the reach (3/4 of the mean spacing), rising linearly over a
// quarter of the soil's spacing. Summed over a lattice of wall particles of the soil's spacing
// (3 rows behind the plane y = 0), a particle standing on the wall (half a spacing from the
// plane) is out of reach; one on the plane is within reach wherever it stands along the wall,
// and is pushed back, harder the deeper it goes; a coarse soil particle (twice the wall's
// spacing) at rest is out of reach too.
TEST(WallContact, ReachesAParticleOnlyPastItsRestingPlace)
{
  const double s = 0.01;
  EXPECT_EQ(contact_strain(0.75 * s, s, s), 0.0);
  EXPECT_EQ(contact_strain(1.0 * s, s, s), 0.0);
  EXPECT_NEAR(contact_strain(0.5 * s, s, s), 1.0, 1e-12);
  EXPECT_NEAR(contact_strain(0.5 * s, 2.0 * s, s), 1.25, 1e-12);
  EXPECT_EQ(contact_strain(1.5 * s, 2.0 * s, s), 0.0);

  const double modulus = 1.0;
  auto push = [&](double x, double y, double soil_spacing) {
    double force[2] = {0.0, 0.0};
    for (int i = -10; i <= 10; i++)
      for (int k = 0; k < 3; k++) {
        const double sep[3] = {x - (i + 0.5) * s, y + (k + 0.5) * s, 0.0};
        const double r = std::sqrt(sep[0] * sep[0] + sep[1] * sep[1]);
        const double strain = contact_strain(r, soil_spacing, s);
        const double still[3] = {0.0, 0.0, 0.0};
        if (strain > 0.0) add_contact_force<2>(modulus, 1.0, soil_spacing, strain, sep, r, still, 1.0, force);
      }
    return std::array<double, 2>{force[0], force[1]};
  };
  for (double x : {0.0, 0.2 * s, 0.5 * s}) {
    const auto rest = push(x, 0.5 * s, s);
    EXPECT_EQ(rest[0], 0.0);
    EXPECT_EQ(rest[1], 0.0);
    EXPECT_GT(push(x, 0.0, s)[1], 0.0) << "x = " << x;
    EXPECT_GT(push(x, -0.2 * s, s)[1], push(x, 0.0, s)[1]) << "x = " << x;
    EXPECT_EQ(push(x, 1.0 * s, 2.0 * s)[1], 0.0);
  }
  // the bound without roots holds every pair in reach (2D and 3D, equal and unequal spacings)
  for (double ratio : {0.25, 0.5, 1.0, 2.0, 4.0})
    for (double fraction : {0.5, 0.9, 0.999, 1.001, 1.1}) {
      const double sw = ratio * s, r = fraction * CONTACT_REACH * 0.5 * (s + sw);
      const bool in_reach = contact_strain(r, s, sw) > 0.0;
      if (in_reach) {
        EXPECT_TRUE(contact_possible<2>(r * r, s * s, sw * sw)) << ratio << " " << fraction;
        EXPECT_TRUE(contact_possible<3>(r * r, s * s * s, sw * sw * sw)) << ratio << " " << fraction;
      }
    }
  EXPECT_FALSE(contact_possible<2>(s * s, s * s, s * s));    // a wall particle a spacing away
  EXPECT_FALSE(contact_possible<3>(s * s, s * s * s, s * s * s));
  // directly over a wall particle, on the plane: one contact at strain 1, the modulus on the face
  EXPECT_NEAR(push(0.5 * s, 0.0, s)[1], modulus * s, 1e-12);
  // the dashpot: 4 rho c (critical damping of the spring) on the approach; never a pull
  const double sep[3] = {0.0, 0.5 * s, 0.0}, rho = 2000.0, c = 100.0;
  for (double approach : {0.0, 0.01, -0.01, -10.0}) {
    double force[2] = {0.0, 0.0};
    const double v[3] = {0.0, -approach, 0.0};
    add_contact_force<2>(rho * c * c, rho * c, s, 0.2, sep, 0.5 * s, v, 1.0, force);
    EXPECT_NEAR(force[1], std::max(0.0, s * (rho * c * c * 0.2 + 4.0 * rho * c * approach)), 1e-9)
        << "approach " << approach;
    EXPECT_EQ(force[0], 0.0);
  }
}

// A footing of spacing s: its base the plane y = 0 (normal -y, its particles at y = s/2, 3s/2),
// its right side the plane x = 0 (normal +x, particles at x = -s/2, -3s/2, above the base's
// corner rows). A soil particle beside the side and above the base's plane (behind it) stands in
// front of the side: the base's particles stand for no image of it, the side's do. One under the
// base is imaged by the base alone; past the corner, in front of both, by both. One that crossed
// the base (behind every plane it pairs with) keeps the base's images, which push it back out.
TEST(WallImage, PastAConvexCornerOnlyTheFaceInFrontImages)
{
  const double s = 0.01, half = 0.5 * s;
  const double base_normal[3] = {0.0, -1.0, 0.0}, side_normal[3] = {1.0, 0.0, 0.0};
  const double base_particle[PACKED] = {-half, half, 0.0};    // a packed row: position first
  const double side_particle[PACKED] = {-half, 3.0 * half, 0.0};
  auto beyond = [&](const double *soil, const double *wall, const double *n) {
    const double separation[3] = {soil[0] - wall[0], soil[1] - wall[1], 0.0};
    return beyond_wall_plane<2>(separation, n, half);
  };
  auto front_most = [&](const double *soil) {
    return std::max(beyond(soil, base_particle, base_normal), beyond(soil, side_particle, side_normal));
  };
  auto images = [&](const double *soil) {
    const double front = front_most(soil);
    return std::array<bool, 2>{has_image<2>(soil, base_particle, base_normal, half, front),
                               has_image<2>(soil, side_particle, side_normal, half, front)};
  };
  const double beside[PACKED] = {half, s, 0.0}, under[PACKED] = {-half, -half, 0.0},
               past[PACKED] = {half, -half, 0.0};
  EXPECT_EQ(images(beside), (std::array<bool, 2>{false, true}));
  EXPECT_EQ(images(under), (std::array<bool, 2>{true, false}));
  EXPECT_EQ(images(past), (std::array<bool, 2>{true, true}));
  // crossed the base, far from the side (it pairs with the base only)
  const double crossed[PACKED] = {-5.0 * s, 0.2 * s, 0.0};
  const double alone = beyond(crossed, base_particle, base_normal);
  EXPECT_LT(alone, 0.0);
  EXPECT_TRUE(has_image<2>(crossed, base_particle, base_normal, half, alone));
  // the pair's image says the same, and a particle without one takes no terms
  const double soil_row[PACKED] = {half, s, 0.0, 0.3, 0.1, 0.0}, wall_row[PACKED] = {-half, half, 0.0};
  MirrorImage image;
  double separation[3] = {soil_row[0] - wall_row[0], soil_row[1] - wall_row[1], 0.0};
  EXPECT_FALSE(mirror_image<2>(soil_row, wall_row, base_normal, half, front_most(soil_row), separation,
                               SLIP_FREE, image));
  EXPECT_NEAR(image.normal_separation, -half, 1e-15);
  PairTerms<2> terms;
  terms.force[0] = terms.gradient[1][1] = 1.0;
  no_pair_terms<2>(terms);
  EXPECT_EQ(terms.density_rate, 0.0);
  EXPECT_EQ(terms.force[0], 0.0);
  EXPECT_EQ(terms.gradient[1][1], 0.0);
}

TEST(DrainedWall, ImageAcrossAGapHoldsItsShareOfTheSoilAndTheWallsWater)
{
  // a soil particle over a no-slip floor (normal +y), effective stress sigma' and pore pressure
  // p_s; its packed total stress sigma' - p_s I, the wall's water at p_w
  const double n[3] = {0.0, 1.0, 0.0};
  const double effective[6] = {-300.0, -700.0, -300.0, 40.0, 0.0, 0.0};
  const double p_s = 2000.0, p_w = 2100.0;
  double total[6];
  for (int k = 0; k < 6; k++) total[k] = effective[k] - (k < 3 ? p_s : 0.0);
  const double separation[3] = {0.001, 0.002, 0.0};
  const double velocity[3] = {0.01, 0.03, 0.0};    // v_s - v_image: sliding and separating
  for (double share : {1.0, 0.25, 0.0}) {
    MirrorImage image;
    for (int k = 0; k < 6; k++) image.stress_sum[k] = 0.0;
    for (int k : {0, 1, 3}) image.stress_sum[k] = 2.0 * total[k];    // mirror_image's, no slip
    for (int a = 0; a < 3; a++) image.dv[a] = velocity[a];
    image.approach = velocity[0] * separation[0] + velocity[1] * separation[1];
    drained_image<2>(total, p_w, share, n, separation, image);
    // the image: share of the soil's total stress (in contact, the mirror's), the rest the
    // wall's water, -p_w I
    for (int k : {0, 1, 3}) {
      const double image_stress = share * total[k] - (1.0 - share) * (k < 2 ? p_w : 0.0);
      EXPECT_NEAR(image.stress_sum[k], total[k] + image_stress, 1e-9) << "share " << share;
    }
    // (2D: the out-of-plane components are not the pair's)
    EXPECT_EQ(image.stress_sum[2], 0.0);
    // sliding kept, the separation's share with the contact
    EXPECT_NEAR(image.dv[0], velocity[0], 1e-15);
    EXPECT_NEAR(image.dv[1], share * velocity[1], 1e-15);
    EXPECT_NEAR(image.approach, image.dv[0] * separation[0] + image.dv[1] * separation[1], 1e-15);
  }
}

TEST(WallFriction, TrialForceStopsTheSlipAndCoulombBoundsIt)
{
  const double normal[3] = {0.0, 1.0, 0.0}, at_rest[3] = {0.0, 0.0, 0.0};
  double contact[CONTACT_SUMS] = {0.0};
  // two partners, 4 and 6, of mu 0.3
  add_contact(contact, 4.0, 0.3, normal, at_rest, 0.0, 0.004);
  add_contact(contact, 6.0, 0.3, normal, at_rest, 0.0, 0.006);
  EXPECT_DOUBLE_EQ(contact[C_NORMAL_FORCE], 10.0);
  EXPECT_DOUBLE_EQ(contact[C_FRICTION], 3.0);
  EXPECT_DOUBLE_EQ(contact[C_AREA], 0.01);
  const double mass = 2.0, dt = 0.01, h = 0.01;
  double ratio[3], pressure = NO_CONTACT;

  // sticking: tangential force 1 and a slip of 0.005 m/s: trial -1 - (2/0.01) 0.005 = -2
  const double f[3] = {1.0, -10.0, 0.5}, v[3] = {0.005, 0.3, 0.0};
  EXPECT_FALSE(contact_friction(contact, mass, f, v, h, 0.0, dt, pressure, ratio));
  EXPECT_NEAR(ratio[0] * 10.0, -2.0, 1e-14);
  EXPECT_NEAR(ratio[1], 0.0, 1e-15);    // nothing along the normal
  EXPECT_NEAR(ratio[2] * 10.0, -0.5, 1e-14);
  EXPECT_DOUBLE_EQ(pressure, 1000.0);    // sticking: the contact's pressure
  // after it, the tangential velocity at the next half step is 0 (f constant)
  EXPECT_NEAR(v[0] + dt * (f[0] + ratio[0] * 10.0) / mass, 0.0, 1e-15);

  // sliding: a slip of 0.1 m/s, trial (-21, 0, -0.5), |T| = mu N = 3 along it
  const double fast[3] = {0.1, 0.3, 0.0};
  EXPECT_TRUE(contact_friction(contact, mass, f, fast, h, 0.0, dt, pressure, ratio));
  const double trial = std::hypot(21.0, 0.5);
  EXPECT_NEAR(ratio[0] * 10.0, -3.0 * 21.0 / trial, 1e-13);
  EXPECT_NEAR(ratio[2] * 10.0, -3.0 * 0.5 / trial, 1e-13);

  // mu = 0: no friction at all
  double smooth[CONTACT_SUMS] = {0.0};
  add_contact(smooth, 10.0, 0.0, normal, at_rest, 0.0, 0.01);
  pressure = NO_CONTACT;
  contact_friction(smooth, mass, f, fast, h, 0.0, dt, pressure, ratio);
  for (int a = 0; a < 3; a++) EXPECT_EQ(ratio[a], 0.0);

  // a wall moving with the soil at 0.1 m/s: no slip, the trial force is the tangential force's
  double moving[CONTACT_SUMS] = {0.0};
  const double wall_velocity[3] = {0.1, 0.0, 0.0};
  add_contact(moving, 10.0, 0.3, normal, wall_velocity, 0.0, 0.01);
  EXPECT_FALSE(contact_friction(moving, mass, f, fast, h, 0.0, dt, pressure, ratio));
  EXPECT_NEAR(ratio[0] * 10.0, -1.0, 1e-13);

  // no contact: no friction, and the state forgets the contact
  double none[CONTACT_SUMS] = {0.0};
  EXPECT_FALSE(contact_friction(none, mass, f, fast, h, 0.0, dt, pressure, ratio));
  for (int a = 0; a < 3; a++) EXPECT_EQ(ratio[a], 0.0);
  EXPECT_EQ(pressure, NO_CONTACT);
}

// Walls of two friction coefficients and an adhesion: the limit is the sum of each pair's
// mu_b N_ab + c_b A_ab.
TEST(WallFriction, LimitIsTheSumOfThePartnersLimits)
{
  const double normal[3] = {0.0, 1.0, 0.0}, at_rest[3] = {0.0, 0.0, 0.0};
  double contact[CONTACT_SUMS] = {0.0};
  add_contact(contact, 4.0, 0.5, normal, at_rest, 100.0, 0.004);
  add_contact(contact, 6.0, 0.0, normal, at_rest, 0.0, 0.006);
  const double f[3] = {0.0, 0.0, 0.0}, v[3] = {1.0, 0.0, 0.0};
  double ratio[3], pressure = NO_CONTACT;
  EXPECT_TRUE(contact_friction(contact, 1.0, f, v, 1.0, 0.0, 1.0e-3, pressure, ratio));
  EXPECT_NEAR(ratio[0] * 10.0, -(2.0 + 0.4), 1e-14);
}

// The regularization: while a particle slides, the pressure that bounds its friction follows
// the contact's over a slip of h (or a time of INTERFACE_RELAXATION h / c_p: c_p = 0 here); a
// jump of the normal force doubles the limit only gradually (here a slip of 0.1 h per step:
// 1 - 0.9^k of the jump after k steps); sticking resets it.
TEST(WallFriction, InterfacePressureFollowsTheContactOverASlipOfH)
{
  const double normal[3] = {0.0, 1.0, 0.0}, at_rest[3] = {0.0, 0.0, 0.0};
  const double f[3] = {0.0, 0.0, 0.0}, v[3] = {1.0, 0.0, 0.0};
  const double dt = 1.0e-3, h = 0.01;    // |v| dt / h = 0.1
  double ratio[3], pressure = NO_CONTACT;
  double contact[CONTACT_SUMS] = {0.0};
  add_contact(contact, 10.0, 0.5, normal, at_rest, 0.0, 0.01);
  EXPECT_TRUE(contact_friction(contact, 1.0, f, v, h, 0.0, dt, pressure, ratio));
  EXPECT_DOUBLE_EQ(pressure, 1000.0);
  EXPECT_NEAR(ratio[0], -0.5, 1e-15);
  // the normal force doubles
  double doubled[CONTACT_SUMS] = {0.0};
  add_contact(doubled, 20.0, 0.5, normal, at_rest, 0.0, 0.01);
  for (int k = 1; k <= 3; k++) {
    EXPECT_TRUE(contact_friction(doubled, 1.0, f, v, h, 0.0, dt, pressure, ratio));
    const double expected = 2000.0 - 1000.0 * std::pow(0.9, k);
    EXPECT_NEAR(pressure, expected, 1e-9) << k;
    EXPECT_NEAR(ratio[0] * 20.0, -0.5 * expected * 0.01, 1e-12) << k;
  }
  // sticking (no slip, no force): the pressure is the contact's at once
  const double still[3] = {0.0, 0.0, 0.0};
  EXPECT_FALSE(contact_friction(doubled, 1.0, f, still, h, 0.0, dt, pressure, ratio));
  EXPECT_DOUBLE_EQ(pressure, 2000.0);
}

// ... and at rest relative to the wall (a slow slip), over a time of INTERFACE_RELAXATION h / c_p.
TEST(WallFriction, InterfacePressureFollowsTheContactOverTimeWithoutSlip)
{
  const double normal[3] = {0.0, 1.0, 0.0}, at_rest[3] = {0.0, 0.0, 0.0};
  // a tangential force far above the limit, no slip yet: sliding, with |v_t| = 0
  const double f[3] = {100.0, 0.0, 0.0}, v[3] = {0.0, 0.0, 0.0};
  const double h = 0.01, c = 100.0, dt = 0.1 * INTERFACE_RELAXATION * h / c;    // 0.1 per step
  double ratio[3], pressure = 1000.0;
  double contact[CONTACT_SUMS] = {0.0};
  add_contact(contact, 20.0, 0.5, normal, at_rest, 0.0, 0.01);
  EXPECT_TRUE(contact_friction(contact, 1.0, f, v, h, c, dt, pressure, ratio));
  EXPECT_NEAR(pressure, 1100.0, 1e-9);
}

// The density's step exp(x): the series is exp to round-off where it is used, the switch to
// std::exp has no visible step, and the factor is positive for any rate (doc/theory.rst 4.1).
TEST(DensityStep, GrowthIsTheExponentialAndPositive)
{
  for (double x = -2.0e-3; x <= 2.0e-3; x += 1.0e-5)
    EXPECT_NEAR(density_growth(x), std::exp(x), 4e-16) << "x = " << x;
  for (double x : {1e-12, -1e-12, 1e-6, -1e-6, 9.999e-4, -9.999e-4})
    EXPECT_NEAR(density_growth(x) / std::exp(x), 1.0, 1e-14) << "x = " << x;
  for (double x : {-1.0, -10.0, -700.0, -1e300}) EXPECT_GE(density_growth(x), 0.0) << "x = " << x;
  EXPECT_GT(density_growth(-10.0), 0.0);
}
