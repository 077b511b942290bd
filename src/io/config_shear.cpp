#include "io/config_shear.hpp"

#include <fmt/format.h>

#include <cmath>

#include "io/config_wall_motion.hpp"
#include "io/config_walls.hpp"
#include "io/input_ranges.hpp"
#include "theory/steady_shear.hpp"

namespace granule {

namespace {

constexpr NumberRange kTimes{0.0, kUnbounded};
constexpr NumberRange kDurations{0.0, kUnbounded, true, false};
constexpr NumberRange kTolerances{1e-9, 0.1};
constexpr NumberRange kRatios{1e-30, 1e30};
const char* const kShearKeys[] = {"boundary.shear_velocity", "boundary.shear_ramp_time", "boundary.shear_schedule",
                                  "boundary.shear_oscillation", "boundary.shear_tolerance"};

bool speed_allowed(double u) { return u == 0.0 || kSpeedRange.contains(std::abs(u)); }

// The image velocity's time dependence; returns the steady U₀ (a schedule's last value).
double resolve_protocol(const ConfigReader& in, RunConfig& c) {
  ShearHistory& h = c.system.shear_history;
  const std::string speeds = "0 or |U| in " + kSpeedRange.text();
  // Any finite U₀ here: its range depends on T_i, checked in resolve_speeds.
  const auto u0 = in.number_if("boundary.shear_velocity", [](double) { return true; }, speeds);
  // Walls on y carry the shear themselves (moving at ±U(t)/2); the images stay at rest.
  const bool wall_driven = !c.lees_edwards && c.system.walls[1];
  if (!c.lees_edwards && !wall_driven) {
    if (u0.value_or(0.0) != 0.0) {
      throw ConfigError{fmt::format("boundary.shear_velocity = {} requires boundary.kind = \"lees-edwards\", or \"walls\" "
                                    "with \"y\" in boundary.wall_axes (a periodic direction has no shear; allowed: 0)", *u0)};
    }
    for (const char* key : kShearKeys) {
      if (in.has(key) && std::string(key) != "boundary.shear_velocity") {
        throw ConfigError{fmt::format("{} requires boundary.kind = \"lees-edwards\", or \"walls\" with \"y\" in "
                                      "boundary.wall_axes (a periodic direction has no shear)", key)};
      }
    }
    return 0.0;
  }
  if (wall_driven && in.has("boundary.shear_tolerance")) {
    throw ConfigError{"boundary.shear_tolerance requires boundary.kind = \"lees-edwards\": the engine follows the images' "
                      "U(t) in constant segments, but walls move at exactly ±U(t)/2"};
  }
  for (const auto& [t, u] : in.number_pairs("boundary.shear_schedule", "[t, U]")) {
    if (!kTimes.contains(t) || !speed_allowed(u) || (!h.schedule.empty() && t < h.schedule.back().time)) {
      throw ConfigError{fmt::format("boundary.shear_schedule point [{}, {}] is not allowed: times t ≥ 0 in "
                                    "non-decreasing order (two points at one time make a step), U {}", t, u, speeds)};
    }
    h.schedule.push_back({t, u});
  }
  h.ramp_time = in.number("boundary.shear_ramp_time", kDurations, " (the time constant τ of U₀(1 − e^{−t/τ}))").value_or(0.0);
  if (!h.schedule.empty() && (u0 || h.ramp_time > 0.0)) {
    throw ConfigError{"boundary.shear_schedule replaces boundary.shear_velocity and boundary.shear_ramp_time: "
                      "give the schedule alone (its last point is the steady U₀)"};
  }
  if (h.ramp_time > 0.0 && u0.value_or(0.0) == 0.0) {
    throw ConfigError{fmt::format("boundary.shear_ramp_time = {} needs boundary.shear_velocity = U₀ ≠ 0 to ramp to",
                                  h.ramp_time)};
  }
  if (in.table_with_keys("boundary.shear_oscillation", {"amplitude", "period", "start", "cycles", "waveform"})) {
    ShearOscillation o;
    const auto amplitude = in.number_if("boundary.shear_oscillation.amplitude", speed_allowed, speeds);
    const auto period = in.number("boundary.shear_oscillation.period", kDurations);
    if (!amplitude || !period) {
      throw ConfigError{"boundary.shear_oscillation needs amplitude and period: { amplitude = A, period = P, "
                        "start = t_s (default 0), cycles = n (default 1) }"};
    }
    o.amplitude = *amplitude;
    o.period = *period;
    o.start = in.number("boundary.shear_oscillation.start", kTimes).value_or(0.0);
    o.cycles = in.number("boundary.shear_oscillation.cycles", kDurations).value_or(1.0);
    const std::string waveform = in.text("boundary.shear_oscillation.waveform", {"sine", "square", "triangle"}).value_or("sine");
    o.waveform = waveform == "square" ? Waveform::kSquare : waveform == "triangle" ? Waveform::kTriangle : Waveform::kSine;
    if (!std::isfinite(o.end())) throw ConfigError{"boundary.shear_oscillation ends beyond the largest finite time"};
    h.oscillation = o;
  }
  h.tolerance = in.number("boundary.shear_tolerance", kTolerances,
                          " (largest |U(t) − Ū| on a constant-velocity segment, relative to the largest |U|)")
                    .value_or(1e-3);
  const double steady = h.schedule.empty() ? u0.value_or(0.0) : h.schedule.back().velocity;
  if (!wall_driven) return steady;
  set_wall_shear(c.system, steady);
  c.system.wall[2].along = scaled(h, -0.5);
  c.system.wall[3].along = scaled(h, 0.5);
  return 0.0;
}

}  // namespace

void resolve_speeds(const ConfigReader& in, RunConfig& c) {
  SystemParams& s = c.system;
  const std::string kind = in.text("boundary.kind", {"periodic", "lees-edwards", "walls"}).value_or("periodic");
  c.lees_edwards = kind == "lees-edwards";
  resolve_walls(in, kind == "walls", c);
  resolve_wall_motion(in, kind == "walls", c);
  s.shear_velocity = resolve_protocol(in, c);
  c.initial_shear_profile = in.boolean("initial.shear_profile").value_or(true);

  c.initial_temperature_over_steady = in.number("initial.temperature_over_steady", kRatios, " (T_i / T₀ of thesis eq 4.5)");
  const auto temperature = in.number("initial.temperature", kTemperatureRange);
  c.initial_temperature = temperature.value_or(1.0);
  if (const auto ratio = c.initial_temperature_over_steady) {
    in.number_if("boundary.shear_velocity", speed_allowed, "0 or |U| in " + kSpeedRange.text());
    if (temperature) throw ConfigError{"initial.temperature and initial.temperature_over_steady are both set: give one"};
    if (s.dimension == 3 || !c.diameters.monodisperse()) {  // eq (4.5) is the kinetic theory of equal disks
      throw ConfigError{fmt::format("initial.temperature_over_steady = {} needs the T₀ of thesis eq (4.5), which is "
                                    "for equal disks: give initial.temperature in 3D and polydisperse runs", *ratio)};
    }
    if (s.shear_velocity == 0.0 || s.restitution >= 1.0) {
      throw ConfigError{fmt::format("initial.temperature_over_steady = {} needs a steady T₀ (4.5): a Lees–Edwards "
                                    "shear U₀ ≠ 0 and system.restitution < 1", *ratio)};
    }
    const double t0 = theory::steady_shear_temperature_kinetic(s.restitution, std::abs(s.shear_velocity) / s.length_y,
                                                               s.diameter, c.packing_fraction);
    c.initial_temperature = *ratio * t0;
    if (!kTemperatureRange.contains(c.initial_temperature)) {
      throw ConfigError{fmt::format("initial.temperature_over_steady = {} gives T_i = {} (T₀ = {}): allowed T_i in {}",
                                    *ratio, c.initial_temperature, t0, kTemperatureRange.text())};
    }
  }
  // Every |U(t)| relative to the thermal speed (see input_ranges.hpp).
  const double thermal_speed = std::sqrt(c.initial_temperature);
  const NumberRange shear_speeds{kSpeedRange.low, std::min(kSpeedRange.high, kMaxShearOverThermalSpeed * thermal_speed)};
  const std::string why = fmt::format("0 or |U| in {} (at most {:g} √T_i with initial.temperature = {}, so that the thermal "
                                      "velocities stay resolved beside the shear profile)",
                                      shear_speeds.text(), kMaxShearOverThermalSpeed, c.initial_temperature);
  in.number_if("boundary.shear_velocity", [&](double u) { return u == 0.0 || shear_speeds.contains(std::abs(u)); }, why);
  const double scale = ShearProtocol(s.shear_velocity, s.shear_history).velocity_scale();
  if (scale != 0.0 && !shear_speeds.contains(scale)) {
    throw ConfigError{fmt::format("the shear protocol reaches |U| = {}: allowed {}", scale, why)};
  }
}

std::string speeds_to_toml(const RunConfig& c) {
  const SystemParams& s = c.system;
  const ShearHistory& h = s.shear_history;
  std::string out = fmt::format("[boundary]\nkind = \"{}\"\n", boundary_kind_name(c)) + walls_to_toml(c) + wall_motion_to_toml(c);
  if (h.schedule.empty()) {
    out += fmt::format("shear_velocity = {:.17g}\n", s.walls[1] ? wall_shear_velocity(s) : s.shear_velocity);
  } else {
    std::string points;
    for (const ShearSchedulePoint& p : h.schedule) points += fmt::format("{}[{:.17g}, {:.17g}]", points.empty() ? "" : ", ", p.time, p.velocity);
    out += "shear_schedule = [" + points + "]\n";
  }
  if (h.ramp_time > 0.0) out += fmt::format("shear_ramp_time = {:.17g}\n", h.ramp_time);
  if (const auto& o = h.oscillation) {
    const char* waveform = o->waveform == Waveform::kSquare ? ", waveform = \"square\"" : o->waveform == Waveform::kTriangle ? ", waveform = \"triangle\"" : "";
    out += fmt::format("shear_oscillation = {{ amplitude = {:.17g}, period = {:.17g}, start = {:.17g}, cycles = {:.17g}{} }}\n",
                       o->amplitude, o->period, o->start, o->cycles, waveform);
  }
  if (c.lees_edwards) out += fmt::format("shear_tolerance = {:.17g}\n", h.tolerance);
  out += "\n[initial]\n";
  // A state taken from another run has neither a temperature nor a profile of its own (the parser
  // refuses them beside initial.from, and a resumed run reads this file back).
  if (const auto& from = c.initial_from) {
    out += fmt::format("from = \"{}\"\n", from->directory);
    if (from->frame) out += fmt::format("frame = {}\n", *from->frame);
  } else {
    out += fmt::format("temperature = {:.17g}\nshear_profile = {}\n", c.initial_temperature, c.initial_shear_profile);
  }
  return out;
}

}  // namespace granule
