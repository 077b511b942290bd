// Grains at rest: the rule that stops a grain bouncing ever lower on a static support, and wakes it
// when it is struck.  Without it a bed on a floor either collapses inelastically (infinitely many
// bounces in a finite time) or, under the TC model, micro-bounces at about one event per t_c per
// grain for as long as it rests.  With it a grain whose hit of a static support leaves it slower
// than `speed` (centre and contact points, |v| and |ω| a, both) while it leans on a static support
// below its centre (leans_on_support) is put at rest: it stops generating events and stands as a fixed support
// (boundary/resting_grains.hpp) until a grain strikes it at a normal speed above `wake_speed`,
// when it and every resting grain it carries move again.  Static supports are walls that neither
// move nor slide, obstacles, and grains at rest.  A hit that puts a grain at rest is perfectly
// inelastic: the support takes the grain's whole momentum and the kinetic energy left is
// dissipated, so momentum and energy budgets stay exact.  (The idea is the sleeping particles of
// DynamO, Bannerman et al. 2011; the support test, the wake rule and the floor's load are Granule's.)
#pragma once

#include <algorithm>
#include <cmath>
#include <span>

#include "geometry/vec.hpp"

namespace granule {

struct RestParams {
  double speed = 0.0;       // a grain slower than this after a hit of a static support may rest; 0: off
  double wake_speed = 0.0;  // a grain at rest struck at a larger normal speed moves again
  bool on() const { return speed > 0.0; }
};

// Whether a grain pulled along the unit vector `down` leans on a support: one of the directions
// `contacts` (unit vectors from its centre to its contact points with static supports) points below
// its centre, so that the support takes its weight.  Not whether it is balanced: a slow grain that
// touches supports on one side only is pressed into them by gravity and can only slide along them,
// which an event-driven engine resolves as ever shorter grazing bounces (the event rate of an
// inelastic collapse); it is put at rest where it is.  The rest speed bounds what that changes:
// such a grain would have slid a distance of order v_rest²/g before its speed passed v_rest.
template <int D>
bool leans_on_support(std::span<const Vec<D>> contacts, const Vec<D>& down, double tolerance) {
  return std::any_of(contacts.begin(), contacts.end(), [&](const Vec<D>& k_hat) { return dot(k_hat, down) > tolerance; });
}

}  // namespace granule
