// The boundaries of the box, one per axis: the one place that knows what lies beyond each face —
// the periodic image (x, z), the Lees–Edwards image sliding at U (y, thesis §1.4.2; U = 0 is plainly
// periodic), or a flat wall at each end (thesis Appendix A.1).  It answers, for the engine, every
// question that depends on it: where the image across a face sits and how fast it moves, whether a
// cell at the edge of the grid has neighbours beyond it, the nearest image of a partner, how a
// position is wrapped into the box, when a grain hits a surface — a wall, a fixed obstacle, which
// may stand anywhere, or a grain at rest — and what the contact is, and what entering from an image
// does.
// Flow along x, gradient along y, z plainly periodic (boundary/shear_frame.hpp).
#pragma once

#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <span>
#include <vector>

#include "boundary/moving_wall_hit.hpp"
#include "boundary/obstacle_hit.hpp"
#include "boundary/obstacle_lists.hpp"
#include "boundary/periodic_wrap.hpp"
#include "boundary/resting_grains.hpp"
#include "boundary/shear_frame.hpp"
#include "boundary/surface_id.hpp"
#include "boundary/surface_set.hpp"
#include "boundary/wall.hpp"
#include "geometry/vec.hpp"

namespace granule {

enum class AxisBoundary : std::uint8_t {
  kPeriodic,     // x and z without walls
  kLeesEdwards,  // y without walls: images above and below slide at ±U (U may be 0)
  kWalls,        // a flat wall at 0 and one at L
};

template <int D>
class BoxBoundaries {
 public:
  using Vector = Vec<D>;

  // Where the box's image one period away across a face sits relative to the box, and how fast its
  // particles move along x relative to their originals.
  struct FaceImage {
    Vector position;
    double velocity_x = 0.0;
  };
  // The image of a partner nearest to a particle: which vertical image (−1, 0, +1) and its shift.
  struct PartnerImage {
    int image_y = 0;
    FaceImage shift;
  };

  BoxBoundaries() = default;
  // Walls on the axes `surfaces.walls` marks (faces 2·axis + side, side 0 at 0 and 1 at L), periodic
  // or Lees–Edwards images elsewhere, and the obstacles, listed by the engine's cells `cells`
  // (ObstacleLists) for grains of radius at most `largest_grain_radius`; `frame` holds L_x, L_y and
  // the present image velocity.
  BoxBoundaries(const SurfaceSet& surfaces, const ShearFrame& frame, double length_z, const CellLayout& cells,
                double largest_grain_radius)
      : frame_(frame), length_{frame.length_x, frame.length_y, length_z} {
    std::array<bool, 3> images{};
    for (int a = 0; a < D; ++a) {
      kind_[static_cast<std::size_t>(a)] = surfaces.walls[static_cast<std::size_t>(a)] ? AxisBoundary::kWalls
                                           : a == 1                                    ? AxisBoundary::kLeesEdwards
                                                                                       : AxisBoundary::kPeriodic;
      walled_ = walled_ || !has_images(a);
      images[static_cast<std::size_t>(a)] = has_images(a);
    }
    obstacle_lists_ = ObstacleLists<D>(surfaces.obstacles, cells, images, length_, largest_grain_radius);
    obstacles_ = surfaces.obstacles;
    if (surfaces.grains_rest) resting_ = RestingGrains<D>(cells, images, length_, largest_grain_radius);
    set_surfaces(surfaces);
  }

  const ObstacleLists<D>& obstacle_lists() const { return obstacle_lists_; }
  // The round surfaces of `kind` (boundary/surface_id.hpp) a grain in `cell` can touch.
  std::span<const RoundSurface<D>> round_surfaces(int kind, std::int32_t cell) const {
    return kind == kObstacleSurface ? obstacle_lists_.in_cell(cell) : resting_.in_cell(cell);
  }
  double round_tolerance(int kind) const {
    return kind == kObstacleSurface ? obstacle_lists_.tolerance() : resting_.tolerance();
  }
  // The grains at rest (physics/rest_rule.hpp): engine particle `particle` of radius `radius`
  // stands at `centre` as a fixed support, or moves again.
  void rest_grain(std::int32_t particle, const Vec<D>& centre, double radius) { resting_.add(particle, centre, radius); }
  void wake_grain(std::int32_t particle, const Vec<D>& centre, double radius) { resting_.remove(particle, centre, radius); }
  RestingGrains<D>& resting_grains() { return resting_; }
  const RestingGrains<D>& resting_grains() const { return resting_; }
  // Calls visit(k̂, surface) for every static support a grain of radius `radius` in cell `cell`
  // at r touches within a gap of `tolerance` — a wall that neither moves nor slides,
  // an obstacle, a grain at rest —, k̂ from the grain's centre to the contact.
  template <typename Visit>
  void for_each_static_support(std::int32_t cell, const Vector& r, double radius, double tolerance, Visit&& visit) const {
    for (int face = 0; face < 2 * D; ++face) {
      const int axis = face / 2;
      if (has_images(axis) || moving(face) || driven_[static_cast<std::size_t>(face)] || norm(wall_velocity(face, 0.0)) != 0.0) continue;
      const double gap = face % 2 == 0 ? r[axis] - radius : length(axis) - radius - r[axis];
      if (gap <= tolerance) visit(wall_normal(face), SurfaceId{face, -1});
    }
    for (const int kind : {kObstacleSurface, kRestingGrainSurface}) {
      for (const auto& round : round_surfaces(kind, cell)) {
        const Vector d = round.centre - r;
        const double distance = norm(d);
        if (distance - (round.radius + radius) <= tolerance && distance > 0.0) visit((1.0 / distance) * d, SurfaceId{kind, round.index});
      }
    }
  }
  // The memory its lists of surfaces by cell take.
  std::size_t bytes() const { return obstacle_lists_.bytes() + resting_.bytes(); }

  AxisBoundary kind(int axis) const { return kind_[static_cast<std::size_t>(axis)]; }
  // Whether the grid has neighbours beyond its faces along `axis` (no: walls).
  bool has_images(int axis) const { return kind(axis) != AxisBoundary::kWalls; }
  // Whether images along `axis` move relative to the box (Lees–Edwards): a grain entering from
  // one changes its velocity, and observers are told (EventObserver::on_boundary_crossing).
  bool moving_images(int axis) const { return kind(axis) == AxisBoundary::kLeesEdwards; }
  // Whether the x images are sheared, that is x and y both have images (the grid then follows the
  // flow in ξ = x − s (y − L_y/2)).
  bool sheared() const { return has_images(0) && has_images(1); }
  double length(int axis) const { return length_[static_cast<std::size_t>(axis)]; }
  const ShearFrame& frame() const { return frame_; }
  // The image velocity U from now on (the shear protocol's present segment).
  void set_image_velocity(double velocity) { frame_.shear_velocity = velocity; }
  double& image_velocity() { return frame_.shear_velocity; }
  double image_velocity() const { return frame_.shear_velocity; }
  const WallParams& wall(int face) const { return wall_[static_cast<std::size_t>(face)]; }
  // New parameters of the same surfaces (those of production: restitutions, the walls' drives; the
  // places stay).
  void set_surfaces(const SurfaceSet& surfaces) {
    for (std::size_t k = 0; k < obstacles_.size(); ++k) {
      obstacles_[k].restitution = surfaces.obstacles[k].restitution;
      obstacles_[k].tangential_restitution = surfaces.obstacles[k].tangential_restitution;
    }
    wall_ = surfaces.wall;
    for (std::size_t face = 0; face < 6; ++face) {
      const WallParams& w = wall_[face];
      along_[face] = ShearProtocol(w.velocity[static_cast<std::size_t>(w.along_axis)], w.along);
      driven_[face] = !along_[face].constant();
      normal_[face] = w.motion.velocity();
      moves_[face] = w.motion.moves() && !has_images(static_cast<int>(face / 2));
    }
  }
  // The walls follow their drives from production time 0 on; before (the elastic pre-run) they
  // rest at their faces and slide at their steady velocities.
  void set_drives_running(bool running) { drives_running_ = running; }
  bool moving(int face) const { return drives_running_ && moves_[static_cast<std::size_t>(face)]; }

  // The image across the face of `axis` in `direction` (±1) at strain s; an axis with images only.
  FaceImage image_across(int axis, int direction, double strain) const {
    FaceImage image{};
    if (axis == 1) {
      const ImageShift shift = frame_.image_shift(0, direction, strain);
      image.position[0] = shift.position.x;
      image.position[1] = shift.position.y;
      image.velocity_x = shift.velocity_x;
    } else {
      image.position[axis] = direction * length(axis);
    }
    return image;
  }

  // The nearest image of a partner at lab offset `offset`, in the sheared frame; unambiguous
  // because cells are at least as large as a contact pair (cells/cell_grid.hpp).  None across walls.
  PartnerImage nearest_image(const Vector& offset, double strain) const {
    const double lx = length(0);
    const double ly = length(1);
    const double dx = offset[0];
    const double dy = offset[1];
    const int iy = !has_images(1) ? 0 : (dy > 0.5 * ly ? -1 : (dy < -0.5 * ly ? 1 : 0));
    const ImageShift row = frame_.image_shift(0, iy, strain);
    FaceImage shift{};
    shift.position[0] = row.position.x;
    shift.position[1] = row.position.y;
    shift.velocity_x = row.velocity_x;
    const double dxi = (dx + shift.position[0]) - strain * (dy + shift.position[1]);
    if (has_images(0)) shift.position[0] -= lx * std::round(dxi / lx);
    if constexpr (D == 3) {
      if (has_images(2)) shift.position[2] = -length(2) * std::round(offset[2] / length(2));
    }
    return {iy, shift};
  }

  // A lab position (and its v_x) mapped into the box by the image rules, at strain s; idempotent
  // inside.  Wall axes are never wrapped: a grain's centre stays a radius inside them.
  void wrap_into_box(Vector& r, double& vx, double strain) const {
    if (has_images(1)) {
      frame_.wrap_into_box(r[0], r[1], vx, strain);  // x walls leave x inside: the wrap does not move it
    } else if (has_images(0)) {
      wrap_periodic(r[0], length(0));
    }
    if constexpr (D == 3) {
      if (has_images(2)) wrap_periodic(r[2], length(2));
    }
  }
  // The same, and x then into [0, L_x) in the sheared abscissa ξ, where the cell grid lives.
  void wrap_into_grid(Vector& r, double& vx, double strain) const {
    wrap_into_box(r, vx, strain);
    if (has_images(1)) r[0] -= length(0) * std::floor(frame_.sheared_x(r[0], r[1], strain) / length(0));
  }

  // The earliest surface contact of a grain of radius `radius()` in cell `cell`, now at r moving at
  // v on `flight` (motion/motion.hpp), if earlier than `best`: its delay into `best` and the surface
  // into `surface`.  Contact with a wall is when the centre is one radius from it; `now` is the
  // production time (where the moving walls are).  The obstacles are those the cell lists, searched
  // up to `best` (the grain's leaving the cell, at the latest).
  template <typename Flight, typename Radius>
  void earliest_surface_hit(const Flight& flight, std::int32_t cell, const Vector& r, const Vector& v, Radius&& grain_radius,
                            double now, double& best, int& surface) const {
    if (walled_) {
      const double radius = grain_radius();
      for (int axis = 0; axis < D; ++axis) {
        if (has_images(axis)) continue;
        for (int side = 0; side < 2; ++side) {
          const int f = 2 * axis + side;
          double t = moving(f) ? moving_wall_hit(flight, axis, r[axis], v[axis], moving_plane(f, radius), now, best,
                                                 gap_tolerance(axis))
                     : side == 0 ? flight.time_to_plane(axis, r[axis], v[axis], radius, -1)
                                 : flight.time_to_plane(axis, r[axis], v[axis], length(axis) - radius, +1);
          if (t == 0.0 && !moving(f)) t = return_to_wall(flight, axis, side, v[axis], now);
          if (t < best) {
            best = t;
            surface = f;
          }
        }
      }
    }
    if (obstacle_lists_.empty() && resting_.count() == 0) return;
    for (const int kind : {kObstacleSurface, kRestingGrainSurface}) {
      for (const auto& round : round_surfaces(kind, cell)) {
        const double t = obstacle_hit<D>(flight, r - round.centre, v, round.radius + grain_radius(), now, best, round_tolerance(kind));
        if (t < best) {
          best = t;
          surface = kind;
        }
      }
    }
  }
  // A grain found beyond a static wall's contact plane by round-off is hit now if it moves into the
  // wall.  Moving away from it — a bounce so slow that the plane's round-off exceeds its rise (a
  // grain set moving from rest) — it is not: its hit would find it moving away, and be found again,
  // forever.  Gravity towards the wall brings it back to the plane's level after 2|v_n|/g_n, or one
  // tick of the clock when it does not move, and it is hit then.
  template <typename Flight>
  static double return_to_wall(const Flight& flight, int axis, int side, double velocity, double now) {
    const double into = side == 0 ? -1.0 : 1.0;
    const double v_in = into * velocity;
    if (v_in > 0.0) return 0.0;
    const double g_in = into * 2.0 * flight.half_acceleration(axis);
    if (!(g_in > 0.0)) return std::numeric_limits<double>::infinity();
    return clock_moves_on(now, 0.0, -2.0 * v_in / g_in);
  }
  // A grain's contact with a surface, as its hit's execution sees it.
  struct SurfaceContact {
    bool touching = false;  // touching it and moving into it: else nothing happens
    Vector k_hat;           // from the grain's centre into the surface
    Vector velocity;        // the surface's (where the grain touches it)
    double restitution = 1.0;
    double tangential_restitution = -1.0;
    SurfaceId surface;
    // A grain at rest: the grains' own collision law applies, with the grain at rest as a body of
    // infinite mass.
    bool grain = false;
  };
  // Whether the grain of radius `radius` in cell `cell`, at r moving at v at production time `now`,
  // touches `surface` while moving into it, by the test its search made (a grain that no longer
  // moves into it, or that a search stopped short of, is left alone); the hit of a round surface
  // finds it again as the one nearest contact, of those the cell lists that the grain touches
  // while moving into them.
  SurfaceContact contact(int surface, std::int32_t cell, const Vector& r, const Vector& v, double radius, double now) const {
    SurfaceContact c;
    if (surface < kObstacleSurface) {
      c.surface = {surface, -1};
      const int axis = surface / 2;
      c.k_hat = wall_normal(surface);
      if (moving(surface)) {
        const MovingPlane plane = moving_plane(surface, radius);
        c.touching = moving_gap(plane, r[axis], now) <= gap_tolerance(axis) && moving_gap_rate(plane, v[axis], now) < 0.0;
      } else {
        c.touching = dot(v, c.k_hat) > 0.0;
      }
      c.velocity = wall_velocity(surface, now);
      c.restitution = wall(surface).restitution;
      c.tangential_restitution = wall(surface).tangential_restitution;
      return c;
    }
    // Of those it touches while moving into them, the nearest: a grain in a pocket touches two.
    double nearest = std::numeric_limits<double>::infinity();
    const RoundSurface<D>* touched = nullptr;
    for (const auto& round : round_surfaces(surface, cell)) {
      const double gap = std::abs(norm(r - round.centre) - (round.radius + radius));
      if (gap < nearest && touches_obstacle<D>(r - round.centre, v, round.radius + radius, round_tolerance(surface))) {
        nearest = gap;
        touched = &round;
      }
    }
    if (touched == nullptr) return c;
    c.touching = true;
    c.k_hat = (1.0 / norm(touched->centre - r)) * (touched->centre - r);
    c.surface = {surface, touched->index};
    c.grain = surface == kRestingGrainSurface;
    if (!c.grain) {
      const Obstacle& o = obstacles_[static_cast<std::size_t>(touched->index)];
      c.restitution = o.restitution;
      c.tangential_restitution = o.tangential_restitution;
    }
    return c;
  }
  // The contact plane of a moving wall for a grain of radius `radius` (boundary/moving_wall_hit.hpp).
  MovingPlane moving_plane(int face, double radius) const {
    const auto f = static_cast<std::size_t>(face);
    return {face % 2 == 0 ? radius : length(face / 2) - radius, face % 2 == 0 ? 1 : -1, wall_[f].motion.reach(), &normal_[f]};
  }
  // The gap within which a grain touches a moving wall: round-off of a coordinate of the box.
  double gap_tolerance(int axis) const { return 1e-12 * length(axis); }
  // The displacement h into the box of the wall at `face` at production time t.
  double displacement(int face, double t) const {
    return moving(face) ? normal_[static_cast<std::size_t>(face)].integral(0.0, t) : 0.0;
  }
  // The unit normal of a face, from a grain touching it towards the wall.
  static Vector wall_normal(int face) {
    Vector k_hat;
    k_hat[face / 2] = face % 2 == 0 ? -1.0 : 1.0;
    return k_hat;
  }
  // The velocity of the wall at `face` at production time t: along itself, and normal to itself
  // when it moves.
  Vector wall_velocity(int face, double t) const {
    const auto f = static_cast<std::size_t>(face);
    Vector v;
    for (int a = 0; a < D; ++a) v[a] = wall(face).velocity[static_cast<std::size_t>(a)];
    if (drives_running_ && driven_[f]) v[wall_[f].along_axis] = along_[f].velocity(t);
    if (moving(face)) v[face / 2] = (face % 2 == 0 ? 1.0 : -1.0) * normal_[f].velocity(t);
    return v;
  }

 private:
  // What every prediction reads first, together; the walls' parameters and drives after them.
  std::array<AxisBoundary, D> kind_{};
  bool walled_ = false;  // some axis has walls
  bool drives_running_ = false;
  std::array<bool, 6> driven_{}, moves_{};
  ShearFrame frame_;
  std::array<double, 3> length_{1.0, 1.0, 1.0};
  std::array<WallParams, 6> wall_{};
  // Per face: the tangential drive and the normal velocity dh/dt, as protocols of time.
  std::array<ShearProtocol, 6> along_{}, normal_{};
  ObstacleLists<D> obstacle_lists_;
  std::vector<Obstacle> obstacles_;  // their restitutions in force
  RestingGrains<D> resting_;
};

}  // namespace granule
