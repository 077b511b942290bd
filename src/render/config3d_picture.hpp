// The configuration picture of a 3D run (spheres as shaded disks, depth-sorted, coloured by v_x or
// the speed): drawn by python/granule_plots/config3d.py with Debian's Python, for `granule plot
// config` and for the picture every 3D `granule run` ends with.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace granule::render {

struct Config3dRequest {
  std::string snapshots;  // a snapshots.h5 with the root attribute dimension = 3
  std::string out;        // PNG
  std::int64_t frame = -1;
  int width = 1000;              // pixels; the height is 3/4 of it
  std::string color = "auto";    // auto (v_x under Lees–Edwards, else speed), velocity_x, speed, none
  std::vector<double> view;      // elevation, azimuth in degrees (empty: the script's default)
  bool perspective = false;
  bool legend = true;
};

// Runs the script and returns its exit code (2: bad input, nothing written).
int draw_config_3d(const Config3dRequest& request);

}  // namespace granule::render
