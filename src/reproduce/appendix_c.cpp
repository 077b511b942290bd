// Appendix C, three-dimensional simulations and simulations with spin: what its captions state, as
// numbers (docs/appendix_c.md, docs/walls_gravity_spin.md):
// - Fig C.1, free spheres (N = 120000, φ = 0.05, ẽ = 0.6): the homogeneous cooling before the
//   transition against Haff's law with the 3D Sonine-corrected loss per collision (van Noije and
//   Ernst 1998; independent of the thesis), and the transition "to an inhomogeneous state" against the
//   2D System II of the same ẽ and φ ("the phenomenology of two-dimensional free flows appears to
//   carry over");
// - Fig C.2, Lees–Edwards shear (U = ±100): "dense clusters aligned at 45° to the streamwise direction,
//   much like the clusters in a two-dimensional sheared system", i.e. structure in the flow–gradient
//   plane rather than layers along the vorticity z;
// - Fig C.3, shear ramped from rest to 50: "a dense streamwise plug in the center";
// - Fig C.4, rough disks under shear: neighbours spin in opposite senses, C_contact < 0 (rough_shear.hpp);
// - Fig C.5, rough disks between frictional walls: "a dense streamwise plug of low internal kinetic
//   energy".
// The density structure is read from the first and last frames of each run's fields.h5
// (density_layers.hpp).
#include <fmt/format.h>

#include <cmath>

#include "reproduce/density_layers.hpp"
#include "reproduce/rough_shear.hpp"
#include "reproduce/study.hpp"
#include "theory/homogeneous_cooling.hpp"

namespace granule::reproduce {

namespace {

constexpr double kRestitution = 0.6;  // Figs C.1–C.3
constexpr int kThesisSpheres = 120000;
// The end of the early window, a third of the onset of the 2D System II of the same ẽ and ν (c* ≈ 13
// at N = 4000, docs/reproduce.md): the gas is still homogeneous there.
constexpr double kEarlyToC = 4.0;
constexpr double kOnsetExcess = 1.2;         // as chapter2: E 20 % above its early exponential (Fig 2.5)
constexpr double kSystemIIOnsetC = 10.0;     // "about 10" collisions per particle, thesis §2.1
constexpr double kPlugBandFraction = 0.2;    // a plug: the densest fifth of the rows along y
constexpr const char* kFields = "/fields.h5";

// The spheres' common configuration; `extra` adds the boundary and initial state of one figure.
std::string spheres_toml(Scale scale, int seed, double until_c, int seeds, const std::string& extra) {
  return fmt::format(R"(seed = {0}
[system]
dimension = 3
particles = {1}
packing_fraction = 0.05
box = [1.0, 1.0, 1.0]
restitution = {2}
tc_duration = 1e-7   # TC model against inelastic collapse (thesis: none), far below the mean free time
{3}
[run]
until_collisions_per_particle = {4}
[output]
every_collisions_per_particle = 0.5
[sweep]
seeds = {5}
)",
                     seed, by_scale(scale, 1500, 16000, kThesisSpheres, kThesisSpheres), kRestitution, extra, until_c, seeds);
}

// Fig C.5's wall-driven shear of rough disks, started from the linear shear profile or from rest.
std::string wall_shear_toml(Scale scale, int seeds, bool shear_profile) {
  return fmt::format(R"(seed = 2245
[system]
particles = {0}
area_fraction = 0.05
box = [1.0, 1.0]
restitution = 0.9
tangential_restitution = -0.8
tc_duration = 1e-7
[boundary]
kind = "walls"
wall_axes = ["y"]
wall_restitution = 0.8
wall_tangential_restitution = -0.8
shear_velocity = 100.0
[initial]
temperature = 1.0
{3}[run]
until_collisions_per_particle = {1}
[output]
every_collisions_per_particle = 1
[fields]
cells = [10, 20]
[sweep]
seeds = {2}
)",
                     by_scale(scale, 1000, 4000, 20000, 20000), by_scale(scale, 20.0, 200.0, 400.0, 600.0), seeds,
                     shear_profile ? "" : "shear_profile = false\n");
}

std::vector<RunGroup> appendix_c_runs(Scale scale) {
  const int seeds = by_scale(scale, 1, 3, 3, 1);
  return {
      {"free_cooling", spheres_toml(scale, 120, by_scale(scale, 15.0, 60.0, 100.0, 200.0), by_scale(scale, 1, 3, 2, 1), "")},
      {"shear", spheres_toml(scale, 121, by_scale(scale, 15.0, 100.0, 150.0, 200.0), seeds, R"([boundary]
kind = "lees-edwards"
shear_velocity = 100.0   # the images at ±U (boundaries at ±U/2), as the caption's U = ±100 is read
)")},
      // The caption's "from 0 to 50 over many collision times": U₀ = 50, τ = 1 (the thesis gives no τ;
      // examples/appendix_c/ramp_fig_c3.toml), from a gas at rest.
      {"ramp", spheres_toml(scale, 122, by_scale(scale, 15.0, 200.0, 300.0, 600.0), seeds, R"([initial]
shear_profile = false
[boundary]
kind = "lees-edwards"
shear_velocity = 50.0
shear_ramp_time = 1.0
)")},
      // Fig C.5 (examples/walls_spin_gravity/wall_shear_fig_c5.toml): walls at ∓U/2, U = 100 (the caption gives no speed),
      // starting from the linear profile; and, as the hypothesis for its disagreement, from a gas at rest.
      {"wall_shear", wall_shear_toml(scale, seeds, true)},
      {"wall_shear_static_start", wall_shear_toml(scale, seeds, false)},
      rough_shear_runs(scale, seeds),
  };
}

// The density structure of each usable point's fields.h5 (points whose file cannot be read are left out).
std::vector<DensityLayers> layers_of(const GroupOutputs& group) {
  std::vector<DensityLayers> layers;
  for (const PointOutputs* p : points_with(group)) {
    try {
      layers.push_back(read_density_layers(p->directory + kFields));
    } catch (const std::exception&) {
      continue;  // the claim then counts fewer runs, and says so
    }
  }
  return layers;
}

std::string layers_checked(const std::vector<DensityLayers>& layers, const std::string& what) {
  if (layers.empty()) return what + "; no fields.h5 could be read";
  const DensityLayers& d = layers.front();
  return fmt::format("{}; instant cell counts of fields.h5 ({} × {} × {} cells) at the last frame (c = {:.3g}) against the "
                     "first frame's (the homogeneous start) fluctuations, {} run(s)",
                     what, d.cells[0], d.cells[1], d.cells[2], d.c_last, layers.size());
}

// The density profiles along each axis of the first run's last frame: what Figs C.1–C.5 show as
// isosurfaces or configurations, reduced to lines.
Figure profiles_figure(const std::string& name, const std::string& thesis_figure, const std::string& caption,
                       const std::vector<DensityLayers>& layers) {
  Figure f{.name = name, .thesis_figure = thesis_figure, .caption = caption, .x_label = "position / L",
           .y_label = "ρ / ρ̄ (profile along the axis)", .series = {}};
  if (layers.empty()) return f;
  const DensityLayers& d = layers.front();
  const char* axes[] = {"along x (flow)", "along y (gradient)", "along z (vorticity)"};
  for (int axis = 0; axis < d.dimension; ++axis) {
    f.series.push_back({fmt::format("{}, c = {:.3g}", axes[axis], d.c_last), d.positions[axis], d.profiles[axis], {}, true});
  }
  return f;
}

void add_free_cooling(const GroupOutputs& group, StudyOutcome& out) {
  const double a2 = theory::sonine_a2(kRestitution, 3);
  const double expected_slope = -2.0 * theory::energy_loss_per_collision(3, kRestitution, a2);
  std::vector<double> slopes, onsets;
  int without_onset = 0, particles = 0;
  FigureSeries measured{"Granule T/T(0)", {}, {}, {}, false}, haff{"exp(−2fc), 3D Sonine f", {}, {}, {}, true};
  for (const PointOutputs* p : points_with(group)) {
    particles = static_cast<int>(summary_number(*p, "particles"));
    const EarlyDecay decay = early_decay(p->samples, kEarlyToC, kOnsetExcess);
    slopes.push_back(decay.temperature_slope);
    without_onset += std::isfinite(decay.onset_c) ? 0 : 1;
    onsets.push_back(decay.onset_c);
    if (measured.x.empty()) {
      for (const DiagnosticsSample& s : p->samples) {
        measured.x.push_back(s.c);
        measured.y.push_back(s.temperature / p->samples.front().temperature);
        if (s.c <= 3.0 * kEarlyToC) {
          haff.x.push_back(s.c);
          haff.y.push_back(std::exp(expected_slope * s.c));
        }
      }
    }
  }
  const std::vector<DensityLayers> layers = layers_of(group);
  const std::string runs = fmt::format("N = {} spheres, φ = 0.05, ẽ = 0.6, periodic cube", particles);
  const Estimate slope = mean_over(slopes);
  out.claims.push_back(estimate_claim(
      "appendix_c.fig_c1.early_decay",
      "Fig C.1's free spheres cool homogeneously before the transition: T decays as exp(−2fc), f the 3D loss per collision",
      "Fig C.1 (N = 120000, ν = 0.05, ẽ = 0.6); f = (1 − ẽ²)/3 · (1 + 3a2/16)/(1 − a2/16), van Noije & Ernst, Granular "
      "Matter 1, 57 (1998)",
      expected_slope, slope, 0.05,
      "as chapter2: the Sonine correction (~1 %) and velocity correlations building up before the onset",
      fmt::format("slope of ln T (cell means removed) against c over c ∈ [1, {}], {} run(s) of {}", kEarlyToC, slope.count, runs)));

  Claim onset = estimate_claim(
      "appendix_c.fig_c1.onset_as_2d",
      "Fig C.1: the free spheres leave the homogeneous state as the 2D gas of the same ẽ and ν does (System II: about 10 c)",
      "Fig C.1 caption ('the phenomenology of two-dimensional free flows appears to carry over'); System II onset, thesis §2.1",
      kSystemIIOnsetC, mean_over(onsets), 2.0,
      "the thesis gives no 3D onset; the 2D one is a round number read off its plots, and the onset grows only as ln N",
      fmt::format("first c where E exceeds its extrapolated early exp decay (c ∈ [1, {}]) by {}× (Fig 2.5's change of slope), "
                  "{} run(s) of {}",
                  kEarlyToC, kOnsetExcess, onsets.size(), runs),
      ToleranceKind::factor);
  if (!layers.empty()) {
    onset.checked += fmt::format("; at the last frame (c = {:.3g}) the cells' density variance is {:.3g} × the start's",
                                 layers.front().c_last, layers.front().clustering_index());
  }
  if (without_onset > 0) onset.unresolvable = fmt::format("no departure from the early decay by c_end in {} run(s)", without_onset);
  out.claims.push_back(onset);

  out.figures.push_back(Figure{.name = "appendix_c_fig_c1_T_against_c",
                               .thesis_figure = "Fig C.1 (its cooling)",
                               .caption = "Free spheres (φ = 0.05, ẽ = 0.6): T/T(0) against c with the 3D Sonine-corrected "
                                          "homogeneous cooling; the thesis shows the clustered state (density isosurfaces)",
                               .x_label = "c (collisions per particle)",
                               .y_label = "T / T(0)",
                               .log_y = true,
                               .series = {haff, measured}});
  out.figures.push_back(profiles_figure("appendix_c_fig_c1_profiles", "Fig C.1",
                                        "Density isosurfaces of a 3D dilute free flow after the transition (N = 120000, ν = "
                                        "0.05, ẽ = 0.6): here the density profiles along x, y, z at the last frame",
                                        layers));
}

// Mean over runs of `value(layers)`, over the runs whose structure `resolved` says is above noise.
template <typename Resolved, typename Value>
Estimate over_resolved(const std::vector<DensityLayers>& layers, Resolved resolved, Value value) {
  std::vector<double> values;
  for (const DensityLayers& d : layers) {
    if (resolved(d)) values.push_back(value(d));
  }
  return mean_over(values);
}

void add_shear(const GroupOutputs& group, StudyOutcome& out) {
  const std::vector<DensityLayers> layers = layers_of(group);
  const Estimate share = over_resolved(
      layers, [](const DensityLayers& d) { return d.clustered(); }, [](const DensityLayers& d) { return d.layer_share(2); });
  Claim c = estimate_claim(
      "appendix_c.fig_c2.clusters_in_flow_plane",
      "Fig C.2: sheared spheres form dense clusters aligned at 45° to the flow, as in 2D: structure in the flow–gradient "
      "plane, not layers along the vorticity z",
      "Fig C.2 caption (N = 120000, ν = 0.05, ẽ = 0.6, U = ±100, L = 1)", 0.0, share, 0.5,
      "clusters in the x–y plane put little of the density variance into z layers (0), vorticity bands all of it (1); 0.5 "
      "parts the two",
      layers_checked(layers, "share of the cells' excess density variance held by the profile along z"), ToleranceKind::absolute);
  if (share.count == 0)
    c.unresolvable = layers.empty() ? "no fields.h5 could be read"
                                    : "the density is homogeneous within noise at the last frame: no clusters yet at this c";
  out.claims.push_back(c);
  out.figures.push_back(profiles_figure("appendix_c_fig_c2_profiles", "Fig C.2",
                                        "Density isosurfaces of a 3D dilute shear flow driven by Lees–Edwards boundaries (N = "
                                        "120000, ν = 0.05, ẽ = 0.6, U = ±100): here the density profiles along x, y, z",
                                        layers));
}

// A dense streamwise plug in the centre: structure uniform along the flow (the flow-averaged map holds
// the cells' excess variance) whose densest fifth of the y profile sits at y = L/2.
void add_plug_claims(const std::string& prefix, const std::string& figure, const std::string& location,
                     const std::vector<DensityLayers>& layers, bool periodic, StudyOutcome& out) {
  const Estimate share = over_resolved(
      layers, [](const DensityLayers& d) { return d.clustered(); }, [](const DensityLayers& d) { return d.streamwise_share(); });
  Claim streamwise = estimate_claim(
      prefix + ".plug_is_streamwise",
      figure + ": a dense streamwise plug forms: the density structure does not vary along the flow x", location, 1.0, share,
      0.5,
      "structure uniform along the flow (a plug, whether a layer or a tube) puts all the excess variance into the "
      "flow-averaged map (1), clusters across the flow little of it; 0.5 parts the two",
      layers_checked(layers, "share of the cells' excess density variance held by the map averaged along x"),
      ToleranceKind::absolute);
  if (!layers.empty() && layers.front().dimension == 3) {
    streamwise.checked += fmt::format("; of it the y profile alone (a layer normal to y) holds {:.2g}, the z profile {:.2g}",
                                      layers.front().layer_share(1), layers.front().layer_share(2));
  }
  if (share.count == 0) streamwise.unresolvable = layers.empty() ? "no fields.h5 could be read" : "the density is homogeneous within noise";
  const Estimate offset = over_resolved(
      layers, [](const DensityLayers& d) { return d.layered(1); },
      [periodic](const DensityLayers& d) {
        return std::abs(d.densest_band_centre(1, kPlugBandFraction, periodic) - 0.5);
      });
  Claim centre = estimate_claim(
      prefix + ".plug_in_centre", figure + ": the plug lies in the centre of the system (y = L/2)", location, 0.0, offset, 0.1,
      "half the height of the band (L/5) that is called the plug", 
      layers_checked(layers, "distance from y = L/2 (in L) of the centre of the densest fifth of the y profile"),
      ToleranceKind::absolute);
  if (offset.count == 0)
    centre.unresolvable = layers.empty() ? "no fields.h5 could be read" : "the y profile is flat within noise: no plug to place";
  out.claims.push_back(streamwise);
  out.claims.push_back(centre);
}

StudyOutcome evaluate_appendix_c(Scale scale, const StudyOutputs& outputs) {
  StudyOutcome out;
  add_free_cooling(outputs.at("free_cooling"), out);
  add_shear(outputs.at("shear"), out);
  const std::vector<DensityLayers> ramp = layers_of(outputs.at("ramp"));
  add_plug_claims("appendix_c.fig_c3", "Fig C.3", "Fig C.3 caption (N = 120000, ν = 0.05, ẽ = 0.6, U from 0 to 50)", ramp, true,
                  out);
  out.figures.push_back(profiles_figure("appendix_c_fig_c3_profiles", "Fig C.3",
                                        "Density isosurfaces of a 3D shear flow whose boundaries' speed rises exponentially from "
                                        "0 to 50 (N = 120000, ν = 0.05, ẽ = 0.6): here the density profiles along x, y, z",
                                        ramp));

  add_spin_claim(outputs.at("rough_shear"), out);

  const std::vector<DensityLayers> walls = layers_of(outputs.at("wall_shear"));
  add_plug_claims("appendix_c.fig_c5", "Fig C.5",
                  "Fig C.5 caption (N = 20000, ν = 0.05, ẽ = 0.9, β = −0.8, walls e_w = 0.8, β_w = −0.8)", walls, false, out);
  // The caption likens the plug to "the plug in a simple shear flow driven from a static initial
  // condition" (Chapter 4): the walls started on a gas at rest.
  const std::vector<DensityLayers> static_start = layers_of(outputs.at("wall_shear_static_start"));
  add_plug_claims("appendix_c.fig_c5.static_start",
                  "Fig C.5 (hypothesis: the walls start on a gas at rest, as the caption's likeness to Chapter 4's static start suggests)",
                  "Fig C.5 caption (N = 20000, ν = 0.05, ẽ = 0.9, β = −0.8, walls e_w = 0.8, β_w = −0.8)", static_start, false,
                  out);
  out.figures.push_back(profiles_figure("appendix_c_fig_c5_static_start_profiles", "Fig C.5",
                                        "The same wall-bounded shear flow started from a gas at rest: here the density profiles "
                                        "along x and y",
                                        static_start));
  out.figures.push_back(profiles_figure("appendix_c_fig_c5_profiles", "Fig C.5",
                                        "A wall-bounded shear flow of rough disks between flat frictional walls moving at ∓U/2 "
                                        "(N = 20000, ν = 0.05, ẽ = 0.9, β = −0.8): here the density profiles along x and y",
                                        walls));
  if (scale != Scale::thesis) {
    out.notes.push_back("Appendix C runs fewer grains than the thesis (120000 spheres, 20000 rough disks) below the thesis "
                        "scale: the structures have less room and appear at other c.");
  }
  out.notes.push_back("The thesis gives neither run lengths nor, for Figs C.3 and C.5, the ramp time or wall speed: τ = 1 and "
                      "U = 100 are Granule's choices (examples/appendix_c, examples/walls_spin_gravity).  Densities are read from fields.h5, "
                      "first frame (the start) against last.");
  return out;
}

}  // namespace

Study appendix_c_study() {
  return {"appendix-c",
          "Spheres and spin: Figs C.1–C.5",
          "Appendix C (3D free cooling, shear and ramp; rough disks under shear and between walls)",
          appendix_c_runs,
          evaluate_appendix_c,
          [](Scale) { return std::vector<PointAnalysis>{rough_shear_spins_analysis()}; }};
}

}  // namespace granule::reproduce
