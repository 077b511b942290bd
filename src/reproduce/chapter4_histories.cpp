#include "reproduce/chapter4_histories.hpp"

#include <fmt/format.h>

#include "reproduce/sheared_gas.hpp"

namespace granule::reproduce::chapter4 {

// The protocol's start (t, in 1/γ = 0.01 units) lies after the cold start has settled (T reaches
// T₀ within ~20 c, c/t ≈ 75 here at any N since ν and γ are fixed) and leaves most of the run after it.
std::vector<History> histories(Scale scale) {
  const double start = by_scale(scale, 0.15, 1.0, 1.0, 1.0);
  // "long relative to the average time between collisions" (§4.3): 22 collision times, as the kick
  // of docs/chapter4.md (N = 20000) that left a layered state; one of 0.1 (7.5 collision times) let
  // the small runs recover (densest band 0.32).  The plug it makes collides fast, so the
  // run is longer, to leave a window after the kick.
  const double period = by_scale(scale, 0.05, 0.3, 0.3, 0.3);
  const int cycles = 3;
  const std::string cold = "temperature_over_steady = 0.1\nequilibrate = 0   # an elastic pre-run under shear would heat the gas";
  return {
      {"cold", "cold start", "shear_velocity = 100.0", cold, 0.0, 1.0},
      {"hot", "hot start", "shear_velocity = 100.0", "temperature_over_steady = 1e5   # T_i ≫ √N T₀ (§4.2)\nequilibrate = 5",
       0.0, 1.0},
      {"ramp", "ramp from rest",
       fmt::format("shear_velocity = 100.0\nshear_ramp_time = {}   # U = U₀ (1 − e^{{−t/τ}}), τ ≫ a collision time", kRampTime),
       "shear_profile = false   # a static gas\ntemperature_over_steady = 1\nequilibrate = 5", kRampReached, 1.0,
       2.0 * kRampReached},
      {"kick", fmt::format("kick of a quasihomogeneous flow (U₀ + 100 sin, {} periods of {} from t = {})", cycles, period, start),
       fmt::format("shear_velocity = 100.0\nshear_oscillation = {{ amplitude = 100.0, period = {}, start = {}, cycles = {} }}", period,
                   start, cycles),
       cold, start + cycles * period, 5.0 / 3.0},
      // The thesis's "small but finite" perturbation has no amplitude in the text: a tenth of U₀.
      {"kick_small", fmt::format("small kick of a quasihomogeneous flow (U₀ + 10 sin, {} periods of {} from t = {})", cycles, period, start),
       fmt::format("shear_velocity = 100.0\nshear_oscillation = {{ amplitude = 10.0, period = {}, start = {}, cycles = {} }}", period,
                   start, cycles),
       cold, start + cycles * period, 5.0 / 3.0},
      // U₀ = 200 is the protocol's last U, so 0.025 T₀(200) = 0.1 T₀(100): the cold start of the others.
      {"step", "step 100 → 200",
       fmt::format("shear_schedule = [[0.0, 100.0], [{0}, 100.0], [{0}, 200.0]]   # two points at one time: a step", start),
       "temperature_over_steady = 0.025\nequilibrate = 0", start, 1.0},
  };
}

std::vector<RunGroup> chapter4_runs(Scale scale) {
  std::vector<RunGroup> groups;
  const double until_c = by_scale(scale, 40.0, 300.0, 400.0, 400.0);
  for (const History& h : histories(scale)) {
    // A run to a time (the ramp) samples in time: its plug collides tens of times faster than the
    // gas, so c per unit t is not known before; the fields' step keeps frames at Fig 4.7's c = 20.
    const std::string ends_and_cadence =
        h.until_t > 0.0
            ? fmt::format("[run]\nuntil_time = {0}\n[output]\nevery_time = {1}\nsnapshot_every_time = {2}\n"
                          "[fields]\nevery_time = {3}\n",
                          h.until_t, h.until_t / 2000.0, h.until_t / 8.0, h.until_t / 600.0)
            : fmt::format("[run]\nuntil_collisions_per_particle = {0}\n[output]\nevery_collisions_per_particle = 1\n"
                          "snapshot_every_collisions_per_particle = {1}\n[fields]\nevery_collisions_per_particle = {2}\n",
                          h.length * until_c, until_c / 4.0, until_c / 60.0);
    groups.push_back({h.group, sheared_gas_tables(45, by_scale(scale, 500, 4000, 10000, kThesisParticles), kRestitution,
                                                  h.boundary) +
                                   fmt::format("[initial]\n{}\n{}[sweep]\nseeds = {}\n", h.initial, ends_and_cadence,
                                               by_scale(scale, 1, 3, 3, 3))});
  }
  return groups;
}

}  // namespace granule::reproduce::chapter4
