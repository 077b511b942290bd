#include "app/run/run_console.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <vector>

#include "driver/run_directory.hpp"
#include "io/config_description.hpp"
#include "granule/version.hpp"

namespace granule::app {

void print_header(const RunConfig& config, bool built_in_example, std::size_t overrides) {
  fmt::print("granule {}: {}\n", kVersion, describe_system(config));
  fmt::print("collision model: {}\n", collision_model_text(config.system));
  if (built_in_example) {
    fmt::print("config: the built-in example (no CONFIG given: a scaled-down System II of thesis §2.1, free cooling "
               "with the TC model t_c = 1e-7){}; the resolved config is written to config.toml\n",
               overrides > 0 ? fmt::format(" with {} --set override{}; keys not overridden keep the example's values",
                                           overrides, overrides == 1 ? "" : "s")
                             : std::string{});
  }
  for (const std::string& line : describe_surfaces(config)) fmt::print("{}\n", line);
  if (config.equilibrate > 0.0) fmt::print("elastic pre-run: {} collisions per particle\n", config.equilibrate);
}

std::string files_written_text(const std::string& out, std::filesystem::file_time_type since) {
  const std::vector<std::string> files = driver::files_written_since(out, since);
  return fmt::format("files written in {}: {}", out, files.empty() ? "none" : fmt::format("{}", fmt::join(files, ", ")));
}

}  // namespace granule::app
