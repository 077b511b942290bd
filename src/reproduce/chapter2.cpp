// Chapter 2, free cooling of Systems I (ẽ = 0.98) and II (ẽ = 0.6), ν = 0.05 (thesis §2.1):
// - before clustering T̄ decays as exp(−εc), ε = 1 − ẽ² (§2.4.2, T0(s) = T0(0) e^{−2εs}, c = 2s);
// - the onset of clustering against the linear-stability estimate of the shear mode (2.35);
// - after clustering T̄ keeps its t⁻² decay (Figs 2.6(C), 2.7(C) and the text before them);
// - the dominant Fourier mode against L0 (1.1) at the last frame, and where the modes appear: the
//   momentum spectrum's before the mass spectrum's (Figs 2.8–2.9).
#include <fmt/format.h>

#include <cmath>

#include "reproduce/cooling_sizes.hpp"
#include "reproduce/dominant_modes.hpp"
#include "reproduce/free_cooling.hpp"
#include "reproduce/study.hpp"
#include "theory/haff.hpp"
#include "theory/kinetic_scales.hpp"

namespace granule::reproduce {

namespace {

struct FreeSystem {
  const char* name;   // "I"
  const char* group;  // "system_I"
  double restitution;
  double until_c;         // the thesis's last figure of it: Fig 2.9 (c = 550), Fig 2.10 (c = 100)
  double thesis_onset_c;  // "approximately 300" (System I), "about 10" (System II), §2.1
};

constexpr FreeSystem kSystems[] = {{"I", "system_I", 0.98, 550.0, 300.0}, {"II", "system_II", 0.6, 100.0, 10.0}};
constexpr int kThesisParticles = 40000;
constexpr double kAreaFraction = kFreeCoolingAreaFraction;
// Every frame's dominant modes (analyzed at every snapshot, so the modes can be watched appearing).
constexpr const char* kSpectraTable = "spectra_all_frames.csv";


std::vector<RunGroup> chapter2_runs(Scale scale) {
  std::vector<RunGroup> groups;
  for (const FreeSystem& system : kSystems) {
    const double until_c = scale == Scale::tiny ? system.until_c / 10.0 : system.until_c;
    groups.push_back({system.group, fmt::format(R"(seed = 1995
[system]
particles = {0}
area_fraction = 0.05
restitution = {1}
tc_duration = 1e-7   # TC model against inelastic collapse (thesis: none; collapse stops a run otherwise)
[initial]
temperature = 1.0
equilibrate = 5
[run]
until_collisions_per_particle = {2}
[output]
every_collisions_per_particle = 0.5
snapshot_every_collisions_per_particle = {4}   # 100 frames: the modes watched as they appear
[sweep]
seeds = {3}
)",
                                                by_scale(scale, 1000, 4000, 20000, kThesisParticles), system.restitution, until_c,
                                                by_scale(scale, 1, 3, 3, 1), until_c / 100.0)});
  }
  groups.push_back(cooling_sizes_runs(scale));
  return groups;
}


// The hypothesis that the last frame's disagreement with L0 comes from coarsening, tested where the
// thesis looks at the modes' birth (Fig 2.8, System I at c = 150, half its onset): the momentum
// spectrum's dominant mode appears before the mass spectrum's, and at appearance it sits near L0.
void add_onset_mode_claims(const FreeSystem& system, const std::vector<RunModes>& runs, double l0, double box,
                           StudyOutcome& out) {
  const std::string prefix = fmt::format("chapter2.system_{}", system.name);
  std::vector<double> leads, lengths;
  int never = 0;  // runs in which P's mode never appeared to stay
  for (const RunModes& modes : runs) {
    const std::vector<DominantMode>& mass = modes.mass;
    const DominantMode* p_first = first_persistent_mode(modes.momentum);
    if (p_first == nullptr) {
      ++never;
      continue;
    }
    const DominantMode* r_first = first_persistent_mode(mass);
    // A mass mode that never appears counts from the run's end: the lead is then a lower bound.
    const double r_c = r_first != nullptr ? r_first->c : mass.empty() ? NAN : mass.back().c;
    leads.push_back(r_c - p_first->c);
    lengths.push_back(p_first->length);
  }
  const std::string frames = fmt::format(
      "granule analyze spectra of every snapshot (M = 64); a mode appears at the first of {} consecutive frames in which it is "
      "the dominant one and significant at 5 % false alarm; P's appeared in {} of {} run(s)",
      kPersistentFrames, lengths.size(), runs.size());
  Claim lead = estimate_claim(
      prefix + ".momentum_mode_first",
      fmt::format("System {}: a dominant mode appears in the momentum spectrum before one appears in the mass spectrum",
                  system.name),
      "thesis §2.2, Fig 2.8 (System I at c = 150: a dominant mode in P, none in R), Fig 2.9", 1.0, mean_over(leads), 0.0,
      "a sign: the thesis shows the order of appearance, not the delay",
      "c at which R's mode appears minus c at which P's does; " + frames, ToleranceKind::sign);
  Claim birth = estimate_claim(
      prefix + ".momentum_mode_L0_at_onset",
      fmt::format("System {}: where the momentum spectrum's dominant mode appears, its length is the cluster separation L0 "
                  "= l/√ε (1.1)",
                  system.name),
      "thesis (1.1), §2.2, Fig 2.8", l0, mean_over(lengths), 2.0,
      "(1.1) is an order-of-magnitude scale (kl ~ √ε, §2.4.3), not a prefactor",
      "2π/|k| of P's dominant mode at the frame where it appears; " + frames, ToleranceKind::factor);
  if (never > 0) {
    const std::string why = fmt::format("the momentum spectrum's dominant mode did not appear in {} of {} run(s)", never,
                                        runs.size());
    lead.unresolvable = why;
    birth.unresolvable = why;
  } else if (birth.measured > 0.5 * box) {
    birth.checked += "; at appearance the mode is already of the box's size (its lowest modes)";
  }
  out.claims.push_back(lead);
  out.claims.push_back(birth);
}

void add_system_claims(const FreeSystem& system, Scale scale, const GroupOutputs& group, StudyOutcome& out) {
  const std::vector<const PointOutputs*> points = points_with(group);
  if (points.empty()) return;
  const PointOutputs& first = *points.front();
  const int particles = static_cast<int>(summary_number(first, "particles"));
  const double estimate =
      linear_stability_onset_c(system.restitution, particles, summary_number(first, "diameter"), summary_number(first, "box.0"));
  std::vector<double> slopes, onsets, exponents, energy_exponents;
  int without_onset = 0;  // runs that ended before any onset: their onset is later than c_end
  for (const PointOutputs* p : points) {
    const CoolingMeasures m = measure_cooling(*p, estimate / 3.0);
    slopes.push_back(m.early_slope);
    without_onset += std::isfinite(m.onset_c) ? 0 : 1;
    onsets.push_back(std::isfinite(m.onset_c) ? m.onset_c : p->samples.back().c);
    exponents.push_back(m.late_exponent);
    energy_exponents.push_back(m.late_energy_exponent);
  }
  const Estimate slope = mean_over(slopes), onset = mean_over(onsets), exponent = mean_over(exponents);
  const std::string prefix = fmt::format("chapter2.system_{}", system.name);
  const std::string runs = fmt::format("{} run(s) of N = {}, ẽ = {}, ν = 0.05", slope.count, particles, system.restitution);

  Claim decay = estimate_claim(
      prefix + ".early_decay",
      fmt::format("System {}: before clustering T̄ decays as exp(−εc), ε = 1 − ẽ² = {:.4g}", system.name,
                  theory::inelasticity(system.restitution)),
      "thesis §2.4.2 (T0(s) = T0(0) exp(−2εs), (2.19); c = 2s), Figs 2.6(B), 2.7(B)", -theory::inelasticity(system.restitution),
      slope, 0.05,
      "the Sonine correction to the loss per collision (~1 %) and velocity correlations building up before the onset",
      fmt::format("slope of ln T̄ against c over c ∈ [1, c*/3] = [1, {:.3g}] of {}", estimate / 3.0, runs));
  out.claims.push_back(decay);

  Claim start = estimate_claim(
      prefix + ".onset_vs_linear_stability",
      fmt::format(
          "System {}: clustering sets in at the c where the box's longest shear mode (2.35) grows from noise to order one",
          system.name),
      "thesis §2.4.2, (2.35) (shear mode λΩ = −ε − 5K²/12); estimate c* = ln N/(ε − 5K²/12), K = 2π l0/L", estimate, onset, 2.0,
      "an order-of-magnitude estimate: the initial amplitude and the threshold enter only through a logarithm",
      fmt::format("first c where E exceeds the extrapolated early exp decay by {}× (Fig 2.5's change of slope), {}", kOnsetExcess,
                  runs),
      ToleranceKind::factor);
  // A run that ended before any onset counts with its c_end, a lower bound: the claim disagrees only
  // when even the bound lies beyond the band.
  const auto bound_onset = [&](Claim& claim) {
    if (without_onset == 0) return;
    claim.error = NAN;  // a bound, not an estimate
    claim.checked += fmt::format("; no onset by c = {} in {} of {} run(s), whose c_end counts as a lower bound", onset.mean,
                                 without_onset, onset.count);
    if (onset.mean <= claim.expected * claim.tolerance)
      claim.unresolvable = "the runs end before the onset, which the band still allows";
  };
  Claim thesis_onset = start;
  bound_onset(start);
  out.claims.push_back(start);

  thesis_onset.id = prefix + ".onset_thesis";
  thesis_onset.statement = fmt::format("System {}: the transition happens after about {} collisions per particle (N = 40000)",
                                       system.name, system.thesis_onset_c);
  thesis_onset.location = "thesis §2.1, text before Figs 2.2 and 2.3";
  thesis_onset.expected = system.thesis_onset_c;
  thesis_onset.tolerance = 1.5;
  thesis_onset.tolerance_reason = "the thesis gives a round number read off its plots";
  bound_onset(thesis_onset);
  if (particles != kThesisParticles) {
    thesis_onset.unresolvable =
        fmt::format("the onset grows as ln N (c* = {:.3g} here, {:.3g} at N = 40000): only the thesis scale compares", estimate,
                    linear_stability_onset_c(system.restitution, kThesisParticles,
                                             summary_number(first, "diameter") * std::sqrt(particles / 40000.0), 1.0));
  }
  out.claims.push_back(thesis_onset);

  Claim late = estimate_claim(
      prefix + ".late_power_law", fmt::format("System {}: after the transition T̄ keeps its t⁻² decay", system.name),
      "thesis §2.1, text before Fig 2.6; Figs 2.6(C), 2.7(C)", -2.0, exponent, 0.2,
      "an exponent read off a log-log plot over about a decade of t",
      fmt::format("slope of ln T̄ against ln t over c ∈ [2 × onset, {}] of {}", points.front()->samples.back().c, runs),
      ToleranceKind::absolute);
  if (scale == Scale::tiny) late.unresolvable = "the tiny runs stop before twice the onset";
  if (without_onset > 0) late.unresolvable = "no clustering onset within the run, so no post-transition decay to fit";
  out.claims.push_back(late);
  // T̄ removes each cell's mean velocity, which after clustering carries much of the energy: the
  // thesis's t⁻² tested on the whole kinetic energy E, and E against the late clustering regime of
  // dilute disks, E ~ t⁻¹ (Nie, Ben-Naim & Chen 2002; ballistic aggregation gives θ = 2d/(d + 2) = 1 too).
  const Estimate energy_exponent = mean_over(energy_exponents);
  out.claims.push_back(hypothesis_claim(late, "energy", "the t⁻² is the whole kinetic energy E's, mean flows included",
                                        energy_exponent, "the same fit to E, the lab kinetic energy per particle",
                                        late.unresolvable));
  Claim clustering = estimate_claim(
      prefix + ".late_energy_clustering_regime",
      fmt::format("System {}: late in the clustering regime the kinetic energy decays as E ~ t⁻¹ (dilute disks)", system.name),
      "X. Nie, E. Ben-Naim and S. Chen, Phys. Rev. Lett. 89, 204301 (2002), molecular dynamics of 2D free cooling", -1.0,
      energy_exponent, 0.2, "the exponent of a long-time limit that finite runs approach from their transient",
      fmt::format("slope of ln E against ln t over c ∈ [2 × onset, {}] of {}", points.front()->samples.back().c, runs),
      ToleranceKind::absolute);
  clustering.unresolvable = late.unresolvable;
  out.claims.push_back(clustering);

  // The dominant mode of the mass spectrum R at the last frame (Fig 2.9 at c = 550, Fig 2.10 at c = 100),
  // from `granule analyze spectra`, only where it stands above the noise of uncorrelated positions.
  const double l0 = theory::cluster_separation(system.restitution, summary_number(first, "diameter"), kAreaFraction);
  const double box = summary_number(first, "box.0");
  std::vector<RunModes> modes;
  std::vector<double> lengths;
  int compared = 0;
  double largest_p = 0.0;
  for (const PointOutputs* p : points) {
    modes.push_back(dominant_modes(p->directory + "/" + kSpectraTable));
    if (modes.back().mass.empty()) continue;
    const DominantMode& last = modes.back().mass.back();
    ++compared;
    if (last.significant) {
      lengths.push_back(last.length);
    } else {
      largest_p = std::max(largest_p, last.noise_p_value);
    }
  }
  Claim mode = estimate_claim(
      prefix + ".dominant_mode_L0",
      fmt::format("System {}: the dominant mode of the mass spectrum sits at the cluster separation L0 = l/√ε (1.1)",
                  system.name),
      "thesis (1.1), §2.2, Figs 2.9–2.10", l0, mean_over(lengths), 2.0,
      "(1.1) is an order-of-magnitude scale (kl ~ √ε, §2.4.3), not a prefactor",
      fmt::format(
          "2π/|k| of the largest R(k) at the last frame (granule analyze spectra, M = 64), significant at 5 % false alarm "
          "in {} of {} run(s)",
          lengths.size(), compared),
      ToleranceKind::factor);
  if (!lengths.empty() && mode.measured > 0.5 * box) {
    // Coarsening has reached the box: the comparison with L0 then says how far, not what L0 is.
    mode.checked += "; the dominant length is of the box's size (its lowest modes): the structure has coarsened to the box";
  }
  if (compared == 0)
    mode.unresolvable = "no spectra were computed (granule analyze spectra failed or did not run)";
  else if (lengths.empty())
    mode.unresolvable =
        fmt::format("no significant dominant mode: noise would put as much power into one mode with p = {:.2g}", largest_p);
  out.claims.push_back(mode);
  add_onset_mode_claims(system, modes, l0, box, out);

  // Figs 2.6(B)/2.7(B): T̄ against c; 2.6(C)/2.7(C): T̄ against t.
  FigureSeries against_c{fmt::format("Granule, N = {}", particles), {}, {}, {}, false}, exponential{"exp(−εc)", {}, {}, {}, true};
  FigureSeries against_t{against_c.label, {}, {}, {}, false}, power{"t⁻² (thesis)", {}, {}, {}, true};
  const DiagnosticsSample& start_sample = first.samples.front();
  for (const DiagnosticsSample& s : first.samples) {
    against_c.x.push_back(s.c);
    against_c.y.push_back(s.temperature / start_sample.temperature);
    // The exponential only down to a decade below the data, which it would otherwise squash.
    const double haff_c = std::exp(-theory::inelasticity(system.restitution) * s.c);
    if (haff_c > 0.1 * first.samples.back().temperature / start_sample.temperature) {
      exponential.x.push_back(s.c);
      exponential.y.push_back(haff_c);
    }
    if (s.t > 0.0) {
      against_t.x.push_back(s.t);
      against_t.y.push_back(s.temperature / start_sample.temperature);
    }
  }
  if (!against_t.x.empty()) {
    // A t⁻² line through the last sample.
    const double t_end = against_t.x.back(), T_end = against_t.y.back();
    for (double f : {0.05, 1.0}) {
      power.x.push_back(t_end * f);
      power.y.push_back(T_end / (f * f));
    }
  }
  const char* figure_c = system.name[1] == '\0' ? "Fig 2.6(B)" : "Fig 2.7(B)";
  const char* figure_t = system.name[1] == '\0' ? "Fig 2.6(C)" : "Fig 2.7(C)";
  out.figures.push_back(
      Figure{.name = prefix + "_T_against_c",
             .thesis_figure = figure_c,
             .caption = fmt::format("System {}: the average fluctuation energy per particle T̄/T̄(0) versus c", system.name),
             .x_label = "c (collisions per particle)",
             .y_label = "T̄ / T̄(0)",
             .log_y = true,
             .series = {against_c, exponential}});
  out.figures.push_back(Figure{.name = prefix + "_T_against_t",
                               .thesis_figure = figure_t,
                               .caption = fmt::format("System {}: T̄/T̄(0) versus the true time", system.name),
                               .x_label = "t",
                               .y_label = "T̄ / T̄(0)",
                               .log_x = true,
                               .log_y = true,
                               .series = {against_t, power}});
}

StudyOutcome evaluate_chapter2(Scale scale, const StudyOutputs& outputs) {
  StudyOutcome out;
  for (const FreeSystem& system : kSystems) add_system_claims(system, scale, outputs.at(system.group), out);
  add_cooling_size_claims(scale, outputs.at(cooling_sizes_runs(scale).name), out);
  out.notes.push_back("Runs use the TC model (t_c = 1e-7) against inelastic collapse; the thesis's runs had none.");
  return out;
}

std::vector<PointAnalysis> chapter2_analyses(Scale) {
  std::vector<PointAnalysis> spectra;
  for (const FreeSystem& system : kSystems) {
    spectra.push_back({system.group,
                       {"analyze", "spectra", "{run}/snapshots.h5", "--frames", "all", "--out", "{run}/spectra.h5", "--csv",
                        "{run}/" + std::string(kSpectraTable)},
                       kSpectraTable});
  }
  return spectra;
}

}  // namespace

Study chapter2_study() {
  return {"chapter2", "Free cooling: Systems I and II", "Chapter 2 (thesis §2.1–2.4)", chapter2_runs, evaluate_chapter2,
          chapter2_analyses};
}

}  // namespace granule::reproduce
