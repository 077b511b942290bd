// A parameter sweep: a base run configuration plus a [sweep] table of keys → lists of values
// (README.md, "Sweeps").  Parsing expands it into its points and validates every point as
// `granule run` would, so that a bad spec is refused before anything is written.
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace granule::sweep {

// One swept key's value at a point: the `--set` text that gives it to `granule run` (TOML, exact)
// and the value as a person reads it (results.csv, the point's name).
struct PointSetting {
  std::string key;       // "system.restitution", "seed"
  std::string toml;      // "0.80000000000000004"
  std::string readable;  // "0.8"
};

// One run of the sweep: its directory name (readable, filesystem-safe, unique within the sweep)
// and the values of every swept key, in the order of SweepSpec::keys.
struct SweepPoint {
  std::string name;
  std::vector<PointSetting> settings;

  // The `--set key=value` assignments that turn the base configuration into this point's.
  std::vector<std::string> overrides() const;
};

struct SweepSpec {
  std::string base_toml;          // the spec without [sweep]: what every point starts from
  std::string canonical_toml;     // the whole spec, normalised (sweep.toml: a restart must match it)
  std::vector<std::string> keys;  // the swept keys, "seed" last when [sweep] seeds is given
  std::vector<SweepPoint> points;
};

struct SweepSpecResult {
  std::optional<SweepSpec> spec;
  std::string error;  // names the [sweep] key (or the point and the config key) and what is allowed
};

// `text` is the TOML of a sweep spec: run-config keys plus [sweep] (keys → non-empty lists;
// `zip = true` or a list of keys that vary together; `seeds` = a list of seeds, or a count of
// seeds from the base seed on).  Every point is checked with the run configuration's parser.
SweepSpecResult parse_sweep_spec(const std::string& text);
SweepSpecResult load_sweep_spec(const std::string& path);

}  // namespace granule::sweep
