// Output of the collision statistics (schema in README.md, "collisions.h5"): impact parameters
// (3.19)–(3.21) and free paths (3.22)–(3.24), (3.36), with their summaries; plus the natural
// tables as CSV (impact_parameters.csv, free_paths.csv).  All files are written atomically; a
// failure throws IoError and publishes nothing incomplete.
#pragma once

#include <string>

#include "analysis/free_paths.hpp"
#include "analysis/impact_parameters.hpp"
#include "engine/system_params.hpp"

namespace granule {

struct CollisionStatisticsMetadata {
  SystemParams system;
  std::string boundary;
  std::string version;
  double from_t = 0.0, from_c = 0.0;  // the measurement window
  double to_t = 0.0, to_c = 0.0;
  FieldGrid density_grid;             // cells in which the local density is measured
};

// Either statistics may be null (switched off).  Writes `<dir>/collisions.h5` and the CSV tables.
void write_collision_statistics(const std::string& dir, const CollisionStatisticsMetadata& metadata,
                                const ImpactParameterStatistics* impacts, const FreePathStatistics* paths);

}  // namespace granule
