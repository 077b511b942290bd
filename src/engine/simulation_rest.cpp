// The engine's part of the rest rule (physics/rest_rule.hpp): which hit leaves a grain at rest, and
// moving grains in and out of the rest state.  A grain at rest keeps its record (its position, a
// zero velocity, the partner kAtRest) but leaves its cell list and the queue: it is listed by the
// boundaries as a fixed support (boundary/resting_grains.hpp), which moving grains hit as they hit
// an obstacle.
#include <cmath>
#include <limits>
#include <span>
#include <vector>

#include "engine/simulation.hpp"

namespace granule {

namespace {
inline std::size_t at(std::int32_t i) { return static_cast<std::size_t>(i); }
// A contact point below the centre by more than this fraction of the radius bears the grain's weight
// (a side wall's contact, at the centre's height, bears none).
constexpr double kBelowTolerance = 1e-9;
}  // namespace

template <int D>
Vec<D> Simulation<D>::down() const {
  Vector g;
  for (int a = 0; a < D; ++a) g[a] = params_.gravity[static_cast<std::size_t>(a)];
  const double magnitude = norm(g);
  return magnitude > 0.0 ? (1.0 / magnitude) * g : g;
}

template <int D>
double Simulation<D>::support_gap() const {
  Vector g;
  for (int a = 0; a < D; ++a) g[a] = params_.gravity[static_cast<std::size_t>(a)];
  // A grain bouncing at the rest speed stays within v²/(2|g|) of its support; twice that, and never
  // less than round-off of a contact distance.
  return params_.rest.speed * params_.rest.speed / norm(g) + 1e-9 * params_.diameter;
}

template <int D>
double Simulation<D>::sliding_lift(const Vector& velocity, const Vector& k_hat) const {
  Vector g;
  for (int a = 0; a < D; ++a) g[a] = params_.gravity[static_cast<std::size_t>(a)];
  const double pressed = dot(g, k_hat);  // gravity into the support
  if (!(pressed > 0.0) || params_.tc_duration == 0.0) return 0.0;
  const double leaving = -dot(velocity, k_hat);
  const double least = pressed * params_.tc_duration;
  return leaving < least ? least - leaving : 0.0;
}

template <int D>
SurfaceId Simulation<D>::wedging_support(std::int32_t i, const Vector& velocity, const SurfaceId& struck) const {
  SurfaceId wedge;
  boundaries_.for_each_static_support(slot(i).cell(), position_now(i), radius_of(i), support_gap(), [&](const Vector& k_hat, SurfaceId s) {
    const bool other = s.kind != struck.kind || s.index != struck.index;
    if (other && !wedge.found() && dot(velocity, k_hat) > 0.0 && (s.resting_grain() >= 0 || struck.resting_grain() >= 0)) wedge = s;
  });
  // Between a wall and a grain at rest, the grain at rest moves.
  if (wedge.found() && wedge.resting_grain() < 0) wedge = struck;
  return wedge;
}

template <int D>
bool Simulation<D>::leans_on_static_support(std::int32_t i, const Vector& r) const {
  constexpr std::size_t kMostSupports = 16;
  std::array<Vector, kMostSupports> contacts;
  std::size_t n = 0;
  boundaries_.for_each_static_support(slot(i).cell(), r, radius_of(i), support_gap(), [&](const Vector& k_hat, SurfaceId s) {
    if (n < kMostSupports && s.resting_grain() != i) contacts[n++] = k_hat;
  });
  return leans_on_support<D>(std::span<const Vector>(contacts.data(), n), down(), kBelowTolerance);
}

template <int D>
bool Simulation<D>::comes_to_rest(std::int32_t i, const SurfaceHit<D>& hit) const {
  const double speed = params_.rest.speed;
  if (norm(hit.side.velocity) >= speed) return false;
  if (hit.side.spins() && std::sqrt(spin_norm2(hit.side.spin)) * radius_of(i) >= speed) return false;
  return leans_on_static_support(i, position_now(i));
}

template <int D>
void Simulation<D>::put_at_rest(std::int32_t i) {
  const Vector r = position_now(i);
  ParticleRecord<D>& p = particles_[at(i)];
  p.r = r;
  p.v = {};
  p.partner = kAtRest;
  if (!spin_[0].empty()) set_spin(i, {});
  lists_.remove(particles_, i, slot(i).cell());
  slot(i).set_kind(EventKind::kNone);
  queue_.update(i, std::numeric_limits<double>::infinity());
  boundaries_.rest_grain(i, r, radius_of(i));
  // Its pairs with its neighbours were covered by its own event, which it no longer has: they are
  // predicted again, and find it as a support.
  for_each_neighbour(i, [&](std::int32_t k, const Vector&, double) { predict(k); });
  // Fewer grains move: the pace of events the collapse detector compares with changes.
  collapse_detector_.reset(collapse_window(), t_now_);
  if (!observers_.empty()) {
    const RestRecord<D> record{time(), user_id(i), r, mass_of(i), true};
    for (EventObserver<D>* observer : observers_) observer->on_rest_change(record);
  }
}

template <int D>
void Simulation<D>::wake(std::int32_t j) {
  const Vector g_hat = down();
  std::vector<std::int32_t> woken{j};
  for (std::size_t k = 0; k < woken.size(); ++k) {
    const std::int32_t w = woken[k];
    if (!at_rest(w)) continue;  // listed twice (through an image), already woken
    ParticleRecord<D>& p = particles_[at(w)];
    const Vector r = p.r;
    const double radius = radius_of(w);
    boundaries_.wake_grain(w, r, radius);
    p.partner = -1;
    ++p.count;
    motion_.base_state(p.r, p.v, t_now_);  // from rest, now
    slot(w).set_cell(cell_of(r));
    lists_.insert(particles_, w, slot(w).cell());
    // The grains at rest it carried fall with it, those touching it from above that lean on no
    // other static support.
    boundaries_.for_each_static_support(slot(w).cell(), r, radius, support_gap(), [&](const Vector& k_hat, SurfaceId s) {
      const std::int32_t above = s.resting_grain();
      if (above >= 0 && dot(k_hat, g_hat) < 0.0 && !leans_on_static_support(above, particles_[at(above)].r)) {
        woken.push_back(above);
      }
    });
    if (!observers_.empty()) {
      const RestRecord<D> record{time(), user_id(w), r, mass_of(w), false};
      for (EventObserver<D>* observer : observers_) observer->on_rest_change(record);
    }
  }
  for (const std::int32_t w : woken) predict(w);
  collapse_detector_.reset(collapse_window(), t_now_);
}

template Vec<2> Simulation<2>::down() const;
template double Simulation<2>::sliding_lift(const Vec<2>&, const Vec<2>&) const;
template double Simulation<2>::support_gap() const;
template bool Simulation<2>::leans_on_static_support(std::int32_t, const Vec<2>&) const;
template SurfaceId Simulation<2>::wedging_support(std::int32_t, const Vec<2>&, const SurfaceId&) const;
template bool Simulation<2>::comes_to_rest(std::int32_t, const SurfaceHit<2>&) const;
template void Simulation<2>::put_at_rest(std::int32_t);
template void Simulation<2>::wake(std::int32_t);
template Vec<3> Simulation<3>::down() const;
template double Simulation<3>::sliding_lift(const Vec<3>&, const Vec<3>&) const;
template double Simulation<3>::support_gap() const;
template bool Simulation<3>::leans_on_static_support(std::int32_t, const Vec<3>&) const;
template SurfaceId Simulation<3>::wedging_support(std::int32_t, const Vec<3>&, const SurfaceId&) const;
template bool Simulation<3>::comes_to_rest(std::int32_t, const SurfaceHit<3>&) const;
template void Simulation<3>::put_at_rest(std::int32_t);
template void Simulation<3>::wake(std::int32_t);

}  // namespace granule
