// Chapter 4's histories (thesis §4.2–4.3, Figs 4.5–4.8): one sheared gas, six ways of bringing it to
// its steady state, and the runs of each (reproduce/chapter4.cpp judges the states they reach).
#pragma once

#include <cmath>
#include <string>
#include <vector>

#include "reproduce/study.hpp"

namespace granule::reproduce::chapter4 {

inline constexpr double kRestitution = 0.6;  // Fig 4.5's system, as every history of §4.2–4.3
inline constexpr int kThesisParticles = 20000;

// The ramp U = U₀(1 − e^{−t/τ}) (Figs 4.7–4.8) has reached its final value, within 1 %, at
// t = τ ln 100.  Fig 4.8 shows the plug "after long times" and the text says it "persists": it is
// judged after that time, in a run twice as long; while U still rises it is reported in a note.
inline constexpr double kRampTime = 0.5;
inline const double kRampReached = kRampTime * std::log(100.0);

// One history: its run group and how it differs from the cold start.
struct History {
  const char* group;
  std::string name;
  // [boundary] and [initial] lines of the history (the shear velocity or its protocol included).
  std::string boundary, initial;
  double protocol_end_t = 0.0;  // the protocol's forcing has ended by this time (kick, step, ramp)
  double length = 1.0;          // the run's c_end in units of the others'
  double until_t = 0.0;         // > 0: the run ends at this time instead (the ramp)
};

// The histories at `scale`: cold, hot, ramp, kick, kick_small, step.
std::vector<History> histories(Scale scale);

// A run group per history.
std::vector<RunGroup> chapter4_runs(Scale scale);

}  // namespace granule::reproduce::chapter4
