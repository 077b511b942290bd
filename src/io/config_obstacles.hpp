// [[obstacles]]: fixed disks or spheres in the box (boundary/obstacle.hpp), each entry one obstacle
// (centre, diameter) or a CSV file of them (file: rows x, y[, z], diameter), with its normal and
// tangential restitution.  Refused under Lees–Edwards images (the images slide past the obstacle).
#pragma once

#include <string>
#include <toml++/toml.h>

#include "io/config.hpp"

namespace granule {

// Needs the geometry, the boundary kind and the shear resolved.
void resolve_obstacles(const toml::table& root, RunConfig& c);
// The obstacles as [[obstacles]] tables, one per obstacle (none without obstacles).
std::string obstacles_to_toml(const RunConfig& c);
// The obstacles of a CSV file: a header naming x, y[, z] and diameter, one obstacle per row.
// Throws ConfigError naming the file, line and column.
std::vector<Obstacle> read_obstacle_csv(const std::string& path, int dimension);

}  // namespace granule
