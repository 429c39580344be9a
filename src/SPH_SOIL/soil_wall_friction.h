/* -*- c++ -*- ----------------------------------------------------------
   SPH_SOIL package: the Coulomb interface of soil against a frictional wall (pure, inline).

   A soil particle a touches a frictional wall through its wall partners b. Their image pairs
   (soil_wall_images.h) push it along the walls' normals only, with the normal forces N_ab > 0;
   the tangential force is this law's alone, and acts on the particle as a whole
   (doc/theory.rst 4.4):
   - the contact's normal n = sum N_ab n_b / |sum N_ab n_b|, its normal force N = sum N_ab and
     the wall's velocity v_w = sum N_ab v_b / N (a wall that moves or turns);
   - the trial (stick) force: the tangential force that makes the particle's tangential velocity
     relative to the wall vanish at the next half step,
         T* = -f_t - (m / dt) (v - v_w)_t,
     with f the particle's other forces (soil, walls' normal push, gravity, other fixes) and v
     its velocity at the half step (velocity Verlet: v(t + dt/2) when the forces of t + dt are
     known). With f constant the slip is gone after one step (a dead-beat predictor: with the
     slip of this step alone, -(m/dt) (v - v_w)_t, the particle would creep at dt f_t / m);
   - the return onto Coulomb's limit: T = T* if |T*| <= mu p~ A + c_a A, else
     (mu p~ A + c_a A) T* / |T*| (sliding, partial slip allowed particle by particle), with the
     particle's contact area A (contact_area()), the adhesion c_a and its interface pressure p~;
   - the regularization (Prakash & Clifton; Cochard & Rice 2000): Coulomb's law with a
     constant mu makes the steady sliding of an elastic body unstable (the friction follows the
     normal force at once and couples the normal and tangential motions: waves along the
     interface grow at a rate proportional to their wavenumber, so the finest particles go
     first: a block sliding at mu = 0.4 came apart after 0.15 s at 2 mm and 0.008 s at 1 mm).
     While a particle slides, its interface pressure p~ follows the contact's normal pressure
     N / A over a slip of one smoothing length h (Prakash-Clifton) or a time of
     INTERFACE_RELAXATION h / c_p, whichever is shorter:
         p~ <- p~ + (N/A - p~) min(1, (|v_t| + c_p / INTERFACE_RELAXATION) dt / h);
     while it sticks (or first touches the wall) p~ = N / A.
   The wall's partners take the opposite force in proportion to their N_ab (Newton's third law:
   contact_friction() returns T / N, the force per unit normal force).
------------------------------------------------------------------------- */

#ifndef LMP_SOIL_WALL_FRICTION_H
#define LMP_SOIL_WALL_FRICTION_H

#include <cmath>

namespace SPHSoil {

// What a soil particle's wall partners add up to (the pair loop's sums): sum N_ab,
// sum mu_b N_ab, the contact area sum A_ab, the adhesion sum c_b A_ab (walls of different mu_b
// and c_b), sum N_ab n_b and sum N_ab v_b
enum {
  C_NORMAL_FORCE = 0,
  C_FRICTION = 1,
  C_AREA = 2,
  C_ADHESION = 3,
  C_NORMAL = 4,
  C_WALL_VELOCITY = 7,
  CONTACT_SUMS = 10
};

// The contact area that a pair of soil particle a and the image of wall particle b stands for:
// A_ab = 2 V_a V_b (-grad W_ab . n) (grad W_ab = factor x_ab). For a soil of normal stress
// -p on the wall, the image pair pushes with N_ab = p A_ab, and summed over the particles of a
// column A_ab adds up to the wall's area: 2 int W dV over a half-space is 1 (doc/theory.rst 4.4).
inline double contact_area(double volume_a, double volume_b, double factor,
                           double normal_separation)
{
  return -2.0 * volume_a * volume_b * factor * normal_separation;
}

// one pair's share of the sums: normal force N_ab > 0, the wall's mu, normal and velocity, its
// adhesion c_a and the pair's contact area (contact_area())
inline void add_contact(double contact[CONTACT_SUMS], double normal_force, double mu,
                        const double n[3], const double wall_velocity[3], double adhesion,
                        double area)
{
  contact[C_NORMAL_FORCE] += normal_force;
  contact[C_FRICTION] += mu * normal_force;
  contact[C_AREA] += area;
  contact[C_ADHESION] += adhesion * area;
  for (int a = 0; a < 3; a++) {
    contact[C_NORMAL + a] += normal_force * n[a];
    contact[C_WALL_VELOCITY + a] += normal_force * wall_velocity[a];
  }
}

// "no contact yet": the state of the interface pressure before a particle's first contact
constexpr double NO_CONTACT = -1.0;
// the interface pressure's relaxation time at rest, in units of h / c_p (the time a wave takes
// to cross a particle): it relaxes at the rate (|v_t| + c_p / INTERFACE_RELAXATION) / h
constexpr double INTERFACE_RELAXATION = 20.0;

// The friction force per unit normal force, ratio[3] (the particle's friction force is
// ratio * contact[C_NORMAL_FORCE], a partner's share ratio * N_ab), of a soil particle of mass
// m, other forces f, half-step velocity v, smoothing length h, P-wave speed c and time step dt,
// from its contact sums. `pressure` is its interface pressure p~ (the state of the regularization, see
// the header; NO_CONTACT before its first contact), updated here. Returns true if the particle
// slides (the trial force exceeded the limit). No contact (sum N_ab <= 0): 0, and the state
// goes back to NO_CONTACT. With a time step per level (soil_level_steps.h), the particle's step
// is `period` time steps: its interface pressure relaxes over it (the sums and f then hold the
// impulses of that period, and the sticking force still stops the slip within dt).
inline bool contact_friction(const double contact[CONTACT_SUMS], double mass, const double f[3],
                             const double v[3], double h, double wave_speed, double dt,
                             double &pressure, double ratio[3], double period = 1.0)
{
  ratio[0] = ratio[1] = ratio[2] = 0.0;
  const double normal_force = contact[C_NORMAL_FORCE], area = contact[C_AREA];
  const double *nsum = contact + C_NORMAL;
  const double nlength = std::sqrt(nsum[0] * nsum[0] + nsum[1] * nsum[1] + nsum[2] * nsum[2]);
  if (!(normal_force > 0.0) || !(nlength > 0.0) || !(area > 0.0)) {
    pressure = NO_CONTACT;
    return false;
  }
  const double n[3] = {nsum[0] / nlength, nsum[1] / nlength, nsum[2] / nlength};
  const double inv_normal_force = 1.0 / normal_force;
  const double mass_rate = mass / dt;
  double trial[3], fn = 0.0, slip_n = 0.0, slip[3];
  for (int a = 0; a < 3; a++) {
    slip[a] = v[a] - contact[C_WALL_VELOCITY + a] * inv_normal_force;
    fn += f[a] * n[a];
    slip_n += slip[a] * n[a];
  }
  double trial2 = 0.0, slip2 = 0.0;
  for (int a = 0; a < 3; a++) {
    const double slip_t = slip[a] - slip_n * n[a];
    trial[a] = -(f[a] - fn * n[a]) - mass_rate * slip_t;
    trial2 += trial[a] * trial[a];
    slip2 += slip_t * slip_t;
  }
  // the interface pressure follows the contact's, over a slip of h or a time of
  // INTERFACE_RELAXATION h / c_p
  const double contact_pressure = normal_force / area;
  if (pressure < 0.0) pressure = contact_pressure;
  const double rate = (std::sqrt(slip2) + wave_speed / INTERFACE_RELAXATION) / h;
  pressure += (contact_pressure - pressure) * std::fmin(1.0, rate * period * dt);
  const double mu = contact[C_FRICTION] * inv_normal_force;
  const double limit = mu * pressure * area + contact[C_ADHESION];
  const bool sliding = trial2 > limit * limit;
  if (!sliding) pressure = contact_pressure;    // sticking: the strength is not engaged
  const double scale = (sliding ? limit / std::sqrt(trial2) : 1.0) * inv_normal_force;
  for (int a = 0; a < 3; a++) ratio[a] = scale * trial[a];
  return sliding;
}

}    // namespace SPHSoil

#endif
