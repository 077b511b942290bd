#include "render/config3d_picture.hpp"

#include <fmt/format.h>

#include "io/snapshot_file.hpp"
#include "render/plot_scripts.hpp"

namespace granule::render {

int draw_config_3d(const Config3dRequest& r) {
  // The frame passes Granule's checks (io/snapshot_file.hpp) before the script reads it with h5py:
  // a damaged file is refused with its reason, not met by a Python traceback.
  read_snapshot(r.snapshots, r.frame);
  std::vector<std::string> arguments{r.snapshots, "--out", r.out, "--frame", std::to_string(r.frame),
                                     "--width", std::to_string(r.width), "--color", r.color};
  if (!r.view.empty()) arguments.insert(arguments.end(), {"--view", fmt::format("{}", r.view.at(0)), fmt::format("{}", r.view.at(1))});
  if (r.perspective) arguments.emplace_back("--perspective");
  if (!r.legend) arguments.emplace_back("--no-legend");
  return run_plot_script("config3d", arguments);
}

}  // namespace granule::render
