#include "io/export_xyz.hpp"

#include <fmt/format.h>

namespace granule {

void write_xyz_frame(std::ostream& out, const ParticleState& p, const XyzFrameInfo& info) {
  fmt::memory_buffer buffer;
  fmt::format_to(std::back_inserter(buffer),
                 "{}\nLattice=\"{} 0 0 0 {} 0 0 0 1\" Properties=species:S:1:pos:R:3:velo:R:3:radius:R:1 Time={} "
                 "collisions_per_particle={} boundary={} pbc=\"T T F\"",
                 p.size(), info.length_x, info.length_y, info.time, info.collisions_per_particle, info.boundary);
  if (info.boundary == "lees-edwards") {
    fmt::format_to(std::back_inserter(buffer), " shear_velocity={} shear_offset={}", info.shear_velocity, info.shear_offset);
  }
  buffer.push_back('\n');
  const double radius = 0.5 * info.diameter;
  // fmt's shortest round-trip representation: exact doubles, no trailing digits.
  for (std::size_t i = 0; i < p.size(); ++i) {
    fmt::format_to(std::back_inserter(buffer), "D {} {} 0 {} {} 0 {}\n", p.x[i], p.y[i], p.vx[i], p.vy[i], radius);
    if (buffer.size() > (1u << 20)) {
      out.write(buffer.data(), static_cast<std::streamsize>(buffer.size()));
      buffer.clear();
    }
  }
  out.write(buffer.data(), static_cast<std::streamsize>(buffer.size()));
}

}  // namespace granule
