// Configuration pictures of a run's saved snapshots (the cairo renderer of
// configuration_picture.hpp), and the picture every `granule run` ends with.
#pragma once

#include <cstdint>
#include <string>

#include "io/snapshot_file.hpp"
#include "render/configuration_picture.hpp"

namespace granule::render {

// Renders one frame read from a snapshot file.
RasterImage render_snapshot_picture(const SnapshotRead& snapshot, const PictureOptions& options);

// Rough grains are coloured by their spin unless the colouring was chosen (thesis Fig C.4); spin
// colours for smooth grains throw InputError.
void choose_spin_coloring(PictureOptions& options, bool coloring_chosen, const SnapshotMetadata& metadata);

// Draws frame `frame` (negative counts from the end) of a 2D snapshot file to the PNG `out`, rough
// grains by choose_spin_coloring; returns the frame's index.  A frame outside the file throws InputError.
std::int64_t write_snapshot_picture(const std::string& snapshots, std::int64_t frame, PictureOptions options,
                                    bool coloring_chosen, const std::string& out);

// Writes `<out_dir>/configuration.png`: the last snapshot of the run, disks coloured by velocity
// direction with the coarse-grained velocity field as arrows (thesis Figs 2.2, 2.3); Lees–Edwards
// runs are coloured relative to the mean shear flow, rough grains by their spin; a 3D run gets the
// sphere picture of config3d_picture.hpp.  Returns the path written.
std::string render_run_picture(const std::string& out_dir);

}  // namespace granule::render
