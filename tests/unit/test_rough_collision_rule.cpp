// The rough collision rule (physics/rough_collision_rule.hpp) against the laws it must obey,
// for random contacts of disks and spheres with unequal sizes and masses: total momentum and the
// angular momentum about the contact point conserved; the energy lost exactly
// (1 − e²) g_n²/(2K_n) + (1 − β²) g_t²/(2K_t), K_n = 1/m1 + 1/m2, K_t = K_n + a1²/I1 + a2²/I2
// (for equal masses and q: (m/4)[(1 − e²) g_n² + q/(1 + q)(1 − β²) g_t²], Luding et al. 1998);
// e = β = 1 elastic; β = −1 leaves the spins alone; the Coulomb branch caps |P_t| at μ|P_n|.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "physics/rough_collision_rule.hpp"

namespace granule {
namespace {

template <int D>
Vec<D> random_vector(std::mt19937_64& rng) {
  std::normal_distribution<double> normal;
  Vec<D> v;
  for (int a = 0; a < D; ++a) v[a] = normal(rng);
  return v;
}

template <int D>
Spin<D> random_spin(std::mt19937_64& rng) {
  if constexpr (D == 2) {
    return std::normal_distribution<double>{}(rng);
  } else {
    return random_vector<3>(rng);
  }
}

// Spin (as 3D vector) for the angular-momentum bookkeeping.
Vec3 as3(double w) { return {0.0, 0.0, w}; }
Vec3 as3(Vec3 w) { return w; }
Vec3 as3(Vec2 v) { return {v.x, v.y, 0.0}; }

struct Contact {
  double e, beta, mu, q1, q2, m1, m2, a1, a2;
};

// Two bodies at random contact (k̂ from 1 to 2, approaching).
template <int D>
struct RandomContact {
  Vec<D> k_hat;
  RoughBody<D> first, second;
};

template <int D>
RandomContact<D> random_contact(std::mt19937_64& rng, const Contact& c) {
  RandomContact<D> out;
  out.k_hat = random_vector<D>(rng);
  out.k_hat = (1.0 / norm(out.k_hat)) * out.k_hat;
  out.first = {random_vector<D>(rng), random_spin<D>(rng), c.a1, 1.0 / c.m1, 1.0 / (c.q1 * c.m1)};
  out.second = {random_vector<D>(rng), random_spin<D>(rng), c.a2, 1.0 / c.m2, 1.0 / (c.q2 * c.m2)};
  if (dot(contact_velocity(out.first, out.second, out.k_hat), out.k_hat) < 0.0) out.k_hat = -out.k_hat;
  return out;
}

template <int D>
double energy(const RoughBody<D>& b) {
  const double m = 1.0 / b.inverse_mass;
  const double inertia = b.radius * b.radius / b.radius2_over_inertia;
  return 0.5 * m * norm2(b.velocity) + 0.5 * inertia * spin_norm2(b.spin);
}

template <int D>
void check_conservation_and_energy(const Contact& c) {
  std::mt19937_64 rng(20261201);
  for (int trial = 0; trial < 200; ++trial) {
    const RandomContact<D> contact = random_contact<D>(rng, c);
    const Vec<D> k = contact.k_hat;
    const RoughBody<D>& first = contact.first;
    const RoughBody<D>& second = contact.second;
    struct {
      RoughBody<D> first, second;
      RoughImpulse<D> impulse;
    } out{first, second, rough_impulse(first, second, k, c.e, TangentialLaw{c.beta, c.mu})};
    apply_rough_impulse(out.first, out.second, k, out.impulse);

    // Momentum.
    const Vec<D> p_before = c.m1 * first.velocity + c.m2 * second.velocity;
    const Vec<D> p_after = c.m1 * out.first.velocity + c.m2 * out.second.velocity;
    for (int a = 0; a < D; ++a) EXPECT_NEAR(p_after[a], p_before[a], 1e-13);
    // Angular momentum about the contact point (body 1 at the origin, 2 at (a1 + a2) k̂, contact
    // at a1 k̂): L = Σ m (r − r_c) × v + I ω.
    const Vec3 arm1 = as3(Vec<D>{} - c.a1 * k);
    const Vec3 arm2 = as3(c.a2 * k);
    auto angular = [&](const RoughBody<D>& b1, const RoughBody<D>& b2) {
      const Vec3 l1 = c.m1 * spin_cross(arm1, as3(b1.velocity)) + (c.q1 * c.m1 * c.a1 * c.a1) * as3(b1.spin);
      const Vec3 l2 = c.m2 * spin_cross(arm2, as3(b2.velocity)) + (c.q2 * c.m2 * c.a2 * c.a2) * as3(b2.spin);
      return l1 + l2;
    };
    const Vec3 l_before = angular(first, second);
    const Vec3 l_after = angular(out.first, out.second);
    for (int a = 0; a < 3; ++a) EXPECT_NEAR(l_after[a], l_before[a], 1e-13);
    // Energy: the closed form, unless the Coulomb cap acted.
    const Vec<D> g = contact_velocity(first, second, k);
    const double g_n = dot(g, k);
    const double g_t2 = norm2(g - g_n * k);
    const double k_n = 1.0 / c.m1 + 1.0 / c.m2;
    const double k_t = k_n + 1.0 / (c.q1 * c.m1) + 1.0 / (c.q2 * c.m2);
    const double loss = energy(first) + energy(second) - energy(out.first) - energy(out.second);
    const double p_n = norm(out.impulse.normal);
    const double p_t = norm(out.impulse.tangential);
    if (p_t < c.mu * p_n * (1.0 - 1e-12)) {
      const double expected = (1.0 - c.e * c.e) * g_n * g_n / (2.0 * k_n) + (1.0 - c.beta * c.beta) * g_t2 / (2.0 * k_t);
      EXPECT_NEAR(loss, expected, 1e-12 * (1.0 + expected)) << "trial " << trial;
      // g' = −e g_n k̂ − β g_t.
      const Vec<D> g_after = contact_velocity(out.first, out.second, k);
      const Vec<D> g_t = g - g_n * k;
      for (int a = 0; a < D; ++a) EXPECT_NEAR(g_after[a], -c.e * g_n * k[a] - c.beta * g_t[a], 1e-12);
    } else {
      EXPECT_NEAR(p_t, c.mu * p_n, 1e-12 * (1.0 + p_n));  // sliding: the cap, and never above it
      EXPECT_GE(loss, (1.0 - c.e * c.e) * g_n * g_n / (2.0 * k_n) - 1e-12);  // friction only dissipates
    }
  }
}

TEST(RoughCollisionRule, DisksConserveMomentumAndAngularMomentumAndLoseTheClosedFormEnergy) {
  check_conservation_and_energy<2>({0.7, -0.4, INFINITY, 0.5, 0.5, 1.0, 1.0, 0.5, 0.5});
  check_conservation_and_energy<2>({0.9, 0.6, INFINITY, 0.5, 0.4, 1.7, 0.6, 0.8, 0.3});
}

TEST(RoughCollisionRule, SpheresConserveMomentumAndAngularMomentumAndLoseTheClosedFormEnergy) {
  check_conservation_and_energy<3>({0.6, -0.8, INFINITY, 0.4, 0.4, 1.0, 1.0, 0.5, 0.5});
  check_conservation_and_energy<3>({0.95, 0.3, INFINITY, 0.4, 2.0 / 3.0, 2.3, 0.9, 0.7, 0.45});
}

TEST(RoughCollisionRule, CoulombFrictionCapsTheTangentialImpulse) {
  check_conservation_and_energy<2>({0.8, 0.4, 0.1, 0.5, 0.5, 1.0, 1.0, 0.5, 0.5});
  check_conservation_and_energy<3>({0.8, 0.4, 0.1, 0.4, 0.4, 1.0, 1.3, 0.5, 0.6});
}

TEST(RoughCollisionRule, PerfectlyRoughElasticGrainsConserveEnergy) {
  check_conservation_and_energy<2>({1.0, 1.0, INFINITY, 0.5, 0.5, 1.0, 1.0, 0.5, 0.5});
  check_conservation_and_energy<3>({1.0, 1.0, INFINITY, 0.4, 0.4, 1.0, 2.0, 0.5, 0.3});
}

TEST(RoughCollisionRule, SmoothLimitLeavesSpinsAndTangentialVelocitiesAlone) {
  std::mt19937_64 rng(7);
  const Contact c{0.8, -1.0, INFINITY, 0.4, 0.4, 1.0, 1.0, 0.5, 0.5};
  for (int trial = 0; trial < 50; ++trial) {
    const RandomContact<3> contact = random_contact<3>(rng, c);
    RoughBody<3> first = contact.first;
    RoughBody<3> second = contact.second;
    const RoughImpulse<3> impulse = rough_impulse(first, second, contact.k_hat, c.e, TangentialLaw{c.beta, c.mu});
    apply_rough_impulse(first, second, contact.k_hat, impulse);
    EXPECT_EQ(norm(impulse.tangential), 0.0);
    for (int a = 0; a < 3; ++a) {
      EXPECT_EQ(first.spin[a], contact.first.spin[a]);
      EXPECT_EQ(second.spin[a], contact.second.spin[a]);
    }
  }
}

TEST(RoughCollisionRule, SmoothGrainOnARoughMovingWallReversesItsSlipByBeta) {
  // A grain of infinite moment of inertia (a²/I = 0) on a wall moving at U along x:
  // v_t' − U = −β_w (v_t − U), v_n' = −e_w v_n.
  const double e_w = 0.8;
  const double beta_w = 0.3;
  RoughBody<2> grain{{1.5, -2.0}, 0.0, 0.5, 1.0 / 1.7, 0.0};
  RoughBody<2> wall{{-0.4, 0.0}, 0.0, 0.0, 0.0, 0.0};
  const Vec2 k{0.0, -1.0};  // towards a floor
  const RoughImpulse<2> p = rough_impulse(grain, wall, k, e_w, TangentialLaw{beta_w, INFINITY});
  apply_rough_impulse(grain, wall, k, p);
  EXPECT_NEAR(grain.velocity.y, e_w * 2.0, 1e-15);
  EXPECT_NEAR(grain.velocity.x - (-0.4), -beta_w * (1.5 - (-0.4)), 1e-15);
  EXPECT_EQ(wall.velocity.x, -0.4);  // the wall does not move
}

}  // namespace
}  // namespace granule
