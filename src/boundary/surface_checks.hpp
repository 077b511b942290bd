// What the engine's invariant checks (engine/simulation_checks.cpp) ask of the surfaces a grain can
// hit — the walls at the box's faces, the fixed obstacles and the grains at rest — so that the checks name no kind of
// surface: a new kind answers these questions here.  Each answer follows the test its hit search
// makes (boundary/moving_wall_hit.hpp, boundary/obstacle_hit.hpp): the round-off it allows is the
// round-off the checks allow.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>

#include "boundary/box_boundaries.hpp"

namespace granule {

// A surface a grain reaches into.
struct SurfaceOverlap {
  SurfaceId surface;  // none found: not found()
  double depth = 0.0;  // beyond the round-off allowed
};

// The first surface that a grain of radius `radius` in cell `cell`, at r at production time t,
// reaches into by more than round-off: `tolerance` of the box's length for a wall, of the contact
// distance for a round surface (an obstacle, a grain at rest).
template <int D>
SurfaceOverlap surface_overlap(const BoxBoundaries<D>& b, std::int32_t cell, const Vec<D>& r, double radius,
                               double tolerance, double t) {
  for (int axis = 0; axis < D; ++axis) {
    if (b.has_images(axis)) continue;
    const double inside = radius - tolerance * b.length(axis);
    const double below = inside + b.displacement(2 * axis, t) - r[axis];
    const double above = r[axis] - (b.length(axis) - inside - b.displacement(2 * axis + 1, t));
    if (below > 0.0 || above > 0.0) return {{2 * axis + (above > below ? 1 : 0), -1}, std::max(below, above)};
  }
  for (const int kind : {kObstacleSurface, kRestingGrainSurface}) {
    for (const auto& round : b.round_surfaces(kind, cell)) {
      const double depth = (round.radius + radius) * (1.0 - tolerance) - norm(r - round.centre);
      if (depth > 0.0) return {{kind, round.index}, depth};
    }
  }
  return {};
}

// How much later than a fresh search's a stored hit of `surface` may lie, beyond the round-off of
// its delay, for a grain of radius `radius` in cell `cell` that reaches r at v at production time
// `then`, under `gravity`.  Searches from different instants stop within a surface's tolerance of
// contact, that is within tolerance / closing speed of each other; a grain resting on a floor has
// a position known to a few ulps ε of L, which a parabola that barely leaves the floor closes in up
// to √(2ε/|g|) (seen: 2·10⁻¹³).
template <int D>
double surface_hit_slack(const BoxBoundaries<D>& b, int surface, std::int32_t cell, const Vec<D>& r, const Vec<D>& v,
                         double radius, double then, const std::array<double, 3>& gravity) {
  constexpr double kRoundOffUlps = 16.0;  // of a box length: a stored position after re-bases and flights
  if (surface < kObstacleSurface) {
    const int axis = surface / 2;
    if (b.moving(surface)) {
      const double closing = std::abs(moving_gap_rate(b.moving_plane(surface, radius), v[axis], then));
      return 2.0 * b.gap_tolerance(axis) / closing;
    }
    const double g = gravity[static_cast<std::size_t>(axis)];
    if (g == 0.0) return 0.0;
    return std::sqrt(2.0 * kRoundOffUlps * std::numeric_limits<double>::epsilon() * b.length(axis) / std::abs(g));
  }
  const double tolerance = b.round_tolerance(surface);
  double closing = std::numeric_limits<double>::infinity();
  for (const auto& round : b.round_surfaces(surface, cell)) {
    const Vec<D> d = r - round.centre;
    if (std::abs(norm(d) - round.radius - radius) <= 2.0 * tolerance) closing = std::abs(dot(d, v)) / norm(d);
  }
  return 2.0 * tolerance / closing;
}

// How far a grain is from touching the surface whose hit is about to be executed.
struct SurfaceHitGap {
  double gap = std::numeric_limits<double>::infinity();  // < 0: inside
  double allowed = 0.0;                                  // the round-off allowed either way
  SurfaceId surface;                                     // the surface measured
  bool may_fall_short = false;  // a search may have stopped short of contact: a positive gap is fine
};

// The gap of a grain of radius `radius` in cell `cell`, at r at production time t, to `surface`
// (for a round surface, to the nearest the cell lists); `tolerance` as in surface_overlap; `curved`:
// flights are parabolas, whose obstacle search may give up short of a contact.
template <int D>
SurfaceHitGap surface_hit_gap(const BoxBoundaries<D>& b, int surface, std::int32_t cell, const Vec<D>& r, double radius,
                              double tolerance, double t, bool curved) {
  SurfaceHitGap g;
  g.surface = {surface, -1};
  if (surface < kObstacleSurface) {
    const int axis = surface / 2;
    const double shift = b.displacement(surface, t);
    const double wall = surface % 2 == 0 ? shift : b.length(axis) - shift;
    g.gap = std::abs(r[axis] - wall) - radius;
    g.allowed = tolerance * b.length(axis);
    g.may_fall_short = b.moving(surface) && g.gap > 0.0;
    return g;
  }
  for (const auto& round : b.round_surfaces(surface, cell)) {
    const double gap = norm(r - round.centre) - round.radius - radius;
    if (std::abs(gap) < std::abs(g.gap)) {
      g.gap = gap;
      g.allowed = b.round_tolerance(surface) + tolerance * (round.radius + radius);
      g.surface = {surface, round.index};
    }
  }
  // A hit of a grain at rest may find it woken since (the hit is then stale, as a collision whose
  // partner has collided).
  g.may_fall_short = g.gap > 0.0 && (surface == kRestingGrainSurface || (std::isfinite(g.gap) && curved));
  return g;
}

}  // namespace granule
