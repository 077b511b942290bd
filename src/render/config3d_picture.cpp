#include "render/config3d_picture.hpp"

#include <fmt/format.h>

#include "render/plot_scripts.hpp"

namespace granule::render {

int draw_config_3d(const Config3dRequest& r) {
  std::vector<std::string> arguments{r.snapshots, "--out", r.out, "--frame", std::to_string(r.frame),
                                     "--width", std::to_string(r.width), "--color", r.color};
  if (!r.view.empty()) arguments.insert(arguments.end(), {"--view", fmt::format("{}", r.view.at(0)), fmt::format("{}", r.view.at(1))});
  if (r.perspective) arguments.emplace_back("--perspective");
  if (!r.legend) arguments.emplace_back("--no-legend");
  return run_plot_script("config3d", arguments);
}

}  // namespace granule::render
