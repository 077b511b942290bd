#include "io/export_xyz.hpp"

#include <fmt/format.h>

namespace granule {

void write_xyz_frame(std::ostream& out, const ParticleState& p, const XyzFrameInfo& info) {
  const bool three_dimensional = p.dimension == 3;
  fmt::memory_buffer buffer;
  // A 2D frame is a periodic plane in a cell of unit depth (pbc F along z); a 3D frame a periodic box.
  fmt::format_to(std::back_inserter(buffer),
                 "{}\nLattice=\"{} 0 0 0 {} 0 0 0 {}\" Properties=species:S:1:pos:R:3:velo:R:3:radius:R:1{} Time={} "
                 "collisions_per_particle={} boundary={} pbc=\"T T {}\"",
                 p.size(), info.length_x, info.length_y, three_dimensional ? info.length_z : 1.0,
                 p.rough() ? ":omega:R:3" : "", info.time,
                 info.collisions_per_particle, info.boundary, three_dimensional ? "T" : "F");
  if (info.boundary == "lees-edwards") {
    fmt::format_to(std::back_inserter(buffer), " shear_velocity={} shear_offset={}", info.shear_velocity, info.shear_offset);
  }
  buffer.push_back('\n');
  // fmt's shortest round-trip representation: exact doubles, no trailing digits.
  for (std::size_t i = 0; i < p.size(); ++i) {
    const double radius = 0.5 * p.diameter_of(i, info.diameter);
    if (three_dimensional) {
      fmt::format_to(std::back_inserter(buffer), "D {} {} {} {} {} {} {}", p.x[i], p.y[i], p.z[i], p.vx[i], p.vy[i], p.vz[i], radius);
    } else {
      fmt::format_to(std::back_inserter(buffer), "D {} {} 0 {} {} 0 {}", p.x[i], p.y[i], p.vx[i], p.vy[i], radius);
    }
    if (p.rough() && three_dimensional) {
      fmt::format_to(std::back_inserter(buffer), " {} {} {}", p.wx[i], p.wy[i], p.wz[i]);
    } else if (p.rough()) {
      fmt::format_to(std::back_inserter(buffer), " 0 0 {}", p.wz[i]);
    }
    buffer.push_back('\n');
    if (buffer.size() > (1u << 20)) {
      out.write(buffer.data(), static_cast<std::streamsize>(buffer.size()));
      buffer.clear();
    }
  }
  out.write(buffer.data(), static_cast<std::streamsize>(buffer.size()));
}

}  // namespace granule
