#include "app/plot/plot_command.hpp"

#include <fmt/format.h>

#include "io/io_error.hpp"

namespace granule::app {

void add_plot_command(CLI::App& root) {
  CLI::App* plot = root.add_subcommand(
      "plot", "Draw pictures, movies and exports from a run's outputs (RUN_DIR or a file; see docs/plots.md)");
  plot->require_subcommand(1);
  add_plot_picture_commands(*plot);
  add_plot_matplotlib_commands(*plot);
  add_plot_spacetime_command(*plot);
  add_plot_export_command(*plot);
  add_plot_sweep_command(*plot);
}

std::vector<std::string> given_options(const CLI::App& command) {
  std::vector<std::string> given;
  for (const CLI::Option* option : command.get_options()) {
    if (option->count() > 0) given.push_back(option->get_name());
  }
  return given;
}

void finish_plot_command(const std::string& kind, const std::function<int()>& body) {
  int code = 0;
  std::string message;
  try {
    code = body();
  } catch (const InputError& error) {
    code = 2;
    message = error.what();
  } catch (const IoError& error) {
    code = 4;
    message = error.what();
  } catch (const std::exception& error) {
    code = 1;
    message = error.what();
  }
  if (!message.empty()) fmt::print(stderr, "granule plot {}: error: {}\n", kind, message);
  throw CLI::RuntimeError(code);
}

}  // namespace granule::app
