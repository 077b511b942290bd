#include "render/figure_scripts.hpp"

#include <utility>

#include "render/plot_scripts.hpp"

namespace granule::render {

namespace {

std::vector<std::string> common_arguments(const FigureRequest& r) {
  return {r.input, "--out", r.out, "--frame", std::to_string(r.frame), "--dpi", std::to_string(r.dpi)};
}

// `option value` for each value given; `option values…` for each list given.
void add_given(std::vector<std::string>& arguments, std::initializer_list<std::pair<const char*, const std::string*>> single,
               std::initializer_list<std::pair<const char*, const std::vector<std::string>*>> lists = {}) {
  for (const auto& [option, value] : single) {
    if (!value->empty()) arguments.insert(arguments.end(), {option, *value});
  }
  for (const auto& [option, values] : lists) {
    if (values->empty()) continue;
    arguments.emplace_back(option);
    arguments.insert(arguments.end(), values->begin(), values->end());
  }
}

}  // namespace

int draw_figure(const std::string& script, const FigureRequest& r) {
  std::vector<std::string> arguments = common_arguments(r);
  if (script == "fields") {
    arguments.insert(arguments.end(), {"--group", r.group, "--colormap", r.colormap});
    add_given(arguments, {{"--smooth", &r.smooth}, {"--average-frames", &r.average_frames}}, {{"--quantities", &r.quantities}});
  }
  if (script == "phase") arguments.insert(arguments.end(), {"--max-points", std::to_string(r.max_points)});
  if (r.window) arguments.insert(arguments.end(), {"--window", *r.window});
  add_given(arguments, {{"--data", &r.data}});
  return run_plot_script(script, arguments);
}

int draw_isosurface(const FigureRequest& r, bool colormap_chosen) {
  std::vector<std::string> arguments = common_arguments(r);
  arguments.insert(arguments.end(), {"--group", r.group});
  if (!r.quantities.empty()) arguments.insert(arguments.end(), {"--quantity", r.quantities[0]});
  if (colormap_chosen) arguments.insert(arguments.end(), {"--colormap", r.colormap});
  add_given(arguments, {{"--level", &r.level}, {"--smooth", &r.smooth}, {"--average-frames", &r.average_frames}, {"--color-by", &r.color_by}},
            {{"--view", &r.view}, {"--size", &r.size}});
  return run_plot_script("fields3d", arguments);
}

}  // namespace granule::render
