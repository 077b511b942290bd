#include "render/spacetime_picture.hpp"

#include "io/atomic_file.hpp"
#include "io/spacetime_file.hpp"
#include "render/plot_scripts.hpp"

namespace granule::render {

int draw_spacetime(const SpacetimeProfiles& profiles, const std::string& out, const std::string& data, int dpi) {
  const std::string partial = data + ".partial";
  const RemovedAtExit cleanup{partial};
  write_spacetime_partial(data, profiles);
  const int status = run_plot_script("spacetime", {partial, "--out", out, "--dpi", std::to_string(dpi)});
  if (status != 0) return status;
  publish_file(partial, data);
  return 0;
}

}  // namespace granule::render
