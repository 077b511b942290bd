// Grains at rest (physics/rest_rule.hpp) against independent results:
//  • a grain dropped on a floor of restitution e_w without the TC model bounces as the geometric
//    series and comes to rest at the first bounce that leaves it slower than the rest speed, k =
//    ⌈ln(v_rest/v₀)/ln e_w⌉ — not an inelastic collapse —, on the floor, and then no event happens;
//  • a bed of disks settling in gravity with the TC model and the rest rule: once settled, it costs
//    at least 100 times fewer events per unit time than the same bed under the TC model alone, and
//    stands as high (mean height within σ/10); a grain thrown at it wakes the grains it strikes
//    and the bed settles again; the state's momentum and energy change exactly as the records say
//    (the rest rule's hits are perfectly inelastic and their momentum is the supports'); the floor
//    carries the bed's weight, exactly up to the change of the grains' momentum, and exactly the
//    weight once all rest; no overlap, no grain in a wall;
//  • a run with grains at rest continues from its checkpoint bit for bit.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

#include "observers/wall_stress.hpp"
#include "validation/same_engine.hpp"
#include "validation/surfaces_setup.hpp"

namespace granule {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr std::int64_t kNoLimit = std::numeric_limits<std::int64_t>::max();

// Every momentum and energy exchange of a run with grains at rest: the impulses surfaces took
// (walls and grains at rest alike), the energy changes of collisions and hits, the grains that
// came to rest and woke, and the floor's load as WallStress measures it.
template <int D>
struct RestLog final : EventObserver<D> {
  explicit RestLog(const SystemParams& p) : stress(p) {}
  WallStress<D> stress;
  Vec<D> impulse_on_surfaces;
  double energy_change = 0.0, magnitude = 0.0;
  std::int64_t came_to_rest = 0, woken = 0, hits = 0, rest_hits = 0;
  double resting_mass = 0.0;   // now
  double resting_weight = 0.0; // ∫ m_rest dt since `since`
  double since = 0.0;
  void on_collision(const CollisionRecord<D>& r) override {
    energy_change += r.energy_change;
    magnitude += std::abs(r.energy_change);
  }
  void on_surface_hit(const SurfaceHitRecord<D>& r) override {
    stress.add(r);
    ++hits;
    rest_hits += r.comes_to_rest ? 1 : 0;
    impulse_on_surfaces = impulse_on_surfaces + r.impulse_on_surface;
    energy_change += r.energy_change;
    magnitude += std::abs(r.energy_change);
  }
  void on_rest_change(const RestRecord<D>& r) override {
    stress.add(r);
    resting_weight += resting_mass * (r.time - since);
    since = r.time;
    resting_mass += r.at_rest ? r.mass : -r.mass;
    (r.at_rest ? came_to_rest : woken) += 1;
  }
  // Open a new interval at t.
  void restart(double t) {
    stress.clear(t);
    impulse_on_surfaces = {};
    energy_change = magnitude = 0.0;
    resting_weight = 0.0;
    since = t;
  }
};

template <int D>
Vec<D> momentum_of(const ParticleState& s) {
  Vec<D> p;
  for (int a = 0; a < D; ++a) {
    for (double v : s.velocity(a)) p[a] += v;
  }
  return p;
}

double mean_height(const ParticleState& s) {
  double sum = 0.0;
  for (double y : s.y) sum += y;
  return sum / static_cast<double>(s.size());
}

template <int D>
void check_drop() {
  const double e_w = 0.5, g = 10.0, h = 0.29, v_rest = 1e-3;
  SystemParams p = one_grain_box<D>(0.02);
  add_walls(p, 1, e_w, -1.0);
  p.gravity[1] = -g;
  p.rest = {v_rest, v_rest};
  Vec<D> r0, v0;
  for (int a = 0; a < D; ++a) r0[a] = 0.5;
  r0[1] = 0.01 + h;
  Simulation<D> sim = single_grain<D>(p, r0, v0);
  sim.start_production(p);
  RestLog<D> log(p);
  sim.add_observer(&log);
  EXPECT_EQ(sim.run(kInf, kNoLimit), StopReason::kNoEvents);  // nothing left to happen
  // It arrives at the k-th hit at u_k = √(2gh) e_w^(k−1) and leaves at e_w u_k: it rests at the
  // first k with e_w u_k < v_rest.
  const double v_first = std::sqrt(2.0 * g * h);
  const auto expected = static_cast<std::int64_t>(std::ceil(std::log(v_rest / v_first) / std::log(e_w)));
  EXPECT_EQ(log.hits, expected);
  EXPECT_EQ(log.rest_hits, 1);
  EXPECT_EQ(log.came_to_rest, 1);
  EXPECT_EQ(sim.grains_at_rest(), 1);
  const ParticleState s = sim.state();
  EXPECT_NEAR(s.y[0], 0.01, 1e-12);
  EXPECT_EQ(s.vy[0], 0.0);
  // The floor took (1 + e_w) u_k at each bounce and the whole u_K at the last: the records' sum
  // against the series.
  const double last = v_first * std::pow(e_w, static_cast<double>(expected - 1));
  const double bounces = (1.0 + e_w) * v_first * (1.0 - std::pow(e_w, static_cast<double>(expected - 1))) / (1.0 - e_w);
  EXPECT_NEAR(-log.impulse_on_surfaces[1], bounces + last, 1e-9 * v_first);
  // Energy: all of it, from the height h, went into the hits.
  EXPECT_NEAR(log.energy_change, -g * h, 1e-9 * g * h);
  sim.check_invariants();
}

TEST(GrainsAtRest, ADiskDroppedOnAFloorComesToRestAtTheBounceTheGeometricSeriesPredicts) { check_drop<2>(); }
TEST(GrainsAtRest, ASphereDroppedOnAFloorComesToRestAtTheBounceTheGeometricSeriesPredicts) { check_drop<3>(); }

// A bed of 128 disks dropped from a lattice onto a floor with friction (ẽ = e_w = 0.5, β_w = −0.5),
// the TC model on (t_c = 10⁻⁵, 7·10⁻⁵ √(σ/g)), x periodic; the top grain, thrown up, lands on the
// settled bed at t ≈ 5 and wakes what it strikes.  (Spheres are not yet put at rest: a bed of them
// keeps waking itself; the configuration refuses the rule in 3D.)
template <int D>
struct SettlingBed {
  SystemParams p;
  ParticleState initial;
  double width = 0.0;
  static constexpr double kThrow = 2.4;  // grain 0's upward speed (apex ≈ 3 above its start)

  explicit SettlingBed(bool rest) {
    std::array<int, D> per_axis;
    per_axis.fill(4);
    per_axis[0] = D == 2 ? 16 : 4;
    per_axis[1] = 8;
    const double sigma = D == 2 ? 0.02 : 0.04;
    width = D == 2 ? 0.4 : 0.2;
    std::array<double, D> box;
    box.fill(width);
    box[1] = 4.0;
    p = surfaces_system<D>(per_axis, box, sigma, 0.5);
    add_walls(p, 1, 0.5, -0.5);  // a floor with friction: a grain sliding on it slows down
    p.gravity[1] = -1.0;
    p.tc_duration = 1e-5;
    if (rest) p.rest = {0.01 * std::sqrt(sigma), 0.1 * std::sqrt(sigma)};  // 1 % and 10 % of √(gσ)
    initial = lattice_gas<D>(p, per_axis, 0.01, 7);
    for (double& y : initial.y) y = 0.5 * sigma + 0.3 * (y - 0.5 * sigma);  // the lower 1.2
    std::size_t top = 0;
    for (std::size_t i = 0; i < initial.size(); ++i) top = initial.y[i] > initial.y[top] ? i : top;
    initial.vy[top] = kThrow;
  }
  double area() const { return std::pow(width, D - 1); }
};

template <int D>
void check_settling_bed() {
  const SettlingBed<D> with_rest(true);
  const SettlingBed<D> tc_only(false);
  const SystemParams& p = with_rest.p;
  const auto n = static_cast<double>(p.particles);
  const double g = -p.gravity[1];
  const CellGrid grid = surfaces_grid<D>(p);
  Simulation<D> resting(p, grid, with_rest.initial);
  Simulation<D> micro(tc_only.p, grid, tc_only.initial);
  resting.start_production(p);
  micro.start_production(tc_only.p);
  RestLog<D> log(p);
  resting.add_observer(&log);
  log.restart(0.0);
  const ParticleState start = resting.state();

  // Settled, before the thrown grain comes down (t ≈ 5): the events of a span of 0.05 with and
  // without the rest rule, and the bed's mean height (the thrown grain, alone in its flight, at
  // the same height in both).
  const double t_settled = 3.0, span = 0.05;
  ASSERT_EQ(resting.run(t_settled, kNoLimit), StopReason::kTimeReached);
  ASSERT_EQ(micro.run(t_settled, kNoLimit), StopReason::kTimeReached);
  const std::int64_t resting_before = resting.events();
  const std::int64_t micro_before = micro.events();
  ASSERT_EQ(resting.run(t_settled + span, kNoLimit), StopReason::kTimeReached);
  ASSERT_EQ(micro.run(t_settled + span, kNoLimit), StopReason::kTimeReached);
  const std::int64_t resting_events = resting.events() - resting_before;
  const std::int64_t micro_events = micro.events() - micro_before;
  const double height_rest = mean_height(resting.state());
  const double height_micro = mean_height(micro.state());
  const std::int64_t settled_at_rest = resting.grains_at_rest();
  resting.check_invariants();
  micro.check_invariants();

  // On to t = 10: the thrown grain lands and wakes the grains it strikes, and the bed settles again.
  const double t_end = 10.0;
  ASSERT_EQ(resting.run(t_end, kNoLimit), StopReason::kTimeReached);
  const ParticleState end = resting.state();
  std::printf("[%dD] settled (t = %.2f): %lld of %lld grains at rest, events in %.2f: %lld with the rest rule, %lld with "
              "TC alone; mean height %.5f vs %.5f (σ = %.3f); by t = %.0f: %lld came to rest, %lld woken, %lld at rest, "
              "%lld events\n",
              D, t_settled, static_cast<long long>(settled_at_rest), static_cast<long long>(p.particles), span,
              static_cast<long long>(resting_events), static_cast<long long>(micro_events), height_rest, height_micro,
              p.diameter, t_end, static_cast<long long>(log.came_to_rest), static_cast<long long>(log.woken),
              static_cast<long long>(resting.grains_at_rest()), static_cast<long long>(resting.events()));
  EXPECT_LE(100 * resting_events, micro_events);
  // The same bed: its mean height within a tenth of a grain diameter of the micro-bouncing one's.
  EXPECT_NEAR(height_rest, height_micro, 0.1 * p.diameter);
  EXPECT_GE(log.woken, 1);  // the thrown grain struck the bed
  EXPECT_EQ(resting.grains_at_rest(), p.particles);

  // Exact budgets over the whole run: gravity acts on the moving grains only, the surfaces (walls,
  // grains at rest) take what the records say.
  const Vec<D> change = momentum_of<D>(end) - momentum_of<D>(start);
  const double gravity_impulse = g * (n * t_end - log.resting_weight - log.resting_mass * (t_end - log.since));
  EXPECT_NEAR(change[1], -gravity_impulse - log.impulse_on_surfaces[1], 1e-9 * n * g * t_end);
  EXPECT_NEAR(change[0], -log.impulse_on_surfaces[0], 1e-9 * n * g * t_end);
  EXPECT_NEAR(total_energy(p, end) - total_energy(p, start), log.energy_change, 1e-9 * log.magnitude);
  // The floor's load as WallStress measures it: the weight, exactly up to the grains' change of
  // momentum (P_floor − P_ceiling = (N m g t + ΔP_y) / (A t)); and, the bed at rest, the weight.
  const auto faces = log.stress.sample(t_end, t_end);
  const double weight = n * g / with_rest.area();
  EXPECT_NEAR(faces[2]->pressure - faces[3]->pressure, weight + change[1] / (with_rest.area() * t_end), 1e-9 * weight);
  log.restart(t_end);
  ASSERT_EQ(resting.run(t_end + 1.0, kNoLimit), StopReason::kTimeReached);
  EXPECT_NEAR(log.stress.sample(t_end + 1.0, 1.0)[2]->pressure, weight, 1e-12 * weight);
  resting.check_invariants();
}

TEST(GrainsAtRest, ASettlingBedOfDisksKeepsItsBudgetsAndItsLoadAndCostsAHundredTimesFewerEvents) { check_settling_bed<2>(); }

// Saved while grains come to rest and are woken (t = 2), restored, and both run on to t = 6, past
// the thrown grain's landing and many clock re-bases: the same engine, bit for bit.
TEST(GrainsAtRest, ARunWithGrainsAtRestContinuesFromItsCheckpointBitForBit) {
  const SettlingBed<2> bed(true);
  const CellGrid grid = surfaces_grid<2>(bed.p);
  Simulation<2> straight(bed.p, grid, bed.initial);
  straight.start_production(bed.p);
  ASSERT_EQ(straight.run(2.0, kNoLimit), StopReason::kTimeReached);
  ASSERT_GT(straight.grains_at_rest(), 0);
  StateArchive saved;
  straight.save(saved, "");
  Simulation<2> restored(bed.p, grid, saved, "");
  ASSERT_EQ(straight.run(6.0, kNoLimit), StopReason::kTimeReached);
  ASSERT_EQ(restored.run(6.0, kNoLimit), StopReason::kTimeReached);
  EXPECT_GT(straight.events(), 30 * bed.p.particles);
  expect_same_engine(straight, restored);
  EXPECT_EQ(straight.grains_at_rest(), restored.grains_at_rest());
  EXPECT_TRUE(saved.contains("rest_speed"));
}

}  // namespace
}  // namespace granule
