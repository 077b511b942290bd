#include "reproduce/dominant_modes.hpp"

#include <cstdlib>

#include "reproduce/run_outputs.hpp"

namespace granule::reproduce {

RunModes dominant_modes(const std::string& path) {
  RunModes out;
  for (const auto& row : read_csv_rows(path)) {
    const std::string& field = row.at("field");
    if (field != "R" && field != "P") continue;
    (field == "R" ? out.mass : out.momentum)
        .push_back({std::stod(row.at("c")), std::stod(row.at("length")), row.at("significant") == "1",
                    // strtod: p-values below the smallest normal double are 0 to the claims, not an error as for stod.
                    std::strtod(row.at("noise_p_value").c_str(), nullptr)});
  }
  return out;
}

const DominantMode* first_persistent_mode(const std::vector<DominantMode>& frames) {
  int run = 0;
  for (std::size_t k = 0; k < frames.size(); ++k) {
    const bool same = k > 0 && frames[k].length == frames[k - 1].length;
    run = !frames[k].significant ? 0 : run > 0 && same ? run + 1 : 1;
    if (run == kPersistentFrames) return &frames[k + 1 - kPersistentFrames];
  }
  return nullptr;
}

}  // namespace granule::reproduce
