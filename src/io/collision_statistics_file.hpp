// Output of the collision statistics (schema in README.md, "collisions.h5"): impact parameters
// (3.19)–(3.21) and free paths (3.22)–(3.24), (3.36), with their summaries; plus the natural
// tables as CSV (impact_parameters.csv, free_paths.csv).  All files are written atomically; a
// failure throws IoError and publishes nothing incomplete.  A 3D file adds what says it is one
// (dimension, length_z, the variables (b/σ)² and cos θ, the isotropy distance, the Boltzmann and
// Enskog mean free paths); a 2D file carries none of these.
#pragma once

#include <string>

#include "observers/free_paths.hpp"
#include "observers/impact_parameters.hpp"
#include "engine/system_params.hpp"
#include "io/file_schema.hpp"

namespace granule {

struct CollisionStatisticsMetadata {
  SystemParams system;
  std::string boundary;
  std::string version;
  double from_t = 0.0, from_c = 0.0;  // the measurement window
  double to_t = 0.0, to_c = 0.0;
  FieldGrid density_grid;             // cells in which the local density is measured
  bool polydisperse = false;          // no monodisperse mean free path to compare with
};

// Either statistics may be null (switched off).  Writes `<dir>/collisions.h5` and the CSV tables.
template <int D>
void write_collision_statistics(const std::string& dir, const CollisionStatisticsMetadata& metadata,
                                const ImpactParameterStatistics<D>* impacts, const FreePathStatistics<D>* paths);

// The mean free path of monodisperse hard spheres of the metadata's system, 1/(√2 π n σ² χ):
// Boltzmann (χ = 1) and Enskog with the Carnahan–Starling contact value.
struct ReferenceMeanFreePaths {
  double boltzmann = 0.0, enskog = 0.0;
};
ReferenceMeanFreePaths sphere_mean_free_paths(const SystemParams& system);

// What collisions.h5 holds (io/file_schema.hpp), checked before a figure script reads it.
const h5::FileSchema& collision_statistics_schema();

}  // namespace granule
