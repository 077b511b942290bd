// boundary.wall_motion: one wall of a walled box moving normal to itself in production (a
// vibrated floor, a piston following a schedule; boundary/wall.hpp, WallMotion).
#pragma once

#include <string>

#include "io/config.hpp"
#include "io/config_reader.hpp"

namespace granule {

// Needs the walls resolved (resolve_walls).  `walls`: boundary.kind is "walls".
void resolve_wall_motion(const ConfigReader& in, bool walls, RunConfig& c);
// boundary.wall_motion as a TOML line of [boundary] (none when no wall moves).
std::string wall_motion_to_toml(const RunConfig& c);
// The faces' names in the configuration: "x0" for the wall at x = 0, "y1" for the wall at y = L_y …
std::string wall_face_name(int face);

}  // namespace granule
