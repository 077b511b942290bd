// The physics of a run as its resolved configuration records it (to_toml), compared key by key:
// a resumed run must be the run its checkpoint was written by, so every key but those a resumed
// run may change (run.*: how long to run; output.*: what to write) must be equal.
#pragma once

#include <string>
#include <vector>

namespace granule {

// "system.restitution: 0.6 in the checkpoint, 0.7 now" for each key whose value differs, is
// missing from one side, or is new; empty when the physics is the same.  Either text that is not
// TOML gives one line saying so.
std::vector<std::string> physics_differences(const std::string& checkpoint_toml, const std::string& current_toml);

}  // namespace granule
