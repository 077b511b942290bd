// The rough collision rule done by rigid-body mechanics (impulse J at the contact point, solved
// from the 3×3 linear map J → change of the contact velocity, no closed form of μ_t) against
// rough_cooling.hpp: the energy one collision dissipates for unequal masses, sizes and inertia
// factors, and, by Monte Carlo over Maxwellian states (fixed seeds), the mean translational and
// rotational energy changes per collision that the cooling equations are built from. Disks are
// spheres moving in the xy plane and spinning about z.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <random>

#include "theory/rough_cooling.hpp"

namespace {

using std::numbers::pi;
using Vec = Eigen::Vector3d;
namespace th = granule::theory;

struct Grain {
  double mass, diameter, inertia_factor;
  Vec velocity, spin;
  double inertia() const { return inertia_factor * mass * diameter * diameter / 4.0; }
  double translational_energy() const { return 0.5 * mass * velocity.squaredNorm(); }
  double rotational_energy() const { return 0.5 * inertia() * spin.squaredNorm(); }
};

// Velocity of the contact point of a grain whose centre sits at −arm from it.
Vec contact_velocity(const Grain& g, const Vec& arm) { return g.velocity + g.spin.cross(arm); }

struct ContactVelocity {
  double normal;   // g·n > 0 approaching
  Vec tangential;  // the part of the relative contact velocity perpendicular to n
};

// n is the unit vector from grain a to grain b.
ContactVelocity relative_contact_velocity(const Grain& a, const Grain& b, const Vec& n) {
  const Vec g =
      contact_velocity(a, 0.5 * a.diameter * n) - contact_velocity(b, -0.5 * b.diameter * n);
  return {g.dot(n), g - g.dot(n) * n};
}

// Applies impulse J to a (and −J to b) at the contact point.
void apply_impulse(Grain& a, Grain& b, const Vec& n, const Vec& impulse) {
  const Vec arm_a = 0.5 * a.diameter * n, arm_b = -0.5 * b.diameter * n;
  a.velocity += impulse / a.mass;
  b.velocity -= impulse / b.mass;
  a.spin += arm_a.cross(impulse) / a.inertia();
  b.spin += arm_b.cross(-impulse) / b.inertia();
}

// g_n' = −e g_n, g_t' = −β g_t. The change of the relative contact velocity is linear in J:
// its matrix is built column by column by applying unit impulses to copies of the grains.
void collide(Grain& a, Grain& b, const Vec& n, double e, double beta) {
  const ContactVelocity before = relative_contact_velocity(a, b, n);
  const Vec g_before = before.normal * n + before.tangential;
  Eigen::Matrix3d response;
  for (int k = 0; k < 3; ++k) {
    Grain a1 = a, b1 = b;
    apply_impulse(a1, b1, n, Vec::Unit(k));
    const ContactVelocity after = relative_contact_velocity(a1, b1, n);
    response.col(k) = after.normal * n + after.tangential - g_before;
  }
  const Vec wanted = -(1.0 + e) * before.normal * n - (1.0 + beta) * before.tangential;
  apply_impulse(a, b, n, response.partialPivLu().solve(wanted));
}

double total_energy(const Grain& a, const Grain& b) {
  return a.translational_energy() + a.rotational_energy() + b.translational_energy() +
         b.rotational_energy();
}

TEST(RoughCollisionRule, EnergyChangeOfOneCollisionIsTheClosedForm) {
  // Unequal masses and sizes, 3D spins and 2D (planar velocities, spin about z). The closed form
  // takes one q for both grains; the grains here share it but not m or σ.
  std::mt19937_64 rng(4242);
  std::normal_distribution<double> gauss;
  for (int d : {2, 3}) {
    for (const th::RoughGrains grains :
         {th::RoughGrains{0.7, 0.3, 0.4}, th::RoughGrains{0.95, -0.6, 0.5},
          th::RoughGrains{1.0, 1.0, 2.0 / 5.0}, th::RoughGrains{0.2, 0.9, 1.0}}) {
      for (int trial = 0; trial < 50; ++trial) {
        auto random_vec = [&](bool planar) {
          return Vec(gauss(rng), gauss(rng), planar ? 0.0 : gauss(rng));
        };
        auto spin = [&]() {
          return d == 3 ? Vec(gauss(rng), gauss(rng), gauss(rng)) : Vec(0.0, 0.0, gauss(rng));
        };
        Grain a{1.3, 0.8, grains.inertia_factor, random_vec(d == 2), spin()};
        Grain b{0.6, 1.7, grains.inertia_factor, random_vec(d == 2), spin()};
        const Vec n = random_vec(d == 2).normalized();
        const ContactVelocity g = relative_contact_velocity(a, b, n);
        const double before = total_energy(a, b);
        collide(a, b, n, grains.normal_restitution, grains.tangential_restitution);
        const double measured = total_energy(a, b) - before;
        const double predicted = th::rough_collision_energy_change(grains, a.mass, b.mass, g.normal,
                                                                   g.tangential.norm());
        EXPECT_NEAR(measured, predicted, 1e-12 * before) << "d = " << d << " trial " << trial;
        const ContactVelocity after = relative_contact_velocity(a, b, n);
        EXPECT_NEAR(after.normal, -grains.normal_restitution * g.normal, 1e-12);
        EXPECT_NEAR((after.tangential + grains.tangential_restitution * g.tangential).norm(), 0.0,
                    1e-12);
      }
    }
  }
}

// Weighted mean Σ w x / Σ w with its standard error (delta method).
class WeightedMean {
 public:
  void add(double weight, double value) {
    sw_ += weight;
    swx_ += weight * value;
    sw2_ += weight * weight;
    sw2x_ += weight * weight * value;
    sw2x2_ += weight * weight * value * value;
  }
  double mean() const { return swx_ / sw_; }
  double standard_error() const {
    const double m = mean();
    return std::sqrt(sw2x2_ - 2.0 * m * sw2x_ + m * m * sw2_) / sw_;
  }

 private:
  double sw_ = 0, swx_ = 0, sw2_ = 0, sw2x_ = 0, sw2x2_ = 0;
};

TEST(RoughCollisionMonteCarlo, MaxwellianEnergyExchangePerCollision) {
  // Velocities N(0, T_tr/m), spins N(0, T_rot/I) per component (one component, about z, in 2D),
  // a contact direction uniform on the circle or sphere, flipped to make the pair approach (the
  // distribution is even in n), collision weight g·n. The pair's translational and rotational
  // energy changes averaged over collisions against mean_energy_change_per_collision at unequal
  // T_tr = 1.3 and T_rot = 0.5. 2.5·10⁵ samples per case: standard errors 0.05–0.33 % of T_tr;
  // the tolerance is 5 of them, so that a factor 2 in any term of the two means would fail (the
  // smallest, 2(d − 1)(η²/q)T_rot = 0.014 at e = 0.9, β = −0.5 in 2D, against 5σ = 0.006).
  const double m = 2.0, sigma = 0.7, t_tr = 1.3, t_rot = 0.5;
  const int samples = 250000;
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  std::normal_distribution<double> gauss;
  unsigned seed = 1000;  // one stream per case
  for (int d : {2, 3}) {
    for (const th::RoughGrains grains :
         {th::RoughGrains{0.8, 0.4, d == 2 ? 0.5 : 0.4}, th::RoughGrains{0.9, -0.5, 0.5},
          th::RoughGrains{0.6, 1.0, 0.4}}) {
      std::mt19937_64 rng(++seed);
      WeightedMean translational, rotational;
      const double spin_scale = std::sqrt(t_rot / (grains.inertia_factor * m * sigma * sigma / 4));
      const double speed_scale = std::sqrt(t_tr / m);
      for (int s = 0; s < samples; ++s) {
        auto velocity = [&]() {
          return Vec(speed_scale * gauss(rng), speed_scale * gauss(rng),
                     d == 3 ? speed_scale * gauss(rng) : 0.0);
        };
        auto spin = [&]() {
          return d == 3 ? Vec(spin_scale * gauss(rng), spin_scale * gauss(rng),
                              spin_scale * gauss(rng))
                        : Vec(0.0, 0.0, spin_scale * gauss(rng));
        };
        Grain a{m, sigma, grains.inertia_factor, velocity(), spin()};
        Grain b{m, sigma, grains.inertia_factor, velocity(), spin()};
        const double azimuth = pi * uniform(rng);
        const double axial = d == 3 ? uniform(rng) : 0.0;
        const double radial = std::sqrt(1.0 - axial * axial);
        Vec n(radial * std::cos(azimuth), radial * std::sin(azimuth), axial);
        if ((a.velocity - b.velocity).dot(n) < 0.0) n = -n;
        const double weight = (a.velocity - b.velocity).dot(n);
        const double tr0 = a.translational_energy() + b.translational_energy();
        const double rot0 = a.rotational_energy() + b.rotational_energy();
        collide(a, b, n, grains.normal_restitution, grains.tangential_restitution);
        translational.add(weight, a.translational_energy() + b.translational_energy() - tr0);
        rotational.add(weight, a.rotational_energy() + b.rotational_energy() - rot0);
      }
      const th::RoughEnergyChange predicted =
          th::mean_energy_change_per_collision(d, grains, {t_tr, t_rot});
      std::printf(
          "d = %d, e = %.2f, beta = %+.2f, q = %.2f: dE_tr = %+.5f ± %.5f (theory %+.5f), "
          "dE_rot = %+.5f ± %.5f (theory %+.5f)\n",
          d, grains.normal_restitution, grains.tangential_restitution, grains.inertia_factor,
          translational.mean(), translational.standard_error(), predicted.translational,
          rotational.mean(), rotational.standard_error(), predicted.rotational);
      for (const auto& [estimate, theory] : {std::pair{&translational, predicted.translational},
                                             std::pair{&rotational, predicted.rotational}}) {
        EXPECT_LT(estimate->standard_error(), 4e-3 * t_tr);
        EXPECT_NEAR(estimate->mean(), theory, 5.0 * estimate->standard_error());
      }
    }
  }
}

}  // namespace
