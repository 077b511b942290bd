// Speed-dependent restitution (physics/restitution_law.hpp) in the engine, against results that do
// not come from its code:
//  • a pair of viscoelastic grains (equal, or of other radii and masses) and a grain on a wall of
//    their material rebound, at speeds over eleven decades, with the ẽ of the collision equation
//    integrated here in its dimensional form (Hertz force and its viscous part, Brilliantov et al.
//    1996) by a plain fixed-step Runge–Kutta, to 2e-7;
//  • the threshold law is elastic below v_c and ẽ above it, for pairs and walls;
//  • a viscoelastic gas cools as the kinetic theory of Brilliantov & Pöschel says: dT/dt ∝ −T^{8/5},
//    so T^{−3/5} grows linearly in t (T ∝ t^{−5/3} late); the same gas with a constant ẽ does not
//    (its T^{−3/5} grows ever faster: Haff's T ∝ t^{−2}, hastened by clustering), so the test can
//    fail for the right reason.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "validation/surfaces_setup.hpp"
#include "validation/viscoelastic_collision.hpp"

namespace granule {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// The grains' material (Young's modulus, Poisson ratio, dissipative constant) and the contact's ẽ
// by integration (validation/viscoelastic_collision.hpp).
const ViscoelasticMaterial kMaterial;
double restitution_by_integration(double radius, double mass, double speed) {
  return restitution_by_integration(kMaterial, radius, mass, speed);
}

// The law of grains of diameter sigma (unit mass for the reference pair).
RestitutionLaw viscoelastic_law(double sigma) {
  RestitutionLaw law;
  law.kind = RestitutionKind::kViscoelastic;
  law.reference_radius = 0.5 * sigma;
  law.viscoelastic_constant = 1.5 * kMaterial.dissipation * std::pow(hertz_rho(kMaterial, 0.25 * sigma, 0.5), 0.4);
  return law;
}

template <int D>
struct ContactLog final : EventObserver<D> {
  std::vector<double> rebound;  // −(after)·k̂ / (before)·k̂ of the normal relative velocity
  std::vector<double> applied;  // the restitution the record reports
  void on_collision(const CollisionRecord<D>& r) override {
    const Vec<D> after = r.first_velocity_after - r.second_velocity_after;
    rebound.push_back(-dot(after, r.contact_normal) / dot(r.relative_velocity, r.contact_normal));
    applied.push_back(r.restitution);
  }
  void on_surface_hit(const SurfaceHitRecord<D>& r) override {
    if (!r.surface.wall()) return;
    rebound.push_back(-r.velocity_after[0] / r.velocity_before[0]);
    applied.push_back(r.restitution);
  }
};

// Two grains of diameters d1, d2 and masses m1, m2 approaching head on along x at relative speed g.
template <int D>
double pair_rebound(const RestitutionLaw& law, double restitution, double d1, double m1, double d2, double m2, double g,
                    double* applied = nullptr) {
  std::array<int, D> two{};
  std::array<double, D> box{};
  two.fill(1);
  two[0] = 2;
  box.fill(1.0);
  SystemParams p = surfaces_system<D>(two, box, std::max(d1, d2), restitution);
  p.restitution_law = law;
  ParticleState s;
  s.dimension = D;
  s.resize(2);
  for (int a = 0; a < D; ++a) s.position(a) = {0.5, 0.5};
  s.x = {0.3, 0.7};
  s.vx = {m2 / (m1 + m2) * g, -m1 / (m1 + m2) * g};  // no total momentum
  if (d1 != d2 || m1 != m2) {
    s.diameter = {d1, d2};
    s.mass = {m1, m2};
  }
  Simulation<D> sim(p, surfaces_grid<D>(p), s);
  ContactLog<D> log;
  sim.add_observer(&log);
  sim.run(kInf, 1);
  EXPECT_EQ(log.rebound.size(), 1u);
  if (applied) *applied = log.applied.at(0);
  return log.rebound.at(0);
}

// One grain of diameter sigma and unit mass hitting the wall at x = L at speed g.
template <int D>
double wall_rebound(const RestitutionLaw& law, double wall_restitution, double sigma, double g) {
  std::array<int, D> one{};
  std::array<double, D> box{};
  one.fill(1);
  box.fill(1.0);
  SystemParams p = surfaces_system<D>(one, box, sigma, 1.0);
  p.restitution_law = law;
  p.walls[0] = true;
  p.wall[0].restitution = p.wall[1].restitution = wall_restitution;
  ParticleState s = lattice_gas<D>(p, one, 0.0, 1);
  s.vx = {g};
  Simulation<D> sim(p, surfaces_grid<D>(p), s);
  ContactLog<D> log;
  sim.add_observer(&log);
  // The wall at x = L is reached at t = (½ − σ/2)/g, the one at 0 not before 1.35/g.
  sim.run(0.675 / g, std::numeric_limits<std::int64_t>::max());
  EXPECT_EQ(log.rebound.size(), 1u);
  return log.rebound.at(0);
}

constexpr double kSpeeds[] = {1e-6, 1e-4, 1e-2, 1.0, 1e2, 1e5};

template <int D>
void check_viscoelastic_contacts() {
  const double sigma = 0.1;
  const RestitutionLaw law = viscoelastic_law(sigma);
  for (const double g : kSpeeds) {
    EXPECT_NEAR(pair_rebound<D>(law, 1.0, sigma, 1.0, sigma, 1.0, g), restitution_by_integration(0.25 * sigma, 0.5, g), 2e-7)
        << D << "D equal grains, g = " << g;
    // Radii σ/4 and σ/2, masses 1/8 and 1: R_eff = σ/6, m_eff = 1/9.
    EXPECT_NEAR(pair_rebound<D>(law, 1.0, 0.5 * sigma, 0.125, sigma, 1.0, g), restitution_by_integration(sigma / 6.0, 1.0 / 9.0, g), 2e-7)
        << D << "D unequal grains, g = " << g;
    EXPECT_NEAR(wall_rebound<D>(law, 1.0, sigma, g), restitution_by_integration(0.5 * sigma, 1.0, g), 2e-7)
        << D << "D wall, g = " << g;
  }
}

TEST(RestitutionLaws, ViscoelasticDisksReboundAsTheirCollisionEquationSays) { check_viscoelastic_contacts<2>(); }
TEST(RestitutionLaws, ViscoelasticSpheresReboundAsTheirCollisionEquationSays) { check_viscoelastic_contacts<3>(); }

TEST(RestitutionLaws, ThresholdIsElasticBelowItsSpeedForPairsAndWalls) {
  RestitutionLaw law;
  law.kind = RestitutionKind::kThreshold;
  law.elastic_below = 0.5;
  for (const double g : {0.01, 0.3, 0.49}) {
    double applied = 0.0;
    EXPECT_NEAR(pair_rebound<2>(law, 0.6, 0.1, 1.0, 0.1, 1.0, g, &applied), 1.0, 1e-12) << "g = " << g;
    EXPECT_EQ(applied, 1.0);
    EXPECT_NEAR(wall_rebound<3>(law, 0.8, 0.1, g), 1.0, 1e-12) << "g = " << g;
  }
  for (const double g : {0.51, 2.0, 100.0}) {
    double applied = 0.0;
    EXPECT_NEAR(pair_rebound<2>(law, 0.6, 0.1, 1.0, 0.1, 1.0, g, &applied), 0.6, 1e-12) << "g = " << g;
    EXPECT_EQ(applied, 0.6);
    EXPECT_NEAR(wall_rebound<3>(law, 0.8, 0.1, g), 0.8, 1e-12) << "g = " << g;
  }
}

// T(t) of a dilute 2D gas of 1600 grains, sampled at geometrically spaced times.
struct Cooling {
  std::vector<double> t, temperature;
};

Cooling cool(const RestitutionLaw& law, double restitution, double until_collisions_per_particle) {
  const std::array<int, 2> per_axis{40, 40};
  SystemParams p = surfaces_system<2>(per_axis, {1.0, 1.0}, std::sqrt(4.0 * 0.05 / (M_PI * 1600.0)), restitution);
  p.restitution_law = law;
  Simulation<2> sim(p, surfaces_grid<2>(p), lattice_gas<2>(p, per_axis, 1.0, 7));
  Cooling c;
  const auto target = static_cast<std::int64_t>(until_collisions_per_particle * 1600);
  for (double t = 1e-3; sim.collisions() < target; t *= 1.2) {
    if (sim.run(t, target) == StopReason::kInelasticCollapse) break;
    const ParticleState s = sim.state();
    double energy = 0.0;
    for (std::size_t i = 0; i < s.size(); ++i) energy += 0.5 * (s.vx[i] * s.vx[i] + s.vy[i] * s.vy[i]);
    c.t.push_back(sim.time());
    c.temperature.push_back(energy / 1600.0);
  }
  return c;
}

// The slope of y = T^{−power} against t over the second half of the time span, over that of the
// first half (past the first 10 % of the run): 1 when T^{−power} grows linearly in t.
double slope_ratio(const Cooling& c, double power) {
  const double end = c.t.back();
  const auto y_at = [&](double t) {
    std::size_t k = 0;
    while (k + 1 < c.t.size() && c.t[k + 1] <= t) ++k;
    return std::pow(c.temperature[k], -power);
  };
  const double t0 = 0.1 * end, t1 = 0.55 * end, t2 = end;
  return ((y_at(t2) - y_at(t1)) / (t2 - t1)) / ((y_at(t1) - y_at(t0)) / (t1 - t0));
}

TEST(RestitutionLaws, ViscoelasticGasCoolsAsTToTheMinusFiveThirds) {
  RestitutionLaw law = viscoelastic_law(std::sqrt(4.0 * 0.05 / (M_PI * 1600.0)));
  const Cooling viscoelastic = cool(law, 1.0, 200.0);
  ASSERT_GT(viscoelastic.temperature.front() / viscoelastic.temperature.back(), 100.0) << "the gas must cool by two decades";
  const double linear = slope_ratio(viscoelastic, 0.6);
  std::printf("viscoelastic: T fell %.3g-fold; slope of T^(-3/5) late/early %.3f, of T^(-1/2) %.3f\n",
              viscoelastic.temperature.front() / viscoelastic.temperature.back(), linear, slope_ratio(viscoelastic, 0.5));
  EXPECT_NEAR(linear, 1.0, 0.1);
  // The same gas with the constant ẽ of its first collisions cools faster than T^{−3/5} ∝ t.
  const Cooling haff = cool(RestitutionLaw{}, viscoelastic_restitution(law.viscoelastic_constant), 200.0);
  std::printf("constant e: slope of T^(-3/5) late/early %.3f, of T^(-1/2) %.3f\n", slope_ratio(haff, 0.6), slope_ratio(haff, 0.5));
  EXPECT_GT(slope_ratio(haff, 0.6), 1.2);
}

}  // namespace
}  // namespace granule
