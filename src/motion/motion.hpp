// The motion policy: how particles fly between events (ballistic, or in a uniform field), the one
// place that computes flights, their false positions at the clock base, and the roots of crossing
// and wall-hit times.  The engine dispatches on it (visit) and instantiates its hot loop (the
// neighbour scan) for each kind, so the plain gas pays nothing for the field.  The dispatch is a
// plain branch on the kind, not std::visit, which GCC 12 did not always inline (measured 2 % of a
// run at N = 10⁵ with the flight read through it at every event).
#pragma once

#include <array>

#include "geometry/vec.hpp"
#include "motion/ballistic.hpp"
#include "motion/uniform_field.hpp"

namespace granule {

template <int D>
class Motion {
 public:
  using Vector = Vec<D>;

  // Ballistic when every component of `acceleration` (x, y, z) is 0, else a uniform field.
  explicit Motion(const std::array<double, 3>& acceleration = {}) {
    for (int a = 0; a < D; ++a) field_.g[a] = acceleration[static_cast<std::size_t>(a)];
    in_field_ = acceleration[0] != 0.0 || acceleration[1] != 0.0 || acceleration[2] != 0.0;
  }

  // Calls f with the flight (Ballistic<D> or UniformField<D>), resolved at compile time inside f.
  template <typename F>
  decltype(auto) visit(F&& f) const {
    return in_field_ ? f(field_) : f(Ballistic<D>{});
  }

  Vector position_at(const Vector& r, const Vector& v, double t) const {
    return visit([&](const auto& flight) {
      Vector at;
      for (int a = 0; a < D; ++a) at[a] = flight.coordinate_at(a, r[a], v[a], t);
      return at;
    });
  }
  Vector velocity_at(const Vector& v, double t) const {
    return visit([&](const auto& flight) {
      Vector at;
      for (int a = 0; a < D; ++a) at[a] = flight.velocity_at(a, v[a], t);
      return at;
    });
  }
  // The base state (r, v) of a new flight through the position now (a delay t after the base) with
  // velocity `v_now`: the false position moves by the change of base velocity times t.
  void start_flight(Vector& r, Vector& v, const Vector& v_now, double t) const {
    visit([&](const auto& flight) {
      for (int a = 0; a < D; ++a) {
        const double v_base = flight.base_velocity(a, v_now[a], t);
        r[a] += (v[a] - v_base) * t;
        v[a] = v_base;
      }
    });
  }
  // The base state (r, v) of the flight that is at r with velocity v a delay t after the base.
  void base_state(Vector& r, Vector& v, double t) const {
    visit([&](const auto& flight) {
      for (int a = 0; a < D; ++a) {
        v[a] = flight.base_velocity(a, v[a], t);
        r[a] -= flight.coordinate_at(a, 0.0, v[a], t);
      }
    });
  }
  void advance_base(Vector& r, Vector& v, double t) const {
    visit([&](const auto& flight) {
      for (int a = 0; a < D; ++a) flight.advance_base(a, r[a], v[a], t);
    });
  }
 private:
  bool in_field_ = false;
  UniformField<D> field_;
};

}  // namespace granule
