// The flat walls of [boundary] (kind = "walls") and the uniform gravity of [system]
// (ARCHITECTURE.md, "Spin, walls and gravity"): which axes end in walls, each wall's normal and
// tangential restitution, the wall velocities of a wall-driven shear, g, and the rule that puts
// grains at rest on static supports.
#pragma once

#include <string>

#include "io/config.hpp"
#include "io/config_reader.hpp"

namespace granule {

// Needs the geometry resolved (dimension, box, largest diameter).  `walls`: boundary.kind is
// "walls"; otherwise every wall key is an error.
void resolve_walls(const ConfigReader& in, bool walls, RunConfig& c);
// A wall-driven shear U: the y walls move along x at −U/2 (at y = 0) and +U/2 (at y = L_y).
void set_wall_shear(SystemParams& s, double shear_velocity);
// The wall keys of [boundary] as TOML lines (none without walls).
std::string walls_to_toml(const RunConfig& c);

// Needs the dimension and the boundary kind resolved (gravity along y is refused with Lees–Edwards).
void resolve_gravity(const ConfigReader& in, RunConfig& c);
// system.gravity as a TOML line of [system] (none without gravity).
std::string gravity_to_toml(const RunConfig& c);
// Grains at rest on static supports (physics/rest_rule.hpp): system.rest_speed and wake_speed.
// Needs gravity resolved.
void resolve_rest(const ConfigReader& in, RunConfig& c);
std::string rest_to_toml(const RunConfig& c);

}  // namespace granule
