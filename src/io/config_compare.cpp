#include "io/config_compare.hpp"

#include <toml++/toml.h>

#include <map>
#include <sstream>

namespace granule {

namespace {

// Keys a resumed run may change (README, "Leaving runs unattended").
bool may_change(const std::string& key) { return key.rfind("run.", 0) == 0 || key.rfind("output.", 0) == 0; }

void flatten(const toml::table& table, const std::string& prefix, std::map<std::string, std::string>& out) {
  for (const auto& [name, node] : table) {
    const std::string key = prefix + std::string(name.str());
    if (const toml::table* inner = node.as_table()) {
      flatten(*inner, key + ".", out);
      continue;
    }
    if (may_change(key)) continue;
    std::ostringstream text;
    node.visit([&](const auto& value) { text << value; });
    out[key] = text.str();
  }
}

}  // namespace

std::vector<std::string> physics_differences(const std::string& checkpoint_toml, const std::string& current_toml) {
  std::map<std::string, std::string> saved, current;
  try {
    flatten(toml::parse(checkpoint_toml), "", saved);
  } catch (const toml::parse_error& error) {
    return {"the configuration recorded in the checkpoint is not TOML: " + std::string(error.description())};
  }
  try {
    flatten(toml::parse(current_toml), "", current);
  } catch (const toml::parse_error& error) {
    return {"the configuration is not TOML: " + std::string(error.description())};
  }
  std::vector<std::string> differences;
  for (const auto& [key, value] : saved) {
    const auto now = current.find(key);
    if (now == current.end()) {
      differences.push_back(key + ": " + value + " in the checkpoint, absent now");
    } else if (now->second != value) {
      differences.push_back(key + ": " + value + " in the checkpoint, " + now->second + " now");
    }
  }
  for (const auto& [key, value] : current) {
    if (!saved.count(key)) differences.push_back(key + ": absent in the checkpoint, " + value + " now");
  }
  return differences;
}

}  // namespace granule
