// Configuration pictures of saved snapshots (the C++ cairo renderer of src/render), and the
// picture every `granule run` ends with.
#pragma once

#include <string>

#include "io/snapshot_file.hpp"
#include "render/configuration_picture.hpp"

namespace granule::app {

// Renders one frame read from a snapshot file.
render::RasterImage render_snapshot_picture(const SnapshotRead& snapshot, const render::PictureOptions& options);

// Writes `<out_dir>/configuration.png`: the last snapshot of the run, disks coloured by velocity
// direction with the coarse-grained velocity field as arrows (thesis Figs 2.2, 2.3); Lees–Edwards
// runs are coloured relative to the mean shear flow, rough grains by their spin; a 3D run gets the sphere picture of
// plot_config3d.hpp.  Returns the path written.
std::string render_run_picture(const std::string& out_dir);

}  // namespace granule::app
