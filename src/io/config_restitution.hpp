// How ẽ depends on the impact speed: the [system] keys restitution_law ("constant", "threshold",
// "viscoelastic"), elastic_below (v_c of the threshold law) and viscoelastic_constant (δ of the
// viscoelastic law), physics/restitution_law.hpp.
#pragma once

#include <string>

#include "io/config.hpp"
#include "io/config_reader.hpp"

namespace granule {

// Needs system.restitution and the diameter resolved first.
void resolve_restitution_law(const ConfigReader& in, RunConfig& c);
// The keys as TOML lines of [system] (restitution_law = "constant" alone for the thesis's law).
std::string restitution_law_to_toml(const RunConfig& c);

}  // namespace granule
