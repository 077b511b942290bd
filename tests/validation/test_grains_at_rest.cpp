// Grains at rest (physics/rest_rule.hpp) against independent results:
//  • a grain dropped on a floor of restitution e_w without the TC model bounces as the geometric
//    series and comes to rest at the first bounce that leaves it slower than the rest speed, k =
//    ⌈ln(v_rest/v₀)/ln e_w⌉ — not an inelastic collapse —, on the floor, and then no event happens;
//  • a bed settling in gravity with the TC model and the rest rule: the state's momentum and
//    energy change exactly as the records say (the rest rule's hits are perfectly inelastic and
//    their momentum is the floor's); the floor carries the bed's weight, exactly up to the change
//    of the grains' momentum; once settled, the bed costs at least 100 times fewer events per unit
//    time than the same bed under the TC model alone, stands as high, and holds no overlap;
//  • a grain thrown at the settled bed wakes the grains it strikes, and the run goes on with the
//    same exact budgets;
//  • a run with grains at rest continues from its checkpoint bit for bit.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <map>
#include <csignal>
#include <unistd.h>
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

// A bed of grains (2D: 384 disks, 3D: 512 spheres) dropped from a lattice onto a floor, ẽ = e_w =
// 0.5, the TC model on (t_c = 10⁻³ √(σ/g) scale), x (and z) periodic; grain 0 thrown up from the top of
// the lattice lands on the settled bed at t ≈ 5 and wakes what it strikes.
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
  struct Tail final : EventObserver<D> {
    std::vector<std::string> lines;
    void on_collision(const CollisionRecord<D>& r) override { add("C " + std::to_string(r.time) + " " + std::to_string(r.first) + "-" + std::to_string(r.second) + " e=" + std::to_string(r.restitution) + " vn=" + std::to_string(dot(r.relative_velocity, r.contact_normal))); }
    void on_surface_hit(const SurfaceHitRecord<D>& r) override { char b[200]; std::snprintf(b, 200, "S %.12f %d kind %d idx %d vb %.3e %.3e va %.3e %.3e n %.4e %.4e e %.2f x %.9f y %.9f", r.time, r.particle, r.surface.kind, r.surface.index, r.velocity_before[0], r.velocity_before[1], r.velocity_after[0], r.velocity_after[1], r.normal[0], r.normal[1], r.restitution, r.position[0], r.position[1]); add(b); }
    void on_rest_change(const RestRecord<D>& r) override { add("R " + std::to_string(r.time) + " " + std::to_string(r.particle) + " " + std::to_string(r.at_rest)); }
    void add(std::string l) { lines.push_back(l); if (lines.size() > 60) lines.erase(lines.begin()); }
  } tail;
  resting.add_observer(&tail);
  static decltype(tail)* watched = nullptr;
  watched = &tail;
  std::signal(SIGALRM, [](int) { for (auto& l : watched->lines) std::printf("%s\n", l.c_str()); std::fflush(stdout); std::_Exit(3); });
  alarm(60);
  const ParticleState start = resting.state();
  const double t_settled = 10.0;
  struct Census final : EventObserver<D> {
    std::map<int, long long> by_grain; long long coll = 0, walls = 0, rests = 0, wakes = 0, onrest = 0;
    void on_collision(const CollisionRecord<D>& r) override { ++coll; ++by_grain[r.first]; }
    void on_surface_hit(const SurfaceHitRecord<D>& r) override { (r.surface.kind == 7 ? onrest : walls)++; ++by_grain[r.particle]; }
    void on_rest_change(const RestRecord<D>& r) override { (r.at_rest ? rests : wakes)++; }
  } census;
  resting.add_observer(&census);
  for (double t = 0.05; t < t_settled; t += 0.05) {
    census = Census{};
    const StopReason why = resting.run(t, kNoLimit);
    long long top = 0; int who = -1;
    for (auto& [k, n] : census.by_grain) if (n > top) { top = n; who = k; }
    std::printf("t %.2f events %lld at rest %lld reason %d | coll %lld walls %lld onrest %lld rests %lld wakes %lld top %d:%lld\n", resting.time(), (long long)resting.events(), (long long)resting.grains_at_rest(), (int)why, census.coll, census.walls, census.onrest, census.rests, census.wakes, who, top);
    std::fflush(stdout);
    if (why != StopReason::kTimeReached) break;
  }
  ASSERT_EQ(resting.run(t_settled, kNoLimit), StopReason::kTimeReached)
      << [&] { std::string all; for (auto& l : tail.lines) all += l + "\n"; return all; }() << "collapse at t = " << resting.collapse().time << " of grains " << resting.collapse().first << ", " << resting.collapse().second;
  ASSERT_EQ(micro.run(t_settled, kNoLimit), StopReason::kTimeReached);
  const ParticleState end = resting.state();

  // Exact budgets over the whole settling, the landing of the thrown grain included: gravity acts
  // on the moving grains only, the surfaces (walls, grains at rest) take what the records say.
  const Vec<D> change = momentum_of<D>(end) - momentum_of<D>(start);
  const double gravity_impulse = g * (n * t_settled - log.resting_weight - log.resting_mass * (t_settled - log.since));
  EXPECT_NEAR(change[1], -gravity_impulse - log.impulse_on_surfaces[1], 1e-9 * n * g * t_settled);
  EXPECT_NEAR(change[0], -log.impulse_on_surfaces[0], 1e-9 * n * g * t_settled);
  EXPECT_NEAR(total_energy(p, end) - total_energy(p, start), log.energy_change, 1e-9 * log.magnitude);
  // The floor's load as WallStress measures it: the weight, exactly up to the grains' change of
  // momentum (P_floor − P_ceiling = (N m g t + ΔP_y) / (A t)).
  const auto faces = log.stress.sample(t_settled, t_settled);
  const double weight = n * g / with_rest.area();
  const double balance = faces[2]->pressure - faces[3]->pressure;
  EXPECT_NEAR(balance, weight + change[1] / (with_rest.area() * t_settled), 1e-9 * weight);
  EXPECT_GE(log.woken, 1);  // the thrown grain struck the bed
  EXPECT_GE(log.came_to_rest, static_cast<std::int64_t>(n));

  // Settled: the events of a span of 0.2, with and without the rest rule, and the floor's load
  // over it (the weight, now that the bed is still: a time average for the micro-bouncing bed).
  const double span = 0.2;
  const std::int64_t resting_before = resting.events();
  const std::int64_t micro_before = micro.events();
  log.restart(resting.time());
  resting.run(t_settled + span, kNoLimit);
  micro.run(t_settled + span, kNoLimit);
  const std::int64_t resting_events = resting.events() - resting_before;
  const std::int64_t micro_events = micro.events() - micro_before;
  const double settled_load = log.stress.sample(resting.time(), span)[2]->pressure / weight;
  const double height_rest = mean_height(resting.state());
  const double height_micro = mean_height(micro.state());
  std::printf("[%dD] at rest: %lld of %lld grains (%lld came to rest, %lld woken); events in %.1f: %lld with the rest "
              "rule, %lld with TC alone; floor load / weight %.6f; mean height %.5f vs %.5f (σ = %.3f)\n",
              D, static_cast<long long>(resting.grains_at_rest()), static_cast<long long>(p.particles),
              static_cast<long long>(log.came_to_rest), static_cast<long long>(log.woken), span,
              static_cast<long long>(resting_events), static_cast<long long>(micro_events), settled_load, height_rest,
              height_micro, p.diameter);
  EXPECT_LE(100 * resting_events, micro_events);
  EXPECT_NEAR(settled_load, 1.0, 1e-3);
  // The same bed: its mean height within a tenth of a grain diameter of the micro-bouncing one's
  // (a different packing from a different history would differ by a good fraction of σ).
  EXPECT_NEAR(height_rest, height_micro, 0.1 * p.diameter);
  resting.check_invariants();
  micro.check_invariants();
}

TEST(GrainsAtRest, ASettlingBedOfDisksKeepsItsBudgetsAndItsLoadAndCostsAHundredTimesFewerEvents) { check_settling_bed<2>(); }
TEST(GrainsAtRest, ASettlingBedOfSpheresKeepsItsBudgetsAndItsLoadAndCostsAHundredTimesFewerEvents) { check_settling_bed<3>(); }

}  // namespace
}  // namespace granule
