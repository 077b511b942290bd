// Hand-built configurations for unit tests: one {x, y, vx, vy} row per disk.
#pragma once

#include <array>
#include <initializer_list>

#include "engine/system_params.hpp"
#include "init/random.hpp"

namespace granule {

inline ParticleState particles_from_rows(std::initializer_list<std::array<double, 4>> rows) {
  ParticleState p;
  for (const auto& r : rows) {
    p.x.push_back(r[0]);
    p.y.push_back(r[1]);
    p.vx.push_back(r[2]);
    p.vy.push_back(r[3]);
  }
  return p;
}

// n disks placed uniformly at random in an L_x × L_y box, at rest.
inline ParticleState uniform_positions(Random& random, std::size_t n, double length_x, double length_y) {
  ParticleState s;
  s.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    s.x[i] = length_x * random.uniform();
    s.y[i] = length_y * random.uniform();
  }
  return s;
}

}  // namespace granule
