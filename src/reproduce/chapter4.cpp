// Chapter 4, shear histories (thesis §4.2–4.3, Figs 4.5–4.8): one sheared gas (ẽ = 0.6, ν = 0.05,
// U₀ = 100, L = 1, the parameters of Fig 4.5) ends in different states depending on its history:
// - a cold start (T_i < T₀ of (4.5)) stays quasihomogeneous (Fig 4.5), at the T₀ of (4.5);
// - a hot start (T_i ≫ √N T₀) clusters before the shear can disperse the clusters: a plugged flow (Fig 4.6);
// - a static gas sheared incrementally forms two layers that converge into a central plug, colder
//   than the dilute regions beside it, fed by a heat flux towards it (Figs 4.7–4.8, §4.3);
// - an instantaneous change of U, or a transient periodic kick of a quasihomogeneous flow, leads to
//   the same kind of plugged state (§4.3, last two paragraphs); the kick at two amplitudes, U₀ and the
//   "small but finite" 0.1 U₀ (the thesis gives no number).
// The states are told apart by the mass in the densest band of L_y/5 (uniform gas: 0.2), from the
// time series (analysis/flow_classification.hpp), and by the streamwise profiles of fields.h5.
// The histories and their runs: reproduce/chapter4_histories.hpp.
#include <fmt/format.h>

#include <cmath>
#include <stdexcept>

#include "reproduce/chapter4_histories.hpp"
#include "reproduce/streamwise_profiles.hpp"
#include "reproduce/study.hpp"
#include "theory/steady_shear.hpp"

namespace granule::reproduce {

namespace {

using chapter4::History;
using chapter4::kRampReached;
using chapter4::kRestitution;
using chapter4::kThesisParticles;
using chapter4::histories;

constexpr double kBandFraction = 0.2;  // the densest band is L_y/5 wide (FlowClassificationSettings)

// The criteria of the states, fixed before the runs.  A uniform gas puts 0.2 of its mass into the
// densest fifth plus the maximum of the counting noise over the band's positions (0.21–0.22 at
// N = 4000–20000, docs/chapter4.md); a plug (Figs 4.6, 4.8: one dense band, dilute regions beside
// it) puts most of the mass there: we call a state plugged when the band holds more than half of it.
constexpr double kUniformBand = 0.2, kUniformBandTolerance = 0.05;
constexpr double kPluggedBand = 0.75, kPluggedBandTolerance = 0.25;  // [0.5, 1]

// Fig 4.7: after 20 collisions per particle two dense streamwise layers span the box.  A layer is a
// run of rows denser than twice the mean (the ramp's layers reach 4–8 ρ̄, docs/chapter4.md); the
// frames of fields.h5 within ±2.5 c of c = 20 are averaged.
constexpr double kEarlyLayersC = 20.0, kEarlyLayersHalfWidth = 2.5, kLayerDensity = 2.0;

// The window of a run in which its state is read: the second half of the run, and after the
// protocol's forcing ended.
struct LateWindow {
  double c_from = 0.0, c_to = 0.0;
};

LateWindow late_window(const PointOutputs& p, double protocol_end_t) {
  LateWindow w{0.5 * p.samples.back().c, p.samples.back().c};
  for (const DiagnosticsSample& s : p.samples) {
    if (s.t >= protocol_end_t) {
      w.c_from = std::max(w.c_from, s.c);
      break;
    }
  }
  return w;
}

// The mass fraction in the densest band over c ∈ [c_from, c_to] of a run's time series.
double band_mean(const PointOutputs& p, double c_from, double c_to) {
  return window_mean(p.samples, c_from, c_to, [](const DiagnosticsSample& s) { return s.flow.densest_band_mass_fraction; });
}

// The second half of the forcing, t ∈ [protocol_end_t / 2, protocol_end_t], in c.
LateWindow forcing_window(const PointOutputs& p, double protocol_end_t) {
  LateWindow w{NAN, NAN};
  for (const DiagnosticsSample& s : p.samples) {
    if (std::isnan(w.c_from) && s.t >= 0.5 * protocol_end_t) w.c_from = s.c;
    if (s.t <= protocol_end_t) w.c_to = s.c;
  }
  return w;
}

// What one history shows, one entry per seed.
struct HistoryMeasures {
  std::vector<double> band, temperature, centre_distance, temperature_ratio, flux_towards;
  std::vector<double> early_layers;  // dense layers of ρ(y) at c ≈ kEarlyLayersC (Fig 4.7)
  std::vector<double> band_forcing;  // the band in the second half of the forcing (the ramp: while U rises)
  std::vector<double> excess_kept;   // the band's excess over a uniform gas at the window's end over that at its start
  LateWindow rising_window;          // of the first seed
  int particles = 0;
  double diameter = 0.0;
  LateWindow window;  // of the first seed, for the report
};

HistoryMeasures measure(const History& h, const GroupOutputs& group) {
  HistoryMeasures m;
  for (const PointOutputs* p : points_with(group)) {
    const LateWindow w = late_window(*p, h.protocol_end_t);
    if (m.band.empty()) m.window = w;
    m.particles = static_cast<int>(summary_number(*p, "particles"));
    m.diameter = summary_number(*p, "diameter");
    m.band.push_back(band_mean(*p, w.c_from, w.c_to));
    m.temperature.push_back(window_mean(p->samples, w.c_from, w.c_to, [](const DiagnosticsSample& s) { return s.temperature; }));
    const StreamwiseProfiles profiles = read_streamwise_profiles(p->directory + "/fields.h5", w.c_from, w.c_to);
    const int band_rows = std::max(1, static_cast<int>(std::lround(kBandFraction * static_cast<double>(profiles.y.size()))));
    const DensestBand band = profiles.frames > 0 ? densest_band(profiles, band_rows) : DensestBand{NAN, NAN, NAN, NAN};
    m.centre_distance.push_back(band.distance_from_middle);
    m.temperature_ratio.push_back(band.temperature_ratio);
    m.flux_towards.push_back(band.flux_towards_band);
    const StreamwiseProfiles early =
        read_streamwise_profiles(p->directory + "/fields.h5", kEarlyLayersC - kEarlyLayersHalfWidth, kEarlyLayersC + kEarlyLayersHalfWidth);
    m.early_layers.push_back(early.frames > 0 ? static_cast<double>(dense_layers(early, kLayerDensity)) : double{NAN});
    if (h.until_t > 0.0) {
      const LateWindow f = forcing_window(*p, h.protocol_end_t);
      if (m.band_forcing.empty()) m.rising_window = f;
      const auto band_over = [&](double from, double to) { return band_mean(*p, from, to); };
      m.band_forcing.push_back(band_over(f.c_from, f.c_to));
      const double tenth = 0.1 * (w.c_to - w.c_from);
      m.excess_kept.push_back((band_over(w.c_to - tenth, w.c_to) - kUniformBand) /
                              (band_over(w.c_from, w.c_from + tenth) - kUniformBand));
    }
  }
  return m;
}

std::string runs_text(const History& h, const HistoryMeasures& m) {
  return fmt::format("{}: {} seed(s) of N = {}, ẽ = 0.6, ν = 0.05, U₀ = 100; c ∈ [{:.4g}, {:.4g}] (second half, after the forcing)",
                     h.name, m.band.size(), m.particles, m.window.c_from, m.window.c_to);
}

Claim band_claim(const History& h, const HistoryMeasures& m, const std::string& id, const std::string& statement,
                 const std::string& location, bool plugged) {
  return estimate_claim(
      id, statement, location, plugged ? kPluggedBand : kUniformBand, mean_over(m.band),
      plugged ? kPluggedBandTolerance : kUniformBandTolerance,
      plugged ? "the thesis shows pictures, no number: 'plugged' is read as more than half of the mass in the densest L_y/5 band "
                "(a uniform gas: 0.2), fixed before the runs"
              : "a uniform gas puts 0.2 of its mass in the densest L_y/5 band, plus counting noise (0.21–0.22 at N = 4000–20000); "
                "weak strips along 45° (Fig 4.5) barely change a streamwise profile",
      fmt::format("densest_band_mass_fraction (timeseries.csv) averaged over the window, {}", runs_text(h, m)),
      ToleranceKind::absolute);
}

// The layers of §4.3 converge at the centre: the densest band's centre within a tenth of L_y of L_y/2.
Claim central_claim(const History& h, const HistoryMeasures& m, const std::string& prefix, const std::string& statement,
                    const std::string& location) {
  return estimate_claim(
      prefix + ".plug_central", fmt::format("{}: {}", h.name, statement), location, 0.0, mean_over(m.centre_distance), 0.1,
      "'at the centre': within a tenth of L_y of y = L_y/2 (the band itself is L_y/5 wide; a band at the Lees–Edwards "
      "boundary lies 0.5 L_y away)",
      fmt::format("|y of the densest L_y/5 band's centre − L_y/2| / L_y, streamwise profiles of fields.h5 averaged over the "
                  "window, {}",
                  runs_text(h, m)),
      ToleranceKind::absolute);
}

// The plug of Fig 4.8: central, colder than the dilute regions beside it, fed by heat flowing to it.
void add_plug_claims(const History& h, const HistoryMeasures& m, const std::string& prefix, const std::string& location,
                     StudyOutcome& out) {
  const std::string profiles = fmt::format("streamwise profiles of fields.h5 averaged over the window, {}", runs_text(h, m));
  out.claims.push_back(central_claim(h, m, prefix, "the layers converge at the centre of the system (Fig 4.8)", location));
  out.claims.push_back(estimate_claim(
      prefix + ".plug_colder",
      fmt::format("{}: a dense plug surrounded by dilute and energetic regions: T in the plug below T beside it", h.name), location,
      0.5, mean_over(m.temperature_ratio), 0.5,
      "the thesis says 'energetic' without a number: the criterion is a mass-weighted T inside the band below that outside "
      "(a ratio in [0, 1])",
      "mass-weighted T(y) inside the densest band over outside it, " + profiles, ToleranceKind::absolute));
  Claim flux = estimate_claim(
      prefix + ".heat_flux_to_plug",
      fmt::format("{}: the heat flux near the boundaries points mostly towards the plug, which it maintains", h.name),
      "thesis §4.3, text after Fig 4.8 (heat-flux measurements of ref. [16])", 1.0, mean_over(m.flux_towards), 0.25,
      "'mostly': more than three quarters of the rows outside the band",
      "the share of rows outside the densest band whose interval-averaged total q_y (kinetic + collisional) points to the band, " +
          profiles,
      ToleranceKind::absolute);
  out.claims.push_back(flux);
}

FigureSeries band_series(const PointOutputs& p, const std::string& label) {
  FigureSeries s{label, {}, {}, {}, false};
  for (const DiagnosticsSample& sample : p.samples) {
    s.x.push_back(sample.c);
    s.y.push_back(sample.flow.densest_band_mass_fraction);
  }
  return s;
}

// ρ(y)/ρ̄ of the first run of a group over c ∈ [c_from, c_to].
FigureSeries density_profile(const GroupOutputs& group, double c_from, double c_to, const std::string& label) {
  FigureSeries s{label, {}, {}, {}, false};
  const std::vector<const PointOutputs*> points = points_with(group);
  if (points.empty()) return s;
  const StreamwiseProfiles p = read_streamwise_profiles(points.front()->directory + "/fields.h5", c_from, c_to);
  double mean = 0.0;
  for (double d : p.density) mean += d / static_cast<double>(p.density.size());
  for (std::size_t r = 0; r < p.density.size(); ++r) {
    s.x.push_back(p.y[r]);
    s.y.push_back(p.density[r] / mean);
  }
  return s;
}

StudyOutcome evaluate_chapter4(Scale scale, const StudyOutputs& outputs) {
  StudyOutcome out;
  std::map<std::string, HistoryMeasures> measured;
  const std::vector<History> all = histories(scale);
  for (const History& h : all) measured[h.group] = measure(h, outputs.at(h.group));
  const auto history = [&](const char* group) -> const History& {
    for (const History& h : all) {
      if (std::string(h.group) == group) return h;
    }
    throw std::logic_error(group);
  };

  const History& cold = history("cold");
  const HistoryMeasures& c = measured["cold"];
  out.claims.push_back(band_claim(cold, c, "chapter4.cold_start.quasihomogeneous",
                                  "a cold start (T_i = 0.1 T₀ < T₀) converges to the quasihomogeneous flow of Fig 4.5",
                                  "thesis §4.2 (end), Fig 4.5", false));
  const double t0 = theory::steady_shear_temperature_kinetic(kRestitution, 100.0, c.diameter, 0.05);
  out.claims.push_back(estimate_claim(
      "chapter4.cold_start.temperature_T0",
      "the quasihomogeneous flow sits at the steady temperature T₀ = l²γ²/(πε) of the homogeneous balance (4.5)",
      "thesis (4.5), §4.1", t0, mean_over(c.temperature), 0.2,
      "(4.5) is the homogeneous balance of the thesis's dilute equations (4.1), without the anisotropy of K; at ẽ = 0.6 the "
      "thesis's own fit (3.1) lies 6 % above it and Jenkins–Richman (3.2) 22 % above: within 20 %",
      fmt::format("T̄ (temperature: cells with u(y) removed) over the window, {}", runs_text(cold, c))));

  const History& hot = history("hot");
  Claim plugged = band_claim(hot, measured["hot"], "chapter4.hot_start.plugged",
                             "a hot start (T_i = 10⁵ T₀ ≫ √N T₀) ends in the plugged flow of Fig 4.6, the same parameters as Fig 4.5",
                             "thesis §4.2 (end), Fig 4.6", true);
  out.claims.push_back(plugged);

  const History& ramp = history("ramp");
  out.claims.push_back(band_claim(ramp, measured["ramp"], "chapter4.ramp.plug",
                                  "a static gas sheared incrementally forms two dense streamwise layers that converge into a plug",
                                  "thesis §4.3, Figs 4.7–4.8", true));
  Claim layers = estimate_claim(
      "chapter4.ramp.two_layers", "ramp from rest: after 20 collisions per particle two dense streamwise layers span the system",
      "thesis §4.3, Fig 4.7 and its caption", 2.0, mean_over(measured["ramp"].early_layers), 0.5,
      "a count: exactly two layers (a layer is a run of rows of fields.h5 denser than twice the mean)",
      fmt::format("dense layers of ρ(y) over fields.h5 frames with c ∈ [{}, {}], {}", kEarlyLayersC - kEarlyLayersHalfWidth,
                  kEarlyLayersC + kEarlyLayersHalfWidth, runs_text(ramp, measured["ramp"])),
      ToleranceKind::absolute);
  if (measured["ramp"].particles != kThesisParticles) {
    // The heated regions grow from the boundaries and the layers at their edges meet in the centre
    // after a number of collisions that grows with the box in mean free paths, L/l ∝ √N.
    layers.unresolvable = fmt::format(
        "the c at which the layers meet grows with L/l ∝ √N: Fig 4.7's c = 20 belongs to N = 20000 (N = {} here)",
        measured["ramp"].particles);
  }
  out.claims.push_back(layers);
  add_plug_claims(ramp, measured["ramp"], "chapter4.ramp", "thesis §4.3, Fig 4.8", out);
  out.claims.push_back(estimate_claim(
      "chapter4.ramp.plug_persists", "ramp from rest: after its creation the plug persists, once U has reached U₀",
      "thesis §4.3, text after Fig 4.8", 1.0, mean_over(measured["ramp"].excess_kept), 0.25,
      "'persists': the densest band keeps more than three quarters of its excess over a uniform gas (0.2) from the "
      "window's first tenth to its last, a time as long as the ramp's (τ ln 100); the band chosen with the small runs' "
      "slow loss of the plug in view",
      fmt::format("(band − 0.2) averaged over the window's last tenth over that of its first tenth, densest_band_mass_fraction "
                  "of timeseries.csv, {}",
                  runs_text(ramp, measured["ramp"])),
      ToleranceKind::absolute));
  const HistoryMeasures& rising = measured["ramp"];
  if (!rising.band_forcing.empty()) {
    const Estimate while_rising = mean_over(rising.band_forcing);
    out.notes.push_back(fmt::format(
        "ramp: the plug claims are judged after U reached U₀ within 1 % (t ≥ τ ln 100 = {:.3g}); while U still rose "
        "(t ∈ [{:.3g}, {:.3g}], c ∈ [{:.4g}, {:.4g}] in the first seed) the densest fifth held {:.4g}{}",
        kRampReached, 0.5 * kRampReached, kRampReached, rising.rising_window.c_from, rising.rising_window.c_to,
        while_rising.mean, std::isfinite(while_rising.error) ? fmt::format(" ± {:.2g}", while_rising.error) : ""));
  }

  const History& step = history("step");
  out.claims.push_back(band_claim(step, measured["step"], "chapter4.step.plug",
                                  "an instantaneous change of the shear rate (U: 100 → 200) of a quasihomogeneous flow leads to "
                                  "the layered, plugged state",
                                  "thesis §4.3, first paragraph", true));
  out.claims.push_back(central_claim(step, measured["step"], "chapter4.step",
                                     "the heated boundary regions push the layers to the centre of the system",
                                     "thesis §4.3, first paragraph, Fig 4.8"));

  // The kicks, strong and small, each against the cold start (same seeds, the same run until the kick).
  for (const auto& [group, statement] :
       {std::pair{"kick", "a strong transient periodic kick of a quasihomogeneous flow leaves a state resembling Fig 4.8 (no "
                          "recovery of the quasihomogeneous state once U is back at U₀)"},
        std::pair{"kick_small", "a small but finite transient periodic kick (the thesis's words; it gives no amplitude: 0.1 U₀ here) "
                                "of a quasihomogeneous flow leaves a state resembling Fig 4.8"}}) {
    Claim kicked = band_claim(history(group), measured[group], fmt::format("chapter4.{}.no_recovery", group), statement,
                              "thesis §4.3, last paragraph", true);
    kicked.checked += "; the cold start (same seeds, the same run until the kick) is the unkicked control";
    out.claims.push_back(kicked);
  }

  // Figs 4.5–4.6 as the measure that tells them apart, over c; Figs 4.7–4.8 as ρ(y).
  FigureSeries uniform{"uniform gas", {0.0, 0.0}, {kUniformBand, kUniformBand}, {}, true};
  std::vector<FigureSeries> bands;
  for (const History& h : all) {
    const std::vector<const PointOutputs*> points = points_with(outputs.at(h.group));
    if (!points.empty()) bands.push_back(band_series(*points.front(), h.name));
    if (!points.empty()) uniform.x[1] = std::max(uniform.x[1], points.front()->samples.back().c);
  }
  bands.push_back(uniform);
  out.figures.push_back(Figure{.name = "chapter4_densest_band",
                               .thesis_figure = "Figs 4.5–4.8",
                               .caption = "One gas (ẽ = 0.6, ν₀ = 0.05, U₀ = 100), five histories: the mass in the densest L_y/5 "
                                          "band against c: quasihomogeneous (Fig 4.5) near 0.2, plugged (Figs 4.6, 4.8) above 0.5",
                               .x_label = "c (collisions per particle)",
                               .y_label = "mass fraction in the densest L_y/5 band",
                               .series = bands});
  const HistoryMeasures& r = measured["ramp"];
  out.figures.push_back(Figure{
      .name = "chapter4_ramp_layers",
      .thesis_figure = "Figs 4.7–4.8",
      .caption = "An incrementally sheared system, U = U₀[1 − exp(−t/τ)], from a static gas: ρ(y)/ρ̄ after 20 collisions per "
                 "particle (two layers, Fig 4.7) and late (converged to a plug in the centre, Fig 4.8)",
      .x_label = "y / L_y",
      .y_label = "ρ(y) / ρ̄",
      .series = {density_profile(outputs.at("ramp"), kEarlyLayersC - kEarlyLayersHalfWidth, kEarlyLayersC + kEarlyLayersHalfWidth,
                                 fmt::format("c ≈ {}", kEarlyLayersC)),
                 density_profile(outputs.at("ramp"), r.window.c_from, r.window.c_to,
                                 fmt::format("c ∈ [{:.3g}, {:.3g}]", r.window.c_from, r.window.c_to))}});
  if (c.particles != kThesisParticles) {
    out.notes.push_back(fmt::format(
        "Chapter 4 runs N = {} (the thesis's Figs 4.5–4.8: 20000); the states' criteria are fractions of the mass and do not "
        "depend on N, but a smaller box holds fewer cluster separations L0, so states may differ.",
        c.particles));
  }
  return out;
}

}  // namespace

Study chapter4_study() {
  return {"chapter4",
          "Shear histories",
          "Chapter 4 (§4.2–4.3: cold and hot starts, ramp from rest, step, kick; Figs 4.5–4.8)",
          chapter4::chapter4_runs,
          evaluate_chapter4,
          {}};
}

}  // namespace granule::reproduce
