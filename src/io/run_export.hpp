// What `granule plot export` writes of a run, from a run directory or one of its files: the
// particles of its snapshots (the writers of export_series.hpp; GSD is written by
// python/granule_plots/export_gsd.py), or its coarse-grained fields as VTK ImageData — those of its
// fields file, or the instantaneous fields of §1.4.3 computed from its snapshots — one frame or
// all of them, under a default name beside the input unless one is given.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "io/export_series.hpp"

namespace granule {

struct ExportRequest {
  std::string input;        // a run directory, a snapshot file or a fields file
  std::string format;       // "xyz", "gsd" or "vtk"
  std::int64_t frame = -1;  // negative counts from the end
  bool all_frames = false;
  std::string out;          // "": the default name beside the input
  std::vector<int> cells;   // fields from snapshots: NX NY (NZ in 3D); empty: ~40 disks, ~20 spheres a cell
  bool relative = false;    // fields from Lees–Edwards snapshots: velocities relative to the mean shear flow
};

// The particles to export: the snapshot file, its frames chosen, and the file written
// (particles_<k>.<format> for one frame; several: one multi-frame .xyz or .gsd, or a .pvd series).
struct ParticleExport {
  std::string snapshots;
  std::vector<std::int64_t> frames;
  std::string out;
};
ParticleExport plan_particle_export(const ExportRequest& request);
// A run's fixed obstacles beside its particles: obstacles.vtp (--format vtk) or obstacles.xyz
// (xyz), one frame of points at their centres with their radii (zero velocities), in the folder of
// `exported.out`; returns the path written, "" when the run has no obstacles (or for GSD).
std::string export_obstacles(const ParticleExport& exported, const std::string& format);

// Writes the fields (fields_<k>.vti for one frame, else a fields.pvd series): from the run's
// fields.h5 when it has one (or the input is a fields file), else computed from its snapshots.
// Bad input (a missing file, a frame or --cells that do not fit) throws InputError.
void export_fields(const ExportRequest& request, const ExportWritten& written);

}  // namespace granule
