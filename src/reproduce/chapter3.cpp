// Chapter 3, steady simple shear (thesis §3.1.1): the steady T̄ against the restitution beside the
// thesis's empirical fit (3.1) and the Jenkins–Richman dilute law (3.2), as in Fig 3.2 (N = 200000,
// U = 100, L = 1, ν̄ = 0.05), at the scale asked.
#include <fmt/format.h>

#include "reproduce/study.hpp"
#include "theory/steady_shear.hpp"

namespace granule::reproduce {

namespace {

constexpr const char* kRestitutions[] = {"0.6", "0.7", "0.8", "0.9"};

std::vector<RunGroup> chapter3_runs(Scale scale) {
  return {{"restitution", fmt::format(R"(seed = 3
[system]
particles = {0}
area_fraction = 0.05
tc_duration = 1e-7   # TC model against inelastic collapse (thesis: none)
[boundary]
kind = "lees-edwards"
shear_velocity = 100.0
[initial]
temperature_over_steady = 1.0   # start near the steady state, as §3.1.1 requires for the stripwise state
equilibrate = 5
[run]
until_collisions_per_particle = {1}
[output]
every_collisions_per_particle = 2
[sweep]
system.restitution = [{2}]
seeds = {3}
)",
                                      by_scale(scale, 400, 2000, 20000, 200000), by_scale(scale, 30, 200, 200, 200),
                                      fmt::join(kRestitutions, ", "), by_scale(scale, 1, 3, 3, 1))}};
}

StudyOutcome evaluate_chapter3(Scale, const StudyOutputs& outputs) {
  StudyOutcome out;
  const GroupOutputs& group = outputs.at("restitution");
  FigureSeries measured{"Granule T̄", {}, {}, {}, false}, fit{"(3.1) Tan's fit", {}, {}, {}, true},
      jr{"(3.2) Jenkins–Richman", {}, {}, {}, true};
  double gamma = 0.0, diameter = 0.0, nu = 0.0;
  int particles = 0;
  for (const char* restitution : kRestitutions) {
    const double e = std::stod(restitution);
    std::vector<double> temperatures;
    for (const PointOutputs* p : points_with(group, "system.restitution", restitution)) {
      temperatures.push_back(summary_number(*p, "steady_shear.temperature_measured"));
      gamma = summary_number(*p, "shear_velocity") / summary_number(*p, "box.1");
      diameter = summary_number(*p, "diameter");
      nu = summary_number(*p, "area_fraction");
      particles = static_cast<int>(summary_number(*p, "particles"));
    }
    const Estimate t = mean_over(temperatures);
    measured.x.push_back(e);
    measured.y.push_back(t.mean);
    measured.error.push_back(t.error);
    Claim claim = estimate_claim(
        fmt::format("chapter3.steady_temperature_fit.e={}", restitution),
        fmt::format("steady T̄ of simple shear at ẽ = {} follows the thesis's fit (3.1), A = 0.080, B = −0.54", restitution),
        "thesis (3.1), §3.1.1, Fig 3.2", theory::steady_shear_temperature_tan_fit(e, gamma, diameter, nu), t, 0.10,
        "(3.1) is a two-constant fit the thesis calls close, given to two digits; its scatter is not stated",
        fmt::format("summary steady_shear.temperature_measured (T̄ over cells with u(y) removed, second half of the run), "
                    "{} seed(s) of N = {}, U = 100, ν̄ = 0.05",
                    t.count, particles));
    out.claims.push_back(claim);
  }
  for (double e = 0.55; e <= 0.951; e += 0.01) {
    fit.x.push_back(e);
    fit.y.push_back(theory::steady_shear_temperature_tan_fit(e, gamma, diameter, nu));
    jr.x.push_back(e);
    jr.y.push_back(theory::steady_shear_temperature_jenkins_richman(e, gamma, diameter, nu));
  }
  out.figures.push_back(
      {"chapter3_T_against_e",
       "Fig 3.2",
       "The average temperature T̄ versus ẽ (thesis: N = 200000, U = 100, L_x = L_y = 1, ν̄ = 0.05), with (3.1) and (3.2)",
       "restitution ẽ",
       "T̄",
       false,
       true,
       {fit, jr, measured}});
  if (particles != 200000) {
    out.notes.push_back(
        fmt::format("Chapter 3 runs N = {} instead of the thesis's 200000: the box holds fewer cluster separations L0, "
                    "which changes the microstructure (§3.1.2, Systems III/IV) and may change T̄.",
                    particles));
  }
  return out;
}

}  // namespace

Study chapter3_study() {
  return {"chapter3",
          "Steady simple shear: T̄ against ẽ",
          "Chapter 3 (thesis §3.1.1, (3.1), (3.2), Fig 3.2)",
          chapter3_runs,
          evaluate_chapter3,
          {}};
}

}  // namespace granule::reproduce
