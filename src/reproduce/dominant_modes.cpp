#include "reproduce/dominant_modes.hpp"

#include "reproduce/run_outputs.hpp"

namespace granule::reproduce {

std::vector<DominantMode> dominant_modes(const std::string& path, const std::string& field) {
  std::vector<DominantMode> out;
  for (const auto& row : read_csv_rows(path)) {
    if (row.at("field") != field) continue;
    out.push_back({std::stod(row.at("c")), std::stod(row.at("length")), row.at("significant") == "1"});
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
