// Hand-built configurations for unit tests: one {x, y, vx, vy} row per disk.
#pragma once

#include <array>
#include <initializer_list>

#include "engine/system_params.hpp"

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

}  // namespace granule
